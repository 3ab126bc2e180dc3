//! Each particle's centre (where its list was last renewed) in 32-bit fixed
//! point across the box: 12 bytes a sphere instead of 24.
//!
//! A centre is only a reference point, so rounding it costs no exactness:
//! a neighbourhood is drawn around the stored centre, and a particle renews
//! when it has moved a shell from that, wherever it stood when it renewed.
//! The rounding only moves the start a box's length / 2^33 off the stored
//! centre, nothing against a shell.

use crate::engine::vector::Vector;

/// Steps across the box per axis.
const STEPS: f64 = 4_294_967_296.0;

#[derive(Debug, Clone)]
pub struct Centres<const D: usize> {
    at: Vec<[u32; D]>,
    /// A step's length per axis, and its inverse.
    step: Vector<D>,
    per_step: Vector<D>,
}

impl<const D: usize> Centres<D> {
    /// The centres nearest to `points`, in a box of `size`.
    pub fn new(size: &Vector<D>, points: impl Iterator<Item = Vector<D>>) -> Self {
        let mut centres = Centres {
            at: Vec::new(),
            step: size.map(|l| l / STEPS),
            per_step: size.map(|l| STEPS / l),
        };
        centres.at = points.map(|x| centres.nearest(&x)).collect();
        centres
    }

    pub fn len(&self) -> usize {
        self.at.len()
    }

    /// The step nearest to x on each axis (a point a hair outside the box,
    /// by round-off at a wall, takes the box's edge).
    fn nearest(&self, x: &Vector<D>) -> [u32; D] {
        std::array::from_fn(|k| {
            (x[k] * self.per_step[k])
                .round()
                .clamp(0.0, u32::MAX as f64) as u32
        })
    }

    #[inline(always)]
    pub fn get(&self, i: usize) -> Vector<D> {
        let at = &self.at[i];
        std::array::from_fn(|k| at[k] as f64 * self.step[k])
    }

    /// Make i's centre the one nearest to x, and return it.
    pub fn set(&mut self, i: usize, x: &Vector<D>) -> Vector<D> {
        self.at[i] = self.nearest(x);
        self.get(i)
    }

    pub fn iter(&self) -> impl Iterator<Item = Vector<D>> + '_ {
        (0..self.at.len()).map(|i| self.get(i))
    }

    /// Where i's centre is kept (for a prefetch hint).
    pub fn slot(&self, i: usize) -> &[u32; D] {
        &self.at[i]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stored centre is within half a step of the point it was set from,
    /// and setting it again from what it holds changes nothing (a save file
    /// restores it exactly).
    #[test]
    fn a_centre_is_half_a_step_from_its_point_and_round_trips() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let size = [120.4, 3.0, 7e5];
        let mut centres = Centres::new(&size, std::iter::empty());
        centres.at.push([0; 3]);
        for _ in 0..10_000 {
            let x: Vector<3> = std::array::from_fn(|k| rng.random_range(0.0..size[k]));
            let c = centres.set(0, &x);
            for k in 0..3 {
                assert!((c[k] - x[k]).abs() <= 0.5 * centres.step[k] * (1.0 + 1e-9));
            }
            assert_eq!(centres.set(0, &c), c);
        }
    }
}
