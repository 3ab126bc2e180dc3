//! `[observe] trajectory`: what a descriptor asks to be written frame by
//! frame, and the file each chosen run gets.

use serde::{Deserialize, Serialize};

/// `[observe] trajectory = { format = "gsd", every = 0.5, runs = [0, 3] }`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrajectorySpec {
    pub format: TrajectoryFormat,
    /// Simulated time between frames; the first frame is at time 0 (the
    /// start, before equilibration), the last at or before the run's end.
    pub every: f64,
    /// The runs written (their `run_id`s); default the plan's first.
    #[serde(default = "first_run")]
    pub runs: Vec<u64>,
}

fn first_run() -> Vec<u64> {
    vec![0]
}

/// HOOMD's GSD schema, or extended XYZ (text).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum TrajectoryFormat {
    Gsd,
    Xyz,
}

impl TrajectoryFormat {
    /// The file's extension.
    pub fn extension(self) -> &'static str {
        match self {
            TrajectoryFormat::Gsd => "gsd",
            TrajectoryFormat::Xyz => "xyz",
        }
    }

    /// Bytes one frame takes beside its particles' (header, box, time).
    pub fn frame_bytes(self, species: usize) -> f64 {
        match self {
            // The index entries and the per-frame chunks; types and other
            // fixed chunks are in frame 0 only.
            TrajectoryFormat::Gsd => 5.0 * 32.0 + 8.0 + 8.0 + 48.0 + 8.0 * species as f64,
            TrajectoryFormat::Xyz => 200.0,
        }
    }

    /// Bytes one particle takes in one frame: GSD doubles (position and
    /// velocity) and image flags; XYZ about 24 characters per number.
    pub fn particle_bytes(self) -> f64 {
        match self {
            TrajectoryFormat::Gsd => 6.0 * 8.0 + 3.0 * 4.0,
            TrajectoryFormat::Xyz => 6.0 * 24.0 + 12.0,
        }
    }
}

impl TrajectorySpec {
    /// Whether the run `run_id` is written.
    pub fn writes(&self, run_id: u64) -> bool {
        self.runs.contains(&run_id)
    }

    /// Frames over a run of `length` (equilibration included): at 0,
    /// `every`, ... up to `length`.
    pub fn frames(&self, length: f64) -> f64 {
        (length / self.every).floor() + 1.0
    }

    /// The file name of run `run_id`'s trajectory in the output folder.
    pub fn file_name(&self, run_id: u64) -> String {
        format!("trajectory-{run_id}.{}", self.format.extension())
    }
}

/// Particle-frames (particles times frames) one trajectory may hold: about
/// 3 GB of GSD, 8 GB of XYZ.
pub const MAX_PARTICLE_FRAMES: f64 = 5e7;
