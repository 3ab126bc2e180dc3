//! Heat exchange with thermal walls and heat conduction in a hard-particle
//! gas (docs/heat.md derives each formula). Reduced units: k = 1.
//!
//! - A full-accommodation wall at T_w sends each particle that hits it back
//!   with the flux-weighted Maxwellian: mean energy (d + 1)/2 T_w (T_w from
//!   the normal Rayleigh component, T_w/2 per tangential one). The particles
//!   hitting it from a Maxwellian gas at T bring (d + 1)/2 T on average, at a
//!   rate n_c sqrt(T / 2 pi m) per unit wall area, n_c the density at contact
//!   (beta P for hard particles at a hard wall).
//! - A gas that stays uniform and Maxwellian ("well mixed") then obeys
//!   dT/dt = c sqrt(T) (T_w - T), solved in closed form by `WellMixed`.
//! - Conductivity: Chapman-Enskog (first Sonine approximation) for the dilute
//!   gas, times Enskog's dense-gas factor with the contact value g(sigma)
//!   of Henderson (disks) or Carnahan-Starling (spheres): Gass 1971 for
//!   disks, Chapman and Cowling ch. 16 for spheres.

use std::f64::consts::PI;

/// Mean kinetic energy of a particle a thermal wall at `kt` emits, over kt:
/// (d + 1)/2 (the same mean that the particles hitting a wall bring from a
/// Maxwellian gas at its own temperature).
pub fn emitted_energy(dimension: usize) -> f64 {
    (dimension as f64 + 1.0) / 2.0
}

/// Wall hits per unit time and wall area from a Maxwellian gas with density
/// `contact` at the wall: n_c <v_x; v_x > 0> = n_c sqrt(kT / (2 pi m)).
pub fn hit_rate(contact: f64, kt: f64, mass: f64) -> f64 {
    contact * (kt / (2.0 * PI * mass)).sqrt()
}

/// Contact value g(sigma) of the pair distribution: Tonks (rods),
/// Henderson 1975 (disks), Carnahan-Starling (spheres), at packing
/// fraction `phi`.
pub fn contact_value(dimension: usize, phi: f64) -> f64 {
    match dimension {
        1 => 1.0 / (1.0 - phi),
        2 => (1.0 - 7.0 * phi / 16.0) / (1.0 - phi).powi(2),
        3 => (1.0 - 0.5 * phi) / (1.0 - phi).powi(3),
        _ => f64::NAN,
    }
}

/// Compressibility factor beta P / n from the contact value: 1 + 2^(d-1) phi g.
pub fn compressibility(dimension: usize, phi: f64) -> f64 {
    1.0 + 2f64.powi(dimension as i32 - 1) * phi * contact_value(dimension, phi)
}

/// The temperature of a well-mixed gas exchanging heat with walls at `wall`:
/// dT/dt = rate sqrt(T) (T_w - T), T(0) = `start`. With s = sqrt(T):
/// ds/dt = (rate/2)(T_w - s^2), so s = s_w tanh(r t + artanh(s0/s_w)) when
/// heating and s_w coth(r t + arcoth(s0/s_w)) when cooling, r = rate s_w/2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WellMixed {
    pub rate: f64,
    pub wall: f64,
    pub start: f64,
}

impl WellMixed {
    /// `u` of the closed form at time `t`, the argument of tanh or coth.
    fn u(&self, t: f64) -> f64 {
        let (sw, s0) = (self.wall.sqrt(), self.start.sqrt());
        let r = self.rate * sw / 2.0;
        let x = s0 / sw;
        let u0 = if x < 1.0 {
            x.atanh()
        } else {
            0.5 * ((x + 1.0) / (x - 1.0)).ln()
        };
        u0 + r * t
    }

    pub fn temperature(&self, t: f64) -> f64 {
        if self.start == self.wall {
            return self.wall;
        }
        let s = if self.start < self.wall {
            self.u(t).tanh()
        } else {
            1.0 / self.u(t).tanh()
        };
        self.wall * s * s
    }

    /// Time at which T - T_w has fallen to `fraction` of T0 - T_w.
    pub fn time_to(&self, fraction: f64) -> f64 {
        let target = self.wall + fraction * (self.start - self.wall);
        let x = (target / self.wall).sqrt();
        let u = if x < 1.0 {
            x.atanh()
        } else {
            0.5 * ((x + 1.0) / (x - 1.0)).ln()
        };
        (u - self.u(0.0)) / (self.rate * self.wall.sqrt() / 2.0)
    }

    /// The 1/e time: T - T_w falls to 1/e of its start.
    pub fn relaxation_time(&self) -> f64 {
        self.time_to(1.0 / std::f64::consts::E)
    }

    /// The linearised time near T_w: 1 / (rate sqrt(T_w)).
    pub fn linear_time(&self) -> f64 {
        1.0 / (self.rate * self.wall.sqrt())
    }
}

/// Rate constant `c` of dT/dt = c sqrt(T) (T_w - T) for N particles of
/// mass `mass` in `dimension` dimensions with thermal walls of total area
/// `area` and the density `contact` at them: every hit moves (d + 1)/2
/// (T_w - T) of energy on average, and E = d N T / 2.
pub fn exchange_rate(dimension: usize, particles: f64, area: f64, contact: f64, mass: f64) -> f64 {
    let d = dimension as f64;
    2.0 / (d * particles) * area * hit_rate(contact, 1.0, mass) * emitted_energy(dimension)
}

/// Dilute-gas (Chapman-Enskog, first Sonine approximation) thermal
/// conductivity of hard disks, (2/sigma) sqrt(kT/(pi m)), or spheres,
/// (75/(64 sigma^2)) sqrt(kT/(pi m)). Rods do not conduct normally (NaN).
pub fn conductivity_dilute(dimension: usize, sigma: f64, mass: f64, kt: f64) -> f64 {
    let root = (kt / (PI * mass)).sqrt();
    match dimension {
        2 => 2.0 / sigma * root,
        3 => 75.0 / (64.0 * sigma * sigma) * root,
        _ => f64::NAN,
    }
}

/// Enskog's conductivity over the dilute one at packing fraction `phi`:
/// (1/g)(1 + 3y/(d + 2))^2 + c_d phi^2 g with y = 2^(d-1) phi g (= B2 n g):
/// the kinetic part, raised by collisional transfer, plus the collisional
/// transfer of the local equilibrium, c_2 = 4/pi, c_3 = 512/(25 pi). For
/// disks this is 1/g + 3 phi + (9/4 + 4/pi) phi^2 g; for spheres
/// 1/g + (6/5) b n + (9/25)(1 + 32/(9 pi)) (b n)^2 g, b n = 4 phi.
pub fn enskog_factor(dimension: usize, phi: f64) -> f64 {
    let g = contact_value(dimension, phi);
    let d = dimension as f64;
    let y = 2f64.powi(dimension as i32 - 1) * phi * g;
    let collisional = match dimension {
        2 => 4.0 / PI,
        3 => 512.0 / (25.0 * PI),
        _ => return f64::NAN,
    };
    (1.0 + 3.0 * y / (d + 2.0)).powi(2) / g + collisional * phi * phi * g
}

/// Mean free path of the dilute gas at number density `n`: 1/(2 sqrt2 n
/// sigma) for disks, 1/(sqrt2 pi n sigma^2) for spheres; infinite for
/// points, NaN for rods (they never pass each other).
pub fn mean_free_path(dimension: usize, n: f64, sigma: f64) -> f64 {
    match dimension {
        2 => 1.0 / (2.0 * 2f64.sqrt() * n * sigma),
        3 => 1.0 / (2f64.sqrt() * PI * n * sigma * sigma),
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn well_mixed_solves_its_equation() {
        for (t0, tw) in [(2.0, 1.0), (0.5, 1.0), (0.2, 3.0)] {
            let m = WellMixed {
                rate: 0.3,
                wall: tw,
                start: t0,
            };
            assert!((m.temperature(0.0) - t0).abs() < 1e-12);
            for t in [0.1, 1.0, 5.0] {
                let h = 1e-5;
                let slope = (m.temperature(t + h) - m.temperature(t - h)) / (2.0 * h);
                let want = 0.3 * m.temperature(t).sqrt() * (tw - m.temperature(t));
                assert!((slope - want).abs() < 1e-7, "{slope} {want}");
            }
            assert!((m.temperature(200.0) - tw).abs() < 1e-9);
            let tau = m.relaxation_time();
            let excess = (m.temperature(tau) - tw) / (t0 - tw);
            assert!((excess - (-1f64).exp()).abs() < 1e-9);
        }
    }

    #[test]
    fn enskog_reduces_to_the_known_forms() {
        for phi in [0.0, 0.1, 0.3] {
            let g = contact_value(2, phi);
            let disks = 1.0 / g + 3.0 * phi + (2.25 + 4.0 / PI) * phi * phi * g;
            assert!((enskog_factor(2, phi) - disks).abs() < 1e-12);
            let g = contact_value(3, phi);
            let bn = 4.0 * phi;
            let spheres = 1.0 / g + 1.2 * bn + 0.36 * (1.0 + 32.0 / (9.0 * PI)) * bn * bn * g;
            assert!((enskog_factor(3, phi) - spheres).abs() < 1e-12);
        }
        assert_eq!(enskog_factor(2, 0.0), 1.0);
        // Eucken: the 2D first Sonine conductivity is 4 (k/m) eta0.
        let eta0 = (1.0 / PI).sqrt() / 2.0;
        assert!((conductivity_dilute(2, 1.0, 1.0, 1.0) - 4.0 * eta0).abs() < 1e-12);
        assert!((compressibility(2, 0.3) - crate::theory::henderson::z(0.3)).abs() < 1e-12);
    }

    /// docs/heat.md: disks between two walls a distance L apart (height h,
    /// both walls thermal) relax near T_w in (1/3) L sqrt(2 pi m / kT_w) / Z.
    #[test]
    fn the_linear_time_between_two_walls() {
        let (length, height, density, phi, mass, kt) = (40.0, 10.0, 0.2, 0.157, 2.0, 1.5);
        let particles = density * length * height;
        let z = compressibility(2, phi);
        let rate = exchange_rate(2, particles, 2.0 * height, z * density, mass);
        let linear = WellMixed {
            rate,
            wall: kt,
            start: 2.0 * kt,
        }
        .linear_time();
        let by_hand = length * (2.0 * PI * mass / kt).sqrt() / (3.0 * z);
        assert!((linear / by_hand - 1.0).abs() < 1e-12, "{linear} {by_hand}");
    }
}
