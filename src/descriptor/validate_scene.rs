//! The scene's part of validation: the scene layer's own checks
//! (`scene::check`, which the builder runs too), so that `study validate`
//! refuses exactly what a run would. The descriptor only places the problem
//! in the file (`descriptor::check`).

use crate::model::problem::Check;
use crate::model::scene::SceneSpec;

pub use crate::scene::check::{count, dimension, particles};

/// Check a resolved scene (no preset left).
pub fn scene(s: &SceneSpec) -> Check {
    crate::scene::check::scene(s)
}
