//! `[observe] movie`: the plan's first run filmed again from its start. Runs
//! are deterministic, so this is the run as it happened: the same scene, the
//! same engine, positions read at exact frame times.

use crate::engine::{Chain, NeighbourList, Neighbourhood, Simulation, Stop};
use crate::model::dimension::{ForDimension, in_dimension};
use crate::model::movie::{Film, MovieSpec};
use crate::model::run_spec::RunSpec;
use crate::model::scene::SceneSpec;
use crate::observe::film::Filming;
use crate::runner::execute::simulate::start;
use crate::scene;
use anyhow::{Context, anyhow, bail};

/// The frames of `spec`'s run over `movie.duration` from time 0, in at most
/// `max_events` events (the run's own, with room to spare: validate keeps a
/// movie within its run, and the filming stops where the budget does, with
/// the frames taken so far).
pub fn film(spec: &RunSpec, movie: &MovieSpec, max_events: u64) -> anyhow::Result<Film> {
    let scene = scene::resolve(&spec.descriptor.scene).map_err(|e| anyhow!(e))?;
    let d = scene.dimension().map_err(|e| anyhow!(e))?;
    let filming = Filmed {
        spec,
        scene: &scene,
        movie,
        max_events,
    };
    in_dimension(d, filming).map_err(|e| anyhow!(e))?
}

/// A movie in the dimension of its scene.
struct Filmed<'a> {
    spec: &'a RunSpec,
    scene: &'a SceneSpec,
    movie: &'a MovieSpec,
    max_events: u64,
}

/// The engine of the measured run: a chain of neighbours for rods; for
/// disks and spheres, plane support only when the scene has a piston wall.
impl ForDimension for Filmed<'_> {
    type Output = anyhow::Result<Film>;
    fn run<const D: usize>(self) -> Self::Output {
        let (built, seed) = start::<D>(self.spec, self.scene)?;
        let size = built.sim_box.size;
        let camera = Filming::new(
            D,
            [size[0], if D > 1 { size[1] } else { 0.0 }],
            built.species.clone(),
            self.spec.run_id,
        );
        let (movie, max_events) = (self.movie, self.max_events);
        if D == 1 {
            shoot::<D, Chain>(&built, camera, seed, movie, max_events)
        } else if built.particles.iter().any(|p| p.is_plane()) {
            shoot::<D, NeighbourList<D, true>>(&built, camera, seed, movie, max_events)
        } else {
            shoot::<D, NeighbourList<D>>(&built, camera, seed, movie, max_events)
        }
    }
}

fn shoot<const D: usize, N: Neighbourhood<D>>(
    built: &scene::build::Built<D>,
    camera: Filming,
    seed: u64,
    movie: &MovieSpec,
    max_events: u64,
) -> anyhow::Result<Film> {
    let mut sim: Simulation<D, N, Filming> =
        Simulation::new(built.particles.clone(), built.sim_box, camera, seed)
            .context("the scene cannot be simulated")?;
    let frames = movie.frames.max(2);
    let every = movie.duration / (frames - 1) as f64;
    sim.sample_every(Some(every));
    // Half a frame past the end: the last frame is at `duration` whatever
    // the rounding of the sample times, and no frame comes after it.
    sim.limit_events(max_events);
    sim.run(Stop::Time(movie.duration + 0.5 * every));
    let halted = sim.halted();
    let mut film = sim.into_observer().into_film();
    if let Some(halt) = halted
        && film.times.len() < 2
    {
        bail!("filming stopped before its second frame: {halt}");
    }
    film.times.truncate(frames);
    for track in &mut film.tracks {
        track.x.truncate(frames);
        track.y.truncate(frames);
        track.vx.truncate(frames);
    }
    Ok(film)
}
