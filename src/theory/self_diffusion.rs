//! Self-diffusion of hard disks and spheres from kinetic theory, the
//! coefficient a diffusive picture of the expansion needs.
//!
//! - Dilute gas, first Chapman-Enskog approximation: disks D0 = (1 / (2 n
//!   sigma)) sqrt(kT / (pi m)) (Gass 1971, J. Chem. Phys. 54, 1898);
//!   spheres D0 = (3 / (8 n sigma^2)) sqrt(kT / (pi m)) (Chapman & Cowling,
//!   The Mathematical Theory of Non-Uniform Gases, 3rd ed. 1970, ch. 10).
//! - Enskog's dense-gas theory divides D0 by the contact value g(sigma) of
//!   the pair distribution (collisions are that much more frequent):
//!   Henderson's for disks, Carnahan-Starling's for spheres. It neglects
//!   correlated collisions, so it is low by up to ~20 % at moderate density
//!   (the long-time tail raises D; Alder, Gass & Wainwright 1970) and high
//!   near freezing.

use super::mixing::{disk_diffusion_dilute, disk_diffusion_enskog};
use std::f64::consts::PI;

/// Dilute self-diffusion of spheres of diameter `sigma`, mass `m`, at
/// number density `n` and temperature `kt`.
pub fn sphere_dilute(n: f64, sigma: f64, kt: f64, m: f64) -> f64 {
    3.0 / (8.0 * n * sigma * sigma) * (kt / (PI * m)).sqrt()
}

/// Enskog's self-diffusion of spheres at packing fraction `eta`.
pub fn sphere_enskog(n: f64, sigma: f64, kt: f64, m: f64, eta: f64) -> f64 {
    let contact = (1.0 - 0.5 * eta) / (1.0 - eta).powi(3);
    sphere_dilute(n, sigma, kt, m) / contact
}

/// Enskog's self-diffusion in `dimension` 2 or 3 (NaN otherwise: rods
/// never pass each other, and points never collide).
pub fn enskog(dimension: usize, n: f64, sigma: f64, kt: f64, m: f64, eta: f64) -> f64 {
    match dimension {
        2 => disk_diffusion_enskog(n, sigma, kt, m, eta),
        3 => sphere_enskog(n, sigma, kt, m, eta),
        _ => f64::NAN,
    }
}

/// The dilute limit of `enskog`.
pub fn dilute(dimension: usize, n: f64, sigma: f64, kt: f64, m: f64) -> f64 {
    match dimension {
        2 => disk_diffusion_dilute(n, sigma, kt, m),
        3 => sphere_dilute(n, sigma, kt, m),
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn enskog_tends_to_the_dilute_gas_and_falls_with_density() {
        for d in [2, 3] {
            let (n, s) = (1e-9, 1.0);
            let r = enskog(d, n, s, 1.0, 1.0, 1e-9) / dilute(d, n, s, 1.0, 1.0);
            assert!((r - 1.0).abs() < 1e-6, "{d}D: {r}");
            assert!(enskog(d, 0.5, s, 1.0, 1.0, 0.3) < dilute(d, 0.5, s, 1.0, 1.0));
        }
        // Its scaling: D0 ~ sqrt(kT/m) / (n s^2).
        let a = sphere_dilute(0.1, 1.0, 1.0, 1.0);
        assert!((sphere_dilute(0.2, 1.0, 4.0, 1.0) / a - 1.0).abs() < 1e-12);
        assert!((sphere_dilute(0.1, 2.0, 1.0, 1.0) / a - 0.25).abs() < 1e-12);
        assert!(enskog(1, 0.1, 1.0, 1.0, 1.0, 0.1).is_nan());
    }
}
