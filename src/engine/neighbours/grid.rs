//! A grid of cells, each a linked list of the points filed in it, for finding
//! every point within one cell width of another in O(1). On periodic axes the
//! grid wraps, and a point found across the boundary comes with the image
//! code of the shift that brings it next to the one asked about.

use super::Image;
use crate::engine::boundary::SimBox;
use crate::engine::vector::Vector;

const NONE: u32 = u32::MAX;

#[derive(Debug, Clone)]
pub struct Grid<const D: usize> {
    n: [u32; D],
    width: [f64; D],
    periodic: [bool; D],
    /// Linear-index stride per axis.
    stride: [usize; D],
    head: Vec<u32>,
    next: Vec<u32>,
    prev: Vec<u32>,
    /// Each point's cell.
    cell: Vec<u32>,
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
        Grid {
            n,
            width: std::array::from_fn(|k| sim_box.size[k] / n[k] as f64),
            periodic: std::array::from_fn(|k| sim_box.axes[k].is_periodic()),
            stride,
            head: vec![NONE; stride[D - 1] * n[D - 1] as usize],
            next: vec![NONE; points],
            prev: vec![NONE; points],
            cell: vec![NONE; points],
        }
    }

    fn coords(&self, x: &Vector<D>) -> [u32; D] {
        std::array::from_fn(|k| ((x[k] / self.width[k]).floor().max(0.0) as u32).min(self.n[k] - 1))
    }

    /// File point `i` (or move it) at position `x`, which lies in the box.
    pub fn place(&mut self, i: usize, x: &Vector<D>) {
        let c = self.coords(x);
        let cell = (0..D)
            .map(|k| c[k] as usize * self.stride[k])
            .sum::<usize>() as u32;
        if self.cell[i] == cell {
            return;
        }
        if self.cell[i] != NONE {
            self.unlink(i);
        }
        self.cell[i] = cell;
        let h = self.head[cell as usize];
        self.next[i] = h;
        self.prev[i] = NONE;
        if h != NONE {
            self.prev[h as usize] = i as u32;
        }
        self.head[cell as usize] = i as u32;
    }

    fn unlink(&mut self, i: usize) {
        let (p, nx) = (self.prev[i], self.next[i]);
        if p != NONE {
            self.next[p as usize] = nx;
        } else {
            self.head[self.cell[i] as usize] = nx;
        }
        if nx != NONE {
            self.prev[nx as usize] = p;
        }
    }

    /// Call `f(j, image)` for every point j filed in the 3^D cells around
    /// position `x` (x itself may be filed there too).
    pub fn for_each_near(&self, x: &Vector<D>, mut f: impl FnMut(usize, Image)) {
        let c = self.coords(x);
        // Walk the neighbouring cells; `offset` counts in base 3.
        'cells: for offset in 0..3usize.pow(D as u32) {
            let mut rest = offset;
            let mut cell = 0usize;
            let mut image: Image = 0;
            let mut place = 1u8;
            for k in 0..D {
                let mut ck = c[k] as i64 + (rest % 3) as i64 - 1;
                rest /= 3;
                let mut digit = 1u8;
                if ck < 0 || ck >= self.n[k] as i64 {
                    if !self.periodic[k] {
                        continue 'cells;
                    }
                    digit = if ck < 0 { 0 } else { 2 };
                    ck = ck.rem_euclid(self.n[k] as i64);
                }
                cell += ck as usize * self.stride[k];
                image += digit * place;
                place *= 3;
            }
            let mut j = self.head[cell];
            while j != NONE {
                f(j as usize, image);
                j = self.next[j as usize];
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
                let mut j = self.head[c0 as usize + r * self.n[0] as usize];
                while j != NONE {
                    f(j as usize);
                    j = self.next[j as usize];
                }
            }
        }
    }
}
