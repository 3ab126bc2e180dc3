//! The seam between a run loop and whatever moves the particles. The run
//! loop (`runner::execute::simulate`) talks only to this trait, so a second integrator
//! (the fixed-step method of the accuracy study) plugs in beside the exact
//! event-driven engine without touching observers or studies.
//!
//! The trait is called a handful of times per run; the work happens inside
//! `advance`, which each implementation compiles with its own observer type
//! (static dispatch), so `dyn Dynamics` costs nothing per event.
//!
//! # What an implementation owes the observers
//! Observers see a run only through the [`Observer`] hooks, and they must get
//! the same kinds of events, with the same payloads, from any implementation:
//! - [`Observer::pair_collision`] once per pair collision actually applied
//!   (a pair that meets but does not approach is not a collision), after the
//!   velocities changed: `time` is absolute, `impulse_i` what `i` received
//!   (`j` got the opposite), `separation` is `r_j - r_i` at contact with the
//!   periodic image applied (for a plane, along axis 0 only). Each one adds
//!   one to `Counts::collisions`.
//! - [`Observer::wall_hit`] once per reflection from a wall (hard or thermal),
//!   after the velocity changed: `impulse` is what the particle received,
//!   `energy_gain` the kinetic energy it gained (0 at a hard wall). Each one
//!   adds one to `Counts::wall_hits`.
//! - [`Observer::sample`] at the times `s, s + dt, s + 2 dt, ...` set by
//!   [`Dynamics::sample_every`] (`s` is the time of that call; the first
//!   sample is at `s` itself), every one up to and including the time at
//!   which `advance` ends, none after it. The snapshot holds the state at exactly that time:
//!   `Snapshot::position` is `pos + (now - t) vel` per particle, so an
//!   implementation whose particles sit at an earlier step time `t` passes
//!   `now` = the sample time and gets free flight to it. Each one adds one to
//!   `Counts::samples`.
//!
//! All three in nondecreasing time order, interleaved: a sample at time `ts`
//! comes after every event before `ts` and before every event after it. A
//! method that resolves collisions at step ends (fixed step) reports them at
//! the step's end time; that is its error, measured against the exact
//! engine, not a break of the contract.

use super::boundary::SimBox;
use super::halt::Halt;
use super::neighbours::Neighbourhood;
use super::observer::Observer;
use super::simulation::{Counts, Simulation, Stop};

/// A system that moves hard particles forward in time and tells observer `O`
/// what happened (see the module documentation for what it must call, and
/// when).
pub trait Dynamics<const D: usize, O: Observer<D>> {
    /// Move forward until `stop`. `Stop::Time(t)` (absolute) must end with
    /// `time() == t` exactly, also when nothing happens on the way (the
    /// measured duration is `time()` after minus before). `Stop::Collisions(n)`
    /// ends once `n` more pair collisions were applied (exactly `n` for the
    /// event-driven engine; a stepper may overshoot within its last step).
    fn advance(&mut self, stop: Stop);

    /// Absolute simulation time.
    fn time(&self) -> f64;

    /// Total kinetic energy now (immovable particles have none).
    fn kinetic_energy(&self) -> f64;

    /// What temperature divides the kinetic energy by; implementations
    /// should use [`super::degrees_of_freedom`] so that all agree.
    fn degrees_of_freedom(&self) -> f64;

    /// What it cost so far. `collisions`, `wall_hits` and `samples` count the
    /// observer calls above; `events` is the implementation's unit of work
    /// (events handled by the event-driven engine, particle moves for a stepper),
    /// the cost the runs table reports.
    fn counts(&self) -> Counts;

    /// The box, walls and periodic axes included.
    fn sim_box(&self) -> &SimBox<D>;

    /// Sample every `every` time units from now on, the first sample now;
    /// `None` (or a step that is not finite and positive) stops sampling.
    fn sample_every(&mut self, every: Option<f64>);

    /// The observer, e.g. to switch its recording on after equilibration.
    fn observer_mut(&mut self) -> &mut O;

    /// Hand back the observer when the run is over.
    fn into_observer(self: Box<Self>) -> O;

    /// Why the last `advance` stopped short of its `Stop`, if it did (the
    /// clock stood still, or the events allowed were spent): such a run
    /// cannot go on. The default: never (a fixed step always moves its
    /// clock on; it halts only on its event limit).
    fn halted(&self) -> Option<Halt> {
        None
    }

    /// Allow at most `events` of `counts().events` in all; past them
    /// `advance` stops short and `halted` says so. The default allows any
    /// number.
    fn limit_events(&mut self, _events: u64) {}

    /// What this method measures about its own errors, as named scalars for
    /// the run's results (a stepper's overlaps, say); the exact engine has
    /// none.
    fn diagnostics(&self) -> Vec<(&'static str, f64)> {
        Vec::new()
    }
}

/// The exact event-driven engine. Each method forwards to the inherent one;
/// `advance` is `Simulation::run`, whose event loop is compiled for `N` and `O`.
impl<const D: usize, N: Neighbourhood<D>, O: Observer<D>> Dynamics<D, O> for Simulation<D, N, O> {
    fn advance(&mut self, stop: Stop) {
        self.run(stop);
    }

    fn time(&self) -> f64 {
        Simulation::time(self)
    }

    fn kinetic_energy(&self) -> f64 {
        Simulation::kinetic_energy(self)
    }

    fn degrees_of_freedom(&self) -> f64 {
        Simulation::degrees_of_freedom(self)
    }

    fn counts(&self) -> Counts {
        self.counts
    }

    fn sim_box(&self) -> &SimBox<D> {
        Simulation::sim_box(self)
    }

    fn sample_every(&mut self, every: Option<f64>) {
        Simulation::sample_every(self, every);
    }

    fn observer_mut(&mut self) -> &mut O {
        &mut self.observer
    }

    fn into_observer(self: Box<Self>) -> O {
        Simulation::into_observer(*self)
    }

    fn halted(&self) -> Option<Halt> {
        Simulation::halted(self)
    }

    fn limit_events(&mut self, events: u64) {
        Simulation::limit_events(self, events);
    }
}
