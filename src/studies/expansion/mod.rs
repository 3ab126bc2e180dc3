//! The expansion analysis (Imperial "Expansion of the gas"): a gas started
//! in the left half of a box with walls spreads into the empty right half.
//! How fast does the split relax toward N/2, against particles that never
//! collide; where does it settle and how much does it fluctuate there?

mod charts;
mod error;
mod group;
mod measure;
mod profiles;
mod section;

use super::{Finished, Start, Study};
use crate::model::descriptor::Descriptor;
use crate::model::need::Need;
use crate::model::report::ReportSection;
use crate::model::run_output::{RunOutput, Series};
use crate::stats::diffusion::diffusion;
use crate::stats::ensemble::Runs;
use crate::stats::passage::first_passage;
use crate::studies::parts::scalars;
pub use measure::{Draw, Gas, draw, late, starts_left};

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
    "diffusion_enskog",
    "relaxation_time_diffusive",
    "diffusion_measured",
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
        "a gas started in the left half spreads into the right: relaxation time of the left fraction against p_max, density and N, beside the exact collisionless prediction (uniform or Maxwellian start) and the diffusive one (Enskog D); profiles of density and temperature; the late split against the binomial"
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
    /// D along y where the run records the mean-squared displacement.
    fn writes(&self, d: &Descriptor) -> Vec<&'static str> {
        let msd = d
            .observe
            .series
            .iter()
            .any(|s| s == "mean_squared_displacement");
        RESULTS
            .iter()
            .copied()
            .filter(|r| msd || *r != "diffusion_measured")
            .collect()
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
        // Only an expansion relaxes: a gas started everywhere has no time.
        let left = starts_left(run.descriptor);
        let tau = if left {
            // The excess f - 1/2 relaxes to 1/e.
            first_passage(t, f, 0.5)
        } else {
            f64::NAN
        };
        let (mean, variance) = late(t, f);
        let drawn = draw(run.descriptor);
        let start = drawn.filter(|_| left);
        let free = start.map_or(f64::NAN, |d| gas.free(d).relaxation_time());
        let enskog = drawn.map_or(f64::NAN, |d| gas.diffusion_enskog(d));
        let diffusive = left.then(|| gas.diffusive(enskog).relaxation_time());
        let n = gas.particles as f64;
        // A run that records the mean-squared displacement (a case with a
        // periodic y axis, the gas filling the box) measures D along y.
        let msd_y = |s: &&Series| s.observable.starts_with("msd.") && s.observable.ends_with(".y");
        let measured = (out.series.iter().find(msd_y)).map(|s| diffusion(&s.t, &s.value).0);
        out.scalars.extend(scalars([
            ("particles", n),
            ("number_density", gas.density),
            ("knudsen", gas.knudsen()),
            ("relaxation_time", tau),
            ("relaxation_time_free", free),
            ("relaxation_ratio", tau / free),
            ("diffusion_enskog", enskog),
            ("relaxation_time_diffusive", diffusive.unwrap_or(f64::NAN)),
            ("late_mean", mean),
            // Independent particles: binomial, variance 1/(4N).
            ("late_variance_ratio", variance * 4.0 * n),
            // Hard particles exclude each other: S(0) of the fluid.
            ("compressibility", gas.compressibility()),
        ]));
        if self.writes(run.descriptor).contains(&"diffusion_measured") {
            let d = measured.unwrap_or(f64::NAN);
            out.scalars.push(("diffusion_measured".into(), d));
        }
        profiles::pool(out);
        Ok(())
    }
    fn theory(&self, d: &Descriptor, result: &str) -> Option<f64> {
        match result {
            "late_mean" => Some(0.5),
            "late_variance_ratio" => Some(Gas::of_descriptor(d)?.compressibility()),
            // The collisionless time: holds only while collisions are rare.
            "relaxation_ratio" if starts_left(d) => Some(1.0),
            "relaxation_time" if starts_left(d) => {
                let free = Gas::of_descriptor(d)?.free(draw(d)?);
                Some(free.relaxation_time())
            }
            _ => None,
        }
    }
    /// The collisionless time, which colliding gases are meant to miss
    /// (exact for point particles).
    fn contrast(&self, d: &Descriptor, result: &str) -> bool {
        let colliding = Gas::of_descriptor(d).is_some_and(|g| g.diameter > 0.0);
        result.starts_with("relaxation_") && colliding
    }
    fn error_model(&self, d: &Descriptor) -> Option<super::ErrorModel> {
        error::error_model(d)
    }
    fn section(&self, _: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection> {
        section::section(runs)
    }
}
