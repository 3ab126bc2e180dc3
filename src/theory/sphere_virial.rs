//! Hard spheres, the virial series Z = 1 + sum_k (B_k / B_2^(k-1)) (4 eta)^(k-1)
//! (B_2 rho = 4 eta for spheres of diameter sigma) with the coefficients up
//! to B10: B3 and B4 exact, B5-B10 by Monte Carlo, from N. Clisby and
//! B. M. McCoy, J. Stat. Phys. 122, 15 (2006), Table 1 (D = 3). With the
//! estimated tail it is an equation of state independent of any fit to
//! simulations: at eta = 0.3 the series gives 3.98281 and the tail adds
//! 0.00122 (Carnahan-Starling 3.97376, 0.258 % lower).

use super::virial_series;

/// B_k / B_2^(k-1) for k = 2..=10.
pub const REDUCED: [f64; 9] = [
    1.0,
    0.625,
    0.286_949_5,
    0.110_252,
    0.038_881_98,
    0.013_023_54,
    0.004_183_2,
    0.001_309_4,
    0.000_403_5,
];

/// Compressibility factor from the series through B_`up_to` (2..=10).
pub fn z(eta: f64, up_to: usize) -> f64 {
    virial_series::sum(&REDUCED, 4.0 * eta, up_to.clamp(1, 10) - 1)
}

/// The series through B10 plus its geometric tail estimate.
pub fn resummed(eta: f64) -> f64 {
    z(eta, 10) + virial_series::tail(&REDUCED, 4.0 * eta)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn carnahan_starling_is_a_quarter_percent_below_at_three_tenths() {
        // docs/pressure.md: 0.258 % below the series with its tail.
        let rel = super::super::carnahan_starling::z(0.3) / resummed(0.3) - 1.0;
        assert!((rel + 2.58e-3).abs() < 0.01e-3, "{rel}");
    }

    #[test]
    fn exact_coefficients() {
        // B3 / B2^2 = 5/8 and B4 / v^3 = 18.3647684 with v the sphere's
        // volume (B2 = 4 v): reduced 18.3647684 / 64 (Clisby-McCoy Table 1).
        assert_eq!(REDUCED[1], 0.625);
        assert!((REDUCED[2] - 18.364_768_4 / 64.0).abs() < 1e-7);
        // Through B4: 1 + 4 eta + 10 eta^2 + 18.3648 eta^3.
        assert!((z(0.1, 4) - (1.0 + 0.4 + 0.1 + 0.018_364_768_4)).abs() < 1e-9);
    }

    #[test]
    fn at_moderate_density() {
        assert!((z(0.3, 10) - 3.982_81).abs() < 1e-5);
        assert!((resummed(0.3) - z(0.3, 10) - 0.001_22).abs() < 1e-5);
    }
}
