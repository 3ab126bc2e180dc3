//! Whether per-bin deviations measured in independent replicas average to
//! zero: a histogram against a law, or two halves of a run against each
//! other. The error of each bin comes from the replicas' spread, so the
//! time correlation of the samples within a run needs no model.
//!
//! Each bin's mean deviation over its standard error is Student's t with
//! R - 1 degrees of freedom under the hypothesis, so its square has mean
//! (R-1)/(R-3) and variance 2(R-1)^2(R-2)/((R-3)^2(R-5)); the statistic is
//! their sum over the bins kept, and `z` its distance from its mean in
//! standard deviations (bins treated as independent: the constraint that
//! fractions sum to one only lowers the variance).

/// The outcome of a test over replicas.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Agreement {
    /// Sum over the bins kept of (mean / standard error)^2.
    pub statistic: f64,
    pub bins: usize,
    pub replicas: usize,
    /// (statistic - its mean) / its standard deviation under the hypothesis.
    pub z: f64,
}

impl Agreement {
    /// statistic / bins: about 1 when the hypothesis holds.
    pub fn per_bin(&self) -> f64 {
        self.statistic / self.bins as f64
    }
}

/// Test that `rows` (one per replica, one deviation per bin) average to
/// zero in the bins where `keep` is true. None with fewer than 6 replicas
/// (the statistic's variance needs R > 5) or no bin kept.
pub fn zero_mean(rows: &[Vec<f64>], keep: &[bool]) -> Option<Agreement> {
    let r = rows.len();
    if r < 6 {
        return None;
    }
    let mut statistic = 0.0;
    let mut bins = 0;
    for (b, _) in keep.iter().enumerate().filter(|(_, k)| **k) {
        let v: Vec<f64> = rows
            .iter()
            .map(|row| row.get(b).copied().unwrap_or(0.0))
            .collect();
        let mean = v.iter().sum::<f64>() / r as f64;
        let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (r - 1) as f64;
        if var <= 0.0 {
            continue;
        }
        statistic += mean * mean / (var / r as f64);
        bins += 1;
    }
    if bins == 0 {
        return None;
    }
    let rf = r as f64;
    let mean1 = (rf - 1.0) / (rf - 3.0);
    let var1 = 2.0 * (rf - 1.0).powi(2) * (rf - 2.0) / ((rf - 3.0).powi(2) * (rf - 5.0));
    let n = bins as f64;
    Some(Agreement {
        statistic,
        bins,
        replicas: r,
        z: (statistic - n * mean1) / (n * var1).sqrt(),
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
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn gauss(rng: &mut ChaCha8Rng) -> f64 {
        let (u, v): (f64, f64) = (rng.random(), rng.random());
        (-2.0 * (1.0 - u).ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }

    /// Under the hypothesis z is about standard: over many trials its mean
    /// is near 0 and its spread near 1; a shift of 1.5 standard errors per
    /// bin is found.
    #[test]
    fn calibrated_under_the_hypothesis_and_sensitive_to_a_shift() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let (r, bins, trials) = (16, 30, 2000);
        let keep = vec![true; bins];
        let mut zs = Vec::new();
        for _ in 0..trials {
            let rows: Vec<Vec<f64>> = (0..r)
                .map(|_| (0..bins).map(|_| gauss(&mut rng)).collect())
                .collect();
            zs.push(zero_mean(&rows, &keep).unwrap().z);
        }
        let mean = zs.iter().sum::<f64>() / trials as f64;
        let sd = (zs.iter().map(|z| (z - mean).powi(2)).sum::<f64>() / trials as f64).sqrt();
        assert!(mean.abs() < 0.1, "{mean}");
        assert!((sd - 1.0).abs() < 0.1, "{sd}");
        let shifted: Vec<Vec<f64>> = (0..r)
            .map(|_| {
                (0..bins)
                    .map(|_| gauss(&mut rng) + 1.5 / (r as f64).sqrt())
                    .collect()
            })
            .collect();
        assert!(zero_mean(&shifted, &keep).unwrap().z > 4.0);
        assert!(zero_mean(&shifted[..5], &keep).is_none());
    }
}
