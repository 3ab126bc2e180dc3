//! Each particle's centre (where its list was last renewed) in 32-bit fixed
//! point: per axis, the index of its cell in the grid, then `FINE` bits for
//! where in that cell. 12 bytes a sphere instead of 24, and the grid keeps
//! the fine bits of each point beside its index, so a search measures the
//! distance to every point of a cell from the cell alone, exactly, in
//! integers (see `grid.rs`).
//!
//! A centre is only a reference point, so rounding it costs no exactness:
//! a neighbourhood is drawn around the stored centre, and a particle renews
//! when it has moved a shell from that, wherever it stood when it renewed.
//! The rounding only moves the start half a step (a cell's width / 2^13)
//! off the stored centre: a few thousandths of a diameter, nothing against
//! a shell.

use crate::engine::vector::Vector;

/// Bits of a centre's coordinate for where it is within its cell.
pub const FINE: u32 = 12;
/// Those bits of a coordinate.
pub const WITHIN: u32 = (1 << FINE) - 1;
/// Cells per axis that a coordinate can count.
pub const MAX_CELLS: u32 = 1 << (32 - FINE);

#[derive(Debug, Clone)]
pub struct Centres<const D: usize> {
    at: Vec<[u32; D]>,
    /// A step's length per axis, and its inverse.
    step: Vector<D>,
    per_step: Vector<D>,
    /// The last step per axis.
    last: [u32; D],
}

impl<const D: usize> Centres<D> {
    /// The centres nearest to `points`, in a box of `size` cut into `cells`
    /// cells per axis (at most `MAX_CELLS`).
    pub fn new(size: &Vector<D>, cells: [u32; D], points: impl Iterator<Item = Vector<D>>) -> Self {
        let steps: [f64; D] = std::array::from_fn(|k| ((cells[k] as u64) << FINE) as f64);
        let mut centres = Centres {
            at: Vec::new(),
            step: std::array::from_fn(|k| size[k] / steps[k]),
            per_step: std::array::from_fn(|k| steps[k] / size[k]),
            last: std::array::from_fn(|k| (((cells[k] as u64) << FINE) - 1) as u32),
        };
        centres.at = points.map(|x| centres.nearest(&x)).collect();
        centres
    }

    pub fn len(&self) -> usize {
        self.at.len()
    }

    /// The step holding x on each axis (a point a hair outside the box, by
    /// round-off at a wall, takes the step at the box's edge).
    pub fn nearest(&self, x: &Vector<D>) -> [u32; D] {
        std::array::from_fn(|k| {
            (x[k] * self.per_step[k])
                .floor()
                .clamp(0.0, self.last[k] as f64) as u32
        })
    }

    /// i's centre: the middle of its step on each axis.
    #[inline(always)]
    pub fn get(&self, i: usize) -> Vector<D> {
        self.position(&self.at[i])
    }

    /// Where a centre at these steps lies.
    #[inline(always)]
    pub fn position(&self, at: &[u32; D]) -> Vector<D> {
        std::array::from_fn(|k| (at[k] as f64 + 0.5) * self.step[k])
    }

    /// i's centre as it is kept: steps from the origin, per axis.
    #[inline(always)]
    pub fn steps(&self, i: usize) -> &[u32; D] {
        &self.at[i]
    }

    /// A step's length per axis.
    pub fn step(&self) -> &Vector<D> {
        &self.step
    }

    /// Make i's centre the one nearest to x, and return it.
    pub fn set(&mut self, i: usize, x: &Vector<D>) -> Vector<D> {
        self.at[i] = self.nearest(x);
        self.get(i)
    }

    pub fn iter(&self) -> impl Iterator<Item = Vector<D>> + '_ {
        (0..self.at.len()).map(|i| self.get(i))
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
        let mut centres = Centres::new(&size, [40, 1, MAX_CELLS], std::iter::empty());
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
