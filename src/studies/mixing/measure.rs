//! The numbers both halves of the mixing study read off a run's series: a
//! first passage, a late average, and the slope of a straight line.

use std::f64::consts::E;

/// Part of the run, at its end, over which settled values are averaged.
pub const LATE: f64 = 0.5;

/// First time the excess `value - target` falls to 1/e of its value at the
/// first sample, interpolated linearly between the samples around the
/// crossing. NaN if it never does within the series (the run did not mix
/// within its length) or if the start was not in excess.
pub fn first_passage(t: &[f64], value: &[f64], target: f64) -> f64 {
    let Some(&first) = value.first() else {
        return f64::NAN;
    };
    let start = first - target;
    if start.is_nan() || start <= 0.0 {
        return f64::NAN;
    }
    let level = start / E;
    for i in 1..value.len().min(t.len()) {
        let (a, b) = (value[i - 1] - target, value[i] - target);
        if b <= level {
            let w = (a - level) / (a - b);
            return t[i - 1] + w * (t[i] - t[i - 1]);
        }
    }
    f64::NAN
}

/// Mean of `value` over the samples in the last `LATE` of the run.
pub fn late_mean(t: &[f64], value: &[f64]) -> f64 {
    let (Some(&t0), Some(&t1)) = (t.first(), t.last()) else {
        return f64::NAN;
    };
    let from = t1 - LATE * (t1 - t0);
    let (sum, n) = t
        .iter()
        .zip(value)
        .filter(|(t, _)| **t >= from)
        .fold((0.0, 0usize), |(s, n), (_, v)| (s + v, n + 1));
    sum / n as f64
}

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
    fn first_passage_is_interpolated_and_nan_when_never_reached() {
        let t = [0.0, 1.0, 2.0, 3.0];
        let y = [1.0, 0.8, 0.5, 0.3];
        // Target 0.2: excess 0.8, level 0.8 / e ~ 0.2943, crossed between
        // t = 2 (excess 0.3) and 3 (0.1).
        let level = 0.8 / E;
        let expect = 2.0 + (0.3 - level) / 0.2;
        assert!((first_passage(&t, &y, 0.2) - expect).abs() < 1e-12);
        assert!(first_passage(&t, &[1.0; 4], 0.2).is_nan());
        assert!(first_passage(&t, &y, 1.5).is_nan());
    }

    #[test]
    fn late_mean_takes_the_last_half() {
        let t = [0.0, 1.0, 2.0, 3.0, 4.0];
        assert_eq!(late_mean(&t, &[9.0, 9.0, 1.0, 2.0, 3.0]), 2.0);
    }

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
