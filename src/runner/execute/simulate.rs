//! One run: scene -> dynamics -> observers -> analyses -> RunOutput.
//!
//! The run loop (`simulate`) is written once against `engine::Dynamics`;
//! which integrator moves the particles is decided by `[run] integrator`
//! and the dimension (`exact`), and nowhere else. When the runner
//! gives the run a checkpoint place (`checkpoint.rs`), the loop advances in
//! short stretches and saves the run's state every few minutes of wall time,
//! and a run that finds its checkpoint continues from it. A stretch ends at
//! a time or a collision count, which the engine resumes from exactly as if
//! it had not stopped, so the results are the same bit for bit.

use crate::engine::{Chain, Dynamics, NeighbourList, Particle, Persist, Simulation, Stepper, Stop};
use crate::model::descriptor::{Integrator, RunSection};
use crate::model::dimension::{ForDimension, in_dimension};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::observe::{self, Context, ObserverSet};
use crate::runner::execute::checkpoint::{self, Phase, Place, Saved};
use crate::runner::execute::cpu_time::thread_cpu_seconds;
use crate::scene;
use crate::studies::{self, Start};
use anyhow::{Context as _, anyhow, bail};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::time::{Duration, Instant};

/// Simulate one planned run. Errors are recorded in `runs.parquet` with the run.
pub fn run(spec: &RunSpec) -> anyhow::Result<RunOutput> {
    let scene = scene::resolve(&spec.descriptor.scene).map_err(|e| anyhow!(e))?;
    let d = scene.dimension().map_err(|e| anyhow!(e))?;
    in_dimension(
        d,
        Simulate {
            spec,
            scene: &scene,
        },
    )
    .map_err(|e| anyhow!(e))?
}

/// One run in the dimension of its scene.
struct Simulate<'a> {
    spec: &'a RunSpec,
    scene: &'a crate::model::scene::SceneSpec,
}

impl ForDimension for Simulate<'_> {
    type Output = anyhow::Result<RunOutput>;
    fn run<const D: usize>(self) -> Self::Output {
        simulate::<D>(self.spec, self.scene)
    }
}

/// What moves a run's particles, seen through the trait only, and able to
/// save its full state for a checkpoint.
pub trait Checkpointable<const D: usize>: Dynamics<D, ObserverSet<D>> {
    /// The full state in the engine's save format (`engine::save`).
    fn save_state(&self) -> std::io::Result<Vec<u8>>;
    /// False for dynamics without a save format: their runs are not
    /// checkpointed (a rerun starts them over).
    fn can_save(&self) -> bool {
        true
    }
}

/// The fixed-step method has no save format: its runs are short (it is the
/// accuracy study's yardstick) and start over when interrupted.
impl<const D: usize> Checkpointable<D> for Stepper<D, ObserverSet<D>> {
    fn save_state(&self) -> std::io::Result<Vec<u8>> {
        Err(std::io::Error::new(
            std::io::ErrorKind::Unsupported,
            "a fixed-step run has no save format",
        ))
    }
    fn can_save(&self) -> bool {
        false
    }
}

impl<const D: usize, N: Persist<D>> Checkpointable<D> for Simulation<D, N, ObserverSet<D>> {
    fn save_state(&self) -> std::io::Result<Vec<u8>> {
        let mut bytes = Vec::new();
        self.save(&mut bytes)?;
        Ok(bytes)
    }
}

type Engine<const D: usize> = Box<dyn Checkpointable<D>>;

/// What a run's dynamics are built from: its particles (the scene's own, a
/// copy, or none when continuing), the built scene, its observers, the seed
/// of its random stream (thermal walls), and the saved state to continue.
struct Parts<'a, const D: usize> {
    particles: Vec<Particle<D>>,
    built: &'a scene::Built<D>,
    observers: ObserverSet<D>,
    seed: u64,
    saved: Option<&'a [u8]>,
}

/// The integrator `[run]` asks for: a fixed step, or the exact engine
/// (which alone continues a saved state).
fn dynamics<const D: usize>(run: &RunSection, parts: Parts<D>) -> anyhow::Result<Engine<D>> {
    let approach_check = match run.integrator {
        Integrator::Exact => return exact(parts),
        Integrator::FixedStep => true,
        Integrator::FixedStepNaive => false,
    };
    if parts.saved.is_some() {
        bail!("a fixed-step run cannot continue from a checkpoint");
    }
    let dt = run
        .dt
        .ok_or_else(|| anyhow!("`run.dt`: a fixed step needs its length"))?;
    let stepper = Stepper::new(
        parts.particles,
        parts.built.sim_box,
        parts.observers,
        parts.seed,
        dt,
        approach_check,
    )
    .context("the scene cannot be stepped")?;
    Ok(Box::new(stepper))
}

/// The event-driven engine: rods with a chain of neighbours; disks and
/// spheres with neighbour lists, with plane support only for scenes with a
/// piston wall (others pay nothing for it).
fn exact<const D: usize>(parts: Parts<D>) -> anyhow::Result<Engine<D>> {
    if D == 1 {
        event_driven::<D, Chain>(parts)
    } else if parts.built.piston.is_some() {
        event_driven::<D, NeighbourList<D, true>>(parts)
    } else {
        event_driven::<D, NeighbourList<D>>(parts)
    }
}

fn event_driven<const D: usize, N: Persist<D> + 'static>(
    parts: Parts<D>,
) -> anyhow::Result<Engine<D>> {
    let sim: Simulation<D, N, ObserverSet<D>> = match parts.saved {
        Some(mut bytes) => Simulation::load(&mut bytes, parts.observers)
            .map_err(|e| anyhow!("the checkpoint cannot be continued: {e}"))?,
        None => Simulation::new(
            parts.particles,
            parts.built.sim_box,
            parts.observers,
            parts.seed,
        )
        .context("the scene cannot be simulated")?,
    };
    Ok(Box::new(sim))
}

/// Where a run stops: a simulation time, or a total collision count.
#[derive(Clone, Copy)]
enum Target {
    Time(f64),
    Collisions(u64),
}

/// A run's checkpointing: where, since when, and what it had spent before.
struct Clock {
    place: Option<Place>,
    last_save: Instant,
    started: Instant,
    cpu_started: f64,
    wall_before: f64,
    cpu_before: f64,
}

impl Clock {
    fn wall(&self) -> f64 {
        self.wall_before + self.started.elapsed().as_secs_f64()
    }
}

/// Advance to `target`: in one go without a checkpoint place; else in
/// stretches of about a tenth of the checkpoint interval (at most a second),
/// saving the run's state whenever the interval has passed.
fn advance<const D: usize>(
    sim: &mut Engine<D>,
    target: Target,
    phase: Phase,
    clock: &mut Clock,
) -> anyhow::Result<()> {
    let Some(every) = clock.place.as_ref().map(|p| p.every) else {
        sim.advance(match target {
            Target::Time(t) => Stop::Time(t),
            Target::Collisions(c) => Stop::Collisions(c.saturating_sub(sim.counts().collisions)),
        });
        return going_on(sim.as_ref());
    };
    let stretch = (every / 10).clamp(Duration::from_millis(2), Duration::from_secs(1));
    // Simulation time or collisions per stretch, adapted to take `stretch`.
    let mut span = match target {
        Target::Time(t) => (t - sim.time()) / 64.0,
        Target::Collisions(_) => 1000.0,
    };
    loop {
        let (stop, last) = match target {
            Target::Time(t) => {
                let next = sim.time() + span;
                if span > 0.0 && next < t && next > sim.time() {
                    (Stop::Time(next), false)
                } else {
                    (Stop::Time(t), true)
                }
            }
            Target::Collisions(c) => {
                let left = c.saturating_sub(sim.counts().collisions);
                let step = span.max(1.0) as u64;
                if step < left {
                    (Stop::Collisions(step), false)
                } else {
                    (Stop::Collisions(left), true)
                }
            }
        };
        let began = Instant::now();
        sim.advance(stop);
        going_on(sim.as_ref())?;
        if last {
            return Ok(());
        }
        let took = began.elapsed();
        if took < stretch / 2 {
            span *= 2.0;
        } else if took > stretch * 2 {
            span /= 2.0;
        }
        if clock.last_save.elapsed() >= every {
            save(sim, phase, clock)?;
            clock.last_save = Instant::now();
        }
    }
}

/// An error if the dynamics stopped short of their stop (a stalled clock,
/// the events allowed spent): the run fails with the reason.
fn going_on<const D: usize>(sim: &dyn Checkpointable<D>) -> anyhow::Result<()> {
    match sim.halted() {
        Some(halt) => bail!("the run cannot go on: {halt}"),
        None => Ok(()),
    }
}

/// Write the run's checkpoint; a run whose observers cannot be saved goes
/// on without checkpoints.
fn save<const D: usize>(
    sim: &mut Engine<D>,
    phase: Phase,
    clock: &mut Clock,
) -> anyhow::Result<()> {
    if !sim.can_save() {
        clock.place = None;
        return Ok(());
    }
    let Some(observers) = sim.observer_mut().save_state() else {
        clock.place = None;
        return Ok(());
    };
    let Some(place) = &clock.place else {
        return Ok(());
    };
    let saved = Saved {
        phase,
        wall_seconds: clock.wall(),
        cpu_seconds: clock.cpu_before + (thread_cpu_seconds() - clock.cpu_started),
        observers,
        engine: sim.save_state().context("cannot save the run's state")?,
    };
    checkpoint::write(place, &saved).context("cannot write the run's checkpoint")
}

/// The run's start: its scene drawn from the run's own stream, then the seed
/// of the engine's thermal walls drawn from the same stream.
pub(super) fn start<const D: usize>(
    spec: &RunSpec,
    scene: &crate::model::scene::SceneSpec,
) -> anyhow::Result<(scene::Built<D>, u64)> {
    let mut rng = ChaCha8Rng::seed_from_u64(spec.seed);
    let built = scene::build::<D>(scene, &mut rng).map_err(|e| anyhow!("scene: {e}"))?;
    Ok((built, rand::RngExt::random::<u64>(&mut rng)))
}

fn simulate<const D: usize>(
    spec: &RunSpec,
    scene: &crate::model::scene::SceneSpec,
) -> anyhow::Result<RunOutput> {
    let started = Instant::now();
    let (mut built, engine_seed) = start::<D>(spec, scene)?;
    let d = &spec.descriptor;
    let mut series = d.observe.series.clone();
    for name in studies::series(d) {
        if !series.iter().any(|s| s == name) {
            series.push(name.to_string());
        }
    }
    let observers = || -> anyhow::Result<ObserverSet<D>> {
        observe::build(
            &series,
            &d.observe.scalars,
            &d.observe.histograms,
            built.piston,
        )
        .map_err(|e| anyhow!("observe: {e}"))
    };
    let place = checkpoint::current();
    // A checkpoint that does not continue (damaged, other observers) is
    // ignored: the run starts over and overwrites it.
    let resumed = place.as_ref().and_then(checkpoint::read).and_then(|saved| {
        let mut set = observers().ok()?;
        set.restore_state(&saved.observers).ok()?;
        let parts = Parts {
            particles: Vec::new(), // the saved state has its own
            built: &built,
            observers: set,
            seed: engine_seed,
            saved: Some(&saved.engine),
        };
        let sim = dynamics(&d.run, parts).ok()?;
        Some((sim, saved))
    });
    let (mut sim, phase, wall_before, cpu_before) = match resumed {
        Some((sim, saved)) => {
            checkpoint::mark_continued();
            (sim, saved.phase, saved.wall_seconds, saved.cpu_seconds)
        }
        None => {
            // The studies read the start when the run is done. Without any,
            // the engine takes the scene's particles, not a copy of them: a
            // sphere's 80 bytes less for the whole run.
            let particles = if studies::named(d).next().is_none() {
                std::mem::take(&mut built.particles)
            } else {
                built.particles.clone()
            };
            let parts = Parts {
                particles,
                built: &built,
                observers: observers()?,
                seed: engine_seed,
                saved: None,
            };
            let sim = dynamics(&d.run, parts)?;
            (sim, Phase::Equilibrating, 0.0, 0.0)
        }
    };
    let mut clock = Clock {
        place,
        last_save: Instant::now(),
        started,
        cpu_started: thread_cpu_seconds(),
        wall_before,
        cpu_before,
    };

    if d.run.duration.is_none() && d.run.collisions.is_none() {
        bail!("[run] needs `duration` or `collisions`");
    }
    let (start, energy0, end_collisions) = match phase {
        Phase::Measuring {
            start,
            energy0,
            end_collisions,
        } => (start, energy0, end_collisions),
        Phase::Equilibrating => {
            let equilibrate = d.run.equilibrate;
            if equilibrate > 0.0 {
                advance(&mut sim, Target::Time(equilibrate), phase, &mut clock)?;
            }
            let start = sim.time();
            let energy0 = sim.kinetic_energy();
            sim.observer_mut().recording = true;
            sim.sample_every(d.run.sample_every);
            let end = match d.run.collisions {
                Some(n) => sim.counts().collisions.saturating_add(n),
                None => 0,
            };
            (start, energy0, end)
        }
    };
    let target = match d.run.duration {
        Some(t) => Target::Time(start + t),
        None => {
            let left = end_collisions.saturating_sub(sim.counts().collisions);
            let budget = event_budget(d, left);
            sim.limit_events(sim.counts().events.saturating_add(budget));
            Target::Collisions(end_collisions)
        }
    };
    let measuring = Phase::Measuring {
        start,
        energy0,
        end_collisions,
    };
    advance(&mut sim, target, measuring, &mut clock)?;
    let duration = sim.time() - start;
    let counts = sim.counts();
    let mut out = RunOutput {
        events: counts.events,
        collisions: counts.collisions,
        ..Default::default()
    };
    let sim_box = *sim.sim_box();
    let volume = sim_box.volume();
    let ctx = Context {
        species: &built.species,
        piston: built.piston,
        duration,
        volume,
        wall_area: (0..D)
            .filter(|&k| !sim_box.axes[k].is_periodic())
            .map(|k| 2.0 * volume / sim_box.size[k])
            .sum(),
        dimension: D,
        degrees_of_freedom: sim.degrees_of_freedom(),
    };
    let energy1 = sim.kinetic_energy();
    let thermal = sim_box.has_thermal_walls();
    let diagnostics = sim.diagnostics();
    sim.into_observer().finish(&ctx, &mut out);
    if !thermal {
        out.scalars.push((
            "energy_drift".into(),
            (energy1 - energy0).abs() / energy0.max(f64::MIN_POSITIVE),
        ));
    }
    out.scalars
        .extend(diagnostics.into_iter().map(|(n, v)| (n.to_string(), v)));
    let finished = studies::Finished {
        descriptor: d,
        start: Start::of(&built),
        context: &ctx,
    };
    studies::per_run(&finished, &mut out).map_err(|e| anyhow!("analysis: {e}"))?;
    if !d.run.full_series {
        out.series.iter_mut().for_each(thin);
    }
    if let Some(prep) = &built.prepared {
        // The cost of compressing the start: collisions and density are
        // results (deterministic), its seconds a timing like the run's.
        out.scalars
            .push(("prepare_collisions".into(), prep.collisions as f64));
        out.scalars
            .push(("prepared_packing_fraction".into(), prep.phi));
        out.prepare_seconds = prep.seconds;
    }
    out.wall_seconds = clock.wall();
    // The runner adds what this thread spent now.
    out.cpu_seconds = clock.cpu_before;
    Ok(out)
}

/// Events a run may take for `left` more pair collisions: a thousand times
/// the events per collision the estimate expects, and 10^9 (a few minutes)
/// more, so that a run whose pairs meet far more rarely than expected (or
/// never: two disks gliding side by side) fails instead of running forever.
fn event_budget(d: &crate::model::descriptor::Descriptor, left: u64) -> u64 {
    let per_collision = crate::runner::plan::estimate::run_cost(d)
        .map(|c| c.event_rate / c.rate)
        .filter(|r| r.is_finite())
        .unwrap_or(1.0)
        .max(1.0);
    // Saturates at u64::MAX.
    (1e9 + 1e3 * per_collision * left as f64) as u64
}

/// Most points kept per stored series. Analyses above saw every sample; the
/// stored table keeps an evenly strided subset so that long, finely sampled
/// runs do not swamp `series.parquet` (the sampling interval sets the
/// analyses' resolution, this only the plots').
pub const MAX_STORED_POINTS: usize = 4000;

fn thin(series: &mut crate::model::run_output::Series) {
    let n = series.t.len();
    if n <= MAX_STORED_POINTS {
        return;
    }
    let stride = n.div_ceil(MAX_STORED_POINTS);
    let keep = |v: &[f64]| v.iter().step_by(stride).copied().collect::<Vec<f64>>();
    series.t = keep(&series.t);
    series.value = keep(&series.value);
}
