//! What one simulation hands back to the study: the contract between the
//! scene/engine side (which produces it) and the runner, store and report.

use serde::{Deserialize, Serialize};

/// Everything one run measured, plus what it cost.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct RunOutput {
    /// Scalar results, one column each in `runs.parquet` (e.g. "frequency").
    pub scalars: Vec<(String, f64)>,
    /// Time series, long form in `series.parquet`.
    pub series: Vec<Series>,
    /// Histograms, long form in `histograms.parquet`.
    pub histograms: Vec<Histogram>,
    /// Engine events processed (collisions, wall hits, list renewals, samples).
    pub events: u64,
    /// Pair collisions (the figure of merit for cost).
    pub collisions: u64,
    /// Wall-clock seconds of this run (excluded from bit-identity checks).
    pub wall_seconds: f64,
    /// CPU seconds of the thread that ran it (NaN where the platform does
    /// not tell; excluded from bit-identity checks).
    pub cpu_seconds: f64,
    /// Wall-clock seconds of those spent preparing the start (compression;
    /// 0 for direct placements; excluded from bit-identity checks).
    pub prepare_seconds: f64,
}

/// One observable sampled over time.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Series {
    pub observable: String,
    pub t: Vec<f64>,
    pub value: Vec<f64>,
}

/// One observable histogrammed; bins are [lo, hi).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Histogram {
    pub observable: String,
    pub lo: Vec<f64>,
    pub hi: Vec<f64>,
    pub count: Vec<f64>,
}

impl RunOutput {
    pub fn scalar(&self, name: &str) -> Option<f64> {
        self.scalars
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| *v)
    }
    pub fn series(&self, name: &str) -> Option<&Series> {
        self.series.iter().find(|s| s.observable == name)
    }
}
