//! 2D/3D: neighbour lists with a shell (after Donev, Torquato and Stillinger,
//! J. Comput. Phys. 202, 737, 2005, and Smallenburg, EPJE 45, 22, 2022).
//!
//! Each particle owns a neighbourhood: the ball of the largest radius plus
//! the shell around its *centre*, the position it had when its list was last
//! renewed (the same size for all, so the lists stay symmetric). While a
//! particle stays inside its neighbourhood it can only touch particles whose
//! neighbourhoods overlap its own, so its list holds exactly those: a handful
//! at any density. When it reaches the edge of its neighbourhood (an event
//! like any other) the list is renewed around where it is now. Between
//! renewals nothing is re-examined, however many cell boundaries it crosses.
//!
//! Lists are symmetric (j is in i's list exactly when i is in j's), so a pair
//! that can meet is seen from both sides, and sorted by index, so they are a
//! function of the centres alone: that is all a save file needs.
//!
//! With `PLANES`, a plane perpendicular to axis 0 (the piston of 2D and 3D
//! scenes) takes part too: its neighbourhood is the slab its faces sweep while
//! it moves less than a shell along axis 0, and its list holds every particle
//! whose neighbourhood meets that slab. Without `PLANES` none of this is
//! compiled into the event loop.

use super::centres::Centres;
use super::grid::{Grid, Near, fine, index};
use super::store::{ListStore, room_for};
use super::{Image, Neighbourhood, PLANE, Persist};
use crate::engine::bodies::Body;
use crate::engine::boundary::{SimBox, ball_volume};
use crate::engine::particle::Particle;
use crate::engine::prefetch::{Lines, Read, prefetch_for};
use crate::engine::vector::{Vector, add_scaled, axis0, dot, norm2, sub};

/// A list entry packs a particle index and an image code: `j << 5 | image`.
const IMAGE_BITS: u32 = 5;
const MAX_PARTICLES: usize = 1 << (32 - IMAGE_BITS);
/// The shell in ideal-gas mean free paths, for balls of diameter `sigma` at
/// number density `density` (tuned on the benchmark systems: see
/// docs/performance.md): 1.0, and in dense 3D fluids up to a fifth more, where
/// renewing costs more than the longer lists do.
fn shell_per_free_path<const D: usize>(density: f64, sigma: f64) -> f64 {
    if D != 3 {
        return 1.0;
    }
    let packing = std::f64::consts::PI / 6.0 * density * sigma.powi(3);
    1.0 + 0.2 * ((packing - 0.35) / 0.10).clamp(0.0, 1.0)
}

/// The shell for `balls` balls of largest radius `largest` in `sim_box`:
/// the distance a particle may wander from its centre. Wider means rarer
/// renewals but longer lists; about a mean free path balances the two.
/// Capped so that periodic axes keep three cells.
fn shell_for<const D: usize>(
    balls: usize,
    largest: f64,
    sim_box: &SimBox<D>,
) -> Result<f64, (Option<usize>, String)> {
    let count = balls.max(1) as f64;
    let sigma = 2.0 * largest;
    let density = count / sim_box.volume();
    // Ideal-gas mean free path 1 / (sqrt2 rho s), s the collision cross
    // section (2 sigma in 2D, pi sigma^2 in 3D), against the spacing.
    let cross_section = if D == 2 {
        2.0 * sigma
    } else {
        std::f64::consts::PI * sigma * sigma
    };
    let free_path = 1.0 / (std::f64::consts::SQRT_2 * density * cross_section);
    let spacing = density.powf(-1.0 / D as f64);
    let per = shell_per_free_path::<D>(density, sigma);
    let mut shell = (per * free_path).clamp(0.1 * sigma, spacing.max(sigma));
    if shell.is_nan() || shell <= 0.0 {
        shell = spacing;
    }
    for k in 0..D {
        if sim_box.axes[k].is_periodic() {
            let room = sim_box.size[k] / 6.0 - largest;
            if room < 0.01 * sigma.max(f64::MIN_POSITIVE) {
                return Err((
                    Some(k),
                    format!(
                        "periodic axis {k} is {} long, too short for particles of diameter {sigma}; \
                     make the box at least {} long or use walls on that axis",
                        sim_box.size[k],
                        3.0 * sigma * 1.02
                    ),
                ));
            }
            shell = shell.min(room);
        }
    }
    Ok(shell)
}

/// The shell and the grid's cells per axis that neighbour lists for
/// `points` points (`balls` of them balls of largest radius `largest`, the
/// rest a plane) in `sim_box` are built with; an error where they cannot
/// follow the particles: a shell that is not a finite length (a box whose
/// volume is not a number), or centres filed (to 1/2^12 of a cell, and the
/// cells are at most a few per point) more coarsely than half the shell,
/// which would renew a particle's neighbourhood again and again at one
/// instant. `study validate` asks the same of a scene.
/// The error names the axis at fault, if one is.
pub fn layout<const D: usize>(
    points: usize,
    balls: usize,
    largest: f64,
    sim_box: &SimBox<D>,
) -> Result<(f64, [u32; D]), (Option<usize>, String)> {
    let shell = shell_for(balls, largest, sim_box)?;
    if !(shell.is_finite() && shell > 0.0) {
        return Err((
            None,
            format!(
                "the box's volume ({:e}) is beyond what the neighbour lists can divide",
                sim_box.volume()
            ),
        ));
    }
    let cells = Grid::cells_for(points, 2.0 * (largest + shell), sim_box);
    let step: Vector<D> = std::array::from_fn(|k| {
        sim_box.size[k] / ((cells[k] as u64) << super::centres::FINE) as f64
    });
    let coarse = norm2(&step).sqrt();
    if coarse > 0.5 * shell {
        let k = (0..D)
            .max_by(|&a, &b| step[a].total_cmp(&step[b]))
            .unwrap_or(0);
        return Err((
            Some(k),
            format!(
                "axis {k} is too long for {balls} particles: the engine's grid (at most a few \
             cells per particle) files positions along it to within {:.2e}, coarser than \
             half the {:.2e} a particle moves before its neighbours are looked up again; \
             with this many particles the axis may be about {:.2e} long at most",
                step[k],
                shell,
                sim_box.size[k] * 0.5 * shell / coarse
            ),
        ));
    }
    Ok((shell, cells))
}

#[inline(always)]
fn pack(j: usize, image: Image) -> u32 {
    (j as u32) << IMAGE_BITS | image as u32
}

#[inline(always)]
fn unpack(e: u32) -> (usize, Image) {
    (
        (e >> IMAGE_BITS) as usize,
        (e & ((1 << IMAGE_BITS) - 1)) as Image,
    )
}

/// `from`, whose entries are all different, into `to` in increasing order.
/// For a ball's list, each entry's place is the count of entries below it:
/// n^2 compares, but with no branch to mispredict they beat a comparison
/// sort (one unpredictable branch per compare) at a few tens of entries.
fn sort_distinct(from: &[u32], to: &mut Vec<u32>) {
    if from.len() > 64 {
        // A plane's list: thousands.
        to.clear();
        to.extend_from_slice(from);
        to.sort_unstable();
        return;
    }
    // Every place below `from.len()` is written: no need to clear first.
    to.resize(from.len(), 0);
    for &e in from {
        let place = from.iter().map(|&x| (x < e) as u32).sum::<u32>();
        to[place as usize] = e;
    }
}

/// The image of i as seen from j, when j is i's image `image`.
fn mirror<const D: usize>(image: Image) -> Image {
    if image == PLANE {
        PLANE
    } else {
        (3u8.pow(D as u32) - 1) - image
    }
}

#[derive(Debug, Clone)]
pub struct NeighbourList<const D: usize, const PLANES: bool = false> {
    shell: f64,
    size: Vector<D>,
    periodic: [bool; D],
    /// How far apart two centres may be for a pair to count as neighbours:
    /// twice the largest radius and the shell, the same for every pair so
    /// that lists stay symmetric (`plane_reach` for a pair with the plane).
    reach: f64,
    plane_reach: f64,
    centre: Centres<D>,
    /// The centres of every particle but the plane.
    grid: Grid<D>,
    /// Every ball's list.
    lists: ListStore,
    /// The plane's index (with `PLANES`), and its list, sorted.
    plane: Option<usize>,
    plane_list: Vec<u32>,
    /// Room to work in while renewing, kept to spare an allocation each time.
    scratch: [Vec<u32>; 2],
    /// The last renewal's changes to other lists, not yet made (see
    /// `catch_up`): take `renewed` out of j's list, or put `e` in.
    changes: Vec<(usize, Option<u32>)>,
    renewed: usize,
    /// The cells the next renewal will search, worked out when it was asked
    /// ahead for.
    ahead: CellsAhead<D>,
}

/// The cells around a centre, which follow from its steps alone: asking
/// ahead for a renewal works them out, and its search reuses them if the
/// centre is the one asked for.
#[derive(Debug, Clone, Default)]
struct CellsAhead<const D: usize> {
    steps: Option<[u32; D]>,
    near: [Near; 27],
    count: usize,
}

impl<const D: usize, const PLANES: bool> NeighbourList<D, PLANES> {
    fn list(&self, i: usize) -> &[u32] {
        self.lists.get(i)
    }

    /// Does the neighbourhood of ball i meet the slab of the plane k?
    fn meets_plane(&self, i: usize, k: usize) -> bool {
        (self.centre.get(k)[0] - self.centre.get(i)[0]).abs() < self.plane_reach
    }

    /// Put `e` into list i, keeping it sorted.
    fn insert(&mut self, i: usize, e: u32) {
        if PLANES && Some(i) == self.plane {
            let at = self.plane_list.partition_point(|&x| x < e);
            self.plane_list.insert(at, e);
            return;
        }
        self.lists.insert(i, e);
    }

    /// Take particle j out of list i.
    fn remove(&mut self, i: usize, j: usize) {
        let key = |e: &u32| (e >> IMAGE_BITS) as usize;
        if PLANES && Some(i) == self.plane {
            if let Ok(at) = self.plane_list.binary_search_by_key(&j, key) {
                self.plane_list.remove(at);
            }
            return;
        }
        self.lists.remove(i, |e| key(&e) == j);
    }

    /// Where p is from its centre, and how it moves, as its neighbourhood
    /// sees it (a plane's along axis 0 only).
    #[inline(always)]
    fn relative_to_centre(&self, i: usize, p: &Body<D>) -> (Vector<D>, Vector<D>) {
        let (d, v) = (sub(&p.pos, &self.centre.get(i)), p.vel);
        if PLANES && Some(i) == self.plane {
            (axis0(&d), axis0(&v))
        } else {
            (d, v)
        }
    }

    /// How far a particle may go from its centre before its list is renewed:
    /// a hair inside the shell the lists were drawn with, so that round-off
    /// in a renewal time can never carry a particle past the shell.
    #[inline(always)]
    fn edge(&self) -> f64 {
        self.shell * (1.0 - 1e-9)
    }

    /// How far a search reaches: widened by the round-off, it can never
    /// miss a point.
    #[inline(always)]
    fn search_reach(&self) -> f64 {
        self.reach + self.grid.rounding()
    }

    /// Everything whose neighbourhood meets that of i at its current centre,
    /// into `found`, sorted (`unsorted` is room to work in, only ever grown).
    fn find(&self, i: usize, found: &mut Vec<u32>, unsorted: &mut Vec<u32>) {
        let c = &self.centre.get(i);
        let kept = if PLANES && Some(i) == self.plane {
            unsorted.clear();
            let reach = self.plane_reach + self.grid.rounding();
            self.grid.for_each_in_slab(c[0] - reach, c[0] + reach, |j| {
                if (self.centre.get(j)[0] - c[0]).abs() < reach {
                    unsorted.push(pack(j, PLANE));
                }
            });
            unsorted.len()
        } else {
            // Most points tested are not neighbours, at random: write every
            // one and keep it or not without a branch that would mispredict.
            let reach = self.search_reach();
            let reach2 = reach * reach;
            let steps = self.centre.steps(i);
            let mut own = [Near::default(); 27];
            let near = match &self.ahead {
                CellsAhead {
                    steps: Some(s),
                    near,
                    count,
                } if s == steps => {
                    // Asked for an event ago, into L2: asking again brings
                    // them all on to L1 at once.
                    self.grid.prefetch_cells(&near[..*count], Read::Soon);
                    &near[..*count]
                }
                _ => {
                    let count = self
                        .grid
                        .cells_around(steps, c, reach, &mut own, Read::Soon);
                    &own[..count]
                }
            };
            // A point's offset from the centre, in steps, is exact in
            // integers: the same, but for its sign, seen from either end, so
            // a pair is in both lists or in neither.
            let step = self.centre.step();
            let mut kept = 0;
            for cell in near {
                let points = self.grid.points(cell);
                // Room for every point so far and the plane.
                if unsorted.len() <= kept + points.len() {
                    unsorted.resize(kept + points.len() + 1, 0);
                }
                let from: [i32; D] = std::array::from_fn(|k| cell.from(k));
                for &e in points {
                    let j = index(e);
                    let r: Vector<D> =
                        std::array::from_fn(|k| (from[k] + fine(e, k)) as f64 * step[k]);
                    unsorted[kept] = pack(j, cell.image);
                    kept += ((j != i) & (norm2(&r) < reach2)) as usize;
                }
            }
            if let Some(k) = self.plane.filter(|_| PLANES)
                && self.meets_plane(i, k)
            {
                unsorted[kept] = pack(k, PLANE);
                kept += 1;
            }
            kept
        };
        sort_distinct(&unsorted[..kept], found);
    }

    /// Renew i's list around its current centre, and its partners' lists.
    /// Most partners stay partners, so only the differences between the old
    /// list and the new (both sorted) touch other lists.
    /// `bodies`: ask for the new partners' bodies as soon as they are found
    /// (a renewal's prediction reads them next).
    fn relist(&mut self, i: usize, bodies: Option<Lines>) {
        self.catch_up();
        let [mut new, mut unsorted] = std::mem::take(&mut self.scratch);
        let mut changes = std::mem::take(&mut self.changes);
        self.find(i, &mut new, &mut unsorted);
        if let Some(bodies) = bodies {
            for &e in &new {
                bodies.ask(unpack(e).0, Read::Later);
            }
        }
        self.differences(i, &new, &mut changes);
        // Every list the changes touch asked for at once, so that the misses
        // on these scattered lists overlap; the changes wait for `catch_up`.
        for &(j, _) in &changes {
            self.lists.prefetch(j, Read::Soon);
        }
        if PLANES && Some(i) == self.plane {
            self.plane_list.clear();
            self.plane_list.extend_from_slice(&new);
        } else {
            self.lists.set(i, &new);
        }
        self.scratch = [new, unsorted];
        self.changes = changes;
        self.renewed = i;
    }

    /// What renewing i's list to `new` does to other lists, by a merge of
    /// the old list and the new: take i out of j's list (`None`), or put
    /// this entry in.
    fn differences(&self, i: usize, new: &[u32], changes: &mut Vec<(usize, Option<u32>)>) {
        changes.clear();
        let old = if PLANES && Some(i) == self.plane {
            &self.plane_list[..]
        } else {
            self.list(i)
        };
        let entry = |e: u32| Some(pack(i, mirror::<D>(unpack(e).1)));
        let (mut a, mut b) = (0, 0);
        while a < old.len() || b < new.len() {
            let key = |e: Option<&u32>| e.map_or(usize::MAX, |&e| unpack(e).0);
            let (j_old, j_new) = (key(old.get(a)), key(new.get(b)));
            if j_old < j_new {
                changes.push((j_old, None));
                a += 1;
            } else if j_new < j_old {
                changes.push((j_new, entry(new[b])));
                b += 1;
            } else {
                if old[a] != new[b] {
                    // Same partner, new image (i wrapped round the box).
                    changes.push((j_new, None));
                    changes.push((j_new, entry(new[b])));
                }
                a += 1;
                b += 1;
            }
        }
    }

    /// Build every list from the centres.
    fn list_all(&mut self) {
        self.lists.clear();
        self.plane_list.clear();
        self.grid.clear();
        for i in 0..self.centre.len() {
            if Some(i) != self.plane {
                self.grid.place(i, self.centre.steps(i), None);
            }
        }
        let [mut buf, mut unsorted] = std::mem::take(&mut self.scratch);
        for i in 0..self.centre.len() {
            self.find(i, &mut buf, &mut unsorted);
            for &e in &buf {
                let (j, image) = unpack(e);
                if j > i {
                    self.insert(i, e);
                    self.insert(j, pack(i, mirror::<D>(image)));
                }
            }
        }
        self.scratch = [buf, unsorted];
    }
}

impl<const D: usize, const PLANES: bool> Neighbourhood<D> for NeighbourList<D, PLANES> {
    const PLANES: bool = PLANES;

    fn build(particles: &[Particle<D>], sim_box: &SimBox<D>) -> Result<Self, String> {
        if D < 2 {
            return Err("neighbour lists are for two and three dimensions".into());
        }
        if particles.len() >= MAX_PARTICLES {
            return Err(format!(
                "{} particles is more than this engine indexes ({MAX_PARTICLES})",
                particles.len()
            ));
        }
        let plane = particles.iter().position(Particle::is_plane);
        if plane.is_some() && !PLANES {
            return Err(
                "this system has a plane (a piston wall); build it with NeighbourList<D, true>"
                    .into(),
            );
        }
        let largest_radius = particles
            .iter()
            .filter(|p| !p.is_plane())
            .map(|p| p.radius)
            .fold(0.0, f64::max);
        let n = particles.len();
        let balls = n - usize::from(plane.is_some());
        let (shell, cells) = layout(n, balls, largest_radius, sim_box).map_err(|(_, why)| why)?;
        let reach = 2.0 * (largest_radius + shell);
        let grid = Grid::new(n, cells, sim_box);
        let mut lists = NeighbourList {
            shell,
            size: sim_box.size,
            periodic: std::array::from_fn(|k| sim_box.axes[k].is_periodic()),
            reach,
            plane_reach: plane.map_or(0.0, |k| particles[k].radius) + largest_radius + 2.0 * shell,
            centre: Centres::new(
                &sim_box.size,
                grid.cells_per_axis(),
                particles.iter().map(|p| p.pos),
            ),
            grid,
            // Room for the mean list of particles spread evenly over the box
            // (an ideal gas: a fluid's lists are a little shorter).
            lists: ListStore::new(
                n,
                room_for(n as f64 / sim_box.volume() * ball_volume(D, reach)),
            ),
            plane,
            plane_list: Vec::new(),
            scratch: Default::default(),
            changes: Vec::new(),
            renewed: 0,
            ahead: CellsAhead::default(),
        };
        lists.list_all();
        Ok(lists)
    }

    #[inline(always)]
    fn candidates(&self, i: usize) -> impl Iterator<Item = (usize, Image)> {
        let list = if PLANES && Some(i) == self.plane {
            &self.plane_list[..]
        } else {
            self.list(i)
        };
        list.iter().map(|&e| unpack(e))
    }

    /// List i's length, its centre and the two ends of its room (a hint).
    #[inline(always)]
    fn prefetch(&self, i: usize, when: Read) {
        self.lists.prefetch(i, when);
        prefetch_for(self.centre.steps(i), when);
    }

    /// The cells around where p will renew at t, kept for its search.
    #[inline]
    fn prefetch_renewal(&mut self, i: usize, p: &Body<D>, t: f64) {
        if PLANES && Some(i) == self.plane {
            return;
        }
        let mut x = p.position_at(t);
        for k in (0..D).filter(|&k| self.periodic[k]) {
            x[k] = into_box(x[k], self.size[k]);
        }
        let steps = self.centre.nearest(&x);
        let reach = self.search_reach();
        let ahead = &mut self.ahead;
        ahead.count = self.grid.cells_around(
            &steps,
            &self.centre.position(&steps),
            reach,
            &mut ahead.near,
            Read::Later,
        );
        ahead.steps = Some(steps);
    }

    /// When p (particle i) reaches the edge of its neighbourhood.
    #[inline]
    fn next_renewal(&self, i: usize, p: &Body<D>) -> Option<f64> {
        let (d, v) = self.relative_to_centre(i, p);
        // Solve |d + v s| = edge for s > 0, d inside: cancellation-free roots.
        let edge = self.edge();
        let (a, b, c) = (dot(&v, &v), dot(&d, &v), dot(&d, &d) - edge * edge);
        if a == 0.0 {
            return None;
        }
        if c >= 0.0 {
            return Some(p.t);
        }
        let root = (b * b - a * c).sqrt();
        let s = if b <= 0.0 {
            (root - b) / a
        } else {
            -c / (b + root)
        };
        Some(p.t + s)
    }

    /// Whether p is within the edge at `t`: the edge `next_renewal` uses, a
    /// hair inside the shell, so a yes that round-off got wrong at the edge
    /// still leaves p inside the shell the lists were drawn with.
    #[inline(always)]
    fn inside_at(&self, i: usize, p: &Body<D>, t: f64) -> bool {
        let (d, v) = self.relative_to_centre(i, p);
        let edge = self.edge();
        let x = add_scaled(&d, t - p.t, &v);
        dot(&x, &x) < edge * edge
    }

    fn catch_up(&mut self) {
        if self.changes.is_empty() {
            return;
        }
        let changes = std::mem::take(&mut self.changes);
        for &(j, entry) in &changes {
            match entry {
                None => self.remove(j, self.renewed),
                Some(e) => self.insert(j, e),
            }
        }
        self.changes = changes;
        self.changes.clear();
    }

    fn renew(&mut self, i: usize, p: &mut Body<D>, now: f64, bodies: Option<Lines>) -> bool {
        p.advance_to(now);
        let mut wrapped = false;
        for k in 0..D {
            if self.periodic[k] && !(0.0..self.size[k]).contains(&p.pos[k]) {
                p.pos[k] = into_box(p.pos[k], self.size[k]);
                wrapped = true;
            }
        }
        let was = *self.centre.steps(i);
        self.centre.set(i, &p.pos);
        self.relist(i, bodies);
        // Filed after the search (which passes over i wherever it is filed),
        // which has brought the cells it leaves and enters into the cache.
        if Some(i) != self.plane {
            self.grid.place(i, self.centre.steps(i), Some(&was));
        }
        wrapped
    }
}

/// x moved into [0, size) by whole box lengths. Not `rem_euclid`, which
/// calls `fmod` (1.6 % of the time at 10^6 spheres, asking ahead for
/// renewals' cells); `floor` is one instruction.
#[inline(always)]
fn into_box(x: f64, size: f64) -> f64 {
    let y = x - size * (x / size).floor();
    if y >= size { 0.0 } else { y }
}

/// Saved as every centre, each coordinate as two words (low, high): the lists
/// follow from the centres.
impl<const D: usize, const PLANES: bool> Persist<D> for NeighbourList<D, PLANES> {
    const KIND: u32 = 2 + PLANES as u32;

    fn state(&self) -> Vec<u32> {
        self.centre
            .iter()
            .flatten()
            .flat_map(|x| {
                let bits = x.to_bits();
                [bits as u32, (bits >> 32) as u32]
            })
            .collect()
    }

    fn restore(
        particles: &[Particle<D>],
        sim_box: &SimBox<D>,
        state: &[u32],
    ) -> Result<Self, String> {
        let mut lists = Self::build(particles, sim_box)?;
        let words = 2 * D * particles.len();
        if state.len() != words {
            return Err(format!(
                "neighbour-list state has {} words; {} particles need {words}",
                state.len(),
                particles.len()
            ));
        }
        let coords: Vec<f64> = state
            .chunks_exact(2)
            .map(|w| f64::from_bits(w[0] as u64 | (w[1] as u64) << 32))
            .collect();
        if coords.iter().any(|x| !x.is_finite()) {
            return Err("neighbour-list state holds a centre that is not a finite number".into());
        }
        for (i, saved) in coords.chunks_exact(D).enumerate() {
            lists.centre.set(i, &std::array::from_fn(|k| saved[k]));
        }
        lists.list_all();
        Ok(lists)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two spheres whose centres are a hair inside the reach, in the far
    /// corner of a large box where round-off (of the centres' fixed point,
    /// and in the distance) is largest: each must be in the other's list
    /// whenever their stored centres are within the reach.
    #[test]
    fn a_pair_just_inside_the_reach_is_listed_despite_rounding() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let side = 3072.0;
        let sim_box = SimBox::<3>::periodic([side; 3]);
        let corner = [side - 0.3, side - 1.7, side - 0.9];
        let ball = |x| Particle::new(x, [1.0, 0.0, 0.0], 1.0, 0.5);
        let pair = |partner| vec![ball(corner), ball(partner)];
        // The reach depends on the number of particles, not where they are.
        let reach = NeighbourList::<3>::build(&pair([1.0; 3]), &sim_box)
            .unwrap()
            .reach;
        let mut inside = 0;
        for _ in 0..200 {
            let u: Vector<3> = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
            let direction = u.map(|x| x / norm2(&u).sqrt());
            let hair = 1.0 - 1e-9 * rng.random::<f64>();
            let partner =
                std::array::from_fn(|k| (corner[k] - reach * hair * direction[k]).rem_euclid(side));
            let lists = NeighbourList::<3>::build(&pair(partner), &sim_box).unwrap();
            let d = sub(&lists.centre.get(0), &lists.centre.get(1));
            let d = d.map(|x| x - side * (x / side).round());
            if norm2(&d) < reach * reach {
                inside += 1;
                let listed = |i: usize, j: usize| lists.candidates(i).any(|(k, _)| k == j);
                assert!(listed(0, 1) && listed(1, 0), "{partner:?}, reach {reach}");
            }
        }
        assert!(inside > 50, "only {inside} pairs within the reach");
    }

    /// Short lists are sorted by counting, a plane's long one by comparison:
    /// both give what a comparison sort gives.
    #[test]
    fn distinct_entries_come_out_in_order_short_or_long() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let mut sorted = Vec::new();
        for len in [0, 1, 2, 13, 64, 65, 3000] {
            let mut entries: Vec<u32> = Vec::new();
            while entries.len() < len {
                let e = rng.random::<u32>();
                if !entries.contains(&e) {
                    entries.push(e);
                }
            }
            sort_distinct(&entries, &mut sorted);
            entries.sort_unstable();
            assert_eq!(sorted, entries, "{len} entries");
        }
    }

    /// The cells a renewal's search reuses, worked out when it was asked
    /// ahead for, change no list: renewals asked ahead for (the right one,
    /// or another: a guess of the next event can be wrong) leave every list
    /// as renewals that were not, near the box's faces and corners too.
    #[test]
    fn cells_worked_out_ahead_change_no_list() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let side = 9.0;
        let sim_box = SimBox::<3>::periodic([side; 3]);
        let particles: Vec<_> = (0..400)
            .map(|_| {
                let x = std::array::from_fn(|_| rng.random_range(0.0..side));
                Particle::new(x, [0.0; 3], 1.0, 0.5)
            })
            .collect();
        let mut asked = NeighbourList::<3>::build(&particles, &sim_box).unwrap();
        let mut not_asked = asked.clone();
        let mut bodies = crate::engine::bodies::Bodies::new(&particles);
        let (mut reused, mut now) = (0, 0.0);
        for _ in 0..2_000 {
            let i = rng.random_range(0..particles.len());
            let guess = if rng.random_bool(0.8) {
                i
            } else {
                rng.random_range(0..particles.len())
            };
            for k in [i, guess] {
                let p = &mut bodies.bodies_mut()[k];
                p.vel = std::array::from_fn(|_| rng.random_range(-3.0..3.0));
            }
            now += 0.1;
            let ahead = bodies.bodies()[guess];
            asked.prefetch_renewal(guess, &ahead, now);
            let mut p = bodies.bodies()[i];
            asked.renew(i, &mut p, now, Some(Lines::of(bodies.bodies())));
            asked.catch_up();
            reused += usize::from(asked.ahead.steps.as_ref() == Some(asked.centre.steps(i)));
            let mut q = bodies.bodies()[i];
            not_asked.renew(i, &mut q, now, None);
            not_asked.catch_up();
            assert_eq!(p, q);
            bodies.bodies_mut()[i] = p;
            for j in [i, guess] {
                assert!(
                    asked.candidates(j).eq(not_asked.candidates(j)),
                    "list {j} after renewing {i}"
                );
            }
        }
        for j in 0..particles.len() {
            assert!(asked.candidates(j).eq(not_asked.candidates(j)), "list {j}");
        }
        assert!(reused > 1_400, "the search reused the cells {reused} times");
    }

    /// A particle found inside its neighbourhood at a time renews no
    /// earlier than that time (what lets a prediction skip the renewal), and
    /// one found outside renews no later: random places inside the shell,
    /// velocities and times, a ball's neighbourhood and a plane's.
    #[test]
    fn inside_at_a_time_means_renewing_no_earlier() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let sim_box = SimBox::<3>::periodic([12.0; 3]);
        let ball = |x| Particle::new(x, [0.0; 3], 1.0, 0.5);
        let mut particles = vec![ball([2.0; 3]), ball([8.0; 3])];
        particles.push(Particle::plane(5.0, 0.0, 10.0, 0.5));
        let lists = NeighbourList::<3, true>::build(&particles, &sim_box).unwrap();
        let bodies = crate::engine::bodies::Bodies::new(&particles);
        let (mut inside, mut outside) = (0, 0);
        for _ in 0..20_000 {
            let i = rng.random_range(0..3);
            let mut p = bodies.bodies()[i];
            let d: Vector<3> = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
            let d = d.map(|x| x * lists.shell * 0.57);
            p.pos = std::array::from_fn(|k| lists.centre.get(i)[k] + d[k]);
            p.vel = std::array::from_fn(|_| rng.random_range(-2.0..2.0));
            p.t = rng.random_range(-1.0..1.0);
            let t = p.t + rng.random_range(0.0..1.0) * lists.shell;
            let renewal = lists.next_renewal(i, &p).unwrap();
            // Round-off at the edge may put the two an ulp or so apart.
            let ulps = 1e-12 * (1.0 + t.abs());
            if lists.inside_at(i, &p, t) {
                inside += 1;
                assert!(
                    renewal >= t - ulps,
                    "{i}: inside at {t}, renews at {renewal}"
                );
            } else {
                outside += 1;
                assert!(
                    renewal <= t + ulps,
                    "{i}: outside at {t}, renews at {renewal}"
                );
            }
        }
        assert!(
            inside > 1000 && outside > 1000,
            "{inside} inside, {outside} outside"
        );
    }
}
