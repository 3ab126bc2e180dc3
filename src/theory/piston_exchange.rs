//! In 2D and 3D the piston compresses a gas along x only: its x-motion heats
//! first, and collisions share that heat with the other axes. The gas is a
//! relaxing medium (Debye): compressed slowly it follows its adiabat,
//! gamma_0 = (d + 2)/d; quickly, the collisionless one, gamma_inf = 3; in
//! between it lags behind and dissipates: a compression along one axis is
//! partly a shear, which the shear viscosity resists (dilute hard disks have
//! no bulk viscosity; uniaxial strain gives sigma_xx = eta d(eps)/dt in 2D).
//! Each gas's stiffness is k (1 + (Delta/gamma_0) i w tau / (1 + i w tau)),
//! Delta = gamma_inf - gamma_0, tau the time in which the anisotropy of its
//! kinetic energy relaxes at fixed volume: tau = eta / p, with eta the
//! Chapman–Enskog shear viscosity (first Sonine approximation,
//! eta = (d + 2) Gamma(d/2) sqrt(m kT) / (8 pi^((d-1)/2) sigma^(d-1))), p = n kT g
//! (the collision rate scaled by the contact value g of the pair
//! distribution). Nothing of this exists in 1D, where a gas has one axis.

use std::f64::consts::PI;

/// Time in which the anisotropy of a gas's kinetic energy relaxes, eta/(n kT g):
/// disks eta = sqrt(m kT / pi) / (2 sigma), spheres 5 sqrt(m kT / pi) / (16 sigma^2);
/// g from Henderson (disks) or Carnahan–Starling (spheres) at packing
/// fraction `phi`. Infinite in 1D.
pub fn exchange_time(
    dimension: usize,
    density: f64,
    sigma: f64,
    mass: f64,
    kt: f64,
    phi: f64,
) -> f64 {
    let root = (mass * kt / PI).sqrt();
    let (eta, contact) = match dimension {
        2 => (
            root / (2.0 * sigma),
            (1.0 - 7.0 * phi / 16.0) / (1.0 - phi).powi(2),
        ),
        3 => (
            5.0 * root / (16.0 * sigma * sigma),
            (1.0 - 0.5 * phi) / (1.0 - phi).powi(3),
        ),
        _ => return f64::INFINITY,
    };
    eta / (density * kt * contact)
}

/// The two gases as relaxing springs: (stiffness, exchange time) per side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Relaxing {
    pub dimension: usize,
    pub sides: [(f64, f64); 2],
}

impl Relaxing {
    /// (Re k(w) / k(0), Im k(w) / Re k(w)): how much stiffer the gases are
    /// at angular frequency w, and the energy they dissipate per radian.
    pub fn response(&self, omega: f64) -> (f64, f64) {
        let g0 = (self.dimension as f64 + 2.0) / self.dimension as f64;
        let step = (3.0 - g0) / g0;
        let (mut k0, mut re, mut im) = (0.0, 0.0, 0.0);
        for &(k, tau) in &self.sides {
            let wt = if tau.is_finite() { omega * tau } else { 0.0 };
            let lag = 1.0 / (1.0 + wt * wt);
            k0 += k;
            re += k * (1.0 + step * wt * wt * lag);
            im += k * step * wt * lag;
        }
        (re / k0, im / re)
    }

    /// The frequency of the relaxing oscillator whose frequency with
    /// instantly shared heat is `omega0`: w^2 = omega0^2 Re k(w) / k(0),
    /// between omega0 and the collisionless sqrt(gamma_inf / gamma_0) omega0.
    pub fn frequency(&self, omega0: f64) -> f64 {
        let g0 = (self.dimension as f64 + 2.0) / self.dimension as f64;
        let (mut lo, mut hi) = (omega0, omega0 * (3.0 / g0).sqrt().max(1.0));
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if mid * mid < omega0 * omega0 * self.response(mid).0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// Time in which the oscillation's energy falls by e at angular
    /// frequency w: 1 / (w Im k / Re k).
    pub fn decay_time(&self, omega: f64) -> f64 {
        1.0 / (omega * self.response(omega).1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The limits: slow compression is adiabatic and lossless, fast is
    /// collisionless (gamma 3 over 2 in 2D) and lossless; the loss peaks at
    /// w tau = 1 (one side) where the stiffening is half its full value.
    #[test]
    fn debye_limits_and_peak() {
        let r = Relaxing {
            dimension: 2,
            sides: [(1.0, 10.0), (0.0, 10.0)],
        };
        let (slow, loss_slow) = r.response(1e-9);
        let (fast, loss_fast) = r.response(1e6);
        assert!((slow - 1.0).abs() < 1e-9 && loss_slow < 1e-6);
        assert!((fast - 1.5).abs() < 1e-9 && loss_fast < 1e-6);
        let (mid, loss) = r.response(0.1);
        assert!((mid - 1.25).abs() < 1e-12);
        // Im/Re = 0.5 * 0.5 / 1.25.
        assert!((loss - 0.2).abs() < 1e-12);
        // Slow: decay time 1 / (w^2 tau Delta/gamma_0) = 2 / (w^2 tau), up to
        // 1.5 (w tau)^2.
        let w = 1e-4;
        assert!((r.decay_time(w) * w * w * 10.0 / 2.0 - 1.0).abs() < 2e-6);
        assert!(!r.frequency(0.1).is_nan());
        let w = r.frequency(0.1);
        assert!((w * w - 0.01 * r.response(w).0).abs() < 1e-12);
    }

    /// tau = eta/p is the mean free time of dilute disks: each sweeps a
    /// strip 2 sigma wide at the mean relative speed sqrt(pi kT/m).
    #[test]
    fn disks_relax_in_a_free_time() {
        let (n, sigma, m, kt) = (0.02, 1.0, 1.3, 0.8);
        let free = 1.0 / (2.0 * sigma * n * (PI * kt / m).sqrt());
        assert!((exchange_time(2, n, sigma, m, kt, 0.0) / free - 1.0).abs() < 1e-12);
        assert!(exchange_time(1, n, sigma, m, kt, 0.0).is_infinite());
    }
}
