//! Imperial's equilibration: the standard deviation of the speeds against
//! time from a start with uniform momenta, until it settles at its
//! equilibrium value; how long that takes and what it costs.

use crate::stats::passage::first_passage;
use crate::stats::summary::Stats;

/// std of sqrt(m)|v| in d dimensions for Maxwell-Boltzmann at kT = 1:
/// sqrt(d - <chi_d>^2), <chi_d> = sqrt(2) Gamma((d+1)/2) / Gamma(d/2).
pub fn maxwell_speed_std(dimension: usize) -> f64 {
    use statrs::function::gamma::ln_gamma;
    let d = dimension as f64;
    let mean = 2f64.sqrt() * (ln_gamma(0.5 * (d + 1.0)) - ln_gamma(0.5 * d)).exp();
    (d - mean * mean).sqrt()
}

/// The settled level (mean of the last half of the curve) and the first
/// time the curve's distance from it falls to 1/e of its distance at the
/// start, interpolated between samples (NaN if it never does).
pub fn equilibration(t: &[f64], mean: &[Stats]) -> (f64, f64) {
    let n = mean.len();
    if n < 4 {
        return (f64::NAN, f64::NAN);
    }
    let level = mean[n / 2..].iter().map(|s| s.mean).sum::<f64>() / (n - n / 2) as f64;
    let distance: Vec<f64> = mean.iter().map(|s| (s.mean - level).abs()).collect();
    (level, first_passage(t, &distance, 0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn speed_std_of_maxwell_boltzmann() {
        // 2D: sqrt(2 - pi/2); 3D: sqrt(3 - 8/pi).
        assert!((maxwell_speed_std(2) - (2.0 - std::f64::consts::FRAC_PI_2).sqrt()).abs() < 1e-12);
        assert!((maxwell_speed_std(3) - (3.0 - 8.0 / std::f64::consts::PI).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn exponential_approach_is_timed() {
        let t: Vec<f64> = (0..1000).map(|i| i as f64 * 0.1).collect();
        let mean: Vec<Stats> = t
            .iter()
            .map(|t| Stats::of(&[1.0 + 0.5 * (-t / 2.0f64).exp()]))
            .collect();
        let (level, tau) = equilibration(&t, &mean);
        assert!((level - 1.0).abs() < 1e-6);
        assert!((tau - 2.0).abs() < 0.01, "{tau}");
    }
}
