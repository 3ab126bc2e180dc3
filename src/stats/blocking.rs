//! Error bar of the mean of a correlated series by block averaging
//! (Flyvbjerg and Petersen, J. Chem. Phys. 91, 461 (1989)): the series is
//! cut into blocks of 1, 2, 4, ... samples; the standard error from the
//! block means grows with the block length while blocks are shorter than
//! the correlation time and levels off once they are longer. The block
//! length chosen is the first whose doubling no longer raises the estimate
//! by more than the estimate's own statistical error.

/// Fewest blocks an estimate is made from.
pub const MIN_BLOCKS: usize = 32;

/// A block-average error bar and how it was chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Blocked {
    /// Standard error of the mean.
    pub stderr: f64,
    /// Samples per block.
    pub length: usize,
    /// The estimate with blocks twice as long over this one (about 1 on a
    /// plateau; NaN when there are too few samples to double).
    pub doubling: f64,
    /// Whether the estimate levelled off before the blocks ran out.
    pub plateau: bool,
}

/// Standard error of the mean from blocks of `length` samples (the tail
/// that does not fill a block is left out).
fn estimate(x: &[f64], length: usize) -> (f64, usize) {
    let n = x.len() / length;
    let means: Vec<f64> = x
        .chunks_exact(length)
        .map(|c| c.iter().sum::<f64>() / length as f64)
        .collect();
    let mean = means.iter().sum::<f64>() / n as f64;
    let var = means.iter().map(|m| (m - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    ((var / n as f64).sqrt(), n)
}

/// The block-average error bar of the mean of `x`; None for fewer than
/// `MIN_BLOCKS` samples.
pub fn blocked(x: &[f64]) -> Option<Blocked> {
    if x.len() < MIN_BLOCKS {
        return None;
    }
    let mut length = 1;
    loop {
        let (s, n) = estimate(x, length);
        if x.len() / (2 * length) < MIN_BLOCKS {
            return Some(Blocked {
                stderr: s,
                length,
                doubling: f64::NAN,
                plateau: false,
            });
        }
        let (s2, _) = estimate(x, 2 * length);
        // Relative error of a standard error from n blocks: 1/sqrt(2(n-1)).
        if s2 <= s * (1.0 + 2.0 / (2.0 * (n as f64 - 1.0)).sqrt()) {
            return Some(Blocked {
                stderr: s,
                length,
                doubling: s2 / s,
                plateau: true,
            });
        }
        length *= 2;
    }
}

/// The mean of the second half of `x` minus the first's, over the block
/// error of that difference: about N(0, 1) for a stationary series, large
/// for one still relaxing. NaN when a half is too short for blocks.
pub fn drift(x: &[f64]) -> f64 {
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (a, b) = x.split_at(x.len() / 2);
    match (blocked(a), blocked(b)) {
        (Some(ea), Some(eb)) => (mean(b) - mean(a)) / ea.stderr.hypot(eb.stderr),
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    /// AR(1) noise with correlation `a` per step: the standard error of the
    /// mean is sqrt((1 + a) / (1 - a) / n) times the unit innovations'.
    fn ar1(a: f64, n: usize, seed: u64) -> Vec<f64> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut x = 0.0;
        (0..n)
            .map(|_| {
                let e: f64 = rand::RngExt::random::<f64>(&mut rng) - 0.5;
                x = a * x + e * 12f64.sqrt() * (1.0 - a * a).sqrt();
                x
            })
            .collect()
    }

    #[test]
    fn uncorrelated_needs_no_blocks() {
        let x = ar1(0.0, 1 << 14, 1);
        let b = blocked(&x).unwrap();
        let expected = 1.0 / (x.len() as f64).sqrt();
        assert!(b.plateau && b.length <= 2, "{b:?}");
        assert!((b.stderr / expected - 1.0).abs() < 0.1, "{b:?}");
    }

    #[test]
    fn correlated_levels_off_at_the_right_error() {
        // a = 0.9: the error is sqrt(19) = 4.36 times the naive one.
        let n = 1 << 16;
        let x = ar1(0.9, n, 2);
        let b = blocked(&x).unwrap();
        let expected = (19.0 / n as f64).sqrt();
        assert!(b.plateau && b.length >= 16, "{b:?}");
        assert!((b.stderr / expected - 1.0).abs() < 0.25, "{b:?} {expected}");
    }

    #[test]
    fn a_stationary_series_does_not_drift_and_a_ramp_does() {
        let x = ar1(0.5, 1 << 12, 3);
        assert!(drift(&x).abs() < 4.0, "{}", drift(&x));
        let ramp: Vec<f64> = x
            .iter()
            .enumerate()
            .map(|(i, v)| v + i as f64 * 1e-3)
            .collect();
        assert!(drift(&ramp) > 10.0, "{}", drift(&ramp));
        assert!(drift(&x[..40]).is_nan());
    }
}
