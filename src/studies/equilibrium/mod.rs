//! The equilibrium analysis (MacKay's ten and N particles, Imperial's
//! distributions): each particle's velocity and position histograms
//! against the exact finite-N laws of the ensemble the run samples and
//! their large-N (Gaussian, Maxwell-Boltzmann) limits; the std ratio of the
//! lightest and heaviest particle against sqrt(mass ratio); MacKay's
//! "dimple" put to the test; and in 2D the speeds, the density profile and
//! g(r) at contact beside the measured pressure.

mod charts;
mod dimple;
mod ensemble;
mod measure;
mod moments;
mod section;
mod settling;
mod tests_of;

use super::{Finished, Start, Study};
use crate::model::descriptor::Descriptor;
use crate::model::need::Need;
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::stats::ensemble::Runs;
pub use ensemble::Ensemble;
pub use tests_of::{Tests, tests_of};

/// Every result `per_run` may add (each group where the run observes what
/// it needs, see `writes`); the report's equilibrium section presents them.
pub const RESULTS: &[&str] = &[
    "kT",
    "lightest_mass",
    "heaviest_mass",
    "std_lightest",
    "std_heaviest",
    "std_ratio",
    "sqrt_mass_ratio",
    "std_ratio_exact",
    "std_ratio_over_exact",
    "kurtosis_lightest",
    "kurtosis_heaviest",
    "kurtosis_vx",
    "packing_fraction",
    "g_contact",
    "Z_contact",
    "Z_virial",
    "Z_contact_over_virial",
    "wall_density",
    "contact_theorem_ratio",
];

/// The equilibrium study as a plug-in.
pub struct Equilibrium;

impl Study for Equilibrium {
    fn name(&self) -> &'static str {
        "equilibrium"
    }
    fn about(&self) -> &'static str {
        "equilibrium distributions: each particle's velocity and position histograms against the exact finite-N microcanonical laws and the Gaussian, std ratio against sqrt(mass ratio), early against late halves; 2D speeds against Maxwell-Boltzmann, density profile, g(r) at contact against the pressure"
    }
    fn needs(&self) -> &'static [Need] {
        &[Need::Sampling]
    }
    fn results(&self) -> &'static [&'static str] {
        RESULTS
    }
    /// kT always; each other group where the run observes what it is
    /// measured from (NaN where the scene does not allow it: g at contact
    /// needs a periodic box of one size, the wall density walls along x).
    fn writes(&self, d: &Descriptor) -> Vec<&'static str> {
        let o = &d.observe;
        let histogram = |n: &str| o.histograms.iter().any(|h| h == n);
        let scalar = |n: &str| o.scalars.iter().any(|s| s == n);
        let contact = histogram("pair_distance");
        let written = |r: &&str| match *r {
            "kT" => true,
            "kurtosis_vx" => histogram("scaled_velocity_x"),
            "packing_fraction" | "g_contact" | "Z_contact" => contact,
            "Z_virial" | "Z_contact_over_virial" => contact && scalar("virial_pressure"),
            "wall_density" | "contact_theorem_ratio" => {
                histogram("density_x") && scalar("wall_pressure")
            }
            _ => histogram("velocity_x_each"),
        };
        RESULTS.iter().copied().filter(written).collect()
    }
    fn per_run(&self, run: &Finished, out: &mut RunOutput) -> Result<(), String> {
        let e = match run.start {
            Start::Rods(b) => Ensemble::of(b),
            Start::Disks(b) => Ensemble::of(b),
            Start::Spheres(b) => Ensemble::of(b),
        };
        measure::measure(&e, run.context, out);
        Ok(())
    }
    fn theory(&self, d: &Descriptor, result: &str) -> Option<f64> {
        match result {
            "std_ratio_over_exact" | "Z_contact_over_virial" | "contact_theorem_ratio" => Some(1.0),
            // The excess kurtosis of a component of a uniform point on a
            // sphere in f dimensions (docs/equilibrium.md).
            "kurtosis_lightest" | "kurtosis_heaviest" | "kurtosis_vx" => {
                Ensemble::of_seed(&d.scene, 0).map(|e| -6.0 / (e.dof + 2.0))
            }
            _ => None,
        }
    }
    fn section(&self, _: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection> {
        section::section(runs)
    }
}
