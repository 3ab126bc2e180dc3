//! Z against 1/N: points of one dimension and packing fraction (periodic
//! boxes) with different N, fitted with Z(N) = Z_inf + b/N by weighted
//! least squares, and Z_inf compared with the reference equation. The
//! canonical finite-size effect of a periodic box of fixed N is of order
//! 1/N (methods.md, "Ensemble"); when the smallest box already shows the
//! next term (the line's χ² beyond its 99 % point), it is left out and the
//! line refitted through the larger ones.

use super::points::Point;
use crate::stats::groups::first_seen;
use crate::stats::line::Sums;
use statrs::distribution::{ChiSquared, ContinuousCDF};

/// One group's fit.
pub struct Fit {
    pub dimension: usize,
    pub eta: f64,
    /// (N, Z, error) of the points fitted.
    pub data: Vec<(usize, f64, f64)>,
    pub z_inf: f64,
    pub z_inf_err: f64,
    pub slope: f64,
    pub slope_err: f64,
    /// Chi-squared and degrees of freedom (0 for two points).
    pub chi2: f64,
    pub dof: usize,
    /// Smaller boxes left out, each with the χ² and dof of the line that
    /// still included it.
    pub left_out: Vec<(usize, f64, usize)>,
}

/// Whether a line with this χ² over `dof` degrees of freedom is rejected
/// at the 1 % level.
fn rejected(chi2: f64, dof: usize) -> bool {
    dof > 0 && ChiSquared::new(dof as f64).is_ok_and(|d| chi2 > d.inverse_cdf(0.99))
}

/// Packing fractions closer than this are the same (box lengths are
/// written to 10 digits).
const SAME_ETA: f64 = 1e-7;

pub fn fits(points: &[Point]) -> Vec<Fit> {
    let fitted = points.iter().filter(|p| !p.walls && p.z.n >= 2);
    first_seen(fitted, |a, b| {
        a.dimension == b.dimension && (a.eta - b.eta).abs() < SAME_ETA
    })
    .into_iter()
    .filter_map(|mut g| {
        g.sort_by_key(|p| p.particles);
        g.dedup_by_key(|p| p.particles);
        (g.len() >= 2).then(|| {
            let mut left_out = Vec::new();
            let mut f = fit(&g);
            while g.len() > 2 && rejected(f.chi2, f.dof) {
                left_out.push((g[0].particles, f.chi2, f.dof));
                g.remove(0);
                f = fit(&g);
            }
            Fit { left_out, ..f }
        })
    })
    .collect()
}

/// Weighted least squares of Z on x = 1/N.
fn fit(g: &[&Point]) -> Fit {
    let data: Vec<(usize, f64, f64)> = g
        .iter()
        .map(|p| (p.particles, p.z.mean, p.error().0))
        .collect();
    let s = Sums::of_errors(data.iter().map(|&(n, z, e)| (1.0 / n as f64, z, e)));
    let (z_inf, slope) = (s.intercept(), s.slope());
    // Not `chi_square`: slope / N rounds unlike slope * (1 / N).
    let chi2 = data
        .iter()
        .map(|&(n, z, e)| ((z - z_inf - slope / n as f64) / e).powi(2))
        .sum();
    Fit {
        dimension: g[0].dimension,
        eta: g[0].eta,
        z_inf,
        z_inf_err: s.intercept_error(),
        slope,
        slope_err: s.slope_error(),
        chi2,
        dof: data.len() - 2,
        data,
        left_out: Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::super::points::tests::point;

    /// Points of disks at η = 0.3 with Z(N) and error `err` at each N.
    fn points(ns: &[usize], z: impl Fn(f64) -> f64, err: f64) -> Vec<super::Point> {
        ns.iter()
            .map(|&n| point(2, n, 0.3, z(n as f64), err))
            .collect()
    }

    #[test]
    fn exact_line_through_two_points() {
        let f = super::fits(&points(&[64, 1024], |n| 2.0 - 0.7 / n, 1e-3));
        assert_eq!(f.len(), 1);
        assert!((f[0].z_inf - 2.0).abs() < 1e-12);
        assert!((f[0].slope + 0.7).abs() < 1e-9);
        // Extrapolated error: (16/15) of the large box's, with the small's.
        let expected = 1e-3 * ((16.0f64 / 15.0).powi(2) + (1.0f64 / 15.0).powi(2)).sqrt();
        assert!((f[0].z_inf_err / expected - 1.0).abs() < 1e-9);
        assert!(f[0].left_out.is_empty());
    }

    #[test]
    fn a_small_box_off_the_line_is_left_out() {
        // Z(N) = 2 - 0.7/N - 150/N^2: the line through all three has
        // chi2 = 16 for 1 dof; the line through 256 and 1024 is kept.
        let z = |n: f64| 2.0 - 0.7 / n - 150.0 / (n * n);
        let f = super::fits(&points(&[64, 256, 1024], z, 1e-3));
        assert_eq!(f[0].left_out.len(), 1);
        assert_eq!(f[0].left_out[0].0, 64);
        assert_eq!(f[0].data.len(), 2);
        assert!((f[0].z_inf - 2.0).abs() < 6e-4, "{}", f[0].z_inf);
        // Within the noise the line through all three is kept.
        let f = super::fits(&points(&[64, 256, 1024], z, 1e-2));
        assert!(f[0].left_out.is_empty());
    }
}
