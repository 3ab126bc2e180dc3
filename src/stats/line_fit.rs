//! A weighted straight-line fit whose slope error owns up to scatter
//! beyond the error bars.

use crate::stats::line::{Sums, chi_square};

/// Weighted least-squares line through (x, y ± e): slope, its standard
/// error (scaled up by sqrt(chi^2/dof) when the scatter exceeds the error
/// bars), intercept and chi^2/dof.
pub fn fit_line(points: &[(f64, f64, f64)]) -> Option<(f64, f64, f64, f64)> {
    if points.len() < 3 {
        return None;
    }
    let sums = Sums::of_errors(points.iter().copied());
    let det = sums.det();
    if det.is_nan() || det <= 0.0 {
        return None;
    }
    let (slope, intercept) = (sums.slope(), sums.intercept());
    let chi2 = chi_square(points, slope, intercept) / (points.len() - 2) as f64;
    let se = sums.slope_error() * chi2.max(1.0).sqrt();
    Some((slope, se, intercept, chi2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_fit_recovers_a_power_law() {
        let pts: Vec<(f64, f64, f64)> = [10.0f64, 100.0, 1000.0]
            .iter()
            .map(|m| (m.ln(), (3.0 * m.powf(1.5)).ln(), 0.1))
            .collect();
        let (b, se, a, chi2) = fit_line(&pts).expect("fits");
        assert!((b - 1.5).abs() < 1e-12 && (a - 3f64.ln()).abs() < 1e-12);
        assert!(chi2 < 1e-20);
        // Error of the slope from the error bars alone: 0.1 / sqrt(sum (x - xbar)^2).
        let spread = 2.0 * (10f64.ln()).powi(2);
        assert!((se - 0.1 / spread.sqrt()).abs() < 1e-12);
    }
}
