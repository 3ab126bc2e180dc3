//! Hard disks, the virial series Z = 1 + sum_k (B_k / B_2^(k-1)) (2 eta)^(k-1)
//! (B_2 rho = 2 eta for disks of diameter sigma) with the known coefficients
//! up to B10: B3, B4 exact, B5-B10 by Monte Carlo, from N. Clisby and
//! B. M. McCoy, "Ninth and tenth order virial coefficients for hard spheres
//! in D dimensions", J. Stat. Phys. 122, 15 (2006), Table 1 (D = 2). The
//! truncated series falls below the fluid's pressure as eta grows: the
//! terms left out (estimated by `virial_series::tail`) are 5e-5 of Z at
//! eta = 0.3, 0.6 % at 0.5 and 14 % at the liquid-hexatic
//! transition (0.70-0.72), where no fluid equation holds.

use super::virial_series;

/// B_k / B_2^(k-1) for k = 2..=10 (k = 2 is 1 by definition).
pub const REDUCED: [f64; 9] = [
    1.0,
    0.782_004_4,
    0.532_231_80,
    0.333_556_04,
    0.198_842_5,
    0.114_872_8,
    0.064_993_0,
    0.036_219_3,
    0.019_953_7,
];

/// Compressibility factor from the series through B_`up_to` (2..=10).
pub fn z(eta: f64, up_to: usize) -> f64 {
    virial_series::sum(&REDUCED, 2.0 * eta, up_to.clamp(1, 10) - 1)
}

/// The series through B10 plus its geometric tail estimate.
pub fn resummed(eta: f64) -> f64 {
    z(eta, 10) + virial_series::tail(&REDUCED, 2.0 * eta)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn known_values() {
        assert_eq!(z(0.0, 10), 1.0);
        // B3 and B4 are exact (Clisby-McCoy; in units of the disk's area
        // v, B2 = 2 v, B3 = (16/3 - 4 sqrt3/pi) v^2, B4 = (16 - 36 sqrt3/pi
        // + 80/pi^2) v^3).
        let s3 = 3f64.sqrt();
        assert!((REDUCED[1] - (16.0 / 3.0 - 4.0 * s3 / PI) / 4.0).abs() < 1e-7);
        assert!((REDUCED[2] - (16.0 - 36.0 * s3 / PI + 80.0 / (PI * PI)) / 8.0).abs() < 1e-8);
        // Through B3: Z = 1 + 2 eta + 4 (B3 / B2^2) eta^2.
        assert!((z(0.1, 3) - (1.0 + 0.2 + 4.0 * REDUCED[1] * 0.01)).abs() < 1e-12);
        // The series and Henderson agree to 3e-4 at eta = 0.3, 1e-2 at 0.5.
        let ratio = |eta| z(eta, 10) / crate::theory::henderson::z(eta) - 1.0;
        assert!(ratio(0.3).abs() < 3e-4 + 1e-6);
        assert!((ratio(0.5) + 0.0103).abs() < 1e-4);
        // Each term adds pressure (all coefficients positive).
        assert!(z(0.3, 10) > z(0.3, 9));
    }

    #[test]
    fn truncation() {
        // At 0.3: 2.063163 through B10; the tail adds 1.0e-4.
        assert!((z(0.3, 10) - 2.063_163).abs() < 1e-6);
        let tail = resummed(0.3) - z(0.3, 10);
        assert!(tail > 0.9e-4 && tail < 1.1e-4, "{tail}");
    }
}
