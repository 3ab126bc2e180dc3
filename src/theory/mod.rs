//! Theory predictions, one file each, set beside measurements in the summary.

pub mod expansion;
pub mod piston;
pub mod piston_equilibrium;
pub mod piston_exchange;
pub mod piston_room;
