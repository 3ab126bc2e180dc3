//! `[observe] movie`: the plan's first run filmed again from its start. Runs
//! are deterministic, so this is the run as it happened: the same scene, the
//! same engine, positions read at exact frame times.

use super::simulate::{balls, rods, start};
use crate::engine::{Dynamics, Stop};
use crate::model::movie::{Film, MovieSpec};
use crate::model::run_spec::RunSpec;
use crate::observe::film::Filming;
use crate::scene;
use anyhow::{anyhow, bail};

/// The frames of `spec`'s run over `movie.duration` from time 0.
pub fn film(spec: &RunSpec, movie: &MovieSpec) -> anyhow::Result<Film> {
    let scene = scene::resolve(&spec.descriptor.scene).map_err(|e| anyhow!(e))?;
    match scene.dimension().map_err(|e| anyhow!(e))? {
        1 => {
            let (built, seed) = start::<1>(spec, &scene)?;
            let camera = camera(&built, spec);
            shoot(rods(&built, camera, seed)?, movie)
        }
        2 => {
            let (built, seed) = start::<2>(spec, &scene)?;
            let camera = camera(&built, spec);
            shoot(balls(&built, camera, seed)?, movie)
        }
        3 => {
            let (built, seed) = start::<3>(spec, &scene)?;
            let camera = camera(&built, spec);
            shoot(balls(&built, camera, seed)?, movie)
        }
        d => bail!("scene.dimension = {d}; use 1, 2 or 3"),
    }
}

fn camera<const D: usize>(built: &scene::build::Built<D>, spec: &RunSpec) -> Filming {
    let size = built.sim_box.size;
    Filming::new(
        D,
        [size[0], if D > 1 { size[1] } else { 0.0 }],
        built.species.clone(),
        spec.run_id,
    )
}

fn shoot<const D: usize>(
    mut sim: Box<dyn Dynamics<D, Filming>>,
    movie: &MovieSpec,
) -> anyhow::Result<Film> {
    let frames = movie.frames.max(2);
    let every = movie.duration / (frames - 1) as f64;
    sim.sample_every(Some(every));
    // Half a frame past the end: the last frame is at `duration` whatever
    // the rounding of the sample times, and no frame comes after it.
    sim.advance(Stop::Time(movie.duration + 0.5 * every));
    let mut film = sim.into_observer().into_film();
    film.times.truncate(frames);
    for track in &mut film.tracks {
        track.x.truncate(frames);
        track.y.truncate(frames);
        track.vx.truncate(frames);
    }
    Ok(film)
}
