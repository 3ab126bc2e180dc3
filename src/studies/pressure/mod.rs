//! Pressure against density: the equation of state of hard rods between
//! walls and of hard disks and spheres in periodic boxes, as the
//! compressibility factor Z = beta P / rho against the packing fraction,
//! beside the exact (rods) and published (disks, spheres) equations.

mod charts;
mod equations;
mod error;
mod finite_size;
mod measure;
mod packing;
mod phases;
mod points;
mod section;

use super::{Finished, Start, Study};
use crate::model::descriptor::Descriptor;
use crate::model::problem::{Check, bad};
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::model::scene::SceneSpec;
use crate::stats::ensemble::Runs;

pub use equations::{Equation, of as equations};
pub use packing::of_scene as described_packing;

/// The results it can add to a run; `writes` says which a descriptor gets.
pub const RESULTS: &[&str] = &[
    "Z",
    "Z_wall",
    "Z_virial",
    "packing_fraction",
    "density",
    "equilibration_cut",
    "Z_block_stderr",
    "block_time",
    "block_doubling",
    "Z_run_stderr",
    "Z_drift",
];

/// The pressure study as a plug-in.
pub struct Pressure;

impl Study for Pressure {
    fn name(&self) -> &'static str {
        "pressure"
    }
    fn about(&self) -> &'static str {
        "compressibility factor Z = βP/ρ from the wall or virial pressure against packing fraction, with equilibration cuts, block-average errors and the 1/N extrapolation, beside Tonks (rods), Kolafa-Rottner, the virial series and Henderson (disks), Hansen-Goos, Carnahan-Starling-Kolafa, the virial series and Carnahan-Starling (spheres)"
    }
    fn check(&self, d: &Descriptor, scene: &SceneSpec, key: &str) -> Check {
        if scene.piston.is_some() {
            return bad(
                key,
                "the pressure analysis needs a scene without a piston",
                Some("remove `[scene.piston]`: a piston moves the walls the pressure is read on"),
            );
        }
        let o = &d.observe;
        let pressure = |n: &String| n == "wall_pressure" || n == "virial_pressure";
        if o.scalars.iter().chain(&o.series).any(pressure) {
            return Ok(());
        }
        bad(
            key,
            "the pressure analysis needs a pressure: `wall_pressure` or `virial_pressure` observed",
            Some(
                "add `scalars = [\"wall_pressure\"]` (walls) or `[\"virial_pressure\"]` to \
                 [observe], or the same under `series` for equilibration cuts and block errors",
            ),
        )
    }
    fn results(&self) -> &'static [&'static str] {
        RESULTS
    }
    /// `Z_wall` and `Z_virial` where that pressure is observed, the block
    /// and equilibration results where a pressure series is.
    fn writes(&self, d: &Descriptor) -> Vec<&'static str> {
        let o = &d.observe;
        let observed = |name: &str| o.scalars.iter().chain(&o.series).any(|n| n == name);
        let series = o.series.iter().any(|n| n.ends_with("_pressure"));
        (RESULTS.iter().copied())
            .filter(|r| match *r {
                "Z_wall" => observed("wall_pressure"),
                "Z_virial" => observed("virial_pressure"),
                "equilibration_cut" | "Z_block_stderr" | "block_time" | "block_doubling"
                | "Z_drift" => series,
                _ => true,
            })
            .collect()
    }
    fn per_run(&self, run: &Finished, out: &mut RunOutput) -> Result<(), String> {
        let (piston, m) = match run.start {
            Start::Rods(b) => (b.piston, measure::measure(&b.particles, run.context, out)),
            Start::Disks(b) => (b.piston, measure::measure(&b.particles, run.context, out)),
            Start::Spheres(b) => (b.piston, measure::measure(&b.particles, run.context, out)),
        };
        if piston.is_some() {
            return Err("the pressure analysis needs a scene without a piston".into());
        }
        let writes = self.writes(run.descriptor);
        for (name, v) in RESULTS.iter().zip(m?) {
            if writes.contains(name) {
                out.scalars.push((name.to_string(), v));
            }
        }
        Ok(())
    }
    fn theory(&self, d: &Descriptor, result: &str) -> Option<f64> {
        if result != "Z" {
            return None;
        }
        let s = packing::described(d)?;
        let eta = packing::of_scene(&s.scene)?;
        // Walls in 2D and 3D add a surface term that no bulk equation has.
        if s.dimension > 1 && s.walls {
            return None;
        }
        Some((equations::of(s.dimension)[0].z)(eta))
    }
    fn error_model(&self, d: &Descriptor) -> Option<super::ErrorModel> {
        error::error_model(d)
    }
    fn section(&self, _: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection> {
        section::section(runs)
    }
}
