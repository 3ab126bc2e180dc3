//! 2D/3D: a grid of cells at least one diameter wide, each a linked list of
//! its particles. A particle can only touch particles in its own or the 3^D - 1
//! adjacent cells, and it is re-examined each time it crosses into a new cell,
//! so the cost of an event does not grow with N.

use super::{Crossing, Image, Neighbourhood, Persist};
use crate::engine::boundary::SimBox;
use crate::engine::particle::Particle;

const NONE: u32 = u32::MAX;

#[derive(Debug, Clone)]
pub struct CellGrid<const D: usize> {
    n: [u32; D],
    width: [f64; D],
    length: [f64; D],
    periodic: [bool; D],
    /// Linear-index stride per axis.
    stride: [usize; D],
    head: Vec<u32>,
    next: Vec<u32>,
    prev: Vec<u32>,
    coord: Vec<[u32; D]>,
}

impl<const D: usize> CellGrid<D> {
    /// Cells per axis: as many as fit at one (largest) diameter each, but no
    /// more than a few per particle in all, so a dilute gas in a huge box
    /// does not allocate a huge grid.
    fn cells_per_axis(
        n_particles: usize,
        diameter: f64,
        sim_box: &SimBox<D>,
    ) -> Result<[u32; D], String> {
        let budget = (4 * n_particles + 64) as f64;
        let mut n = [1u32; D];
        for k in 0..D {
            let fit = if diameter > 0.0 {
                (sim_box.size[k] / (diameter * (1.0 + 1e-9))).floor()
            } else {
                f64::INFINITY
            };
            n[k] = fit.min(budget).max(1.0) as u32;
        }
        let total: f64 = n.iter().map(|&x| x as f64).product();
        if total > budget {
            let f = (budget / total).powf(1.0 / D as f64);
            for x in &mut n {
                *x = ((*x as f64 * f).floor() as u32).max(1);
            }
        }
        for k in 0..D {
            if sim_box.axes[k].is_periodic() {
                let fit = if diameter > 0.0 {
                    (sim_box.size[k] / (diameter * (1.0 + 1e-9))).floor()
                } else {
                    f64::INFINITY
                };
                if fit < 3.0 {
                    return Err(format!(
                        "periodic axis {k} is {} long, less than three of the largest diameter ({diameter}); \
                         make the box at least {} long or use walls on that axis",
                        sim_box.size[k],
                        3.0 * diameter
                    ));
                }
                n[k] = n[k].max(3);
            }
        }
        Ok(n)
    }

    #[inline(always)]
    fn linear(&self, c: &[u32; D]) -> usize {
        let mut idx = 0;
        for k in 0..D {
            idx += c[k] as usize * self.stride[k];
        }
        idx
    }

    fn insert(&mut self, i: usize) {
        let cell = self.linear(&self.coord[i]);
        let h = self.head[cell];
        self.next[i] = h;
        self.prev[i] = NONE;
        if h != NONE {
            self.prev[h as usize] = i as u32;
        }
        self.head[cell] = i as u32;
    }

    fn remove(&mut self, i: usize) {
        let (p, nx) = (self.prev[i], self.next[i]);
        if p != NONE {
            self.next[p as usize] = nx;
        } else {
            let cell = self.linear(&self.coord[i]);
            self.head[cell] = nx;
        }
        if nx != NONE {
            self.prev[nx as usize] = p;
        }
    }

    pub fn cell_count(&self) -> usize {
        self.head.len()
    }
}

impl<const D: usize> Neighbourhood<D> for CellGrid<D> {
    fn build(particles: &[Particle<D>], sim_box: &SimBox<D>) -> Result<Self, String> {
        let diameter = particles.iter().map(|p| 2.0 * p.radius).fold(0.0, f64::max);
        let n = Self::cells_per_axis(particles.len(), diameter, sim_box)?;
        let width = std::array::from_fn(|k| sim_box.size[k] / n[k] as f64);
        let mut stride = [1usize; D];
        for k in 1..D {
            stride[k] = stride[k - 1] * n[k - 1] as usize;
        }
        let cells = stride[D - 1] * n[D - 1] as usize;
        let coord = particles
            .iter()
            .map(|p| {
                std::array::from_fn(|k| {
                    ((p.pos[k] / width[k]).floor().max(0.0) as u32).min(n[k] - 1)
                })
            })
            .collect();
        let mut grid = CellGrid {
            n,
            width,
            length: sim_box.size,
            periodic: std::array::from_fn(|k| sim_box.axes[k].is_periodic()),
            stride,
            head: vec![NONE; cells],
            next: vec![NONE; particles.len()],
            prev: vec![NONE; particles.len()],
            coord,
        };
        for i in 0..particles.len() {
            grid.insert(i);
        }
        Ok(grid)
    }

    #[inline]
    fn for_each_candidate(&self, i: usize, mut f: impl FnMut(usize, Image)) {
        let c = self.coord[i];
        // Walk the 3^D neighbouring cells; `offset` counts in base 3.
        let neighbours = 3usize.pow(D as u32);
        'cells: for offset in 0..neighbours {
            let mut rest = offset;
            let mut cell = 0usize;
            let mut image: Image = 0;
            for k in (0..D).rev() {
                let o = (rest % 3) as i64 - 1;
                rest /= 3;
                let mut ck = c[k] as i64 + o;
                let mut wrap = 1u8;
                if ck < 0 || ck >= self.n[k] as i64 {
                    if !self.periodic[k] {
                        continue 'cells;
                    }
                    wrap = if ck < 0 { 0 } else { 2 };
                    ck = ck.rem_euclid(self.n[k] as i64);
                }
                cell += ck as usize * self.stride[k];
                image += wrap * 3u8.pow(k as u32);
            }
            let mut j = self.head[cell];
            while j != NONE {
                if j as usize != i {
                    f(j as usize, image);
                }
                j = self.next[j as usize];
            }
        }
    }

    #[inline]
    fn next_crossing(&self, i: usize, p: &Particle<D>) -> Option<(f64, Crossing)> {
        let c = &self.coord[i];
        let mut best: Option<(f64, Crossing)> = None;
        for k in 0..D {
            let v = p.vel[k];
            let (edge, up) = if v > 0.0 {
                if !self.periodic[k] && c[k] + 1 == self.n[k] {
                    continue;
                }
                ((c[k] + 1) as f64 * self.width[k], true)
            } else if v < 0.0 {
                if !self.periodic[k] && c[k] == 0 {
                    continue;
                }
                (c[k] as f64 * self.width[k], false)
            } else {
                continue;
            };
            let t = p.t + ((edge - p.pos[k]) / v).max(0.0);
            if best.is_none_or(|(tb, _)| t < tb) {
                best = Some((t, Crossing { axis: k as u8, up }));
            }
        }
        best
    }

    fn cross(&mut self, i: usize, crossing: Crossing, p: &mut Particle<D>) -> bool {
        let k = crossing.axis as usize;
        self.remove(i);
        let mut wrapped = false;
        let c = &mut self.coord[i][k];
        if crossing.up {
            *c += 1;
            if *c == self.n[k] {
                *c = 0;
                p.pos[k] -= self.length[k];
                wrapped = true;
            }
        } else if *c == 0 {
            *c = self.n[k] - 1;
            p.pos[k] += self.length[k];
            wrapped = true;
        } else {
            *c -= 1;
        }
        self.insert(i);
        wrapped
    }
}

/// Saved as: each particle's cell coordinates, then the lists (head, next,
/// prev). The grid's shape is recomputed by `build` from the radii and box.
impl<const D: usize> Persist<D> for CellGrid<D> {
    const KIND: u32 = 1;

    fn state(&self) -> Vec<u32> {
        let mut s: Vec<u32> = self.coord.iter().flatten().copied().collect();
        s.extend(&self.head);
        s.extend(&self.next);
        s.extend(&self.prev);
        s
    }

    fn restore(
        particles: &[Particle<D>],
        sim_box: &SimBox<D>,
        state: &[u32],
    ) -> Result<Self, String> {
        let mut grid = Self::build(particles, sim_box)?;
        let (n, cells) = (particles.len(), grid.head.len());
        if state.len() != D * n + cells + 2 * n {
            return Err(format!(
                "cell grid state has {} words; {n} particles in {cells} cells need {}",
                state.len(),
                D * n + cells + 2 * n
            ));
        }
        let (coords, lists) = state.split_at(D * n);
        for (c, saved) in grid.coord.iter_mut().zip(coords.chunks_exact(D)) {
            c.copy_from_slice(saved);
        }
        let (head, rest) = lists.split_at(cells);
        let (next, prev) = rest.split_at(n);
        grid.head.copy_from_slice(head);
        grid.next.copy_from_slice(next);
        grid.prev.copy_from_slice(prev);
        let cell_ok = grid.coord.iter().all(|c| (0..D).all(|k| c[k] < grid.n[k]));
        let link_ok = lists.iter().all(|&j| j == NONE || (j as usize) < n);
        if !(cell_ok && link_ok) {
            return Err("cell grid state points outside the grid or the particles".into());
        }
        Ok(grid)
    }
}
