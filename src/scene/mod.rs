//! Scenes: the physical setup a run starts from.

pub mod build;
pub mod placement;
pub mod presets;
pub mod resolve;
pub mod spec;
pub mod velocities;

pub use build::{Built, build};
pub use resolve::resolve;
