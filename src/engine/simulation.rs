//! The event loop. Each particle has exactly one scheduled event: the earliest
//! of its next collision, wall hit or neighbourhood renewal. Repeatedly: take the
//! earliest event in the queue, move the particles it involves to that time,
//! apply it, and predict new events for those particles. In 2D and 3D a
//! prediction passes over a partner whose own event comes first: that partner
//! will look again when its event is done, so for every pair the earlier of
//! the two scheduled events is never later than the pair's contact. A
//! collision predicted with a partner that has since collided with a third is
//! stale and is simply re-predicted (each particle carries an event stamp).

use std::borrow::Borrow;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use super::bodies::Bodies;
use super::boundary::{SimBox, Wall, wall_time};
use super::build::{BuildError, check_overlaps, validate};
use super::collide::{bounce, line_contact_time};
use super::contacts::{BATCH, Batch};
use super::halt::{Halt, stall_bound};
use super::neighbours::{Image, Neighbourhood, PLANE, image_shift, no_shift, separation};
use super::next::{Event, Next, Packed};
use super::observer::{Observer, PairCollision, Snapshot, WallHit};
use super::particle::Particle;
use super::prefetch::{Lines, Read, prefetch, prefetch_for};
use super::queue::EventQueue;
use super::thermal;
use super::vector::{Vector, axis0, dot, norm2, sub};

/// Tallies of what the engine did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counts {
    pub events: u64,
    pub collisions: u64,
    pub wall_hits: u64,
    pub renewals: u64,
    pub stale: u64,
    pub samples: u64,
}

/// When to stop a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stop {
    /// At this absolute simulation time.
    Time(f64),
    /// After this many more pair collisions.
    Collisions(u64),
}

#[derive(Debug, Clone)]
pub struct Simulation<const D: usize, N: Neighbourhood<D>, O: Observer<D>> {
    pub(super) particles: Bodies<D>,
    pub(super) sim_box: SimBox<D>,
    pub(super) neighbours: N,
    /// Each particle's event: its time, what it is, and the particle's stamp.
    pub(super) queue: EventQueue<Event>,
    /// Particles whose scheduled collision still lacks its partner's stamp
    /// (once predictions ask ahead): a prediction asks for the winner's
    /// stamp line, read as the next event begins, so that no prediction
    /// waits on it.
    pub(super) unstamped: Vec<u32>,
    /// Displacement of each periodic image code.
    pub(super) shifts: Vec<Vector<D>>,
    /// Engine time, measured from `origin` (reset now and then so that long
    /// runs keep full precision in `now - t`).
    pub(super) now: f64,
    pub(super) origin: f64,
    pub(super) rebase_every: u64,
    pub(super) events_since_rebase: u64,
    pub(super) sample_every: Option<f64>,
    pub(super) samples_taken: u64,
    pub(super) sample_start: f64,
    pub(super) rng: ChaCha8Rng,
    /// Whether a prediction asks for its partners' records ahead (worth it
    /// only once the system outgrows the caches).
    pub(super) prefetch_partners: bool,
    /// Room for a prediction's partners (kept to spare its setting up).
    pub(super) batch: Batch<D>,
    pub counts: Counts,
    /// Events handled in a row without the clock moving on, and how many
    /// make a stalled clock (`halt::stall_bound`).
    pub(super) same_instant: u64,
    pub(super) stall_after: u64,
    /// Events the run may take in all (`limit_events`).
    pub(super) event_limit: u64,
    /// Set when a run stopped short of its `Stop` and cannot go on.
    pub(super) halt: Option<Halt>,
    pub observer: O,
}

impl<const D: usize, N: Neighbourhood<D>, O: Observer<D>> Simulation<D, N, O> {
    /// Build a system at time 0; `seed` feeds the thermal walls' random stream.
    pub fn new(
        mut particles: Vec<Particle<D>>,
        sim_box: SimBox<D>,
        observer: O,
        seed: u64,
    ) -> Result<Self, BuildError> {
        validate(&mut particles, &sim_box)?;
        for p in &mut particles {
            p.t = 0.0;
        }
        let neighbours = N::build(&particles, &sim_box).map_err(BuildError)?;
        check_overlaps(&particles, &sim_box, &neighbours)?;
        let n = particles.len();
        let mut sim = Simulation {
            shifts: (0..3u32.pow(D as u32))
                .map(|c| image_shift(c as Image, &sim_box.size))
                .collect(),
            particles: Bodies::new(&particles),
            sim_box,
            neighbours,
            queue: EventQueue::new(n),
            unstamped: Vec::new(),
            now: 0.0,
            origin: 0.0,
            rebase_every: (16 * n as u64).max(4096),
            events_since_rebase: 0,
            sample_every: None,
            samples_taken: 0,
            sample_start: 0.0,
            rng: ChaCha8Rng::seed_from_u64(seed),
            batch: Batch::new(),
            prefetch_partners: worth_prefetching(n),
            counts: Counts::default(),
            same_instant: 0,
            stall_after: stall_bound(n),
            event_limit: u64::MAX,
            halt: None,
            observer,
        };
        for i in 0..n {
            sim.predict(i);
        }
        sim.stamp_partners();
        // Anew: those first predictions left room in it for every particle.
        sim.unstamped = Vec::new();
        sim.queue.retune();
        Ok(sim)
    }

    /// Sample the state every `every` time units from now on (first sample now).
    pub fn sample_every(&mut self, every: Option<f64>) {
        self.sample_every = every.filter(|dt| *dt > 0.0 && dt.is_finite());
        self.sample_start = self.time();
        self.samples_taken = 0;
    }

    /// Hand back the observer when the run is over.
    pub fn into_observer(self) -> O {
        self.observer
    }

    /// Absolute simulation time.
    pub fn time(&self) -> f64 {
        self.origin + self.now
    }

    pub fn particles(&self) -> &Bodies<D> {
        &self.particles
    }

    pub fn sim_box(&self) -> &SimBox<D> {
        &self.sim_box
    }

    pub fn snapshot(&self) -> Snapshot<'_, D> {
        Snapshot {
            time: self.time(),
            now: self.now,
            particles: &self.particles,
            sim_box: &self.sim_box,
        }
    }

    pub fn kinetic_energy(&self) -> f64 {
        self.particles.iter().map(|p| p.kinetic_energy()).sum()
    }

    pub fn momentum(&self) -> Vector<D> {
        let mut p = [0.0; D];
        for q in self.particles.iter().filter(|q| !q.is_immovable()) {
            for k in 0..D {
                p[k] += q.vel[k] / q.inv_mass;
            }
        }
        p
    }

    /// Kinetic degrees of freedom, what temperature divides the kinetic energy
    /// by: D per movable ball and 1 per movable plane, less one for each axis
    /// along which total momentum is conserved (periodic, with nothing
    /// immovable to take momentum up).
    pub fn degrees_of_freedom(&self) -> f64 {
        degrees_of_freedom(&self.particles, &self.sim_box)
    }

    /// Why the last `run` stopped short of its `Stop`, if it did; a halted
    /// system does not run again.
    pub fn halted(&self) -> Option<Halt> {
        self.halt
    }

    /// Allow at most `events` events in all (`counts.events`): past them
    /// `run` stops short and `halted` says so.
    pub fn limit_events(&mut self, events: u64) {
        self.event_limit = events;
    }

    /// Run until `stop`, taking samples on the way; short of it if the clock
    /// stalls or the event limit is spent (see `halted`).
    pub fn run(&mut self, stop: Stop) {
        if self.halt.is_some() {
            return;
        }
        let end_collisions = match stop {
            Stop::Collisions(n) => self.counts.collisions.saturating_add(n),
            Stop::Time(_) => u64::MAX,
        };
        let end_absolute = match stop {
            Stop::Time(t) => t,
            Stop::Collisions(_) => f64::INFINITY,
        };
        let ask_ahead = worth_asking_ahead(self.particles.len());
        loop {
            // Relative to the current origin, which a rebase moves.
            let end_time = end_absolute - self.origin;
            let (i, t) = self.queue.peek().unwrap_or((0, f64::INFINITY));
            if let Some(ts) = self.next_sample_time()
                && ts <= t
                && ts <= end_time
            {
                self.take_sample(ts);
                continue;
            }
            if t > end_time || self.counts.collisions >= end_collisions || t.is_infinite() {
                if t.is_infinite()
                    && end_time.is_infinite()
                    && self.counts.collisions < end_collisions
                {
                    self.halt = Some(Halt::Still {
                        collisions: self.counts.collisions,
                    });
                }
                break;
            }
            // A clock that does not move on (or is not a number) is counted;
            // one compare per event while it moves.
            if t > self.now {
                self.same_instant = 0;
            } else {
                self.same_instant += 1;
                if self.same_instant >= self.stall_after {
                    self.halt = Some(Halt::Stalled {
                        time: self.origin + t,
                        events: self.same_instant,
                    });
                    break;
                }
            }
            if self.counts.events >= self.event_limit {
                self.halt = Some(Halt::Spent {
                    limit: self.event_limit,
                    collisions: self.counts.collisions,
                });
                break;
            }
            self.now = t;
            self.handle(i);
            // The next event is almost always the queue's front now: start
            // loading what it will read while this loop iteration finishes.
            if let Some((i, t)) = self.queue.peek() {
                prefetch(self.queue.what(i));
                prefetch(&self.particles[i]);
                self.neighbours.prefetch(i, Read::Soon);
                if ask_ahead {
                    self.ask_ahead(i, t);
                }
            }
            self.events_since_rebase += 1;
            if self.events_since_rebase >= self.rebase_every {
                self.rebase();
            }
        }
        self.stamp_partners();
        self.neighbours.catch_up();
        if end_absolute.is_finite() && self.halt.is_none() {
            self.now = end_absolute - self.origin;
        }
    }

    fn next_sample_time(&self) -> Option<f64> {
        self.sample_every
            .map(|dt| self.sample_start + self.samples_taken as f64 * dt - self.origin)
    }

    fn take_sample(&mut self, t: f64) {
        self.now = t;
        self.samples_taken += 1;
        self.counts.samples += 1;
        let snapshot = Snapshot {
            time: self.time(),
            now: self.now,
            particles: &self.particles,
            sim_box: &self.sim_box,
        };
        self.observer.sample(&snapshot);
    }

    /// In a system far larger than the caches, a pipeline one event deep: for
    /// the next event (particle i at time t, whose own records were asked
    /// for an event ago) ask for what its second stage will read (its
    /// partner's records and its own partners' bodies, or the cells of its
    /// renewal); for the one after it, its records. All of it into L2 only,
    /// so that it holds none of the core's L1 miss buffers (`Read::Later`).
    fn ask_ahead(&mut self, i: usize, t: f64) {
        match self.next(i) {
            Next::Pair { j, .. } => {
                let j = j as usize;
                // The collision moves j's stamp on and reschedules j.
                prefetch_for(self.queue.what(j), Read::Later);
                prefetch_for(&self.particles[j], Read::Later);
                self.neighbours.prefetch(j, Read::Later);
                for (k, _) in self.neighbours.candidates(i) {
                    prefetch_for(&self.particles[k], Read::Later);
                }
            }
            Next::Renew => self.neighbours.prefetch_renewal(i, &self.particles[i], t),
            _ => {}
        }
        if let Some(k) = self.queue.peek_second() {
            prefetch_for(self.queue.what(k), Read::Later);
            prefetch_for(&self.particles[k], Read::Later);
            self.neighbours.prefetch(k, Read::Later);
        }
    }

    /// Apply particle i's scheduled event, which is due now.
    fn handle(&mut self, i: usize) {
        self.counts.events += 1;
        self.stamp_partners();
        self.neighbours.catch_up();
        match self.next(i) {
            Next::Pair { j, stamp, image } => {
                if Next::same_stamp(stamp, self.stamp(j as usize)) {
                    self.collide(i, j as usize, image);
                } else {
                    self.counts.stale += 1;
                    self.predict(i);
                }
            }
            Next::Wall { axis, high } => self.hit_wall(i, axis as usize, high),
            Next::Renew => {
                self.counts.renewals += 1;
                let bodies = worth_asking_ahead(self.particles.len())
                    .then(|| Lines::of(self.particles.bodies()));
                if self
                    .neighbours
                    .renew(i, &mut self.particles[i], self.now, bodies)
                {
                    // The stored position jumped by a box length: partners'
                    // predictions used the old image, so they must be redone.
                    self.move_stamp_on(i);
                }
                self.predict(i);
            }
            Next::Nothing => self.schedule(i, f64::INFINITY),
        }
    }

    fn collide(&mut self, i: usize, j: usize, image: Image) {
        let now = self.now;
        if worth_asking_ahead(self.particles.len()) {
            // j's list was asked for an event ago: its partners' bodies load
            // while the collision is done and i is predicted.
            for (k, _) in self.neighbours.candidates(j) {
                prefetch_for(&self.particles[k], Read::Later);
            }
        }
        self.particles[i].advance_to(now);
        self.particles[j].advance_to(now);
        let (p, q) = (&self.particles[i], &self.particles[j]);
        let r = separation(&p.pos, &q.pos, image, &self.shifts, N::PLANES);
        let dist = norm2(&r).sqrt();
        // On a line the side is known from the chain order, even for point
        // rods in contact (no separation to take a direction from).
        let normal = if D == 1 {
            Some([line_side(i, j, image); D])
        } else if dist > 0.0 {
            Some(std::array::from_fn(|k| r[k] / dist))
        } else {
            None
        };
        if let Some(n) = normal
            && let Some(b) = bounce(
                &p.vel,
                &q.vel,
                self.particles.inv_mass(i),
                self.particles.inv_mass(j),
                &n,
            )
        {
            for k in 0..D {
                self.particles[i].vel[k] += b.dv_i[k];
                self.particles[j].vel[k] += b.dv_j[k];
            }
            self.counts.collisions += 1;
            let event = PairCollision {
                time: self.time(),
                i,
                j,
                impulse_i: b.impulse_i,
                separation: r,
            };
            self.observer.pair_collision(&event);
        }
        self.move_stamp_on(i);
        self.move_stamp_on(j);
        // j's list and centre load while i is predicted.
        self.neighbours.prefetch(j, Read::Soon);
        self.predict(i);
        self.predict(j);
    }

    fn hit_wall(&mut self, i: usize, axis: usize, high: bool) {
        let now = self.now;
        let inv_mass = self.particles.inv_mass(i);
        let p = &mut self.particles[i];
        p.advance_to(now);
        let outward = if high { 1.0 } else { -1.0 };
        if p.vel[axis] * outward > 0.0
            && let Some(wall) = self.sim_box.axes[axis].wall(high)
        {
            let before = p.vel;
            match wall {
                Wall::Hard => p.vel[axis] = -p.vel[axis],
                Wall::Thermal { temperature } => {
                    p.vel =
                        thermal::emit::<D>(&mut self.rng, temperature, inv_mass, axis, -outward);
                }
            }
            let m = 1.0 / inv_mass;
            let impulse = std::array::from_fn(|k| m * (p.vel[k] - before[k]));
            let energy_gain = 0.5 * m * (norm2(&p.vel) - norm2(&before));
            self.counts.wall_hits += 1;
            let event = WallHit {
                time: self.time(),
                i,
                axis,
                high,
                impulse,
                energy_gain,
            };
            self.observer.wall_hit(&event);
        }
        self.move_stamp_on(i);
        self.predict(i);
    }

    /// Find particle i's earliest event and put it in the queue.
    fn predict(&mut self, i: usize) {
        let now = self.now;
        let p = &self.particles[i];
        let radius = self.particles.radius(i);
        let mut best_t = f64::INFINITY;
        let mut best = Next::Nothing;
        for k in 0..D {
            if !self.neighbours.can_reach_wall(i, p.vel[k] > 0.0) {
                continue;
            }
            if let Some((dt, high)) = wall_time(
                p.pos[k],
                p.vel[k],
                radius,
                self.sim_box.size[k],
                &self.sim_box.axes[k],
            ) {
                let t = (p.t + dt).max(now);
                if t < best_t {
                    best_t = t;
                    best = Next::Wall {
                        axis: k as u8,
                        high,
                    };
                }
            }
        }
        // Partners' bodies lie scattered in memory: ask for all of them
        // first, so that their cache misses overlap. (This particle's
        // calendar record is in cache: its event was read from it.)
        if self.prefetch_partners {
            for (j, _) in self.neighbours.candidates(i) {
                prefetch(&self.particles[j]);
            }
        }
        // Once the system outgrows the caches, the winner's stamp is left to
        // `stamp_partners`, so that no prediction waits on its line.
        let stamps = (!self.prefetch_partners).then_some(&self.queue);
        let x_i = p.position_at(now);
        if D == 1 {
            for (j, image) in self.neighbours.candidates(i) {
                let q = &self.particles[j];
                let gap = q.position_at(now)[0] + self.shifts[image as usize][0] - x_i[0];
                let dt = line_contact_time(
                    gap,
                    p.vel[0] - q.vel[0],
                    line_side(i, j, image),
                    radius + self.particles.radius(j),
                );
                if let Some(t) = dt.map(|dt| now + dt)
                    && t < best_t
                {
                    best_t = t;
                    best = pair_with(j, image, stamps);
                }
            }
        } else {
            // Everything the gather reads, as plain slices: their lengths and
            // addresses stay in registers while the batch is written.
            let (bodies, shifts) = (&self.particles, &self.shifts[..]);
            let particles = bodies.bodies();
            let batch = &mut self.batch;
            let mut candidates = self.neighbours.candidates(i);
            loop {
                let mut m = 0;
                for (j, image) in candidates.by_ref().take(BATCH) {
                    let q = &particles[j];
                    let r = separation(&x_i, &q.position_at(now), image, shifts, N::PLANES);
                    let v = sub(&q.vel, &p.vel);
                    // A plane moves along axis 0 only, and only that part of the
                    // other's motion brings them together.
                    let v = if N::PLANES && image == PLANE {
                        axis0(&v)
                    } else {
                        v
                    };
                    batch.put(m, (j, image), &r, &v, radius + bodies.radius(j), q.due);
                    m += 1;
                }
                if m > 0
                    && let Some((j, image)) = batch.earliest(m, now, &mut best_t)
                {
                    best = pair_with(j, image, stamps);
                }
                if m < BATCH {
                    break;
                }
            }
        }
        // The renewal, last: a particle still inside its neighbourhood when
        // its best event falls due renews later, and its renewal time (a
        // square root and a division) is not needed. It wins a tie with a
        // collision, loses one with a wall.
        let collision = matches!(best, Next::Pair { .. });
        if !(best_t.is_finite() && self.neighbours.inside_at(i, p, best_t))
            && let Some(t) = self.neighbours.next_renewal(i, p)
        {
            let t = t.max(now);
            if t < best_t || (collision && t == best_t) {
                best_t = t;
                best = Next::Renew;
            }
        }
        if let Next::Pair { j, .. } = best
            && self.prefetch_partners
        {
            prefetch(self.queue.what(j as usize));
            self.unstamped.push(i as u32);
        }
        self.queue.what_mut(i).next = Packed::pack(best);
        self.schedule(i, best_t);
    }

    /// Give each collision predicted since the last call its partner's
    /// stamp. Stamps move on only when an event is handled, so this is the
    /// stamp the prediction saw.
    fn stamp_partners(&mut self) {
        for &i in &self.unstamped {
            let i = i as usize;
            if let Next::Pair { j, image, .. } = self.next(i) {
                self.queue.what_mut(i).next = Packed::pack(Next::Pair {
                    j,
                    stamp: self.stamp(j as usize),
                    image,
                });
            }
        }
        self.unstamped.clear();
    }

    /// What particle i has scheduled.
    #[inline(always)]
    fn next(&self, i: usize) -> Next {
        self.queue.what(i).next.unpack()
    }

    #[inline(always)]
    fn stamp(&self, i: usize) -> u32 {
        self.queue.what(i).stamp
    }

    /// Particle i's motion changed: predictions that used the old one are stale.
    #[inline(always)]
    fn move_stamp_on(&mut self, i: usize) {
        let stamp = &mut self.queue.what_mut(i).stamp;
        *stamp = stamp.wrapping_add(1);
    }

    /// Put i's next event at time t in the queue, and in i's body, where a
    /// prediction reads it for every partner.
    #[inline(always)]
    fn schedule(&mut self, i: usize, t: f64) {
        self.particles[i].due = t;
        self.queue.set(i, t);
    }

    /// Move the time origin to now: every particle is brought to the present
    /// and all times shift, so `now - t` never loses digits to a large `now`.
    fn rebase(&mut self) {
        let now = self.now;
        for p in self.particles.bodies_mut() {
            p.advance_to(now);
            p.t = 0.0;
            p.due -= now;
        }
        self.queue.rebase(now);
        self.origin += now;
        self.now = 0.0;
        self.events_since_rebase = 0;
    }

    /// The deepest overlap among all pairs, as a fraction of their contact
    /// distance (0 when none overlap). O(N) over neighbour cells; for tests.
    pub fn max_overlap(&self) -> f64 {
        let mut worst: f64 = 0.0;
        for (i, p) in self.particles.bodies().iter().enumerate() {
            let x_i = p.position_at(self.now);
            for (j, image) in self.neighbours.candidates(i) {
                let q = &self.particles[j];
                let x_j = q.position_at(self.now);
                let r = separation(&x_i, &x_j, image, &self.shifts, N::PLANES);
                let sigma = self.particles.radius(i) + self.particles.radius(j);
                if sigma > 0.0 {
                    worst = worst.max(1.0 - dot(&r, &r).sqrt() / sigma);
                }
            }
        }
        worst
    }

    /// How far any particle sits outside a wall, in diameters (0 when none).
    pub fn max_wall_violation(&self) -> f64 {
        let mut worst: f64 = 0.0;
        for (i, p) in self.particles.bodies().iter().enumerate() {
            let x = p.position_at(self.now);
            let radius = self.particles.radius(i);
            // A plane spans every axis but 0.
            for k in 0..if self.particles.is_plane(i) { 1 } else { D } {
                if !self.sim_box.axes[k].is_periodic() {
                    let out = (radius - x[k]).max(x[k] + radius - self.sim_box.size[k]);
                    worst = worst.max(out / (2.0 * radius).max(1e-300));
                }
            }
        }
        worst
    }

    /// The no-shift image code, for callers building their own pair geometry.
    pub fn identity_image() -> Image {
        no_shift::<D>()
    }
}

/// See [`Simulation::degrees_of_freedom`]; `particles` a slice of them or
/// a [`Bodies`].
pub fn degrees_of_freedom<const D: usize, P: Borrow<Particle<D>>>(
    particles: impl IntoIterator<Item = P>,
    sim_box: &SimBox<D>,
) -> f64 {
    let (mut free, mut movable, mut anchored) = (0usize, 0usize, false);
    for p in particles {
        let p = p.borrow();
        if p.is_immovable() {
            anchored = true;
        } else {
            movable += 1;
            free += if p.is_plane() { 1 } else { D };
        }
    }
    let conserved = if anchored || movable == 0 {
        0
    } else {
        sim_box.axes.iter().filter(|a| a.is_periodic()).count()
    };
    free.saturating_sub(conserved) as f64
}

/// Whether a system of `n` particles has outgrown the caches enough for
/// predictions to ask for their partners' records ahead: measured with
/// spheres at packing 0.45 on a machine with 1 MiB of L2 per core, asking
/// costs 1 % at N = 4,000 and saves 1 % at 8,788 and 5 % from 16,384 on.
pub(super) fn worth_prefetching(n: usize) -> bool {
    n >= 6000
}

/// Whether a system of `n` particles is large enough for the event loop to
/// ask one event ahead (`ask_ahead`): measured with spheres at packing 0.30,
/// it saves about 10 % at N = 10^6 and, since a renewal's search reuses the
/// cells worked out for it, 12 % at 256,000; at 32,000, whose state fits in
/// this machine's 32 MiB of L3, it is flat.
fn worth_asking_ahead(n: usize) -> bool {
    n >= 200_000
}

/// A collision with j as it is now: its stamp read from `stamps`, or
/// (without) filled in by `stamp_partners`.
#[inline(always)]
fn pair_with(j: usize, image: Image, stamps: Option<&EventQueue<Event>>) -> Next {
    Next::Pair {
        j: j as u32,
        stamp: stamps.map_or(0, |q| q.what(j).stamp),
        image,
    }
}

/// In 1D: +1 if j is i's right-hand neighbour in the chain, -1 if left
/// (image codes: 0 one box left, 1 none, 2 one box right).
#[inline(always)]
fn line_side(i: usize, j: usize, image: Image) -> f64 {
    if image == 2 || (image == 1 && j > i) {
        1.0
    } else {
        -1.0
    }
}
