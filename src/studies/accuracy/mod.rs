//! What accuracy costs in time (issue 15): the Imperial project's fixed-step
//! integrator against the exact event-driven engine on the same scenes, over
//! steps dt spanning decades. Per run it adds the collision rate and, with a
//! piston, the piston's frequency; the section compares each step's wall
//! pressure, collision rate, frequency and energy against the exact engine's
//! runs of the same scene, and sets every error beside the CPU time it cost.

mod effort;
mod groups;
mod headlines;
mod section;

use super::{Finished, Start, Study};
use crate::engine::Particle;
use crate::model::descriptor::Descriptor;
use crate::model::need::Need;
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::stats::ensemble::Runs;

/// The results it adds to each run (the frequency only with a piston).
pub const RESULTS: &[&str] = &["collision_rate", "beta_pressure", "piston_frequency"];

/// Run results the section shows in its tables (the stepper's own
/// diagnostics and the observables the descriptor asks for).
pub const SHOWN: &[&str] = &[
    "wall_pressure",
    "energy_drift",
    "steps",
    "dt",
    "overlap_depth_max",
    "overlap_depth_mean",
    "overlap_steps_max",
    "repeat_collisions",
    "stuck_pairs",
];

/// Full periods the piston's frequency is measured over, and the hysteresis
/// band of its turning points (as the piston study's defaults).
const PERIODS: usize = 4;
const BAND: f64 = 0.1;

/// The accuracy study as a plug-in.
pub struct Accuracy;

impl Study for Accuracy {
    fn name(&self) -> &'static str {
        "accuracy"
    }
    fn about(&self) -> &'static str {
        "the fixed-step integrator against the exact engine: wall pressure, collision rate, piston frequency and energy errors, overlaps and sticking, against CPU time"
    }
    fn needs(&self) -> &'static [Need] {
        // Walls only where `wall_pressure` is asked for (its own check):
        // the other studies' headline cases include a periodic box.
        &[Need::Sampling]
    }
    fn series(&self) -> &'static [&'static str] {
        &["piston_position"]
    }
    fn results(&self) -> &'static [&'static str] {
        RESULTS
    }
    /// βP where the wall pressure is observed, the frequency where there is a piston.
    fn writes(&self, d: &Descriptor) -> Vec<&'static str> {
        let walls = d.observe.scalars.iter().any(|n| n == "wall_pressure");
        let piston = crate::scene::resolve(&d.scene).is_ok_and(|s| s.piston.is_some());
        let given = [true, walls, piston];
        (RESULTS.iter().zip(given))
            .filter_map(|(r, g)| g.then_some(*r))
            .collect()
    }
    fn per_run(&self, run: &Finished, out: &mut RunOutput) -> Result<(), String> {
        let duration = run.context.duration;
        out.scalars.push((
            "collision_rate".into(),
            out.collisions as f64 / duration.max(f64::MIN_POSITIVE),
        ));
        // Each run's gas has its own energy (a Maxwellian draw of a few
        // dozen particles scatters by ~10 %), and the pressure follows it:
        // βP = P / kT with the run's own kT = 2K/f is what runs share.
        let kinetic = match run.start {
            Start::Rods(b) => energy(&b.particles),
            Start::Disks(b) => energy(&b.particles),
            Start::Spheres(b) => energy(&b.particles),
        };
        if let Some(p) = out.scalar("wall_pressure") {
            let kt = 2.0 * kinetic / run.context.degrees_of_freedom;
            out.scalars.push(("beta_pressure".into(), p / kt));
        }
        if run.context.piston.is_none() {
            // Recorded for the piston scenes only: elsewhere it is all NaN.
            out.series.retain(|s| s.observable != "piston_position");
        } else if let Some(x) = out.series("piston_position") {
            let omega = crate::stats::oscillation::oscillation(&x.t, &x.value, PERIODS, BAND)
                .map_or(f64::NAN, |m| m.omega);
            out.scalars.push(("piston_frequency".into(), omega));
        }
        Ok(())
    }
    fn section(&self, _: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection> {
        Ok(section::section(runs))
    }
}

/// Kinetic energy at the start (both integrators conserve it).
fn energy<const D: usize>(particles: &[Particle<D>]) -> f64 {
    particles.iter().map(Particle::kinetic_energy).sum()
}
