//! Least-squares straight lines through points: slope, intercept, their
//! errors and χ².

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

/// The weighted sums of the normal equations of a straight line, in the
/// order the points are added: the form in which an intercept and its error
/// come out directly.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Sums {
    pub w: f64,
    pub x: f64,
    pub y: f64,
    pub xx: f64,
    pub xy: f64,
}

impl Sums {
    /// Sums over (x, y, error), each point weighted by 1 / error².
    pub fn of_errors(points: impl IntoIterator<Item = (f64, f64, f64)>) -> Sums {
        let mut s = Sums::default();
        for (x, y, e) in points {
            s.add(x, y, 1.0 / (e * e));
        }
        s
    }

    pub fn add(&mut self, x: f64, y: f64, w: f64) {
        self.w += w;
        self.x += w * x;
        self.y += w * y;
        self.xx += w * x * x;
        self.xy += w * x * y;
    }

    /// The determinant of the normal equations: zero when all x coincide.
    pub fn det(&self) -> f64 {
        self.w * self.xx - self.x * self.x
    }

    pub fn slope(&self) -> f64 {
        (self.w * self.xy - self.x * self.y) / self.det()
    }

    pub fn intercept(&self) -> f64 {
        (self.xx * self.y - self.x * self.xy) / self.det()
    }

    /// Standard errors of slope and intercept when the weights are
    /// 1 / variance.
    pub fn slope_error(&self) -> f64 {
        (self.w / self.det()).sqrt()
    }

    pub fn intercept_error(&self) -> f64 {
        (self.xx / self.det()).sqrt()
    }
}

/// χ² of the points (x, y, error) about the line y = intercept + slope x.
pub fn chi_square(points: &[(f64, f64, f64)], slope: f64, intercept: f64) -> f64 {
    points
        .iter()
        .map(|&(x, y, e)| ((y - intercept - slope * x) / e).powi(2))
        .sum()
}

/// Least-squares slope of ln y against ln x, unweighted; None with fewer
/// than `least` points or a single x.
pub fn log_slope(points: &[(f64, f64)], least: usize) -> Option<f64> {
    if points.len() < least.max(2) {
        return None;
    }
    let n = points.len() as f64;
    let (mx, my) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + x.ln() / n, b + y.ln() / n)
    });
    let sxy: f64 = points
        .iter()
        .map(|(x, y)| (x.ln() - mx) * (y.ln() - my))
        .sum();
    let sxx: f64 = points.iter().map(|(x, _)| (x.ln() - mx).powi(2)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
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

    /// Points 0, 1, 2 with errors 1, 1, 2 on y = 3 + 0.5 x: S = 2.25,
    /// Sx = 1.5, Sxx = 2, det = 2.25, so the slope's error is
    /// sqrt(S / det) = 1 and the intercept's sqrt(Sxx / det) = sqrt(8) / 3;
    /// exact points give χ² = 0.
    #[test]
    fn normal_equations_of_a_hand_checked_case() {
        let pts: Vec<(f64, f64, f64)> = [(0.0, 1.0), (1.0, 1.0), (2.0, 2.0)]
            .iter()
            .map(|&(x, e)| (x, 3.0 + 0.5 * x, e))
            .collect();
        let s = Sums::of_errors(pts.iter().copied());
        assert_eq!((s.w, s.x, s.xx, s.det()), (2.25, 1.5, 2.0, 2.25));
        assert!((s.slope() - 0.5).abs() < 1e-12 && (s.intercept() - 3.0).abs() < 1e-12);
        assert!((s.slope_error() - 1.0).abs() < 1e-12);
        assert!((s.intercept_error() - 8f64.sqrt() / 3.0).abs() < 1e-12);
        assert!(chi_square(&pts, s.slope(), s.intercept()) < 1e-24);
        // A line 2 below: residuals of 2, 2 and 2 over errors of 1, 1 and 2.
        assert_eq!(chi_square(&pts, 0.5, 1.0), 4.0 + 4.0 + 1.0);
    }

    #[test]
    fn a_power_law_has_its_exponent_as_log_slope() {
        let pts: Vec<(f64, f64)> = [1.0f64, 2.0, 4.0, 8.0]
            .iter()
            .map(|&c| (c, 3.0 * c.powf(-0.5)))
            .collect();
        assert!((log_slope(&pts, 3).unwrap() + 0.5).abs() < 1e-12);
        assert_eq!(log_slope(&pts[..2], 3), None);
        assert_eq!(log_slope(&[(2.0, 1.0), (2.0, 3.0)], 2), None);
    }
}
