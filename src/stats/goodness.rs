//! Whether a fit's χ² is as small as chance allows.

use statrs::distribution::{ChiSquared, ContinuousCDF};

/// Chance that a χ² on `dof` degrees of freedom is at least `chi2` when
/// the model and the error bars hold; NaN without degrees of freedom.
pub fn chi_square_tail(chi2: f64, dof: usize) -> f64 {
    match ChiSquared::new(dof as f64) {
        Ok(d) if chi2.is_finite() => d.sf(chi2),
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tail_of_a_chi_square() {
        // On 2 degrees of freedom the tail is exp(-chi2 / 2).
        assert!((chi_square_tail(3.0, 2) - (-1.5f64).exp()).abs() < 1e-12);
        assert!(chi_square_tail(1.0, 0).is_nan());
    }
}
