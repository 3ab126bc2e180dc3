//! A grid of cells, each holding its points, for finding every point within
//! one cell width of another in O(1) and in a few contiguous reads. On
//! periodic axes the grid wraps, and a point found across the boundary comes
//! with the image code of the shift that brings it next to the one asked
//! about.
//!
//! A point is filed as its index and the fine bits of its centre (where it
//! is within its cell, see `centres.rs`): a search reads where each point
//! of a cell is from the cell itself, not from the caller's scattered
//! centres, and a point's cell follows from its centre, so the grid keeps
//! nothing per point.

use super::Image;
use super::centres::{FINE, MAX_CELLS, WITHIN};
use super::store::{ListStore, room_for};
use crate::engine::boundary::SimBox;
use crate::engine::prefetch::Read;
use crate::engine::vector::{Vector, norm2};

/// A filed point: its index in the low `INDEX_BITS` bits, then `FINE` bits
/// per axis for where it is in its cell.
pub type Point = u64;
const INDEX_BITS: u32 = 28;
const _: () = assert!(INDEX_BITS + 3 * FINE <= 64);

/// The index of a filed point.
#[inline(always)]
pub fn index(e: Point) -> usize {
    (e & ((1 << INDEX_BITS) - 1)) as usize
}

/// Where a filed point is within its cell along axis k, in steps.
#[inline(always)]
pub fn fine(e: Point, k: usize) -> i32 {
    ((e >> (INDEX_BITS + FINE * k as u32)) & WITHIN as Point) as i32
}

/// A cell found by a search: its index, the image its points are seen
/// through, and per axis its corner's offset in steps from the centre
/// searched around (image shift included: a point's offset is this plus its
/// fine bits), packed 16 bits an axis, each biased to be positive, so that
/// the axes' parts of a cell's offset add up without carries.
#[derive(Debug, Clone, Copy, Default)]
pub struct Near {
    cell: usize,
    pub image: Image,
    from: u64,
}
const BIAS: i32 = 1 << 14;

impl Near {
    /// The corner's offset from the centre along axis k, in steps.
    #[inline(always)]
    pub fn from(&self, k: usize) -> i32 {
        ((self.from >> (16 * k)) & 0xFFFF) as i32 - BIAS
    }
}

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
    /// cells' points at once (see `prefetch_cells`).
    cells: ListStore<Point>,
    /// See [`Grid::rounding`].
    rounding: f64,
}

impl<const D: usize> Grid<D> {
    /// The cells per axis of a grid for `points` points whose cells are at
    /// least `min_width` wide, but no more than a few cells per point in
    /// all, so a dilute gas in a huge box does not allocate a huge grid.
    /// Periodic axes need at least three cells, so that no point is found
    /// twice; the caller checks that. No axis has more than `MAX_CELLS`, so
    /// that a centre can count them.
    pub fn cells_for(points: usize, min_width: f64, sim_box: &SimBox<D>) -> [u32; D] {
        let budget = (4 * points + 64) as f64;
        let mut n = [1u32; D];
        for k in 0..D {
            let fit = (sim_box.size[k] / min_width).floor();
            n[k] = if fit.is_nan() {
                1
            } else {
                fit.clamp(1.0, budget.min(MAX_CELLS as f64)) as u32
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
        n
    }

    /// A grid of `n` cells per axis (`cells_for`) for `points` points.
    pub fn new(points: usize, n: [u32; D], sim_box: &SimBox<D>) -> Self {
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
            rounding: 4.0 * f64::EPSILON * norm2(&sim_box.size).sqrt(),
        }
    }

    /// A bound, with a margin, on the round-off between a centre's steps
    /// and its position, and in measuring how far apart two points are: a
    /// few units in the last place of the box's diagonal. A search widened
    /// by it finds every point within its reach whatever the round-off.
    pub fn rounding(&self) -> f64 {
        self.rounding
    }

    /// Cells per axis (what a centre's coordinates count).
    pub fn cells_per_axis(&self) -> [u32; D] {
        self.n
    }

    /// The cell of a centre at `steps`.
    fn cell_of(&self, steps: &[u32; D]) -> usize {
        (0..D)
            .map(|k| (steps[k] >> FINE) as usize * self.stride[k])
            .sum()
    }

    /// Cell c's points.
    fn members(&self, c: usize) -> &[Point] {
        self.cells.get(c)
    }

    /// Empty every cell.
    pub fn clear(&mut self) {
        self.cells.clear();
    }

    /// File point `i`, whose centre is at `steps` (moving it from where it
    /// was filed at `was`, if it was).
    pub fn place(&mut self, i: usize, steps: &[u32; D], was: Option<&[u32; D]>) {
        let cell = self.cell_of(steps);
        let mut e = i as Point;
        for (k, &s) in steps.iter().enumerate() {
            e |= ((s & WITHIN) as Point) << (INDEX_BITS + FINE * k as u32);
        }
        if let Some(was) = was {
            let old = self.cell_of(was);
            let at = self.members(old).iter().position(|&m| index(m) == i);
            let at = at.expect("filed");
            if old == cell {
                self.cells.replace(cell, at, e);
                return;
            }
            self.cells.swap_remove(old, at);
        }
        self.cells.push(cell, e);
    }

    /// A found cell's points.
    #[inline(always)]
    pub fn points(&self, near: &Near) -> &[Point] {
        self.members(near.cell)
    }

    /// Start loading these cells' points (and counts), to be read `when`,
    /// all at once so that their cache misses overlap (a hint; see
    /// prefetch.rs). Each cell's place is known without reading anything
    /// (but for the few cells that spilled).
    #[inline(always)]
    pub fn prefetch_cells(&self, near: &[Near], when: Read) {
        for cell in near {
            self.cells.prefetch(cell.cell, when);
        }
    }

    /// The (up to) 3^D cells around a centre (at `steps`, at position `x`;
    /// D <= 3) that may hold a point within `reach` of it (the centre's own
    /// point may be filed there too), into `near`, and how many there are.
    /// (Written in place: returned, the array would be copied.) Their
    /// points are asked for, to be read `when`.
    ///
    /// A cell is left out when its nearest face, edge or corner is beyond
    /// `reach` and twice the rounding (a corner cell, half the time, in 3D):
    /// a point in it is then more than `reach` and the rounding away, so the
    /// caller's search, widened by the rounding, would not have kept it.
    // Inlined, so that each caller's `when` picks its hint at compile time.
    #[inline]
    pub fn cells_around(
        &self,
        steps: &[u32; D],
        x: &Vector<D>,
        reach: f64,
        near: &mut [Near; 27],
        when: Read,
    ) -> usize {
        // Per axis, the (up to) three neighbouring rows: their part of the
        // linear cell index, of the image code and of the packed offset
        // from the centre, and how far x is from them.
        let mut rows = [[(0usize, 0u8, 0u64, 0.0f64); 3]; D];
        let mut count = [0usize; D];
        let mut place = 1u8;
        for k in 0..D {
            let c = (steps[k] >> FINE) as i64;
            let low = c as f64 * self.width[k];
            // The centre's cell starts this many steps below it.
            let within = (steps[k] & WITHIN) as i32;
            for offset in [-1i64, 0, 1] {
                let mut ck = c + offset;
                let from = ((((offset as i32) << FINE) - within + BIAS) as u64) << (16 * k);
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
                rows[k][count[k]] = (ck as usize * self.stride[k], digit * place, from, gap);
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
            let (mut cell, mut image, mut from, mut gap2) = (0usize, 0 as Image, 0u64, 0.0);
            for k in 0..D {
                let (part, digit, offset, gap) = rows[k][at[k]];
                cell += part;
                image += digit;
                from += offset;
                gap2 += gap * gap;
            }
            near[found] = Near { cell, image, from };
            found += (gap2 < limit2) as usize;
            let mut k = 0;
            while k < D {
                at[k] += 1;
                if at[k] < count[k] {
                    break;
                }
                at[k] = 0;
                k += 1;
            }
            if k == D {
                break;
            }
        }
        self.prefetch_cells(&near[..found], when);
        found
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
                for &e in self.members(c0 as usize + r * self.n[0] as usize) {
                    f(index(e));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The steps of a centre at x, as `centres.rs` keeps them.
    fn steps_at<const D: usize>(grid: &Grid<D>, x: &Vector<D>) -> [u32; D] {
        std::array::from_fn(|k| (x[k] / grid.width[k] * (1 << FINE) as f64) as u32)
    }

    /// Two neighbouring cells filled past their room in line, then the
    /// other points piled into one cell, then all but one of those moved
    /// out again and into another, and moved within it: cells spill and
    /// come back, and every cell still holds exactly the points filed there,
    /// each where it was filed last.
    #[test]
    fn a_cell_that_fills_spills_and_keeps_every_point() {
        let sim_box = SimBox::periodic([9.0; 3]);
        let mut grid = Grid::<3>::new(48, Grid::<3>::cells_for(48, 3.0, &sim_box), &sim_box);
        let mut filed = vec![None; 48];
        let mut place = |grid: &mut Grid<3>, i: usize, x: Vector<3>| {
            let steps = steps_at(grid, &x);
            grid.place(i, &steps, filed[i].as_ref());
            filed[i] = Some(steps);
        };
        for i in 40..48 {
            let x = if i < 44 { 4.0 } else { 7.0 };
            place(&mut grid, i, [x, 1.0 + 0.1 * (i % 4) as f64, 1.0]);
        }
        for i in 0..40 {
            place(&mut grid, i, [1.0 + 0.01 * i as f64, 1.0, 1.0]);
        }
        for i in 1..40 {
            place(&mut grid, i, [7.0, 3.0 + 0.05 * i as f64, 4.0]);
        }
        for i in 1..40 {
            place(&mut grid, i, [7.5, 3.0 + 0.05 * i as f64, 4.5]);
        }
        // The points filed in the cell holding x.
        let ids = |x: &Vector<3>| {
            let mut ids: Vec<usize> = grid
                .members(grid.cell_of(&steps_at(&grid, x)))
                .iter()
                .map(|&e| index(e))
                .collect();
            ids.sort();
            ids
        };
        assert_eq!(ids(&[1.0, 1.0, 1.0]), vec![0]);
        assert_eq!(ids(&[7.0, 4.0, 4.0]), (1..40).collect::<Vec<_>>());
        assert_eq!(ids(&[4.0, 1.0, 1.0]), (40..44).collect::<Vec<_>>());
        assert_eq!(ids(&[7.0, 1.0, 1.0]), (44..48).collect::<Vec<_>>());
        let cells = grid.n.iter().map(|&k| k as usize).product::<usize>();
        let mut points: Vec<Point> = (0..cells).flat_map(|c| grid.members(c).to_vec()).collect();
        points.sort_by_key(|&e| index(e));
        assert_eq!(points.len(), 48);
        for (i, &e) in points.iter().enumerate() {
            let steps = filed[i].unwrap();
            assert_eq!(index(e), i);
            for k in 0..3 {
                assert_eq!(fine(e, k) as u32, steps[k] % (1 << FINE), "point {i}");
            }
        }
    }

    /// Whatever cells the search leaves out, every point within the reach
    /// of the centre asked about is in one it keeps, seen through the right
    /// image, and the offset the cell gives is the one counted in steps
    /// between the two: random points and centres, a periodic box and one
    /// with a periodic axis between walls, in 2D and 3D.
    fn no_point_in_reach_is_left_out<const D: usize>(sim_box: SimBox<D>, reach: f64) {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        let mut grid = Grid::<D>::new(3000, Grid::<D>::cells_for(3000, reach, &sim_box), &sim_box);
        let length: [i64; D] = std::array::from_fn(|k| (grid.n[k] as i64) << FINE);
        let step: Vector<D> = std::array::from_fn(|k| grid.width[k] / (1 << FINE) as f64);
        let at = |rng: &mut rand_chacha::ChaCha8Rng| -> [u32; D] {
            std::array::from_fn(|k| rng.random_range(0..length[k]) as u32)
        };
        let points: Vec<[u32; D]> = (0..3000).map(|_| at(&mut rng)).collect();
        for (i, s) in points.iter().enumerate() {
            grid.place(i, s, None);
        }
        let within = |d: &[i64; D]| {
            let r: Vector<D> = std::array::from_fn(|k| d[k] as f64 * step[k]);
            norm2(&r) < reach * reach
        };
        let mut kept_cells = 0;
        for _ in 0..300 {
            let c = at(&mut rng);
            let x: Vector<D> = std::array::from_fn(|k| (c[k] as f64 + 0.5) * step[k]);
            let mut near = [Near::default(); 27];
            let count = grid.cells_around(&c, &x, reach, &mut near, Read::Soon);
            kept_cells += count;
            let mut seen = vec![None; points.len()];
            for cell in &near[..count] {
                for &e in grid.points(cell) {
                    let d: [i64; D] = std::array::from_fn(|k| (cell.from(k) + fine(e, k)) as i64);
                    if within(&d) {
                        seen[index(e)] = Some((cell.image, d));
                    }
                }
            }
            for (j, p) in points.iter().enumerate() {
                // The nearest image of j, by brute force.
                let near = (0..3u32.pow(D as u32)).find_map(|image| {
                    let shift: [i64; D] =
                        std::array::from_fn(|k| (image / 3u32.pow(k as u32) % 3) as i64 - 1);
                    let d: [i64; D] =
                        std::array::from_fn(|k| p[k] as i64 + shift[k] * length[k] - c[k] as i64);
                    // Only a periodic axis has images beyond the box.
                    let exists = (0..D).all(|k| shift[k] == 0 || sim_box.axes[k].is_periodic());
                    (exists && within(&d)).then_some((image as Image, d))
                });
                assert_eq!(seen[j], near, "point {j} from {c:?}");
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
