//! Hard disks, the virial series Z = 1 + sum_k (B_k / B_2^(k-1)) (2 eta)^(k-1)
//! (B_2 rho = 2 eta for disks of diameter sigma) with the known coefficients
//! up to B10: B3, B4 exact, B5-B10 by Monte Carlo, from N. Clisby and
//! B. M. McCoy, "Ninth and tenth order virial coefficients for hard spheres
//! in D dimensions", J. Stat. Phys. 122, 15 (2006), Table 1 (D = 2). The
//! truncated series falls below the fluid's pressure as eta grows: the
//! terms left out (B11 ~ 0.011 B2^10 onwards) are ~1e-4 of Z at eta = 0.3,
//! ~0.5 % at 0.5 and of order one at the liquid-hexatic transition
//! (0.70-0.72), where no fluid equation holds.

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
    let x = 2.0 * eta;
    let terms = up_to.clamp(1, 10) - 1;
    1.0 + REDUCED[..terms]
        .iter()
        .enumerate()
        .map(|(i, b)| b * x.powi(i as i32 + 1))
        .sum::<f64>()
}

#[cfg(test)]
mod tests {
    use super::z;

    #[test]
    fn known_values() {
        assert_eq!(z(0.0, 10), 1.0);
        // B3 is exact: B3 / B2^2 = 4/3 - sqrt(3)/pi, so through B3
        // Z = 1 + 2 eta + b3 eta^2 with b3 = 4 B3 / B2^2 = 3.128018.
        let b3 = 4.0 * (4.0 / 3.0 - 3f64.sqrt() / std::f64::consts::PI);
        assert!((super::REDUCED[1] - b3 / 4.0).abs() < 1e-7);
        assert!((z(0.1, 3) - (1.0 + 0.2 + b3 * 0.01)).abs() < 1e-8);
        // The series and Henderson agree to 3e-4 at eta = 0.3, 1e-2 at 0.5.
        let ratio = |eta| z(eta, 10) / crate::theory::henderson::z(eta) - 1.0;
        assert!(ratio(0.3).abs() < 3e-4 + 1e-6);
        assert!((ratio(0.5) + 0.0103).abs() < 1e-4);
        // Each term adds pressure (all coefficients positive).
        assert!(z(0.3, 10) > z(0.3, 9));
    }
}
