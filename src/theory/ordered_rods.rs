//! Where each rod of a 1D hard-rod gas between walls is (the Tonks gas):
//! rods never pass, so the k-th from the left keeps its rank. Their
//! centres are uniform over the ordered configurations; taking out the
//! space the rods fill, y_k = x_k - r_k - sum_{j<k} 2 r_j, maps these onto
//! ordered points in [0, L - sum 2 r_j]: the order statistics of N
//! uniform points, y_k / L' ~ Beta(k, N - k + 1). Masses do not enter.

use statrs::function::beta::{checked_beta_reg, ln_beta};

/// The law of the centre of the rod of rank `rank` (1 = leftmost).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RodPosition {
    pub rank: usize,
    pub count: usize,
    /// Lowest centre it can reach.
    pub offset: f64,
    /// Free length L' = L - sum of diameters.
    pub free: f64,
}

/// Every rod's law, by rank, for a box of length L and the rods' radii
/// from left to right.
pub fn positions(length: f64, radii: &[f64]) -> Vec<RodPosition> {
    let filled: f64 = radii.iter().map(|r| 2.0 * r).sum();
    let mut below = 0.0;
    radii
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let law = RodPosition {
                rank: k + 1,
                count: radii.len(),
                offset: below + r,
                free: length - filled,
            };
            below += 2.0 * r;
            law
        })
        .collect()
}

impl RodPosition {
    fn ab(&self) -> (f64, f64) {
        (self.rank as f64, (self.count - self.rank + 1) as f64)
    }

    pub fn cdf(&self, x: f64) -> f64 {
        let (a, b) = self.ab();
        let u = ((x - self.offset) / self.free).clamp(0.0, 1.0);
        checked_beta_reg(a, b, u).unwrap_or(f64::NAN)
    }

    pub fn pdf(&self, x: f64) -> f64 {
        let u = (x - self.offset) / self.free;
        if !(0.0..=1.0).contains(&u) {
            return 0.0;
        }
        let (a, b) = self.ab();
        let ln = (a - 1.0) * u.ln() + (b - 1.0) * (1.0 - u).ln() - ln_beta(a, b);
        ln.exp() / self.free
    }

    pub fn mean(&self) -> f64 {
        self.offset + self.free * self.rank as f64 / (self.count + 1) as f64
    }

    pub fn probability(&self, lo: f64, hi: f64) -> f64 {
        self.cdf(hi) - self.cdf(lo)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Rejection sampling of hard rods in a box (uniform centres, kept when
    /// no two overlap), sorted: the fraction of draws with the k-th centre
    /// below x is the law's, within 4 binomial errors.
    #[test]
    fn monte_carlo_hard_rods() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let radii = [0.5, 0.2, 0.5, 0.3];
        let length = 7.0;
        let laws = positions(length, &radii);
        let at = [1.0, 2.5, 4.0, 5.5];
        let mut below = [[0usize; 4]; 4];
        let mut kept = 0usize;
        while kept < 30_000 {
            // Draw in rank order's space directly would assume the answer:
            // draw every rod anywhere, keep the ordered, non-overlapping ones.
            let x: Vec<f64> = radii
                .iter()
                .map(|r| r + (length - 2.0 * r) * rng.random::<f64>())
                .collect();
            let ok = (1..4).all(|k| x[k] - x[k - 1] >= radii[k] + radii[k - 1]);
            if !ok {
                continue;
            }
            kept += 1;
            for k in 0..4 {
                for (j, a) in at.iter().enumerate() {
                    below[k][j] += (x[k] < *a) as usize;
                }
            }
        }
        for k in 0..4 {
            for (j, a) in at.iter().enumerate() {
                let p = laws[k].cdf(*a);
                let got = below[k][j] as f64 / kept as f64;
                let se = (p * (1.0 - p) / kept as f64).sqrt().max(1e-4);
                assert!((got - p).abs() < 4.0 * se, "rank {k} at {a}: {got} vs {p}");
            }
        }
    }

    #[test]
    fn pdf_integrates_to_the_cdf() {
        let laws = positions(11.0, &[0.0; 10]);
        for law in &laws {
            let n = 100_000;
            let h = 11.0 / n as f64;
            let mut sum = 0.0;
            for i in 0..n {
                sum += law.pdf((i as f64 + 0.5) * h) * h;
                if i % 20_000 == 19_999 {
                    assert!((sum - law.cdf((i + 1) as f64 * h)).abs() < 1e-6);
                }
            }
            assert!((sum - 1.0).abs() < 1e-6);
            assert!((law.mean() - 11.0 * law.rank as f64 / 11.0).abs() < 1e-12);
        }
    }
}
