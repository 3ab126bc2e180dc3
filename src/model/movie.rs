//! A movie of a run's first moments: what `[observe] movie` asks for, and the
//! frames a run hands back (positions exactly as the engine moved them, at
//! evenly spaced times, never interpolated).

use serde::{Deserialize, Serialize};

/// `[observe] movie = { duration = 20.0, frames = 200 }`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MovieSpec {
    /// Simulated time filmed, from the start of the run (before equilibration).
    pub duration: f64,
    /// Frames, evenly spaced over `duration`, the first at time 0.
    pub frames: usize,
    /// The run filmed (its `run_id`); the plan's first when it has no such
    /// run (e.g. in a `--quick` plan) or that run failed.
    #[serde(default)]
    pub run: u64,
}

/// One particle's path through the frames.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Track {
    pub radius: f64,
    pub species: u16,
    /// A piston wall spanning the box across x (2D and 3D), drawn as a line.
    pub plane: bool,
    /// Position along x and y (y is 0 in 1D; 3D is seen along z) per frame.
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    /// Velocity along x per frame (drawn as an arrow on 1D rods).
    pub vx: Vec<f64>,
}

/// The frames of one run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Film {
    pub dimension: usize,
    /// Box size along x and y (y is 0 in 1D).
    pub size: [f64; 2],
    /// Simulated time of each frame.
    pub times: Vec<f64>,
    pub tracks: Vec<Track>,
    /// Species names by species index.
    pub species: Vec<String>,
    /// Which run it is (for the caption).
    pub run_id: u64,
}
