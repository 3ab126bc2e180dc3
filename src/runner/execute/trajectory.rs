//! `[observe] trajectory`: a chosen run filmed again from its start into
//! `OUT/trajectory-<run_id>.<gsd|xyz>`. Runs are deterministic, so this is
//! the measured run as it happened (the same scene, seed and engine, read at
//! exact frame times); a run that asks for no trajectory is never filmed.
//! The file is written under a temporary name and renamed when whole, so a
//! killed run leaves none and its rerun writes it again, byte for byte.

use crate::engine::{Chain, NeighbourList, Neighbourhood, Simulation, Stop};
use crate::model::dimension::{ForDimension, in_dimension};
use crate::model::run_spec::RunSpec;
use crate::model::scene::SceneSpec;
use crate::model::trajectory::{MAX_PARTICLE_FRAMES, TrajectoryFormat, TrajectorySpec};
use crate::observe::trajectory::gsd::Gsd;
use crate::observe::trajectory::xyz::Xyz;
use crate::observe::trajectory::{FrameSink, Framing, samples_per_frame};
use crate::runner::execute::simulate::start;
use crate::scene;
use anyhow::{Context, anyhow, bail};
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

/// Where run `run_id`'s trajectory goes.
pub fn file(out_dir: &Path, spec: &TrajectorySpec, run_id: u64) -> PathBuf {
    out_dir.join(spec.file_name(run_id))
}

/// The trajectory `spec`'s run is to have, if its descriptor asks for one.
pub fn wanted(spec: &RunSpec) -> Option<&TrajectorySpec> {
    let t = spec.descriptor.observe.trajectory.as_ref()?;
    t.writes(spec.run_id).then_some(t)
}

/// Film `spec`'s run into its trajectory file, in at most `max_events`
/// events (the run's own, with room to spare).
pub fn write(
    spec: &RunSpec,
    trajectory: &TrajectorySpec,
    out_dir: &Path,
    max_events: u64,
) -> anyhow::Result<()> {
    let path = file(out_dir, trajectory, spec.run_id);
    crate::files::write_via_temp(&path, |file| {
        let scene = scene::resolve(&spec.descriptor.scene).map_err(|e| anyhow!(e))?;
        let d = scene.dimension().map_err(|e| anyhow!(e))?;
        let filmed = Filmed {
            spec,
            scene: &scene,
            trajectory,
            max_events,
            file,
        };
        in_dimension(d, filmed).map_err(|e| anyhow!(e))?
    })
    .with_context(|| format!("writing the trajectory {}", path.display()))
}

struct Filmed<'a> {
    spec: &'a RunSpec,
    scene: &'a SceneSpec,
    trajectory: &'a TrajectorySpec,
    max_events: u64,
    file: &'a mut File,
}

impl ForDimension for Filmed<'_> {
    type Output = anyhow::Result<()>;
    fn run<const D: usize>(self) -> Self::Output {
        let file = self.file.try_clone()?;
        match self.trajectory.format {
            TrajectoryFormat::Gsd => {
                let sink = Gsd::new(BufWriter::new(file))?;
                film::<D, _>(&self, sink)
            }
            TrajectoryFormat::Xyz => film::<D, _>(&self, Xyz::new(BufWriter::new(file))),
        }
    }
}

/// The run from its start with `sink` as its only observer: the engine of
/// the measured run (a chain of neighbours for rods; neighbour lists for
/// disks and spheres, with plane support only for a piston wall).
fn film<const D: usize, S: FrameSink>(f: &Filmed, sink: S) -> anyhow::Result<()> {
    let (built, seed) = start::<D>(f.spec, f.scene)?;
    let run = &f.spec.descriptor.run;
    let t = f.trajectory;
    // Frames over the run: every `every` from 0 to its end, and for a run
    // stopped by collisions at most the cap allows.
    let n = built.particles.len().max(1) as f64;
    let cap = (MAX_PARTICLE_FRAMES / n).floor();
    let frames = match run.duration {
        Some(duration) => t.frames(run.equilibrate + duration).min(cap),
        None => cap,
    } as u64;
    let energy: f64 = built.particles.iter().map(|p| p.kinetic_energy()).sum();
    let lightest = built
        .particles
        .iter()
        .filter(|p| !p.is_immovable())
        .map(|p| p.mass())
        .fold(f64::INFINITY, f64::min);
    let shortest = (0..D)
        .filter(|&k| built.sim_box.axes[k].is_periodic())
        .map(|k| built.sim_box.size[k])
        .reduce(f64::min);
    let per_frame = samples_per_frame(t.every, (2.0 * energy / lightest).sqrt(), shortest);
    let sample_every = t.every / per_frame as f64;
    let framing = Framing::new(sink, built.species.clone(), per_frame, frames, sample_every);
    if D == 1 {
        shoot::<D, Chain, S>(&built, framing, seed, f, sample_every)
    } else if built.particles.iter().any(|p| p.is_plane()) {
        shoot::<D, NeighbourList<D, true>, S>(&built, framing, seed, f, sample_every)
    } else {
        shoot::<D, NeighbourList<D>, S>(&built, framing, seed, f, sample_every)
    }
}

fn shoot<const D: usize, N: Neighbourhood<D>, S: FrameSink>(
    built: &scene::build::Built<D>,
    framing: Framing<S>,
    seed: u64,
    f: &Filmed,
    sample_every: f64,
) -> anyhow::Result<()> {
    let mut sim: Simulation<D, N, Framing<S>> =
        Simulation::new(built.particles.clone(), built.sim_box, framing, seed)
            .context("the scene cannot be simulated")?;
    let run = &f.spec.descriptor.run;
    sim.sample_every(Some(sample_every));
    sim.limit_events(f.max_events);
    match (run.duration, run.collisions) {
        // Half a sample past the end: the last frame is at the end whatever
        // the rounding of the sample times.
        (Some(duration), _) => sim.run(Stop::Time(run.equilibrate + duration + 0.5 * sample_every)),
        (None, Some(collisions)) => {
            if run.equilibrate > 0.0 {
                sim.run(Stop::Time(run.equilibrate));
            }
            sim.run(Stop::Collisions(collisions));
        }
        (None, None) => bail!("[run] needs `duration` or `collisions`"),
    }
    if let Some(halt) = sim.halted() {
        bail!("filming stopped short: {halt}");
    }
    sim.into_observer().finish().map_err(|e| anyhow!(e))?;
    Ok(())
}
