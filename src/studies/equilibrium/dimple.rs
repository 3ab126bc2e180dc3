//! MacKay's "dimple" in P(v1), made definite so that it can be counted: the
//! particle's histogram regrouped into 20 equal bins across its range, and
//! a dimple when the two central bins together hold fewer counts than the
//! pair beside them on each side. Counted over replicas, and for
//! independent draws from the exact law by Monte Carlo.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Bins a histogram is regrouped into (MacKay's are of this order).
pub const COARSE: usize = 20;

/// Whether counts over a symmetric range (a multiple of `COARSE` bins)
/// show a dimple.
pub fn has_dimple(counts: &[f64]) -> bool {
    if counts.is_empty() || !counts.len().is_multiple_of(COARSE) {
        return false;
    }
    let k = counts.len() / COARSE;
    let c: Vec<f64> = counts.chunks(k).map(|b| b.iter().sum()).collect();
    let h = COARSE / 2;
    let centre = c[h - 1] + c[h];
    centre < c[h - 3] + c[h - 2] && centre < c[h + 1] + c[h + 2]
}

/// The share of the counts in the two central bins of `COARSE`.
pub fn central_share(counts: &[f64]) -> f64 {
    let k = counts.len() / COARSE;
    let h = counts.len() / 2;
    let total: f64 = counts.iter().sum();
    counts[h - k..h + k].iter().sum::<f64>() / total
}

/// How many independent samples a run's histogram is worth: the binomial
/// variance p(1 - p)/n of the central share, solved for n with the
/// variance measured over the replicas.
pub fn independent_samples(shares: &[f64]) -> f64 {
    let n = shares.len() as f64;
    let p = shares.iter().sum::<f64>() / n;
    let var = shares.iter().map(|s| (s - p).powi(2)).sum::<f64>() / (n - 1.0);
    p * (1.0 - p) / var
}

/// The chance that `samples` independent draws from the exact law of a
/// component (f degrees of freedom), binned over ±`half` in units of its
/// reach, show a dimple: the share of `trials` seeded trials.
pub fn chance(dof: usize, half: f64, samples: usize, trials: usize, seed: u64) -> f64 {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut gauss = || {
        let (u, v): (f64, f64) = (rng.random(), rng.random());
        (-2.0 * (1.0 - u).ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    };
    let hits = (0..trials).filter(|_| {
        let mut counts = vec![0.0; COARSE];
        for _ in 0..samples {
            // A component of a uniform point on the sphere in f dimensions.
            let g: Vec<f64> = (0..dof).map(|_| gauss()).collect();
            let t = g[0] / g.iter().map(|x| x * x).sum::<f64>().sqrt();
            let b = ((t + half) / (2.0 * half) * COARSE as f64).floor();
            if (0.0..COARSE as f64).contains(&b) {
                counts[b as usize] += 1.0;
            }
        }
        has_dimple(&counts)
    });
    hits.count() as f64 / trials as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dip_in_the_middle_is_a_dimple_and_a_peak_is_not() {
        let peak: Vec<f64> = (0..60).map(|b| 30.0 - (b as f64 - 29.5).abs()).collect();
        assert!(!has_dimple(&peak));
        let mut dip = peak.clone();
        for b in 24..36 {
            dip[b] = 5.0;
        }
        assert!(has_dimple(&dip));
        // Many draws from the exact law: its peak shows, no dimple.
        assert_eq!(chance(10, 1.0, 20_000, 20, 1), 0.0);
        // Few draws: sometimes.
        let p = chance(10, 1.0, 100, 400, 2);
        assert!(p > 0.02 && p < 0.5, "{p}");
        assert_eq!(
            central_share(&peak),
            (29.5 + 28.5 + 28.5 + 29.5 + 27.5 + 27.5) / 900.0
        );
    }
}
