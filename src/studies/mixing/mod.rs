//! The mixing-time analysis (MacKay's Bonkers; Imperial "Mixing"). In 1D:
//! rods between walls, all the energy started in one rod; how long until it
//! is shared as equilibrium shares it, against the gas's mass spread, its
//! size and the hot rod's mass, and which runs never get there. In 2D: two
//! species started in the two halves of a box; how long until each fills
//! both, against the time diffusion predicts from the measured
//! self-diffusion coefficient. docs/mixing.md defines both.

mod disks;
mod error;
mod rods;
mod section;
mod section_disks;
mod section_rods;

use super::{Finished, Start, Study};
use crate::model::descriptor::Descriptor;
use crate::model::need::Need;
use crate::model::problem::{Check, bad};
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::model::scene::SceneSpec;
use crate::stats::ensemble::Runs;

/// The series every run records for it.
pub const SERIES: &[&str] = &[
    "energy_concentration",
    "energy_share",
    "energy_autocorrelation",
    "side_counts",
    "mean_squared_displacement",
];

/// Every result `per_run` adds (1D and 2D runs add their own subsets).
pub const RESULTS: &[&str] = &[
    "particles",
    "mixed",
    "mixing_time",
    "mass_spread",
    "hot_mass_ratio",
    "mixing_collisions",
    "collision_rate",
    "late_concentration_ratio",
    "concentration_change",
    "hot_share_ratio",
    "packing_fraction",
    "mass_ratio",
    "knudsen",
    "late_left_fraction",
    "diffusion",
    "diffusion_enskog",
    "diffusion_ratio",
    "memory_ratio",
];

/// The mixing study as a plug-in.
pub struct Mixing;

impl Study for Mixing {
    fn name(&self) -> &'static str {
        "mixing"
    }
    fn about(&self) -> &'static str {
        "mixing time: in 1D the energy of one hot rod spreading to equipartition (equal masses never mix), against mass spread, N and the hot rod's mass; in 2D two species started apart, against density and mass ratio, beside diffusion from the measured self-diffusion coefficient and Enskog"
    }
    fn needs(&self) -> &'static [Need] {
        // Walls too, except for the periodic boxes that measure D (2D):
        // rods check theirs in `per_run`.
        &[Need::Sampling]
    }
    fn check(&self, _: &Descriptor, scene: &SceneSpec, key: &str) -> Check {
        use crate::scene::check::{count, dimension};
        let walled = scene
            .boundary
            .as_ref()
            .is_none_or(|b| b.first() != Some(&crate::model::scene::Boundary::Periodic));
        match dimension(scene) {
            1 if !walled => bad(
                key,
                "the mixing analysis in 1D needs walls (its equilibrium assumes only the energy \
                 is conserved; on a ring momentum is too)",
                Some("set `boundary = [\"walls\"]` in [scene]"),
            ),
            2 if scene.species.len() < 2 || count(scene, 0) == 0 || count(scene, 1) == 0 => bad(
                key,
                "the mixing analysis in 2D needs two species, each with particles (the first \
                 starts on the left, the second on the right)",
                Some("give `[[scene.species]]` two entries with `count` >= 1"),
            ),
            3 => bad(
                key,
                "the mixing analysis is for rods (1D) and disks (2D)",
                Some("use `dimension = 1` or `2`"),
            ),
            _ => Ok(()),
        }
    }
    fn series(&self) -> &'static [&'static str] {
        SERIES
    }
    fn results(&self) -> &'static [&'static str] {
        RESULTS
    }
    /// Rods: the hot rod's spreading; disks: the box, then mixing between
    /// walls along x or diffusion in a periodic box.
    fn writes(&self, d: &Descriptor) -> Vec<&'static str> {
        let Ok(scene) = crate::scene::resolve(&d.scene) else {
            return Vec::new();
        };
        let rods = scene.dimension() == Ok(1);
        let disks = scene.dimension() == Ok(2);
        let apart = disks && !scene.periodic(0);
        let bulk = disks && scene.periodic(0) && scene.periodic(1);
        RESULTS
            .iter()
            .copied()
            .filter(|r| match *r {
                "particles" => rods || disks,
                "mixed" | "mixing_time" => rods || apart,
                "packing_fraction" | "mass_ratio" | "knudsen" => disks,
                "late_left_fraction" => apart,
                "diffusion" | "diffusion_enskog" | "diffusion_ratio" | "memory_ratio" => bulk,
                _ => rods,
            })
            .collect()
    }
    fn per_run(&self, run: &Finished, out: &mut RunOutput) -> Result<(), String> {
        match run.start {
            Start::Rods(b) => rods::per_run(run.descriptor, b, out),
            Start::Disks(b) => disks::per_run(run.descriptor, b, run.context.species, out),
            Start::Spheres(_) => Err("the mixing analysis is for rods (1D) and disks (2D)".into()),
        }
    }
    fn theory(&self, _: &Descriptor, result: &str) -> Option<f64> {
        match result {
            "late_concentration_ratio" | "hot_share_ratio" => Some(1.0),
            "late_left_fraction" => Some(0.5),
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
