//! The least-squares straight line through points, with its slope's error.

/// Least-squares straight line y = a + b x through the points, weighted by
/// `w` (1 / variance; all ones for an unweighted fit): (b, its standard
/// error, a). With weights from error bars the slope's error is
/// sqrt(1 / S_xx); unweighted, it is scaled by the residuals. NaN with fewer
/// than two distinct x (three unweighted).
pub fn line(x: &[f64], y: &[f64], w: Option<&[f64]>) -> (f64, f64, f64) {
    let n = x.len();
    let weight = |i: usize| w.map_or(1.0, |w| w[i]);
    let sw: f64 = (0..n).map(weight).sum();
    if n < 2 || sw <= 0.0 {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let mx = (0..n).map(|i| weight(i) * x[i]).sum::<f64>() / sw;
    let my = (0..n).map(|i| weight(i) * y[i]).sum::<f64>() / sw;
    let sxx: f64 = (0..n).map(|i| weight(i) * (x[i] - mx).powi(2)).sum();
    let sxy: f64 = (0..n).map(|i| weight(i) * (x[i] - mx) * (y[i] - my)).sum();
    if sxx <= 0.0 {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let b = sxy / sxx;
    let a = my - b * mx;
    let se = match w {
        Some(_) => (1.0 / sxx).sqrt(),
        None if n > 2 => {
            let rss: f64 = (0..n).map(|i| (y[i] - a - b * x[i]).powi(2)).sum();
            (rss / (n - 2) as f64 / sxx).sqrt()
        }
        None => f64::NAN,
    };
    (b, se, a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_through_exact_points_has_their_slope() {
        let x = [0.0, 1.0, 2.0, 3.0];
        let y: Vec<f64> = x.iter().map(|x| 1.0 - 2.0 * x).collect();
        let (b, se, a) = line(&x, &y, None);
        assert!((b + 2.0).abs() < 1e-12 && (a - 1.0).abs() < 1e-12 && se < 1e-12);
        // Weighted: the slope's error is 1 / sqrt(sum w (x - mean)^2).
        let (b, se, _) = line(&x, &y, Some(&[4.0; 4]));
        assert!((b + 2.0).abs() < 1e-12 && (se - (1.0 / 20.0f64).sqrt()).abs() < 1e-12);
    }
}
