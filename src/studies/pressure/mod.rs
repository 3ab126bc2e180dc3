//! Pressure against density: the equation of state of hard rods between
//! walls and of hard disks and spheres in periodic boxes, as the
//! compressibility factor Z = beta P / rho against the packing fraction,
//! beside the exact (rods) and published (disks, spheres) equations.

mod equations;
mod measure;
mod packing;
mod section;

use super::{Finished, Start, Study};
use crate::model::descriptor::Descriptor;
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;

pub use equations::{Equation, of as equations};
pub use packing::of_scene as described_packing;

/// The results it adds to each run.
pub const RESULTS: &[&str] = &["Z", "packing_fraction", "density"];

/// The pressure study as a plug-in.
pub struct Pressure;

impl Study for Pressure {
    fn name(&self) -> &'static str {
        "pressure"
    }
    fn about(&self) -> &'static str {
        "compressibility factor Z = βP/ρ from the wall or virial pressure against packing fraction, beside Tonks (rods), Henderson and the virial series (disks), Kolafa-Labík-Malijevský and Carnahan-Starling (spheres)"
    }
    fn results(&self) -> &'static [&'static str] {
        RESULTS
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
        let m = m?;
        out.scalars.extend([
            ("Z".to_string(), m.z),
            ("packing_fraction".to_string(), m.packing_fraction),
            ("density".to_string(), m.density),
        ]);
        Ok(())
    }
    fn theory(&self, d: &Descriptor, result: &str) -> Option<f64> {
        if result != "Z" {
            return None;
        }
        let scene = crate::scene::resolve(&d.scene).ok()?;
        let eta = packing::of_scene(&scene)?;
        Some((equations::of(scene.dimension().ok()?)[0].z)(eta))
    }
    fn section(
        &self,
        _: &Descriptor,
        runs: &[(RunSpec, RunOutput)],
    ) -> anyhow::Result<ReportSection> {
        section::section(runs)
    }
}
