//! The settled value of a series: its mean over the end of the run.

/// Part of the run, at its end, over which settled values are averaged.
pub const LATE: f64 = 0.5;

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn late_mean_takes_the_last_half() {
        let t = [0.0, 1.0, 2.0, 3.0, 4.0];
        assert_eq!(late_mean(&t, &[9.0, 9.0, 1.0, 2.0, 3.0]), 2.0);
    }
}
