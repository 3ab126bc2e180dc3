//! A grid of cells, each holding the indices of its points, for finding
//! every point within one cell width of another in O(1) and in a few
//! contiguous reads. On periodic axes the grid wraps, and a point found
//! across the boundary comes with the image code of the shift that brings it
//! next to the one asked about.
//!
//! The grid keeps no positions: its caller keeps every point's centre
//! already (4 bytes a point here, instead of 16 with a single-precision
//! copy of it).

use super::Image;
use super::store::{ListStore, room_for};
use crate::engine::boundary::SimBox;
use crate::engine::vector::{Vector, norm2};

const NONE: u32 = u32::MAX;

#[derive(Debug, Clone)]
pub struct Grid<const D: usize> {
    n: [u32; D],
    width: [f64; D],
    periodic: [bool; D],
    /// Linear-index stride per axis.
    stride: [usize; D],
    /// Each cell's points, with room in line for a little more than a
    /// cell's share (a fuller cell spills, see `store.rs`). A cell's place
    /// is computed, not read from a header, so a search can ask for all its
    /// cells' points at once (see `cells_around`).
    cells: ListStore,
    /// Each point's cell.
    cell: Vec<u32>,
    /// See [`Grid::rounding`].
    rounding: f64,
}
impl<const D: usize> Grid<D> {
    /// A grid for `points` points whose cells are at least `min_width` wide,
    /// but no more than a few cells per point in all, so a dilute gas in a
    /// huge box does not allocate a huge grid. Periodic axes need at least
    /// three cells, so that no point is found twice; the caller checks that.
    pub fn new(points: usize, min_width: f64, sim_box: &SimBox<D>) -> Self {
        let budget = (4 * points + 64) as f64;
        let mut n = [1u32; D];
        for k in 0..D {
            let fit = (sim_box.size[k] / min_width).floor();
            n[k] = if fit.is_nan() {
                1
            } else {
                fit.clamp(1.0, budget) as u32
            };
        }
        let total: f64 = n.iter().map(|&x| x as f64).product();
        if total > budget {
            let f = (budget / total).powf(1.0 / D as f64);
            for (k, x) in n.iter_mut().enumerate() {
                let least = if sim_box.axes[k].is_periodic() { 3 } else { 1 };
                *x = ((*x as f64 * f).floor() as u32).max(least).min(*x);
            }
        }
        let mut stride = [1usize; D];
        for k in 1..D {
            stride[k] = stride[k - 1] * n[k - 1] as usize;
        }
        let cells = stride[D - 1] * n[D - 1] as usize;
        Grid {
            n,
            width: std::array::from_fn(|k| sim_box.size[k] / n[k] as f64),
            periodic: std::array::from_fn(|k| sim_box.axes[k].is_periodic()),
            stride,
            cells: ListStore::new(cells, room_for(points as f64 / cells as f64)),
            cell: vec![NONE; points],
            rounding: 4.0 * f64::EPSILON * norm2(&sim_box.size).sqrt(),
        }
    }

    /// A bound, with a margin, on the round-off in placing a point in its
    /// cell and in measuring how far apart two points are: a few units in
    /// the last place of the box's diagonal. A search widened by it finds
    /// every point within its reach whatever the round-off.
    pub fn rounding(&self) -> f64 {
        self.rounding
    }

    fn coords(&self, x: &Vector<D>) -> [u32; D] {
        std::array::from_fn(|k| ((x[k] / self.width[k]).floor().max(0.0) as u32).min(self.n[k] - 1))
    }

    /// Cell c's points.
    fn members(&self, c: usize) -> &[u32] {
        self.cells.get(c)
    }

    /// File point `i` at position `x`, which lies in the box (moving it if
    /// it was filed before).
    pub fn place(&mut self, i: usize, x: &Vector<D>) {
        let c = self.coords(x);
        let cell = (0..D)
            .map(|k| c[k] as usize * self.stride[k])
            .sum::<usize>();
        if self.cell[i] != NONE {
            let old = self.cell[i] as usize;
            if old == cell {
                return;
            }
            let at = self.cells.get(old).iter().position(|&m| m == i as u32);
            self.cells.swap_remove(old, at.expect("filed"));
        }
        self.cells.push(cell, i as u32);
        self.cell[i] = cell as u32;
    }

    /// The (up to) 3^D cells around position `x` that may hold a point within
    /// `reach` of it (x itself may be filed there too), into `cells`, and how
    /// many there are: each one's points and the image code they are seen
    /// through. (Written in place: returned, the array would be copied.)
    pub fn cells_around<'a>(
        &'a self,
        x: &Vector<D>,
        reach: f64,
        cells: &mut [(Image, &'a [u32]); 27],
    ) -> usize {
        let mut near = [(0usize, 0 as Image); 27];
        let count = self.cells_near(x, reach, &mut near);
        // Each cell's points lie elsewhere in memory, at a place known
        // without reading anything (but for the few cells that spilled):
        // ask for all of them (and their counts) first, so that their cache
        // misses overlap (see prefetch.rs).
        for &(cell, _) in &near[..count] {
            self.cells.prefetch(cell);
        }
        for (slot, &(cell, image)) in cells.iter_mut().zip(&near[..count]) {
            *slot = (image, self.members(cell));
        }
        count
    }

    /// The (up to) 3^D cells around position `x` (D <= 3) that may hold a
    /// point within `reach` of it, into `near`, and how many: each one's
    /// linear index and the image code of the points found there.
    ///
    /// A cell is left out when its nearest face, edge or corner is beyond
    /// `reach` and twice the rounding (a corner cell, half the time, in 3D):
    /// a point in it is then more than `reach` and the rounding away, so the
    /// caller's search, widened by the rounding, would not have kept it.
    fn cells_near(&self, x: &Vector<D>, reach: f64, near: &mut [(usize, Image); 27]) -> usize {
        let c = self.coords(x);
        // Per axis, the (up to) three neighbouring rows: their part of the
        // linear cell index and of the image code, and how far x is from
        // them along that axis.
        let mut rows = [[(0usize, 0u8, 0.0f64); 3]; D];
        let mut count = [0usize; D];
        let mut place = 1u8;
        for k in 0..D {
            let low = c[k] as f64 * self.width[k];
            for offset in [-1i64, 0, 1] {
                let mut ck = c[k] as i64 + offset;
                let mut digit = 1u8;
                if ck < 0 || ck >= self.n[k] as i64 {
                    if !self.periodic[k] {
                        continue;
                    }
                    digit = if ck < 0 { 0 } else { 2 };
                    ck = ck.rem_euclid(self.n[k] as i64);
                }
                let gap = match offset {
                    -1 => (x[k] - low).max(0.0),
                    0 => 0.0,
                    _ => (low + self.width[k] - x[k]).max(0.0),
                };
                rows[k][count[k]] = (ck as usize * self.stride[k], digit * place, gap);
                count[k] += 1;
            }
            place *= 3;
        }
        let limit = reach + 2.0 * self.rounding;
        let limit2 = limit * limit;
        // Every combination of rows, odometer style; each is written, and
        // kept or not without a branch.
        let mut found = 0;
        let mut at = [0usize; D];
        loop {
            let (mut cell, mut image, mut gap2) = (0usize, 0 as Image, 0.0);
            for k in 0..D {
                let (part, digit, gap) = rows[k][at[k]];
                cell += part;
                image += digit;
                gap2 += gap * gap;
            }
            near[found] = (cell, image);
            found += (gap2 < limit2) as usize;
            let mut k = 0;
            loop {
                at[k] += 1;
                if at[k] < count[k] {
                    break;
                }
                at[k] = 0;
                k += 1;
                if k == D {
                    return found;
                }
            }
        }
    }

    /// Call `f(j)` for every point filed in the slab of cells whose axis-0
    /// range meets [lo, hi].
    pub fn for_each_in_slab(&self, lo: f64, hi: f64, mut f: impl FnMut(usize)) {
        let first = ((lo / self.width[0]).floor().max(0.0) as u32).min(self.n[0] - 1);
        let last = ((hi / self.width[0]).floor().max(0.0) as u32).min(self.n[0] - 1);
        let rest: usize = (1..D).map(|k| self.n[k] as usize).product();
        for c0 in first..=last {
            // Cells sharing an axis-0 index are n[0] apart in the linear order.
            for r in 0..rest {
                for &j in self.members(c0 as usize + r * self.n[0] as usize) {
                    f(j as usize);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two neighbouring cells filled past their room in line, then the
    /// other points piled into one cell, then all but one of those moved
    /// out again and into another: cells spill and come back, and every
    /// cell still holds exactly the points filed there.
    #[test]
    fn a_cell_that_fills_spills_and_keeps_every_point() {
        let sim_box = SimBox::periodic([9.0; 3]);
        let mut grid = Grid::<3>::new(48, 3.0, &sim_box);
        for i in 40..48 {
            let x = if i < 44 { 4.0 } else { 7.0 };
            grid.place(i, &[x, 1.0 + 0.1 * (i % 4) as f64, 1.0]);
        }
        for i in 0..40 {
            grid.place(i, &[1.0 + 0.01 * i as f64, 1.0, 1.0]);
        }
        for i in 1..40 {
            grid.place(i, &[7.0, 3.0 + 0.05 * i as f64, 4.0]);
        }
        // The points filed in the cell holding x.
        let ids = |x: &Vector<3>| {
            let c = grid.coords(x);
            let cell = (0..3).map(|k| c[k] as usize * grid.stride[k]).sum();
            let mut ids = grid.members(cell).to_vec();
            ids.sort();
            ids
        };
        assert_eq!(ids(&[1.0, 1.0, 1.0]), vec![0]);
        assert_eq!(ids(&[7.0, 4.0, 4.0]), (1..40).collect::<Vec<_>>());
        assert_eq!(ids(&[4.0, 1.0, 1.0]), (40..44).collect::<Vec<_>>());
        assert_eq!(ids(&[7.0, 1.0, 1.0]), (44..48).collect::<Vec<_>>());
        let cells = grid.n.iter().map(|&k| k as usize).product::<usize>();
        let filed: usize = (0..cells).map(|c| grid.members(c).len()).sum();
        assert_eq!(filed, 48);
    }

    /// Whatever cells the search leaves out, every point within the reach
    /// of the position asked about is in one it keeps, seen through the right
    /// image: random points and positions, a periodic box and one with a
    /// periodic axis between walls, in 2D and 3D.
    fn no_point_in_reach_is_left_out<const D: usize>(sim_box: SimBox<D>, reach: f64) {
        use super::super::image_shift;
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        let at = |rng: &mut rand_chacha::ChaCha8Rng| -> Vector<D> {
            std::array::from_fn(|k| rng.random::<f64>() * sim_box.size[k])
        };
        let points: Vec<Vector<D>> = (0..3000).map(|_| at(&mut rng)).collect();
        let mut grid = Grid::<D>::new(points.len(), reach, &sim_box);
        for (i, x) in points.iter().enumerate() {
            grid.place(i, x);
        }
        let mut kept_cells = 0;
        for _ in 0..300 {
            let x = at(&mut rng);
            let mut cells = [(0, &[][..]); 27];
            let count = grid.cells_around(&x, reach, &mut cells);
            kept_cells += count;
            let mut seen = vec![false; points.len()];
            for &(image, members) in &cells[..count] {
                let s = image_shift(image, &sim_box.size);
                for &j in members {
                    let r: Vector<D> = std::array::from_fn(|k| points[j as usize][k] + s[k] - x[k]);
                    seen[j as usize] |= norm2(&r) < reach * reach;
                }
            }
            for (j, p) in points.iter().enumerate() {
                // The nearest image of j, by brute force.
                let near = (0..3u32.pow(D as u32)).any(|image| {
                    let s = image_shift(image as Image, &sim_box.size);
                    // Only a periodic axis has images beyond the box.
                    let exists = (0..D).all(|k| s[k] == 0.0 || sim_box.axes[k].is_periodic());
                    let r: Vector<D> = std::array::from_fn(|k| p[k] + s[k] - x[k]);
                    exists && norm2(&r) < reach * reach
                });
                assert_eq!(seen[j], near, "point {j} from {x:?}");
            }
        }
        // The search did leave some cells out.
        assert!(kept_cells < 300 * 3usize.pow(D as u32), "{kept_cells}");
    }

    #[test]
    fn cells_left_out_hold_no_point_in_reach() {
        no_point_in_reach_is_left_out(SimBox::<3>::periodic([10.0, 11.0, 12.5]), 2.4);
        let mut walls = SimBox::<3>::hard([10.0, 11.0, 12.5]);
        walls.axes[1] = crate::engine::boundary::Axis::Periodic;
        no_point_in_reach_is_left_out(walls, 2.4);
        no_point_in_reach_is_left_out(SimBox::<2>::periodic([30.0, 20.0]), 1.7);
    }
}
