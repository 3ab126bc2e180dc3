//! Goodness-of-fit helpers for the scene tests: p-values, so that each
//! seeded test's threshold comes from the distribution, not from the outcome.
#![allow(dead_code)]

use statrs::distribution::{ChiSquared, ContinuousCDF};

/// Kolmogorov–Smirnov test of a sample against a continuous CDF: the
/// p-value of the largest distance (Kolmogorov's limit law with Stephens'
/// finite-n correction).
pub fn ks_p(mut xs: Vec<f64>, cdf: impl Fn(f64) -> f64) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len() as f64;
    let d = xs
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            let f = cdf(x);
            (f - i as f64 / n).abs().max((f - (i + 1) as f64 / n).abs())
        })
        .fold(0.0, f64::max);
    let lambda = (n.sqrt() + 0.12 + 0.11 / n.sqrt()) * d;
    let q: f64 = (1..=100)
        .map(|k| {
            let k = k as f64;
            let sign = if k as u64 % 2 == 1 { 1.0 } else { -1.0 };
            2.0 * sign * (-2.0 * k * k * lambda * lambda).exp()
        })
        .sum();
    q.clamp(0.0, 1.0)
}

/// Pearson's chi-square test of counts against expected counts: the p-value
/// with `bins - 1 - fitted` degrees of freedom.
pub fn chi_square_p(observed: &[f64], expected: &[f64], fitted: usize) -> f64 {
    let x: f64 = observed
        .iter()
        .zip(expected)
        .map(|(o, e)| (o - e).powi(2) / e)
        .sum();
    let dof = (observed.len() - 1 - fitted) as f64;
    ChiSquared::new(dof).expect("degrees of freedom").sf(x)
}

/// Standard normal CDF.
pub fn normal_cdf(z: f64) -> f64 {
    0.5 * statrs::function::erf::erfc(-z / std::f64::consts::SQRT_2)
}

/// The p-value threshold every seeded test here uses: a true law fails one
/// test in ten thousand.
pub const P_MIN: f64 = 1e-4;

/// Mean and standard error of a series from the means of `blocks` equal
/// blocks (for correlated time series).
pub fn block_mean(xs: &[f64], blocks: usize) -> (f64, f64) {
    let size = xs.len() / blocks;
    let means: Vec<f64> = (0..blocks)
        .map(|b| xs[b * size..(b + 1) * size].iter().sum::<f64>() / size as f64)
        .collect();
    let mean = means.iter().sum::<f64>() / blocks as f64;
    let var = means.iter().map(|m| (m - mean).powi(2)).sum::<f64>() / (blocks - 1) as f64;
    (mean, (var / blocks as f64).sqrt())
}
