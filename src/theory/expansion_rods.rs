//! Free expansion of hard rods of one mass in 1D, exactly. Rods of length
//! sigma never pass each other, but two equal rods that collide swap
//! velocities, which is what two points passing through each other would
//! do. Tonks' mapping makes that exact: with the rods sorted, y_i = x_i -
//! sigma/2 - i sigma turns N rods in a box L into N points in L' = L -
//! N sigma that move freely and reflect off the walls. Random placement of
//! the rods in the left half is N independent points uniform on [0, c], c
//! = L/2 - N sigma. Rod i is left of the middle when y_(i) < z_i = L/2 -
//! (i + 1/2) sigma; since y_(i) increases and z_i decreases, the rods on
//! the left are a prefix and their expected number is
//!
//!   E K = sum_i P(y_(i) < z_i) = sum_i P(Bin(N, F_t(z_i)) >= i + 1),
//!
//! F_t(z) the probability that one free point is below z at time t.

use super::expansion::{FreeExpansion, Mixture, Speeds};

/// N rods of length `sigma` of one mass, started at random in the left half.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rods {
    /// One free point in the reduced box.
    pub point: FreeExpansion,
    pub count: usize,
    pub sigma: f64,
    pub box_length: f64,
}

impl Rods {
    /// None when the rods do not fit in the left half.
    pub fn new(box_length: f64, count: usize, sigma: f64, speeds: Speeds) -> Option<Rods> {
        let reduced = box_length - count as f64 * sigma;
        let start = 0.5 * box_length - count as f64 * sigma;
        (start > 0.0).then_some(Rods {
            point: FreeExpansion {
                length: reduced,
                start,
                speeds,
            },
            count,
            sigma,
            box_length,
        })
    }

    pub fn left_fraction(&self, t: f64) -> f64 {
        let n = self.count;
        let expected: f64 = (0..n)
            .map(|i| {
                let z = 0.5 * self.box_length - (i as f64 + 0.5) * self.sigma;
                binomial_tail(n, self.point.below(z, t), i + 1)
            })
            .sum();
        expected / n as f64
    }
}

/// P(Bin(n, p) >= k), summing the probabilities from k up (in logs, so
/// that none underflows).
fn binomial_tail(n: usize, p: f64, k: usize) -> f64 {
    if p <= 0.0 {
        return if k == 0 { 1.0 } else { 0.0 };
    }
    if p >= 1.0 {
        return if k <= n { 1.0 } else { 0.0 };
    }
    let ln = |j: usize| -> f64 {
        let (j, nf) = (j as f64, n as f64);
        ln_gamma(nf + 1.0) - ln_gamma(j + 1.0) - ln_gamma(nf - j + 1.0)
            + j * p.ln()
            + (nf - j) * (1.0 - p).ln()
    };
    (k..=n).map(|j| ln(j).exp()).sum::<f64>().min(1.0)
}

fn ln_gamma(x: f64) -> f64 {
    statrs::function::gamma::ln_gamma(x)
}

/// The collisionless prediction of a scene: free particles (any kinds) or
/// rods of one mass in 1D.
#[derive(Debug, Clone, PartialEq)]
pub enum Collisionless {
    Free(Mixture),
    Rods(Rods),
}

impl Collisionless {
    pub fn left_fraction(&self, t: f64) -> f64 {
        match self {
            Collisionless::Free(m) => m.left_fraction(t),
            Collisionless::Rods(r) => r.left_fraction(t),
        }
    }

    pub fn relaxation_time(&self) -> f64 {
        match self {
            Collisionless::Free(m) => m.relaxation_time(),
            Collisionless::Rods(r) => super::expansion::first_below(
                &|t| r.left_fraction(t) - 0.5,
                0.5 / std::f64::consts::E,
                r.point.length / r.point.speeds.scale(),
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    #[test]
    fn binomial_tail_sums_to_the_mean() {
        let (n, p) = (30, 0.37);
        let mean: f64 = (1..=n).map(|k| binomial_tail(n, p, k)).sum();
        assert!((mean - n as f64 * p).abs() < 1e-10);
        assert_eq!(binomial_tail(n, p, 0), 1.0);
    }

    /// Short rods are points: the split is the free one.
    #[test]
    fn vanishing_rods_are_free_points() {
        let speeds = Speeds::Uniform(1.0);
        let rods = Rods::new(40.0, 20, 1e-9, speeds).unwrap();
        let free = FreeExpansion::with(40.0, 0.0, speeds);
        for t in [3.0, 15.0, 40.0] {
            assert!((rods.left_fraction(t) - free.left_fraction(t)).abs() < 1e-6);
        }
        assert!(Rods::new(40.0, 40, 1.0, speeds).is_none());
    }

    /// The mapping against a direct draw of the same free points: sorted,
    /// shifted back to rods, counted left of the middle.
    #[test]
    fn matches_a_monte_carlo_of_the_mapped_points() {
        let rods = Rods::new(30.0, 8, 1.0, Speeds::Maxwell(1.0)).unwrap();
        let (l, c) = (rods.point.length, rods.point.start);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        let runs = 40_000;
        for t in [2.0, 6.0, 20.0] {
            let mut total = 0.0;
            let mut squares = 0.0;
            for _ in 0..runs {
                let mut y: Vec<f64> = (0..8)
                    .map(|_| {
                        let (a, b): (f64, f64) = (rng.random(), rng.random());
                        let v =
                            (-2.0 * (1.0 - a).ln()).sqrt() * (2.0 * std::f64::consts::PI * b).cos();
                        let mut x = c * rng.random::<f64>() + v * t;
                        while !(0.0..=l).contains(&x) {
                            x = if x < 0.0 { -x } else { 2.0 * l - x };
                        }
                        x
                    })
                    .collect();
                y.sort_by(f64::total_cmp);
                let left = (0..8).filter(|&i| y[i] + (i as f64 + 0.5) < 15.0).count() as f64 / 8.0;
                total += left;
                squares += left * left;
            }
            let mean = total / runs as f64;
            let se = ((squares / runs as f64 - mean * mean) / runs as f64).sqrt();
            let exact = rods.left_fraction(t);
            assert!(
                (mean - exact).abs() < 4.0 * se,
                "t = {t}: {mean} +- {se}, {exact}"
            );
        }
    }
}
