//! The runs grouped as the section compares them: per scene, the exact
//! engine's runs and each (integrator, dt) of the fixed step, with the
//! ensemble statistics of every quantity the section shows.

use crate::model::descriptor::Integrator;
use crate::stats::ensemble::Runs;
use crate::stats::point_runs::{PointRuns, by_point};
use crate::stats::summary::Stats;

/// The runs of one scene with one integrator and step.
pub struct Group {
    pub scene: String,
    pub integrator: Integrator,
    /// NaN for the exact engine.
    pub dt: f64,
    /// Simulated time of each run (NaN for runs stopped by collisions).
    pub duration: f64,
    /// Whether the scene has a piston (its frequency is then the headline).
    pub piston: bool,
    pub runs: usize,
    /// Wall pressure over each run's own kT.
    pub pressure: Stats,
    pub collision_rate: Stats,
    pub frequency: Stats,
    /// Mean over runs of |E_end - E_start| / E_start.
    pub energy_drift: f64,
    /// Over all runs: the deepest overlap (fraction of the contact
    /// distance), the mean depth, the longest overlap in steps.
    pub depth_max: f64,
    pub depth_mean: f64,
    pub longest: f64,
    /// Stuck pairs (overlap episodes longer than a pass through) per run.
    pub stuck: f64,
    /// Repeat collisions over all collisions.
    pub repeat_share: f64,
    /// Mean CPU seconds of one run.
    pub cpu: f64,
}

/// The groups of the points that are not headline cases, in the points'
/// order.
pub fn groups(runs: &Runs) -> Vec<Group> {
    (by_point(runs).iter())
        .filter(|p| super::headlines::model_of(p.spec).is_none())
        .map(group)
        .collect()
}

fn group(p: &PointRuns) -> Group {
    let run = &p.spec.descriptor.run;
    let values = |name: &'static str| {
        (p.outs.iter().filter_map(move |o| o.scalar(name))).filter(|v| v.is_finite())
    };
    let max = |name: &'static str| values(name).fold(f64::NAN, f64::max);
    let repeats: f64 = values("repeat_collisions").sum();
    Group {
        // Its preset, or "scene".
        scene: (p.spec.descriptor.scene.preset.clone()).unwrap_or_else(|| "scene".into()),
        integrator: run.integrator,
        dt: run.dt.unwrap_or(f64::NAN),
        duration: run.duration.unwrap_or(f64::NAN),
        // A run with a piston records its frequency (NaN if unmeasured).
        piston: p
            .outs
            .iter()
            .any(|o| o.scalar("piston_frequency").is_some()),
        runs: p.outs.len(),
        pressure: p.stat("beta_pressure"),
        collision_rate: p.stat("collision_rate"),
        frequency: p.stat("piston_frequency"),
        energy_drift: p.stat("energy_drift").mean,
        depth_max: max("overlap_depth_max"),
        depth_mean: p.stat("overlap_depth_mean").mean,
        longest: max("overlap_steps_max"),
        stuck: p.stat("stuck_pairs").mean,
        repeat_share: repeats / (p.collisions().max(1) as f64),
        cpu: p.cpu() / p.outs.len() as f64,
    }
}

/// The relative error of a group's `stat` against the exact engine's on the
/// same scene, |a / b - 1|, with its standard error; None when either is
/// missing.
pub fn error(a: &Stats, b: &Stats) -> Option<(f64, f64)> {
    if a.n == 0 || b.n == 0 || b.mean == 0.0 || !(a.mean.is_finite() && b.mean.is_finite()) {
        return None;
    }
    let ratio = a.mean / b.mean;
    let rel = |s: &Stats| {
        if s.n > 1 { s.stderr / s.mean } else { 0.0 }
    };
    let se = ratio.abs() * (rel(a).powi(2) + rel(b).powi(2)).sqrt();
    Some(((ratio - 1.0).abs(), se))
}
