//! Whether per-bin deviations measured in independent replicas average to
//! zero: a histogram against a law, or two halves of a run against each
//! other. Errors come from the replicas alone, so neither the time
//! correlation of the samples within a run nor the correlation between
//! bins (a slow collective mode moves many bins of a run together) needs a
//! model.
//!
//! The statistic is S = sum over bins of (mean deviation / its standard
//! error)^2. Its null distribution is found by sign flips: replicas are
//! independent and, if the law holds, each replica's deviation vector is as
//! likely as its negative, so S recomputed with each replica's vector
//! multiplied by a random sign is a draw from that distribution, with the
//! bins' correlations kept. `z` is S's distance from the flipped mean in
//! flipped standard deviations; `p` the share of flips at least as large.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Random sign patterns drawn (seeded: a test gives the same answer on
/// every run).
pub const FLIPS: usize = 1000;

/// The outcome of a test over replicas.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Agreement {
    /// Sum over the bins kept of (mean / standard error)^2.
    pub statistic: f64,
    pub bins: usize,
    pub replicas: usize,
    /// (statistic - flipped mean) / flipped standard deviation.
    pub z: f64,
    /// Share of the sign flips (the observed pattern counted in) whose
    /// statistic is at least the observed one.
    pub p: f64,
}

/// S of `rows` with signs `sign` over the bins kept.
fn statistic(rows: &[Vec<f64>], sign: &[f64], keep: &[usize]) -> f64 {
    let r = rows.len() as f64;
    let mut s = 0.0;
    for &b in keep {
        let v = rows.iter().zip(sign).map(|(row, e)| e * row[b]);
        let (sum, sq) = v.fold((0.0, 0.0), |(a, q), x| (a + x, q + x * x));
        let mean = sum / r;
        let var = (sq - r * mean * mean) / (r - 1.0);
        if var > 0.0 {
            s += mean * mean / (var / r);
        }
    }
    s
}

/// Test that `rows` (one per replica, one deviation per bin) average to
/// zero in the bins where `keep` is true. None with fewer than 6 replicas
/// (too few sign patterns) or no bin with any spread.
pub fn zero_mean(rows: &[Vec<f64>], keep: &[bool]) -> Option<Agreement> {
    let r = rows.len();
    if r < 6 {
        return None;
    }
    let kept: Vec<usize> = (keep.iter().enumerate())
        .filter(|(b, k)| **k && rows.iter().all(|row| *b < row.len()))
        .map(|(b, _)| b)
        .collect();
    let observed = statistic(rows, &vec![1.0; r], &kept);
    if kept.is_empty() || observed == 0.0 {
        return None;
    }
    let mut rng = ChaCha8Rng::seed_from_u64(0x5eed);
    let flipped: Vec<f64> = (0..FLIPS)
        .map(|_| {
            let sign: Vec<f64> = (0..r)
                .map(|_| if rng.random::<bool>() { 1.0 } else { -1.0 })
                .collect();
            statistic(rows, &sign, &kept)
        })
        .collect();
    let n = FLIPS as f64;
    let mean = flipped.iter().sum::<f64>() / n;
    let sd = (flipped.iter().map(|s| (s - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    let above = flipped.iter().filter(|s| **s >= observed).count();
    Some(Agreement {
        statistic: observed,
        bins: kept.len(),
        replicas: r,
        z: (observed - mean) / sd,
        p: (1 + above) as f64 / (1.0 + n),
    })
}

/// A histogram's counts as fractions of its total.
pub fn fractions(counts: &[f64]) -> Vec<f64> {
    let total: f64 = counts.iter().sum();
    counts
        .iter()
        .map(|c| c / total.max(f64::MIN_POSITIVE))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gauss(rng: &mut ChaCha8Rng) -> f64 {
        let (u, v): (f64, f64) = (rng.random(), rng.random());
        (-2.0 * (1.0 - u).ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }

    /// Under the hypothesis z is about standard whether the bins are
    /// independent or share a common fluctuation per replica (where a
    /// variance that assumed independent bins would be far too small);
    /// a shift of 1.5 standard errors per bin is found.
    #[test]
    fn calibrated_with_independent_and_correlated_bins() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let (r, bins, trials) = (12, 30, 200);
        let keep = vec![true; bins];
        for common in [0.0, 3.0] {
            let mut zs = Vec::new();
            for _ in 0..trials {
                let rows: Vec<Vec<f64>> = (0..r)
                    .map(|_| {
                        let c = common * gauss(&mut rng);
                        (0..bins).map(|_| c + gauss(&mut rng)).collect()
                    })
                    .collect();
                zs.push(zero_mean(&rows, &keep).unwrap().z);
            }
            let mean = zs.iter().sum::<f64>() / trials as f64;
            let sd = (zs.iter().map(|z| (z - mean).powi(2)).sum::<f64>() / trials as f64).sqrt();
            // Four standard errors of the mean and of the spread.
            assert!(
                mean.abs() < 4.0 / (trials as f64).sqrt(),
                "{common}: mean {mean}"
            );
            assert!((sd - 1.0).abs() < 0.25, "{common}: sd {sd}");
        }
        let shifted: Vec<Vec<f64>> = (0..r)
            .map(|_| {
                (0..bins)
                    .map(|_| gauss(&mut rng) + 1.5 / (r as f64).sqrt())
                    .collect()
            })
            .collect();
        let a = zero_mean(&shifted, &keep).unwrap();
        assert!(a.z > 4.0 && a.p < 0.01, "{a:?}");
        assert!(zero_mean(&shifted[..5], &keep).is_none());
    }
}
