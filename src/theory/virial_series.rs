//! A truncated virial series Z = 1 + sum_k (B_k / B_2^(k-1)) x^(k-1), with
//! x = B_2 rho (2 eta for disks, 4 eta for spheres), and an estimate of the
//! terms left out: the known coefficients of hard disks and spheres fall
//! off nearly geometrically (B_k / (B_2 B_(k-1)) is 0.55-0.57 for disks
//! and 0.31-0.32 for spheres at k = 8-10), so the tail is continued with
//! the ratio of the last two terms.

/// Z through the first `terms` reduced coefficients (1 = B2 only).
pub fn sum(reduced: &[f64], x: f64, terms: usize) -> f64 {
    1.0 + reduced[..terms.min(reduced.len())]
        .iter()
        .enumerate()
        .map(|(i, b)| b * x.powi(i as i32 + 1))
        .sum::<f64>()
}

/// The terms beyond the last known one, continued geometrically with the
/// ratio of the last two terms (a guide to the truncation error, not a
/// bound).
pub fn tail(reduced: &[f64], x: f64) -> f64 {
    let n = reduced.len();
    let last = reduced[n - 1] * x.powi(n as i32);
    let before = reduced[n - 2] * x.powi(n as i32 - 1);
    let ratio = last / before;
    if ratio < 1.0 {
        last * ratio / (1.0 - ratio)
    } else {
        f64::INFINITY
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn geometric_series() {
        // 1 + x + x^2 + x^3 through three terms and the tail of the rest.
        let r = [1.0, 1.0, 1.0];
        assert_eq!(super::sum(&r, 0.5, 3), 1.875);
        assert!((super::sum(&r, 0.5, 3) + super::tail(&r, 0.5) - 2.0).abs() < 1e-15);
    }
}
