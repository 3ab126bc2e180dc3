//! A power law y ∝ x^b through measured points: a weighted straight line
//! through (ln x, ln y), each point weighted by its relative error.

use super::line::{chi_square, line};
use super::summary::Stats;

/// The fit ln y = intercept + exponent ln x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLaw {
    pub exponent: f64,
    /// The exponent's standard error, from the error bars alone.
    pub error: f64,
    pub intercept: f64,
    /// χ² of the points about the line.
    pub chi2: f64,
    pub points: usize,
}

/// (ln x, ln y, relative error of y) of a positive `y` with an error bar.
pub fn log_point(x: f64, y: &Stats) -> Option<(f64, f64, f64)> {
    (x > 0.0 && y.mean > 0.0 && y.stderr > 0.0).then(|| (x.ln(), y.mean.ln(), y.stderr / y.mean))
}

impl PowerLaw {
    /// Weighted least squares through `log_point`s, weights 1/error²; NaN
    /// with fewer than `least` points or two distinct x.
    pub fn fit(points: &[(f64, f64, f64)], least: usize) -> PowerLaw {
        let (x, y): (Vec<f64>, Vec<f64>) = points.iter().map(|p| (p.0, p.1)).unzip();
        let w: Vec<f64> = points.iter().map(|p| 1.0 / (p.2 * p.2)).collect();
        let (exponent, error, intercept) = match points.len() >= least {
            true => line(&x, &y, Some(&w)),
            false => (f64::NAN, f64::NAN, f64::NAN),
        };
        let chi2 = chi_square(points, exponent, intercept);
        let points = points.len();
        PowerLaw {
            exponent,
            error,
            intercept,
            chi2,
            points,
        }
    }

    /// χ² per degree of freedom: about 1 when the power law and the error
    /// bars hold together (NaN with two points or fewer).
    pub fn chi2_per_dof(&self) -> f64 {
        match self.points {
            n if n > 2 => self.chi2 / (n - 2) as f64,
            _ => f64::NAN,
        }
    }

    /// The fitted y at `x`.
    pub fn at(&self, x: f64) -> f64 {
        (self.intercept + self.exponent * x.ln()).exp()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_power_law_is_fitted_exactly() {
        let pts: Vec<(f64, f64, f64)> = [10.0f64, 20.0, 40.0, 80.0]
            .iter()
            .map(|&n| (n.ln(), (2.0 * n.powf(0.3)).ln(), 0.01))
            .collect();
        let f = PowerLaw::fit(&pts, 3);
        assert!((f.exponent - 0.3).abs() < 1e-12 && f.error > 0.0 && f.chi2 < 1e-18);
        assert!((f.at(30.0) - 2.0 * 30f64.powf(0.3)).abs() < 1e-12);
        assert_eq!(f.chi2_per_dof(), f.chi2 / 2.0);
        assert!(PowerLaw::fit(&pts[..2], 3).exponent.is_nan());
        let s = Stats::of(&[1.0, 3.0]);
        assert_eq!(log_point(1.0, &s), Some((0.0, 2f64.ln(), s.stderr / 2.0)));
        assert_eq!(log_point(0.0, &s), None);
    }
}
