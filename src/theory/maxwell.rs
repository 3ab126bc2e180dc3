//! The large-N (canonical) laws beside the exact finite-N ones: a Gaussian
//! velocity component and the Maxwell-Boltzmann law of sqrt(m)|v| in d
//! dimensions (Imperial, 2D: rho(v) = (m v / kT) exp(-m v^2 / 2kT)).

use statrs::function::erf::erfc;
use statrs::function::gamma::{checked_gamma_lr, ln_gamma};

/// Normal distribution function at x of mean mu and standard deviation s.
pub fn normal_cdf(x: f64, mu: f64, s: f64) -> f64 {
    0.5 * erfc(-(x - mu) / (s * std::f64::consts::SQRT_2))
}

pub fn normal_pdf(x: f64, mu: f64, s: f64) -> f64 {
    let z = (x - mu) / s;
    (-0.5 * z * z).exp() / (s * (std::f64::consts::TAU).sqrt())
}

/// sqrt(m)|v| at temperature kT in d dimensions: a chi law with d degrees
/// of freedom, scaled by sqrt(kT).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaxwellSpeed {
    pub kt: f64,
    pub dimension: f64,
}

impl MaxwellSpeed {
    pub fn cdf(&self, s: f64) -> f64 {
        if s <= 0.0 {
            return 0.0;
        }
        checked_gamma_lr(0.5 * self.dimension, s * s / (2.0 * self.kt)).unwrap_or(f64::NAN)
    }

    pub fn pdf(&self, s: f64) -> f64 {
        if s <= 0.0 {
            return 0.0;
        }
        let a = 0.5 * self.dimension;
        let x = s * s / (2.0 * self.kt);
        ((a - 1.0) * x.ln() - x - ln_gamma(a)).exp() * s / self.kt
    }

    pub fn probability(&self, lo: f64, hi: f64) -> f64 {
        self.cdf(hi) - self.cdf(lo)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_dimensions_is_imperials_law_and_integrates() {
        let law = MaxwellSpeed {
            kt: 1.7,
            dimension: 2.0,
        };
        for s in [0.1f64, 0.8, 2.0, 4.0] {
            let imperial = s / 1.7 * (-s * s / (2.0 * 1.7f64)).exp();
            assert!((law.pdf(s) - imperial).abs() < 1e-12);
            assert!((law.cdf(s) - (1.0 - (-s * s / 3.4f64).exp())).abs() < 1e-12);
        }
        for d in [1.0, 3.0] {
            let law = MaxwellSpeed {
                kt: 0.6,
                dimension: d,
            };
            let n = 200_000;
            let h = 10.0 / n as f64;
            let total: f64 = (0..n).map(|i| law.pdf((i as f64 + 0.5) * h) * h).sum();
            assert!((total - 1.0).abs() < 1e-6);
            let half: f64 = (0..n / 10).map(|i| law.pdf((i as f64 + 0.5) * h) * h).sum();
            assert!((half - law.cdf(1.0)).abs() < 1e-6);
        }
        assert!((normal_cdf(0.3, 0.3, 2.0) - 0.5).abs() < 1e-15);
    }
}
