//! Scenes: the physical setup a run starts from.

pub mod build;
pub mod check;
pub mod compress;
pub mod lattice;
pub mod on_built;
pub mod piston;
pub mod placement;
pub mod presets;
pub mod refusal;
pub mod resolve;
pub mod rods;
pub mod slots;
pub mod space;
pub mod velocities;

pub use build::{Built, build};
pub use compress::Preparation;
pub use on_built::{OnBuilt, on_built};
pub use resolve::resolve;
