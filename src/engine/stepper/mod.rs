//! The Imperial project's fixed-step integrator, beside the exact engine:
//! every particle moves by dt, then whatever overlaps a wall or another
//! particle is bounced (only if approaching, the seeds' fix for sticking).
//! It drives the same observers through [`Dynamics`], reporting each step's
//! bounces at the step's end, so every observable and study runs on it and
//! its error can be measured against the exact engine's. Pairs come from a
//! cell list rebuilt each step (no all-pairs loop), particles are stored as
//! the engine stores them.

mod cells;
mod step;
mod tally;

use super::bodies::Bodies;
use super::boundary::SimBox;
use super::build::{BuildError, validate};
use super::dynamics::Dynamics;
use super::halt::Halt;
use super::observer::{Observer, Snapshot};
use super::particle::Particle;
use super::simulation::{Counts, Stop, degrees_of_freedom};
use cells::Cells;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use tally::Tally;

/// A fixed-step system of hard balls (rods, disks, spheres; no planes).
#[derive(Debug, Clone)]
pub struct Stepper<const D: usize, O: Observer<D>> {
    particles: Vec<Particle<D>>,
    sim_box: SimBox<D>,
    dt: f64,
    approach_check: bool,
    /// Absolute time; every particle's `pos` holds at it (`t` stays 0).
    time: f64,
    cells: Cells<D>,
    found: Vec<(usize, usize, [f64; D])>,
    tally: Tally,
    rng: ChaCha8Rng,
    counts: Counts,
    sample_every: Option<f64>,
    sample_start: f64,
    samples_taken: u64,
    /// The particles as a snapshot shows them, refreshed at each sample.
    view: Bodies<D>,
    /// Events (particle moves) allowed in all, and whether they ran out.
    event_limit: u64,
    halt: Option<Halt>,
    observer: O,
}

impl<const D: usize, O: Observer<D>> Stepper<D, O> {
    /// A system at time 0 stepping by `dt`; `approach_check` false is the
    /// seeds' version with the sticking bug. `seed` feeds thermal walls.
    pub fn new(
        mut particles: Vec<Particle<D>>,
        sim_box: SimBox<D>,
        observer: O,
        seed: u64,
        dt: f64,
        approach_check: bool,
    ) -> Result<Self, BuildError> {
        validate(&mut particles, &sim_box)?;
        if !(dt.is_finite() && dt > 0.0) {
            return Err(BuildError(format!(
                "the fixed step dt is {dt}; it must be a positive finite number"
            )));
        }
        if let Some(i) = particles.iter().position(Particle::is_plane) {
            return Err(BuildError(format!(
                "particle {i} is a plane (a 2D/3D piston); the fixed-step integrator moves balls only: \
                 use `integrator = \"exact\"` for it"
            )));
        }
        if let Some(i) = particles.iter().position(|p| p.radius <= 0.0) {
            return Err(BuildError(format!(
                "particle {i} has radius 0; the fixed-step integrator finds collisions by overlap, \
                 which point particles never show: give every particle a radius > 0"
            )));
        }
        let reach = 2.0 * particles.iter().map(|p| p.radius).fold(0.0, f64::max);
        for k in 0..D {
            if sim_box.axes[k].is_periodic() && sim_box.size[k] <= 2.0 * reach {
                return Err(BuildError(format!(
                    "periodic axis {k} is {} long; the fixed-step integrator needs it longer than two \
                     contact distances ({}) so that each pair has one nearest image",
                    sim_box.size[k],
                    2.0 * reach
                )));
            }
        }
        for p in &mut particles {
            p.t = 0.0;
        }
        let n = particles.len();
        Ok(Stepper {
            cells: Cells::new(&sim_box, reach, n),
            particles,
            sim_box,
            dt,
            approach_check,
            time: 0.0,
            found: Vec::new(),
            tally: Tally::default(),
            rng: ChaCha8Rng::seed_from_u64(seed),
            counts: Counts::default(),
            event_limit: u64::MAX,
            halt: None,
            sample_every: None,
            sample_start: 0.0,
            samples_taken: 0,
            view: Bodies::default(),
            observer,
        })
    }

    pub fn particles(&self) -> &[Particle<D>] {
        &self.particles
    }

    /// Take every sample due before `until` (exclusive), or up to and
    /// including it when `inclusive`.
    fn samples_before(&mut self, until: f64, inclusive: bool) {
        let Some(every) = self.sample_every else {
            return;
        };
        loop {
            let ts = self.sample_start + self.samples_taken as f64 * every;
            if ts > until || (ts == until && !inclusive) {
                return;
            }
            self.samples_taken += 1;
            self.counts.samples += 1;
            // Particles sit at `time`; `now` is the sample's offset from it
            // (free flight until the step resolves its bounces).
            self.view.refresh(&self.particles);
            let snapshot = Snapshot {
                time: ts,
                now: ts - self.time,
                particles: &self.view,
                sim_box: &self.sim_box,
            };
            self.observer.sample(&snapshot);
        }
    }
}

impl<const D: usize, O: Observer<D>> Dynamics<D, O> for Stepper<D, O> {
    fn advance(&mut self, stop: Stop) {
        let (end, collisions) = match stop {
            Stop::Time(t) => (t, u64::MAX),
            Stop::Collisions(n) => (f64::INFINITY, self.counts.collisions.saturating_add(n)),
        };
        while self.time < end && self.counts.collisions < collisions {
            if self.counts.events >= self.event_limit {
                self.halt = Some(Halt::Spent {
                    limit: self.event_limit,
                    collisions: self.counts.collisions,
                });
                break;
            }
            // The last step is shortened to land on `end` exactly; one that
            // would leave a sliver of a step takes the sliver along.
            let next = self.time + self.dt;
            let to = if end - next <= 1e-9 * self.dt {
                end
            } else {
                next
            };
            self.samples_before(to, false);
            self.step(to);
        }
        self.samples_before(self.time, true);
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn halted(&self) -> Option<Halt> {
        self.halt
    }

    fn limit_events(&mut self, events: u64) {
        self.event_limit = events;
    }

    fn kinetic_energy(&self) -> f64 {
        self.particles.iter().map(Particle::kinetic_energy).sum()
    }

    fn degrees_of_freedom(&self) -> f64 {
        degrees_of_freedom(&self.particles, &self.sim_box)
    }

    fn counts(&self) -> Counts {
        self.counts
    }

    fn sim_box(&self) -> &SimBox<D> {
        &self.sim_box
    }

    fn sample_every(&mut self, every: Option<f64>) {
        self.sample_every = every.filter(|dt| *dt > 0.0 && dt.is_finite());
        self.sample_start = self.time;
        self.samples_taken = 0;
    }

    fn observer_mut(&mut self) -> &mut O {
        &mut self.observer
    }

    fn into_observer(self: Box<Self>) -> O {
        self.observer
    }

    fn diagnostics(&self) -> Vec<(&'static str, f64)> {
        self.tally.scalars(self.dt)
    }
}
