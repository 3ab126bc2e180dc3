//! A cell list rebuilt every step: the box cut into cells at least one
//! contact distance wide, so an overlapping pair always lies in one cell or
//! two adjacent ones, and about as many cells as particles, so that a dilute
//! gas does not pay for empty cells. Flat arrays (a counting sort), no
//! allocation per step.

use crate::engine::boundary::SimBox;
use crate::engine::particle::Particle;

#[derive(Debug, Clone)]
pub struct Cells<const D: usize> {
    /// Cells along each axis.
    count: [usize; D],
    /// 1 / width of a cell along each axis.
    inverse_width: [f64; D],
    /// Particles of cell c are `items[start[c]..start[c + 1]]`.
    start: Vec<u32>,
    items: Vec<u32>,
    cell_of: Vec<u32>,
    /// Scratch for the counting sort (next free slot per cell).
    next: Vec<u32>,
    /// Cells adjacent to c with a higher index, each once (periodic wrap
    /// applied): `up[up_start[c]..up_start[c + 1]]`. With the pairs inside a
    /// cell this visits every pair of neighbouring cells exactly once.
    up_start: Vec<u32>,
    up: Vec<u32>,
}

impl<const D: usize> Cells<D> {
    /// Cells for a box and particles whose largest contact distance is `reach`.
    pub fn new(sim_box: &SimBox<D>, reach: f64, particles: usize) -> Self {
        let per_particle = (sim_box.volume() / particles.max(1) as f64).powf(1.0 / D as f64);
        let least = reach.max(per_particle).max(f64::MIN_POSITIVE);
        let count: [usize; D] =
            std::array::from_fn(|k| (sim_box.size[k] / least).floor().clamp(1.0, 1e6) as usize);
        let inverse_width = std::array::from_fn(|k| count[k] as f64 / sim_box.size[k]);
        let total: usize = count.iter().product();
        let mut up_start = Vec::with_capacity(total + 1);
        let mut up = Vec::new();
        for c in 0..total {
            up_start.push(up.len() as u32);
            let mut near: Vec<u32> = Vec::new();
            for offset in 0..3usize.pow(D as u32) {
                if let Some(n) = neighbour(c, offset, &count, sim_box)
                    && n > c
                    && !near.contains(&(n as u32))
                {
                    near.push(n as u32);
                }
            }
            near.sort_unstable();
            up.extend(near);
        }
        up_start.push(up.len() as u32);
        Cells {
            count,
            inverse_width,
            start: vec![0; total + 1],
            next: vec![0; total + 1],
            items: vec![0; particles],
            cell_of: vec![0; particles],
            up_start,
            up,
        }
    }

    /// Sort the particles into cells by their stored positions.
    pub fn fill(&mut self, particles: &[Particle<D>]) {
        self.start.iter_mut().for_each(|s| *s = 0);
        for (i, p) in particles.iter().enumerate() {
            let mut c = 0;
            for k in (0..D).rev() {
                // Overlapping a wall puts a centre a little outside the box
                // (truncation sends a little below 0 to cell 0 too).
                let x = ((p.pos[k] * self.inverse_width[k]) as usize).min(self.count[k] - 1);
                c = c * self.count[k] + x;
            }
            self.cell_of[i] = c as u32;
            self.start[c + 1] += 1;
        }
        for c in 1..self.start.len() {
            self.start[c] += self.start[c - 1];
        }
        self.next.copy_from_slice(&self.start);
        for (i, &c) in self.cell_of.iter().enumerate() {
            let slot = &mut self.next[c as usize];
            self.items[*slot as usize] = i as u32;
            *slot += 1;
        }
    }

    /// Call `f(i, j)` once for every pair in the same or adjacent cells, in
    /// a fixed order (so runs are reproducible).
    #[inline]
    pub fn pairs(&self, mut f: impl FnMut(usize, usize)) {
        for c in 0..self.start.len() - 1 {
            let here = self.members(c);
            if here.is_empty() {
                continue;
            }
            for (a, &i) in here.iter().enumerate() {
                for &j in &here[a + 1..] {
                    f(i as usize, j as usize);
                }
            }
            let ups = &self.up[self.up_start[c] as usize..self.up_start[c + 1] as usize];
            for &n in ups {
                for &i in here {
                    for &j in self.members(n as usize) {
                        f(i as usize, j as usize);
                    }
                }
            }
        }
    }

    fn members(&self, c: usize) -> &[u32] {
        &self.items[self.start[c] as usize..self.start[c + 1] as usize]
    }
}

/// The cell at `offset` (base-3 digits: -1, 0, +1 per axis) from cell `c`,
/// wrapped on periodic axes; None past a wall.
fn neighbour<const D: usize>(
    c: usize,
    offset: usize,
    count: &[usize; D],
    sim_box: &SimBox<D>,
) -> Option<usize> {
    let mut rest = c;
    let mut code = offset;
    let mut index = [0usize; D];
    for k in 0..D {
        let x = (rest % count[k]) as isize + (code % 3) as isize - 1;
        rest /= count[k];
        code /= 3;
        let n = count[k] as isize;
        index[k] = if (0..n).contains(&x) {
            x as usize
        } else if sim_box.axes[k].is_periodic() {
            x.rem_euclid(n) as usize
        } else {
            return None;
        };
    }
    Some((0..D).rev().fold(0, |acc, k| acc * count[k] + index[k]))
}
