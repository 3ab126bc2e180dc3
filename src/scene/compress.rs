//! Lubachevsky–Stillinger compression: dense packings by growing particles
//! in an exact event-driven run (Lubachevsky & Stillinger, J. Stat. Phys. 60,
//! 561, 1990).
//!
//! Every radius grows in proportion, r_i(t) = rho_i (s0 + g t), from a
//! random (or lattice) start at a low density until the scale s reaches 1,
//! where each particle has its requested radius rho_i. A pair touches when
//! |r + v t| = sigma0 + a t (sigma0 its contact distance now, a its growth
//! rate). At a collision the rate at which the gap closes, w = u - a (u the
//! normal relative velocity), is reversed: the pair separates faster than it
//! grows, which is the elastic rule plus twice the growth rate in the normal
//! relative velocity. A particle meets a wall (or the edge of its region)
//! the same way. Collisions add energy, so the velocities are rescaled to
//! kT = 1 after every 4N collisions; that keeps the growth rate a fixed
//! fraction of the thermal speed. Positions come out exact to round-off;
//! the velocities are discarded (the growth rule skews them) and the scene
//! draws its own.

use super::lattice;
use super::placement;
use super::space::{CellList, Slot, Space, ball_volume, region_volume};
use crate::engine::queue::EventQueue;
use crate::engine::thermal::gaussian;
use crate::model::scene::CompressFrom;
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

/// Default growth rate: fraction of the final size gained per unit time.
pub const GROWTH_RATE: f64 = 0.005;

/// The densest targets compression is asked to reach, 2D and 3D. Equal
/// disks compressed at practical rates freeze into polycrystals whose grain
/// boundaries jam well below hexagonal close packing (0.9069): in a periodic
/// square box of 400 disks they jammed between 0.878 and 0.885 at the default
/// rate, and at 0.883 five times slower; so from about 0.87 a run may jam
/// (a clear error, see `STALL`) and above 0.88 it is refused. Spheres reach
/// random close packing, about 0.64 (0.64 took 3 s for 250); beyond it lies
/// only the crystal (fcc, 0.7405). Denser targets: use a lattice.
pub const LIMIT: [f64; 2] = [0.88, 0.64];

/// Packing fraction of the start, well below random insertion's jamming
/// (0.547 in 2D, 0.38 in 3D) so that it is quick.
const START: [f64; 2] = [0.35, 0.2];

/// Jamming shows as growth that stalls while collisions go on: the packing
/// is declared jammed when the scale takes more than `STALL` collisions per
/// particle (at the default rate; proportionally more at slower rates) to
/// gain `WINDOW`. Compressions to 0.85-0.88 (2D) and 0.60-0.63 (3D) need at
/// most 180 in their last, densest window.
const WINDOW: f64 = 0.005;
const STALL: f64 = 2000.0;

/// Velocities are rescaled to kT = 1 after this many collisions per particle.
const THERMOSTAT: u64 = 4;

/// What compression cost, for the report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Preparation {
    /// Wall-clock seconds spent (start placement included).
    pub seconds: f64,
    pub collisions: u64,
    /// Packing fraction of the start and of the result (whole box).
    pub start_phi: f64,
    pub phi: f64,
}

pub struct Settings {
    pub growth_rate: f64,
    pub from: CompressFrom,
}

/// Positions of all slots at their full radii. The packing is a
/// configuration, so it is grown with equal masses whatever the species'
/// (the scene assigns those after): with a mass ratio of 1e6 a light gas
/// would carry all the motion and the heavy particles jam at 0.5-0.6.
pub fn compress<const D: usize>(
    slots: &[Slot<D>],
    space: &Space<D>,
    names: &[String],
    settings: &Settings,
    rng: &mut ChaCha8Rng,
) -> Result<(Vec<[f64; D]>, Preparation), String> {
    let started = Instant::now();
    // The rate is positive: see `check`.
    let rate = settings.growth_rate;
    let target = densest_region(slots, names)?;
    let box_phi = |scale: f64| {
        slots
            .iter()
            .map(|s| ball_volume(D, s.radius * scale))
            .sum::<f64>()
            / space.volume()
    };
    let s0 = if target > 0.0 {
        (START[D - 2] / target).powf(1.0 / D as f64).min(1.0)
    } else {
        1.0
    };
    let small: Vec<Slot<D>> = slots
        .iter()
        .map(|s| Slot {
            radius: s.radius * s0,
            ..*s
        })
        .collect();
    let start = match settings.from {
        CompressFrom::Random => placement::random(&small, space, rng)?,
        CompressFrom::Lattice => lattice::place(&small, space, None, names, rng)?,
    };
    let mut g = Grower::new(slots, space, start, s0, rate, rng)?;
    let t_end = (1.0 - s0) / rate;
    let stall = (STALL * (GROWTH_RATE / rate) * slots.len() as f64) as u64 + 1000;
    g.run(t_end, stall).map_err(|stalled| {
        format!(
            "compression jammed at packing fraction {:.4} (box) after {} collisions, short of the \
             target {:.4}: the particles are caught in a glass or a defective crystal{}. Use a lower \
             density, a slower growth_rate, or `placement = {{ kind = \"lattice\" }}` for a crystal",
            box_phi(stalled),
            g.collisions,
            box_phi(1.0),
            walls_note(slots, space)
        )
    })?;
    let positions = g.finish(t_end);
    Ok((
        positions,
        Preparation {
            seconds: started.elapsed().as_secs_f64(),
            collisions: g.collisions,
            start_phi: box_phi(s0),
            phi: box_phi(1.0),
        },
    ))
}

/// With walls, how much room they leave: the densest lattice's capacity.
fn walls_note<const D: usize>(slots: &[Slot<D>], space: &Space<D>) -> String {
    let first = &slots[0];
    if (0..D).all(|k| space.wraps(&first.lo, &first.hi, k)) {
        return String::new();
    }
    let members: Vec<&Slot<D>> = slots.iter().filter(|s| s.same_region(first)).collect();
    let radius = members.iter().map(|s| s.radius).fold(0.0, f64::max);
    format!(
        " (walls cost room: even a perfect {} lattice holds only {} of the {} particles of \
         radius {radius} in that region)",
        if D == 2 { "hexagonal" } else { "fcc" },
        lattice::capacity(space, first, radius),
        members.len()
    )
}

/// The highest packing fraction of any region's particles, refused above
/// the limit.
fn densest_region<const D: usize>(slots: &[Slot<D>], names: &[String]) -> Result<f64, String> {
    let mut densest: f64 = 0.0;
    let mut seen: Vec<&Slot<D>> = Vec::new();
    for s in slots {
        if seen.iter().any(|t| t.same_region(s)) {
            continue;
        }
        seen.push(s);
        let filled: f64 = slots
            .iter()
            .filter(|t| t.same_region(s))
            .map(|t| ball_volume(D, t.radius))
            .sum();
        let phi = filled / region_volume(&s.lo, &s.hi);
        let limit = LIMIT[D - 2];
        if phi > limit * (1.0 + 1e-9) {
            let name = names.get(s.species as usize).map_or("?", String::as_str);
            return Err(format!(
                "the particles of `{name}` would fill packing fraction {phi:.4} of their region; \
                 compression reaches at most {limit} in {D}D (beyond it hard {} jam into a glass \
                 or a defective crystal): use `placement = {{ kind = \"lattice\" }}` for denser \
                 crystals, or a larger box",
                if D == 2 { "disks" } else { "spheres" }
            ));
        }
        densest = densest.max(phi);
    }
    Ok(densest)
}

#[derive(Debug, Clone, Copy)]
enum Event {
    Nothing,
    Pair { j: u32, stamp: u32 },
    Wall { axis: usize, high: bool },
    Cross { axis: usize, up: bool },
}

/// The growing system. Positions are stored at each particle's own last
/// event time, as in the engine.
struct Grower<'a, const D: usize> {
    slots: &'a [Slot<D>],
    space: Space<D>,
    /// Per particle and axis: the bounds it bounces off (None where it wraps).
    walls: Vec<[Option<(f64, f64)>; D]>,
    pos: Vec<[f64; D]>,
    vel: Vec<[f64; D]>,
    time: Vec<f64>,
    cells: CellList<D>,
    queue: EventQueue,
    next: Vec<Event>,
    stamp: Vec<u32>,
    now: f64,
    s0: f64,
    rate: f64,
    collisions: u64,
}

impl<'a, const D: usize> Grower<'a, D> {
    fn new(
        slots: &'a [Slot<D>],
        space: &Space<D>,
        pos: Vec<[f64; D]>,
        s0: f64,
        rate: f64,
        rng: &mut ChaCha8Rng,
    ) -> Result<Self, String> {
        let n = slots.len();
        let reach = 2.0 * slots.iter().map(|s| s.radius).fold(0.0, f64::max);
        let mut cells = CellList::new(*space, reach, n)?;
        for x in &pos {
            cells.push(x);
        }
        let vel = (0..n)
            .map(|_| std::array::from_fn(|_| gaussian(rng)))
            .collect();
        let mut g = Grower {
            slots,
            space: *space,
            walls: slots
                .iter()
                .map(|s| {
                    std::array::from_fn(|k| {
                        (!space.wraps(&s.lo, &s.hi, k)).then_some((s.lo[k], s.hi[k]))
                    })
                })
                .collect(),
            pos,
            vel,
            time: vec![0.0; n],
            cells,
            queue: EventQueue::new(n),
            next: vec![Event::Nothing; n],
            stamp: vec![0; n],
            now: 0.0,
            s0,
            rate,
            collisions: 0,
        };
        g.thermalize();
        Ok(g)
    }

    fn scale(&self) -> f64 {
        self.s0 + self.rate * self.now
    }

    fn at(&self, i: usize) -> [f64; D] {
        let dt = self.now - self.time[i];
        std::array::from_fn(|k| self.pos[i][k] + self.vel[i][k] * dt)
    }

    fn advance(&mut self, i: usize) {
        self.pos[i] = self.at(i);
        self.time[i] = self.now;
    }

    /// Run until time `t_end`, or fail (returning the scale reached) when
    /// growth stalls: `stall` collisions without gaining `WINDOW` in scale.
    fn run(&mut self, t_end: f64, stall: u64) -> Result<(), f64> {
        let every = THERMOSTAT * self.slots.len() as u64;
        let mut window = (self.s0 + WINDOW, self.collisions);
        while let Some((i, t)) = self.queue.peek() {
            if t >= t_end {
                break;
            }
            self.now = t;
            if self.scale() >= window.0 {
                window = (self.scale() + WINDOW, self.collisions);
            } else if self.collisions - window.1 > stall {
                return Err(self.scale());
            }
            match self.next[i] {
                Event::Nothing => self.queue.set(i, f64::INFINITY),
                Event::Pair { j, stamp } => {
                    let j = j as usize;
                    if self.stamp[j] == stamp && self.collide(i, j) {
                        if self.collisions.is_multiple_of(every) {
                            self.thermalize();
                        }
                    } else {
                        self.predict(i);
                    }
                }
                Event::Wall { axis, high } => {
                    self.bounce(i, axis, high);
                    self.predict(i);
                }
                Event::Cross { axis, up } => {
                    self.cross(i, axis, up);
                    self.predict(i);
                }
            }
        }
        self.now = t_end;
        Ok(())
    }

    /// Collide a touching pair if it is closing; false if round-off made the
    /// event stale.
    fn collide(&mut self, i: usize, j: usize) -> bool {
        self.advance(i);
        self.advance(j);
        let r = self.space.separation(&self.pos[i], &self.pos[j]);
        let dist = r.iter().map(|x| x * x).sum::<f64>().sqrt();
        let n: [f64; D] = std::array::from_fn(|k| r[k] / dist);
        let u: f64 = (0..D)
            .map(|k| (self.vel[j][k] - self.vel[i][k]) * n[k])
            .sum();
        let a = (self.slots[i].radius + self.slots[j].radius) * self.rate;
        let closing = u - a;
        if !(closing < 0.0 && dist > 0.0) {
            return false;
        }
        // Equal masses: each takes half the reversal of the closing rate.
        for k in 0..D {
            self.vel[i][k] += closing * n[k];
            self.vel[j][k] -= closing * n[k];
        }
        self.stamp[i] = self.stamp[i].wrapping_add(1);
        self.stamp[j] = self.stamp[j].wrapping_add(1);
        self.collisions += 1;
        self.predict(i);
        self.predict(j);
        true
    }

    fn bounce(&mut self, i: usize, k: usize, high: bool) {
        self.advance(i);
        let g = self.slots[i].radius * self.rate;
        let v = &mut self.vel[i][k];
        // Reverse the rate at which the gap to the wall closes.
        if high && *v + g > 0.0 {
            *v = -*v - 2.0 * g;
        } else if !high && g - *v > 0.0 {
            *v = -*v + 2.0 * g;
        }
        self.stamp[i] = self.stamp[i].wrapping_add(1);
    }

    fn cross(&mut self, i: usize, k: usize, up: bool) {
        self.advance(i);
        let n = self.cells.cells_per_axis();
        let mut idx = self.cells.index(self.cells.cell(i));
        let l = self.space.size[k];
        idx[k] = match (up, idx[k]) {
            (true, c) if c + 1 == n[k] => {
                self.pos[i][k] -= l;
                0
            }
            (true, c) => c + 1,
            (false, 0) => {
                self.pos[i][k] += l;
                n[k] - 1
            }
            (false, c) => c - 1,
        };
        let c = (0..D).rev().fold(0, |c, a| c * n[a] + idx[a]);
        self.cells.relocate(i, c);
    }

    /// Particle i's next event from now.
    fn predict(&mut self, i: usize) {
        let x = self.at(i);
        let v = self.vel[i];
        let rho = self.slots[i].radius;
        let s = self.scale();
        let mut best = (f64::INFINITY, Event::Nothing);
        let mut consider = |t: f64, e: Event| {
            if t < best.0 {
                best = (t, e);
            }
        };
        let n = self.cells.cells_per_axis();
        let idx = self.cells.index(self.cells.cell(i));
        let width = self.cells.width();
        for k in 0..D {
            if let Some((lo, hi)) = self.walls[i][k] {
                let g = rho * self.rate;
                if v[k] + g > 0.0 {
                    consider(
                        (hi - x[k] - rho * s).max(0.0) / (v[k] + g),
                        Event::Wall {
                            axis: k,
                            high: true,
                        },
                    );
                }
                if g - v[k] > 0.0 {
                    consider(
                        (x[k] - rho * s - lo).max(0.0) / (g - v[k]),
                        Event::Wall {
                            axis: k,
                            high: false,
                        },
                    );
                }
            }
            // Cell faces; on a walled axis the outermost faces are the box's.
            let periodic = self.space.periodic[k];
            if v[k] > 0.0 && (periodic || idx[k] + 1 < n[k]) {
                let face = (idx[k] + 1) as f64 * width[k];
                consider(
                    (face - x[k]).max(0.0) / v[k],
                    Event::Cross { axis: k, up: true },
                );
            } else if v[k] < 0.0 && (periodic || idx[k] > 0) {
                let face = idx[k] as f64 * width[k];
                consider(
                    (x[k] - face).max(0.0) / -v[k],
                    Event::Cross { axis: k, up: false },
                );
            }
        }
        for j in self.cells.near(self.cells.cell(i)) {
            if j == i {
                continue;
            }
            let r = self.space.separation(&x, &self.at(j));
            let dv: [f64; D] = std::array::from_fn(|k| self.vel[j][k] - v[k]);
            let sum = rho + self.slots[j].radius;
            if let Some(t) = contact(&r, &dv, sum * s, sum * self.rate) {
                consider(
                    t,
                    Event::Pair {
                        j: j as u32,
                        stamp: self.stamp[j],
                    },
                );
            }
        }
        let (t, e) = best;
        self.next[i] = e;
        self.queue.set(i, self.now + t);
    }

    /// Rescale velocities to kT = 1 and predict every event afresh.
    fn thermalize(&mut self) {
        for i in 0..self.pos.len() {
            self.advance(i);
        }
        let kinetic: f64 = self
            .vel
            .iter()
            .map(|v| 0.5 * v.iter().map(|x| x * x).sum::<f64>())
            .sum();
        let c = (0.5 * (D * self.pos.len()) as f64 / kinetic).sqrt();
        if c.is_finite() {
            self.vel.iter_mut().flatten().for_each(|x| *x *= c);
        }
        for i in 0..self.pos.len() {
            self.stamp[i] = self.stamp[i].wrapping_add(1);
        }
        for i in 0..self.pos.len() {
            self.predict(i);
        }
    }

    /// Positions at the end, inside the box and their regions.
    fn finish(&mut self, t_end: f64) -> Vec<[f64; D]> {
        self.now = t_end;
        (0..self.pos.len())
            .map(|i| {
                let mut x = self.at(i);
                let r = self.slots[i].radius;
                for (k, xk) in x.iter_mut().enumerate() {
                    match self.walls[i][k] {
                        Some((lo, hi)) => *xk = xk.clamp(lo + r, hi - r),
                        None => *xk = xk.rem_euclid(self.space.size[k]),
                    }
                }
                x
            })
            .collect()
    }
}

/// Time until two growing spheres first touch: separation r (from i to j),
/// relative velocity v (of j), contact distance sigma now, growing at rate
/// a. The gap |r + v t| - sigma - a t is convex in t, so a touching pair
/// closes now or never, and a parted pair meets at the first root of
/// |r + v t|^2 = (sigma + a t)^2, taken in the form free of cancellation.
/// The closing test is the one `collide` applies, so a pair it refuses is
/// never scheduled again at the same instant.
fn contact<const D: usize>(r: &[f64; D], v: &[f64; D], sigma: f64, a: f64) -> Option<f64> {
    let dot = |p: &[f64; D], q: &[f64; D]| (0..D).map(|k| p[k] * q[k]).sum::<f64>();
    let rv = dot(r, v);
    let c = dot(r, r) - sigma * sigma;
    if c <= 0.0 {
        return (rv < a * dot(r, r).sqrt()).then_some(0.0);
    }
    let b = rv - sigma * a;
    let q = dot(v, v) - a * a;
    if b < 0.0 {
        let disc = b * b - q * c;
        (disc >= 0.0).then(|| c / (-b + disc.sqrt()))
    } else if q < 0.0 {
        Some((b + (b * b - q * c).sqrt()) / -q)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::contact;

    /// Head-on: gap 1 closing at speed 1 while the contact distance grows at
    /// 0.5: they touch after 1 / 1.5.
    #[test]
    fn contact_time_of_growing_pair() {
        let t = contact(&[2.0, 0.0], &[-1.0, 0.0], 1.0, 0.5).unwrap();
        assert!((t - 1.0 / 1.5).abs() < 1e-15);
        // At rest, growth alone closes the gap.
        let t = contact(&[2.0, 0.0], &[0.0, 0.0], 1.0, 0.5).unwrap();
        assert!((t - 2.0).abs() < 1e-15);
        // Receding faster than they grow: never.
        assert!(contact(&[2.0, 0.0], &[1.0, 0.0], 1.0, 0.5).is_none());
        // Touching and parting slower than they grow: now; faster: never.
        assert_eq!(contact(&[1.0, 0.0], &[0.2, 0.0], 1.0, 0.5), Some(0.0));
        assert_eq!(contact(&[1.0, 0.0], &[0.7, 0.0], 1.0, 0.5), None);
    }
}
