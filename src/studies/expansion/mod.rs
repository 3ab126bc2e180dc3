//! The expansion analysis (Imperial "Expansion of the gas"): a gas started
//! in the left half of a box with walls spreads into the empty right half.
//! How fast does the split relax toward N/2, against particles that never
//! collide; where does it settle and how much does it fluctuate there?

mod error;
mod measure;
mod section;

use super::{Finished, Start, Study};
use crate::model::descriptor::Descriptor;
use crate::model::need::Need;
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::stats::ensemble::Runs;
pub use measure::{Gas, late, relaxation_time, temperature};

/// The series every run records for it.
pub const SERIES: &[&str] = &["left_fraction"];

/// Every result `per_run` adds; the report's expansion section presents them.
pub const RESULTS: &[&str] = &[
    "particles",
    "number_density",
    "knudsen",
    "relaxation_time",
    "relaxation_time_free",
    "relaxation_ratio",
    "late_mean",
    "late_variance_ratio",
    "compressibility",
];

/// The expansion study as a plug-in.
pub struct Expansion;

impl Study for Expansion {
    fn name(&self) -> &'static str {
        "expansion"
    }
    fn about(&self) -> &'static str {
        "a gas started in the left half spreads into the right: relaxation time of the left fraction against free particles bouncing between walls, late split and its fluctuations against the binomial"
    }
    fn needs(&self) -> &'static [Need] {
        &[Need::Sampling, Need::Walls]
    }
    fn series(&self) -> &'static [&'static str] {
        SERIES
    }
    fn results(&self) -> &'static [&'static str] {
        RESULTS
    }
    fn per_run(&self, run: &Finished, out: &mut RunOutput) -> Result<(), String> {
        let gas = match run.start {
            Start::Rods(b) => Gas::of(b),
            Start::Disks(b) => Gas::of(b),
            Start::Spheres(b) => Gas::of(b),
        };
        let series = out
            .series("left_fraction")
            .ok_or("the expansion analysis needs the left_fraction series")?;
        let (t, f) = (&series.t, &series.value);
        let tau = relaxation_time(t, f);
        let (mean, variance) = late(t, f);
        let free = temperature(run.descriptor)
            .map(|kt| gas.free(kt).relaxation_time())
            .unwrap_or(f64::NAN);
        let n = gas.particles as f64;
        out.scalars.extend(
            [
                ("particles", n),
                ("number_density", gas.density),
                ("knudsen", gas.knudsen()),
                ("relaxation_time", tau),
                ("relaxation_time_free", free),
                ("relaxation_ratio", tau / free),
                ("late_mean", mean),
                // Independent particles: binomial, variance 1/(4N).
                ("late_variance_ratio", variance * 4.0 * n),
                // Hard particles exclude each other: S(0) of the fluid.
                ("compressibility", gas.compressibility()),
            ]
            .map(|(k, v)| (k.to_string(), v)),
        );
        Ok(())
    }
    fn theory(&self, d: &Descriptor, result: &str) -> Option<f64> {
        match result {
            "late_mean" => Some(0.5),
            "late_variance_ratio" => Some(Gas::of_descriptor(d)?.compressibility()),
            // The collisionless time: holds only while collisions are rare.
            "relaxation_ratio" => Some(1.0),
            "relaxation_time" => {
                let free = Gas::of_descriptor(d)?.free(temperature(d)?);
                Some(free.relaxation_time())
            }
            _ => None,
        }
    }
    fn error_model(&self, d: &Descriptor) -> Option<super::ErrorModel> {
        error::error_model(d)
    }
    fn section(&self, _: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection> {
        section::section(runs)
    }
}
