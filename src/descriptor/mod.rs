//! A study descriptor from TOML: parsed, overridden (`--quick`, sweep
//! values) and checked before anything runs, with errors placed at
//! file:line:column.

pub mod check;
pub mod errors;
pub mod explain;
pub mod load;
pub mod locate;
pub mod overrides;
pub mod point;
pub mod sweep;
pub mod text;
pub mod validate;
pub mod validate_collisions;
pub mod validate_integrator;
pub mod validate_observe;
pub mod validate_room;
pub mod validate_scene;
