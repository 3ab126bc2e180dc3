//! The first passage of a decaying excess to 1/e of its start.

use std::f64::consts::E;

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

#[cfg(test)]
mod tests {
    use super::*;

    /// Excesses over 0.2 (0.8 at the start) and over 0.5 (0.5): each
    /// crosses start / e between the two samples that bracket it.
    #[test]
    fn first_passage_is_interpolated_and_nan_when_never_reached() {
        let t = [0.0, 1.0, 2.0, 3.0];
        let cases = [
            ([1.0, 0.8, 0.5, 0.3], 0.2, 2.0 + (0.3 - 0.8 / E) / 0.2),
            ([1.0, 0.8, 0.6, 0.55], 0.5, 1.0 + (0.3 - 0.5 / E) / 0.2),
        ];
        for (y, target, expect) in cases {
            assert!((first_passage(&t, &y, target) - expect).abs() < 1e-12);
        }
        assert!(first_passage(&t, &[1.0; 4], 0.2).is_nan());
        assert!(first_passage(&t, &[1.0, 0.9, 0.8, 0.75], 0.5).is_nan());
        assert!(first_passage(&t, &cases[0].0, 1.5).is_nan());
    }
}
