//! Mixing: where it ends and how fast diffusion gets there.
//!
//! - Rods between walls conserve only their energy; on the energy shell the
//!   rescaled velocities sqrt(m_i) v_i are uniform on a sphere, so the energy
//!   shares K_i / K are Dirichlet(1/2, ..., 1/2) whatever the masses: each
//!   share averages 1/N and the concentration Y = sum (K_i / K)^2 averages
//!   3 / (N + 2).
//! - Two gases started in the two halves of a box with walls at x = 0 and
//!   L, mixing by diffusion: the concentration of the first obeys the
//!   diffusion equation with no flux through the walls, from a step. Its
//!   modes are cos(k pi x / L); the fraction of it still in its own half is
//!   1/2 + sum over odd k of 4 / (pi k)^2 exp(-k^2 t / tau), with
//!   tau = L^2 / (pi^2 D) the slowest mode's time.
//! - Self-diffusion of hard disks (diameter sigma, mass m) in a dilute gas,
//!   first Chapman-Enskog approximation: D0 = (1 / (2 n sigma)) sqrt(kT /
//!   (pi m)); Enskog's dense-gas theory divides it by the contact value of
//!   the pair distribution g(sigma) (Gass 1971, J. Chem. Phys. 54, 1898).
//! - Two kinds of equal disks that differ in mass: the pair (i, j) diffuses
//!   with its reduced mass, D_ij = (1 / (2 n sigma g)) sqrt(kT (m_i + m_j)
//!   / (2 pi m_i m_j)), and a tracer of kind i with 1 / D_i = sum_j x_j /
//!   D_ij (first Chapman-Enskog approximation for a mixture, Chapman and
//!   Cowling 1970, ch. 9; higher approximations correct it, the more the
//!   more unequal the masses).

use std::f64::consts::{E, PI};

/// Mean energy concentration sum (K_i / K)^2 of `n` rods between walls at
/// equilibrium (microcanonical: energy the only conserved quantity).
pub fn equilibrium_concentration(n: usize) -> f64 {
    3.0 / (n as f64 + 2.0)
}

/// Standard deviation of that concentration at equilibrium: with shares
/// Dirichlet(1/2, ..., 1/2), Var Y = sum_ij E[x_i^2 x_j^2] - (E Y)^2.
pub fn equilibrium_concentration_std(n: usize) -> f64 {
    let a = n as f64 / 2.0;
    // Rising factorials of the total: a (a + 1) (a + 2) (a + 3).
    let rise4 = a * (a + 1.0) * (a + 2.0) * (a + 3.0);
    // E x^4 = (1/2)(3/2)(5/2)(7/2) / rise4; E x_i^2 x_j^2 = ((1/2)(3/2))^2 / rise4.
    let same = 105.0 / 16.0 / rise4;
    let other = 9.0 / 16.0 / rise4;
    let nf = n as f64;
    let second = nf * same + nf * (nf - 1.0) * other;
    let mean = equilibrium_concentration(n);
    (second - mean * mean).max(0.0).sqrt()
}

/// Excess over 1/2 of the fraction of a gas still in the half it started
/// in, diffusing with slowest-mode time `tau`, at time `t` (1/2 at t = 0).
pub fn step_excess(t: f64, tau: f64) -> f64 {
    if t <= 0.0 {
        return 0.5;
    }
    let mut sum = 0.0;
    let mut k = 1.0;
    loop {
        let term = 4.0 / (PI * k).powi(2) * (-k * k * t / tau).exp();
        sum += term;
        if term < 1e-16 {
            return sum;
        }
        k += 2.0;
    }
}

/// When `step_excess` first falls to 1/e of its start: the diffusive
/// prediction of the mixing time as the study measures it, in units of tau
/// times `tau`.
pub fn step_mixing_time(tau: f64) -> f64 {
    let level = 0.5 / E;
    let (mut lo, mut hi) = (0.0, 2.0 * tau);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if step_excess(mid, tau) > level {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Slowest diffusive time L^2 / (pi^2 D) of a box of length `length`.
pub fn slowest_mode_time(length: f64, diffusion: f64) -> f64 {
    length * length / (PI * PI * diffusion)
}

/// Dilute self-diffusion coefficient of hard disks of diameter `sigma`
/// and mass `m` at number density `n` and temperature `kt` (first
/// Chapman-Enskog approximation).
pub fn disk_diffusion_dilute(n: f64, sigma: f64, kt: f64, m: f64) -> f64 {
    (kt / (PI * m)).sqrt() / (2.0 * n * sigma)
}

/// Enskog's self-diffusion of hard disks at packing fraction `eta`: the
/// dilute value over the contact value g(sigma), here from Henderson's
/// equation of state (Z = 1 + 2 eta g(sigma) for disks).
pub fn disk_diffusion_enskog(n: f64, sigma: f64, kt: f64, m: f64, eta: f64) -> f64 {
    let contact = if eta > 0.0 {
        (super::henderson::z(eta) - 1.0) / (2.0 * eta)
    } else {
        1.0
    };
    disk_diffusion_dilute(n, sigma, kt, m) / contact
}

/// Enskog's self-diffusion of each kind in a mixture of equal disks of
/// masses `m` at fractions `x`, averaged with weights `x`: the
/// count-weighted mean of the two tracer coefficients, which is what the
/// mixing study measures.
pub fn disk_mixture_diffusion_enskog(
    n: f64,
    sigma: f64,
    kt: f64,
    m: [f64; 2],
    x: [f64; 2],
    eta: f64,
) -> f64 {
    let tracer = |i| disk_tracer_diffusion_enskog(n, sigma, kt, m[i], m, x, eta);
    x[0] * tracer(0) + x[1] * tracer(1)
}

/// A disk of mass `mi` among the mixture: 1 / D_i = sum_j x_j / D_ij.
fn disk_tracer_diffusion_enskog(
    n: f64,
    sigma: f64,
    kt: f64,
    mi: f64,
    m: [f64; 2],
    x: [f64; 2],
    eta: f64,
) -> f64 {
    // The pair moves with its reduced mass mi mj / (mi + mj): half the
    // mass whose one-kind D equals D_ij.
    let pair = |mj: f64| disk_diffusion_enskog(n, sigma, kt, 2.0 * mi * mj / (mi + mj), eta);
    1.0 / (x[0] / pair(m[0]) + x[1] / pair(m[1]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mixture_of_equal_masses_diffuses_as_one_kind() {
        let one = disk_diffusion_enskog(0.3, 1.0, 1.2, 2.0, 0.2);
        let both = disk_mixture_diffusion_enskog(0.3, 1.0, 1.2, [2.0; 2], [0.3, 0.7], 0.2);
        assert!((both / one - 1.0).abs() < 1e-14);
    }

    #[test]
    fn a_light_disk_among_fixed_ones_is_the_lorentz_gas() {
        // Scatterers too heavy to move: the relative speed is the tracer's
        // own, not sqrt(2) times it as among its like, so D is 1/sqrt(2)
        // of the one-kind value. A heavy tracer among light disks is the
        // Brownian limit: the light gas's friction, whatever its mass M,
        // gives the same D (the pair's reduced mass is the light one's).
        let d1 = disk_diffusion_enskog(0.3, 1.0, 1.0, 1.0, 0.2);
        let heavy = [1.0, 1e12];
        let light = disk_tracer_diffusion_enskog(0.3, 1.0, 1.0, 1.0, heavy, [0.0, 1.0], 0.2);
        assert!((light * 2f64.sqrt() / d1 - 1.0).abs() < 1e-9);
        let slow = disk_tracer_diffusion_enskog(0.3, 1.0, 1.0, 1e12, heavy, [1.0, 0.0], 0.2);
        assert!((slow * 2f64.sqrt() / d1 - 1.0).abs() < 1e-9);
    }

    #[test]
    fn the_step_starts_at_one_half_and_decays_as_its_slowest_mode() {
        // sum over odd k of 1/k^2 is pi^2/8: the series starts at 1/2.
        assert!((step_excess(1e-9, 1.0) - 0.5).abs() < 1e-3);
        let late = step_excess(3.0, 1.0) / (4.0 / (PI * PI) * (-3.0f64).exp());
        assert!((late - 1.0).abs() < 1e-9);
        let t = step_mixing_time(2.0);
        assert!((step_excess(t, 2.0) - 0.5 / E).abs() < 1e-12);
        assert!(t > 0.0 && t < 2.0);
        // In units of tau the 1/e time is 0.790 (docs/mixing.md).
        assert!((step_mixing_time(1.0) - 0.7902).abs() < 1e-4);
    }

    #[test]
    fn enskog_differs_from_the_dilute_value_by_g_even_when_dilute() {
        // Henderson's contact value at eta = 0.05 is 1.0838: 8 % (docs/mixing.md).
        let ratio = disk_diffusion_dilute(1.0, 1.0, 1.0, 1.0)
            / disk_diffusion_enskog(1.0, 1.0, 1.0, 1.0, 0.05);
        let by_hand = ((1.0 + 0.05f64.powi(2) / 8.0) / 0.95f64.powi(2) - 1.0) / 0.1;
        assert!((ratio - by_hand).abs() < 1e-12);
        assert!((ratio - 1.0838).abs() < 1e-4);
    }

    #[test]
    fn equilibrium_concentration_matches_a_direct_draw() {
        // Sample the Dirichlet(1/2, ...) shares as normalised squared Gaussians.
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let n = 7;
        let draws = 200_000;
        let (mut s, mut s2) = (0.0, 0.0);
        for _ in 0..draws {
            let g: Vec<f64> = (0..n)
                .map(|_| crate::engine::thermal::gaussian(&mut rng).powi(2))
                .collect();
            let total: f64 = g.iter().sum();
            let y: f64 = g.iter().map(|x| (x / total).powi(2)).sum();
            s += y;
            s2 += y * y;
        }
        let mean = s / draws as f64;
        let std = (s2 / draws as f64 - mean * mean).sqrt();
        let se = std / (draws as f64).sqrt();
        assert!((mean - equilibrium_concentration(n)).abs() < 4.0 * se);
        assert!((std / equilibrium_concentration_std(n) - 1.0).abs() < 0.02);
    }

    #[test]
    fn enskog_is_the_dilute_value_at_low_density() {
        let d0 = disk_diffusion_dilute(0.01, 1.0, 1.0, 1.0);
        assert!((d0 - 50.0 / PI.sqrt()).abs() < 1e-9);
        let de = disk_diffusion_enskog(0.01, 1.0, 1.0, 1.0, 1e-9);
        assert!((de / d0 - 1.0).abs() < 1e-6);
        // g(sigma) = 1.5 / 0.49... at eta = 0.3: (z - 1) / 0.6.
        let g = (super::super::henderson::z(0.3) - 1.0) / 0.6;
        assert!(
            (disk_diffusion_enskog(1.0, 1.0, 1.0, 1.0, 0.3) * g
                - disk_diffusion_dilute(1.0, 1.0, 1.0, 1.0))
            .abs()
                < 1e-12
        );
    }
}
