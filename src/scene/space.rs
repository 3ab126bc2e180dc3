//! The box as placement sees it (lengths and which axes wrap), where each
//! particle may go, and a small cell list for finding close pairs. Random
//! insertion and compression share these; the engine keeps its own.

/// A particle to place: its radius and the region (absolute bounds per axis)
/// it must lie in, radius included.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slot<const D: usize> {
    pub radius: f64,
    pub lo: [f64; D],
    pub hi: [f64; D],
    /// Species index, for grouping and for error messages.
    pub species: u16,
}

impl<const D: usize> Slot<D> {
    pub fn same_region(&self, other: &Slot<D>) -> bool {
        self.lo == other.lo && self.hi == other.hi
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Space<const D: usize> {
    pub size: [f64; D],
    pub periodic: [bool; D],
}

impl<const D: usize> Space<D> {
    /// Does a region [lo, hi] wrap around axis k (periodic, and spanning it)?
    /// Elsewhere its bounds act as walls.
    pub fn wraps(&self, lo: &[f64; D], hi: &[f64; D], k: usize) -> bool {
        self.periodic[k] && lo[k] <= 0.0 && hi[k] >= self.size[k]
    }

    /// The vector from a to b, by the nearest periodic image.
    pub fn separation(&self, a: &[f64; D], b: &[f64; D]) -> [f64; D] {
        std::array::from_fn(|k| {
            let mut d = b[k] - a[k];
            if self.periodic[k] {
                d -= self.size[k] * (d / self.size[k]).round();
            }
            d
        })
    }

    /// A position brought into the box along its periodic axes, as the
    /// engine folds it (so that placing and checking see where it will be).
    pub fn fold(&self, mut x: [f64; D]) -> [f64; D] {
        for k in 0..D {
            if self.periodic[k] {
                let l = self.size[k];
                x[k] = x[k].rem_euclid(l);
                if x[k] >= l {
                    x[k] = 0.0;
                }
            }
        }
        x
    }

    pub fn volume(&self) -> f64 {
        self.size.iter().product()
    }
}

pub use crate::engine::boundary::ball_volume;

/// Volume of the region [lo, hi].
pub fn region_volume<const D: usize>(lo: &[f64; D], hi: &[f64; D]) -> f64 {
    (0..D).map(|k| hi[k] - lo[k]).product()
}

/// Particles binned by cell. Cells are at least `reach` wide, so a pair
/// closer than `reach` is always in the same or adjacent cells.
#[derive(Debug, Clone)]
pub struct CellList<const D: usize> {
    space: Space<D>,
    n: [usize; D],
    width: [f64; D],
    members: Vec<Vec<u32>>,
    /// Per particle: its cell and its index in that cell's list.
    home: Vec<(usize, usize)>,
    neighbours: Vec<Vec<usize>>,
}

impl<const D: usize> CellList<D> {
    /// Cells for up to `count` particles; no more cells than about two per
    /// particle, whatever the box.
    pub fn new(space: Space<D>, reach: f64, count: usize) -> Result<Self, String> {
        for k in 0..D {
            if space.periodic[k] && space.size[k] < 2.0 * reach {
                return Err(format!(
                    "the box is {} long on periodic axis {k}, less than two particle diameters ({}); \
                     make it longer or the particles smaller",
                    space.size[k],
                    2.0 * reach
                ));
            }
        }
        let sparse = (space.volume() / (2.0 * count.max(1) as f64)).powf(1.0 / D as f64);
        let w = reach.max(sparse).max(f64::MIN_POSITIVE);
        let n: [usize; D] =
            std::array::from_fn(|k| ((space.size[k] / w).floor() as usize).clamp(1, 1 << 20));
        let width = std::array::from_fn(|k| space.size[k] / n[k] as f64);
        let cells: usize = n.iter().product();
        let mut list = CellList {
            space,
            n,
            width,
            members: vec![Vec::new(); cells],
            home: Vec::with_capacity(count),
            neighbours: Vec::new(),
        };
        list.neighbours = (0..cells).map(|c| list.adjacent(c)).collect();
        Ok(list)
    }

    /// The cell holding position x (wrapped on periodic axes, clamped on others).
    pub fn cell_of(&self, x: &[f64; D]) -> usize {
        let mut c = 0;
        for k in (0..D).rev() {
            c = c * self.n[k] + self.coordinate(x[k], k);
        }
        c
    }

    fn coordinate(&self, x: f64, k: usize) -> usize {
        let u = if self.space.periodic[k] {
            x.rem_euclid(self.space.size[k])
        } else {
            x
        };
        ((u / self.width[k]).floor().max(0.0) as usize).min(self.n[k] - 1)
    }

    /// The cell's index along each axis.
    pub fn index(&self, mut c: usize) -> [usize; D] {
        std::array::from_fn(|k| {
            let i = c % self.n[k];
            c /= self.n[k];
            i
        })
    }

    pub fn cells_per_axis(&self) -> [usize; D] {
        self.n
    }

    pub fn width(&self) -> [f64; D] {
        self.width
    }

    /// Add particle `i` (particles are added in index order) at position x.
    pub fn push(&mut self, x: &[f64; D]) {
        let c = self.cell_of(x);
        self.home.push((c, self.members[c].len()));
        self.members[c].push(self.home.len() as u32 - 1);
    }

    pub fn cell(&self, i: usize) -> usize {
        self.home[i].0
    }

    /// Move particle i to cell c.
    pub fn relocate(&mut self, i: usize, c: usize) {
        let (old, at) = self.home[i];
        self.members[old].swap_remove(at);
        if let Some(&moved) = self.members[old].get(at) {
            self.home[moved as usize].1 = at;
        }
        self.home[i] = (c, self.members[c].len());
        self.members[c].push(i as u32);
    }

    /// Every particle in cell c and the cells around it.
    pub fn near(&self, c: usize) -> impl Iterator<Item = usize> + '_ {
        self.neighbours[c]
            .iter()
            .flat_map(|&d| self.members[d].iter().map(|&j| j as usize))
    }

    /// Particles near position x (which need not be in the list).
    pub fn near_point(&self, x: &[f64; D]) -> impl Iterator<Item = usize> + '_ {
        self.near(self.cell_of(x))
    }

    /// Cell c and its neighbours, each once (an axis with fewer than three
    /// cells would otherwise list a cell twice).
    fn adjacent(&self, c: usize) -> Vec<usize> {
        let idx = self.index(c);
        let mut out = Vec::with_capacity(3usize.pow(D as u32));
        'offsets: for offset in 0..3usize.pow(D as u32) {
            let mut cell = 0;
            for k in (0..D).rev() {
                let o = (offset / 3usize.pow(k as u32)) % 3;
                let i = idx[k] as isize + o as isize - 1;
                let n = self.n[k] as isize;
                let i = if self.space.periodic[k] {
                    i.rem_euclid(n)
                } else if (0..n).contains(&i) {
                    i
                } else {
                    continue 'offsets;
                };
                cell = cell * self.n[k] + i as usize;
            }
            out.push(cell);
        }
        out.sort_unstable();
        out.dedup();
        out
    }
}
