//! Disks and spheres are followed by neighbour lists on a grid of at most a
//! few cells per particle, which files each particle's position to 1/2^12
//! of a cell: along an axis far longer than the particles' spacing that is
//! coarser than the distance a particle moves between looks at its
//! neighbours, and the engine would look again and again at one instant.
//! The engine's own rule (`engine::neighbours::layout`), asked of the scene
//! before anything is drawn.

use super::{dimension, particles};
use crate::engine::neighbours::layout;
use crate::model::dimension::{ForDimension, in_dimension};
use crate::model::problem::{Check, bad};
use crate::model::scene::SceneSpec;

pub fn grid(s: &SceneSpec) -> Check {
    in_dimension(dimension(s), Follows(s)).unwrap_or(Ok(()))
}

/// Whether the engine can follow the scene's disks or spheres (rods need
/// no grid).
struct Follows<'a>(&'a SceneSpec);

impl ForDimension for Follows<'_> {
    type Output = Check;
    fn run<const D: usize>(self) -> Check {
        if D == 1 {
            return Ok(());
        }
        follows::<D>(self.0)
    }
}

fn follows<const D: usize>(s: &SceneSpec) -> Check {
    let Ok(sim_box) = crate::scene::build::sim_box::<D>(s) else {
        return Ok(());
    };
    let balls = particles(s);
    let points = balls + usize::from(s.piston.is_some());
    let largest = s
        .species
        .iter()
        .map(|sp| sp.radius.bounds()[1])
        .fold(0.0, f64::max);
    match layout(points, balls, largest, &sim_box) {
        Ok(_) => Ok(()),
        Err((axis, why)) => {
            // A periodic axis too short says its own fix.
            let hint = (!why.starts_with("periodic")).then_some(
                "shorten that axis, or put more particles in the box: the grid has more \
                 cells for more particles",
            );
            bad(
                axis.map_or("scene.box".to_string(), |k| format!("scene.box.{k}")),
                why,
                hint,
            )
        }
    }
}
