//! Theory predictions, one file each, set beside measurements in the summary.

pub mod piston;
pub mod piston_equilibrium;
pub mod piston_exchange;
pub mod piston_room;

use crate::study::descriptor_types::Descriptor;

/// The theory value for scalar result `result` of a run described by `descriptor`
/// (sweep values substituted), or None where no theory applies.
pub fn predict(descriptor: &Descriptor, result: &str) -> Option<f64> {
    crate::analysis::theory(descriptor, result)
}
