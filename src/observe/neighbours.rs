//! The k nearest neighbours of every point, for the bond-order observables
//! (`psi6`, `q6`; `pair_distance` shares their points): nearest periodic
//! image on periodic axes, found through a cell list so a sample costs
//! O(N k) however large N is, and exact for any N > k (the search widens
//! until no unseen cell can hold a nearer point).

use crate::engine::Snapshot;

/// The points the bond orders are taken over: the movable particles that
/// are not planes (immovable obstacles and plane walls hold no order).
pub fn points<const D: usize>(s: &Snapshot<D>) -> Vec<[f64; D]> {
    (0..s.particles.len())
        .filter(|&i| {
            let p = s.particles.get(i);
            !p.is_immovable() && !p.is_plane()
        })
        .map(|i| s.position(i))
        .collect()
}

/// Which axes of a sample's box are periodic.
pub fn periodic<const D: usize>(s: &Snapshot<D>) -> [bool; D] {
    std::array::from_fn(|k| s.sim_box.axes[k].is_periodic())
}

/// A neighbour: its index and the bond from the point to it.
pub type Bond<const D: usize> = (usize, [f64; D]);

/// For each of the points (inside the box `[0, size]`), its `k` nearest
/// other points, nearest first (ties by index), as `k` bonds in a row of
/// the result. Needs more than `k` points.
pub fn nearest<const D: usize>(
    at: &[[f64; D]],
    size: &[f64; D],
    periodic: &[bool; D],
    k: usize,
) -> Vec<Bond<D>> {
    let n = at.len();
    assert!(n > k, "{n} points have no {k} neighbours each");
    let grid = Grid::new(at, size, periodic, k);
    let mut out = Vec::with_capacity(n * k);
    let mut found: Vec<(f64, usize, [f64; D])> = Vec::new();
    for (i, a) in at.iter().enumerate() {
        let home = grid.cell_of(a);
        let mut reach = 1;
        loop {
            found.clear();
            let whole = grid.visit(&home, reach, |j| {
                if j != i {
                    let d = bond(a, &at[j], size, periodic);
                    found.push((d.iter().map(|x| x * x).sum(), j, d));
                }
            });
            found.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
            // An unseen point lies at least `reach` whole cells away.
            let bound = reach as f64 * grid.side;
            if whole || (found.len() >= k && found[k - 1].0 <= bound * bound) {
                break;
            }
            reach += 1;
        }
        out.extend(found[..k].iter().map(|&(_, j, d)| (j, d)));
    }
    out
}

/// `b - a`, the nearest image on periodic axes.
fn bond<const D: usize>(
    a: &[f64; D],
    b: &[f64; D],
    size: &[f64; D],
    periodic: &[bool; D],
) -> [f64; D] {
    std::array::from_fn(|k| {
        let d = b[k] - a[k];
        if periodic[k] {
            d - size[k] * (d / size[k]).round()
        } else {
            d
        }
    })
}

/// Points sorted into cells of about k/3 points each.
struct Grid<const D: usize> {
    cells: [usize; D],
    width: [f64; D],
    /// The smallest cell width.
    side: f64,
    periodic: [bool; D],
    /// The points of cell c are `order[start[c]..start[c + 1]]`.
    start: Vec<usize>,
    order: Vec<usize>,
}

impl<const D: usize> Grid<D> {
    fn new(at: &[[f64; D]], size: &[f64; D], periodic: &[bool; D], k: usize) -> Self {
        let volume: f64 = size.iter().product();
        let wanted = (volume * k as f64 / (3.0 * at.len() as f64)).powf(1.0 / D as f64);
        let cells: [usize; D] = std::array::from_fn(|a| ((size[a] / wanted) as usize).max(1));
        let width: [f64; D] = std::array::from_fn(|a| size[a] / cells[a] as f64);
        let side = width.iter().copied().fold(f64::INFINITY, f64::min);
        let mut grid = Grid {
            cells,
            width,
            side,
            periodic: *periodic,
            start: Vec::new(),
            order: Vec::new(),
        };
        let total: usize = cells.iter().product();
        let id: Vec<usize> = at.iter().map(|a| grid.id(&grid.cell_of(a))).collect();
        let mut start = vec![0; total + 1];
        for &c in &id {
            start[c + 1] += 1;
        }
        for c in 0..total {
            start[c + 1] += start[c];
        }
        let mut next = start.clone();
        let mut order = vec![0; at.len()];
        for (i, &c) in id.iter().enumerate() {
            order[next[c]] = i;
            next[c] += 1;
        }
        grid.start = start;
        grid.order = order;
        grid
    }

    fn cell_of(&self, a: &[f64; D]) -> [usize; D] {
        std::array::from_fn(|k| ((a[k] / self.width[k]).max(0.0) as usize).min(self.cells[k] - 1))
    }

    fn id(&self, c: &[usize; D]) -> usize {
        (0..D).rev().fold(0, |id, k| id * self.cells[k] + c[k])
    }

    /// Calls `f` on every point of the cells within `reach` of `home` (each
    /// cell once); true if that was every cell.
    fn visit(&self, home: &[usize; D], reach: usize, mut f: impl FnMut(usize)) -> bool {
        let mut whole = true;
        let span: [Vec<usize>; D] = std::array::from_fn(|k| {
            let (m, c) = (self.cells[k], home[k]);
            if self.periodic[k] {
                if 2 * reach + 1 >= m {
                    return (0..m).collect();
                }
                whole = false;
                (0..=2 * reach).map(|o| (c + m + o - reach) % m).collect()
            } else {
                let (lo, hi) = (c.saturating_sub(reach), (c + reach).min(m - 1));
                whole &= lo == 0 && hi == m - 1;
                (lo..=hi).collect()
            }
        });
        let mut pick = [0; D];
        loop {
            let cell: [usize; D] = std::array::from_fn(|k| span[k][pick[k]]);
            let id = self.id(&cell);
            self.order[self.start[id]..self.start[id + 1]]
                .iter()
                .for_each(|&j| f(j));
            let Some(k) = (0..D).find(|&k| pick[k] + 1 < span[k].len()) else {
                break;
            };
            pick[k] += 1;
            pick[..k].iter_mut().for_each(|p| *p = 0);
        }
        whole
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    /// The cell list finds what comparing every pair finds, walls or
    /// periodic, dense or sparse, few points or many.
    #[test]
    fn the_cell_list_agrees_with_every_pair() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        for (n, periodic) in [(8, [true, true, false]), (13, [false; 3]), (400, [true; 3])] {
            let size = [3.0, 5.0, 9.0];
            let at: Vec<[f64; 3]> = (0..n)
                .map(|_| std::array::from_fn(|k| size[k] * rng.random::<f64>()))
                .collect();
            let k = 6.min(n - 1);
            let fast = nearest(&at, &size, &periodic, k);
            for (i, a) in at.iter().enumerate() {
                let mut all: Vec<(f64, usize)> = (0..n)
                    .filter(|&j| j != i)
                    .map(|j| {
                        (
                            bond(a, &at[j], &size, &periodic)
                                .iter()
                                .map(|x| x * x)
                                .sum(),
                            j,
                        )
                    })
                    .collect();
                all.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
                let want: Vec<usize> = all[..k].iter().map(|x| x.1).collect();
                let got: Vec<usize> = fast[i * k..(i + 1) * k].iter().map(|b| b.0).collect();
                assert_eq!(got, want, "n = {n}, point {i}");
            }
        }
    }
}
