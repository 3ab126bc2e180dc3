//! One run: scene -> dynamics -> observers -> analyses -> RunOutput.
//!
//! The run loop (`simulate`) is written once against `engine::Dynamics`;
//! which integrator moves the particles is decided by the factory the
//! dimension picks (`rods` or `balls`), and nowhere else.

use crate::engine::{Chain, Dynamics, NeighbourList, Neighbourhood, Simulation, Stop};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::observe::{self, Context, ObserverSet};
use crate::scene;
use crate::studies::{self, Start};
use anyhow::{Context as _, anyhow, bail};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

/// Simulate one planned run. Errors are recorded in `runs.parquet` with the run.
pub fn run(spec: &RunSpec) -> anyhow::Result<RunOutput> {
    let scene = scene::resolve(&spec.descriptor.scene).map_err(|e| anyhow!(e))?;
    match scene.dimension().map_err(|e| anyhow!(e))? {
        1 => simulate::<1>(spec, &scene, rods),
        2 => simulate::<2>(spec, &scene, balls::<2>),
        3 => simulate::<3>(spec, &scene, balls::<3>),
        d => bail!("scene.dimension = {d}; use 1, 2 or 3"),
    }
}

/// What moves a run's particles, seen through the trait only.
type Engine<const D: usize> = Box<dyn Dynamics<D, ObserverSet<D>>>;

/// Builds the dynamics of a built scene, given its observers and the seed of
/// its random stream (thermal walls).
type Factory<const D: usize> =
    fn(&scene::Built<D>, ObserverSet<D>, u64) -> anyhow::Result<Engine<D>>;

/// Rods: the event-driven engine with a chain of neighbours.
fn rods(
    built: &scene::Built<1>,
    observers: ObserverSet<1>,
    seed: u64,
) -> anyhow::Result<Engine<1>> {
    event_driven::<1, Chain>(built, observers, seed)
}

/// Disks and spheres: the event-driven engine with neighbour lists, with
/// plane support only for scenes with a piston wall (others pay nothing for it).
fn balls<const D: usize>(
    built: &scene::Built<D>,
    observers: ObserverSet<D>,
    seed: u64,
) -> anyhow::Result<Engine<D>> {
    if built.particles.iter().any(|p| p.is_plane()) {
        event_driven::<D, NeighbourList<D, true>>(built, observers, seed)
    } else {
        event_driven::<D, NeighbourList<D>>(built, observers, seed)
    }
}

fn event_driven<const D: usize, N: Neighbourhood<D> + 'static>(
    built: &scene::Built<D>,
    observers: ObserverSet<D>,
    seed: u64,
) -> anyhow::Result<Engine<D>> {
    let sim: Simulation<D, N, ObserverSet<D>> =
        Simulation::new(built.particles.clone(), built.sim_box, observers, seed)
            .context("the scene cannot be simulated")?;
    Ok(Box::new(sim))
}

fn simulate<const D: usize>(
    spec: &RunSpec,
    scene: &crate::model::scene::SceneSpec,
    factory: Factory<D>,
) -> anyhow::Result<RunOutput> {
    let started = Instant::now();
    // One stream per run: the scene draws from it first, then the engine's
    // thermal walls get a seed drawn from it.
    let mut rng = ChaCha8Rng::seed_from_u64(spec.seed);
    let built = scene::build::<D>(scene, &mut rng).map_err(|e| anyhow!("scene: {e}"))?;
    let d = &spec.descriptor;
    let mut series = d.observe.series.clone();
    for name in studies::series(d) {
        if !series.iter().any(|s| s == name) {
            series.push(name.to_string());
        }
    }
    let observers: ObserverSet<D> = observe::build(
        &series,
        &d.observe.scalars,
        &d.observe.histograms,
        built.piston,
    )
    .map_err(|e| anyhow!("observe: {e}"))?;
    let engine_seed = rand::RngExt::random::<u64>(&mut rng);
    let mut sim = factory(&built, observers, engine_seed)?;

    let equilibrate = d.run.equilibrate;
    if equilibrate > 0.0 {
        sim.advance(Stop::Time(equilibrate));
    }
    let start = sim.time();
    let energy0 = sim.kinetic_energy();
    sim.observer_mut().recording = true;
    sim.sample_every(d.run.sample_every);
    let stop = match (d.run.duration, d.run.collisions) {
        (Some(t), _) => Stop::Time(start + t),
        (None, Some(n)) => Stop::Collisions(n),
        (None, None) => bail!("[run] needs `duration` or `collisions`"),
    };
    sim.advance(stop);
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
    sim.into_observer().finish(&ctx, &mut out);
    if !thermal {
        out.scalars.push((
            "energy_drift".into(),
            (energy1 - energy0).abs() / energy0.max(f64::MIN_POSITIVE),
        ));
    }
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
    out.wall_seconds = started.elapsed().as_secs_f64();
    Ok(out)
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
