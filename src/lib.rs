//! bonkers: ensemble studies of hard-particle gases on an exact event-driven engine.

// Loops over axes `for k in 0..D` index several vectors at once and read like
// the formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod analysis;
pub mod engine;
pub mod observe;
pub mod report;
pub mod scene;
pub mod simulate;
pub mod study;
pub mod theory;
