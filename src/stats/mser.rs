//! How much of a series is still the start relaxing: the MSER rule (K. P.
//! White, Simulation 69, 323 (1997); "MSER-5": batches of 5 samples). For
//! each candidate cut j (in batches, at most half the series) it computes
//! the variance of the mean of what is left, sum (b - mean)^2 / (K - j)^2
//! over the K - j remaining batch means b; the cut that minimises it trades
//! bias (a transient left in) against noise (data thrown away). On a
//! stationary series that minimum falls anywhere by chance, and a cut that
//! follows the noise biases the mean a little; so a cut is kept only when
//! what it removes differs from what is left by more than `SIGNIFICANT`
//! error bars (block averages, `blocking`), else nothing is cut.

use super::blocking;

/// Samples per batch.
pub const BATCH: usize = 5;

/// Error bars by which the removed start must differ from the rest.
pub const SIGNIFICANT: f64 = 3.0;

/// Samples to discard from the start of `x`.
pub fn cut(x: &[f64]) -> usize {
    let c = mser(x);
    if c == 0 {
        return 0;
    }
    let (head, rest) = x.split_at(c);
    let Some(b) = blocking::blocked(rest) else {
        return c;
    };
    // The removed part's error, at the correlation the rest shows.
    let per_sample = b.stderr * (rest.len() as f64).sqrt();
    let err = (per_sample / (c as f64).sqrt()).hypot(b.stderr);
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    if (mean(head) - mean(rest)).abs() > SIGNIFICANT * err {
        c
    } else {
        0
    }
}

/// The MSER-5 cut, in samples.
fn mser(x: &[f64]) -> usize {
    let batches: Vec<f64> = x
        .chunks_exact(BATCH)
        .map(|c| c.iter().sum::<f64>() / BATCH as f64)
        .collect();
    let k = batches.len();
    if k < 4 {
        return 0;
    }
    let mut best = (f64::INFINITY, 0);
    for j in 0..=k / 2 {
        let rest = &batches[j..];
        let m = rest.len() as f64;
        let mean = rest.iter().sum::<f64>() / m;
        let stat = rest.iter().map(|b| (b - mean).powi(2)).sum::<f64>() / (m * m);
        if stat < best.0 {
            best = (stat, j);
        }
    }
    best.1 * BATCH
}

#[cfg(test)]
mod tests {
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    /// Uniform noise of unit variance around 10, plus `a` e^(-i/50).
    fn series(a: f64, seed: u64) -> Vec<f64> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        (0..4000)
            .map(|i| {
                let u: f64 = rand::RngExt::random::<f64>(&mut rng) - 0.5;
                10.0 + u * 12f64.sqrt() + a * (-(i as f64) / 50.0).exp()
            })
            .collect()
    }

    #[test]
    fn a_flat_series_is_not_cut() {
        for seed in 0..20 {
            assert_eq!(super::cut(&series(0.0, seed)), 0, "seed {seed}");
        }
    }

    #[test]
    fn a_decaying_start_is_cut() {
        for seed in 0..5 {
            // Cut where the transient has fallen to about the noise's
            // error over the rest (20 e^(-i/50) < 0.1 from i = 265).
            let c = super::cut(&series(20.0, seed));
            assert!((100..=500).contains(&c), "seed {seed}: {c}");
        }
    }
}
