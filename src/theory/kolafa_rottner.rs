//! Hard disks, the equation of state of J. Kolafa and M. Rottner,
//! "Simulation-based equation of state of the hard disk fluid and prediction
//! of higher-order virial coefficients", Mol. Phys. 104, 3435 (2006):
//! Z = sum_n C_n x^n with x = eta / (1 - eta), fitted to their simulations
//! of the fluid extrapolated to infinite N, up to a reduced density
//! rho sigma^2 = 0.90 (eta = 0.707), with the virial coefficients that were
//! known built in. They caution that the last interval fitted,
//! rho sigma^2 = 0.89-0.90 (eta = 0.699-0.707), may keep finite-size
//! effects; the fluid itself ends at 0.700 (Bernard and Krauth 2011), and
//! above it the fit means nothing (it has a maximum there).
//!
//! The coefficients were read from a transcription of the paper's table in
//! public code, and checked here (see the tests): expanded in eta, they give
//! B3, B4 and B5 to 5e-8 of the exact and Clisby-McCoy values, and B6-B10
//! within their Monte Carlo errors (1e-5 to 4e-4), which a misread digit in
//! any low coefficient would break.

/// (n, C_n): C_0 = 1 and C_1 = 2 give the ideal gas and B2.
const TERMS: [(i32, f64); 15] = [
    (0, 1.0),
    (1, 2.0),
    (2, 1.128_017_75),
    (3, 0.001_818_952_91),
    (4, -0.052_613_473_7),
    (5, 0.050_496_016_8),
    (6, -0.032_553_779_2),
    (7, 0.013_457_863_2),
    (8, 0.001_408_881_82),
    (9, -0.008_342_736_01),
    (10, 0.006_941_273_67),
    (11, -0.002_622_547_23),
    (12, 0.000_355_746_352),
    (22, -5.246_729_38e-9),
    (57, 5.880_546_39e-23),
];

/// Compressibility factor of the hard-disk fluid at packing fraction `eta`.
pub fn z(eta: f64) -> f64 {
    let x = eta / (1.0 - eta);
    TERMS.iter().map(|&(n, c)| c * x.powi(n)).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::disk_virial::{self, REDUCED};

    /// The Taylor coefficients of Z in eta up to eta^9 (b_k multiplies
    /// eta^(k-1)): x^n = eta^n (1 - eta)^-n = sum_m C(n+m-1, m) eta^(n+m).
    fn taylor() -> [f64; 10] {
        let mut b = [0.0; 10];
        for &(n, c) in &TERMS {
            for (k, slot) in b.iter_mut().enumerate() {
                let Some(m) = (k as i32).checked_sub(n).filter(|m| *m >= 0) else {
                    continue;
                };
                let binomial = (1..=m).fold(1.0, |acc, j| acc * (n + j - 1) as f64 / j as f64);
                *slot += c * if n == 0 {
                    (m == 0) as u8 as f64
                } else {
                    binomial
                };
            }
        }
        b
    }

    #[test]
    fn it_carries_the_virial_coefficients() {
        let b = taylor();
        assert_eq!((b[0], b[1]), (1.0, 2.0));
        // Z = 1 + sum_k (B_k / B_2^(k-1)) (2 eta)^(k-1).
        for k in 3..=10 {
            let known = REDUCED[k - 2] * 2f64.powi(k as i32 - 1);
            let rel = b[k - 1] / known - 1.0;
            // B3-B5 are built in; B6-B10 agree within Clisby and McCoy's
            // Monte Carlo errors.
            let within = if k <= 5 { 1e-7 } else { 5e-4 };
            assert!(rel.abs() < within, "B{k}: {} against {known}", b[k - 1]);
        }
    }

    #[test]
    fn it_agrees_with_the_series_where_the_series_holds() {
        // At 0.3 the resummed series is good to ~1e-5 (its tail is 5e-5).
        assert!((z(0.3) / disk_virial::resummed(0.3) - 1.0).abs() < 1e-5);
        // Dense, the truncated series falls below the fluid.
        assert!(z(0.6) > disk_virial::z(0.6, 10));
        // Known values of the fit (by hand from the coefficients).
        assert!((z(0.5) - 4.106_364).abs() < 1e-6, "{}", z(0.5));
        assert!((z(0.69) - 10.200_71).abs() < 1e-5, "{}", z(0.69));
    }
}
