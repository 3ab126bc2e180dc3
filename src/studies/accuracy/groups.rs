//! The runs grouped as the section compares them: per scene, the exact
//! engine's runs and each (integrator, dt) of the fixed step, with the
//! ensemble statistics of every quantity the section shows.

use crate::model::descriptor::Integrator;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::groups::first_seen;
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

/// A scene's name: its preset, or "scene".
pub fn scene_of(spec: &RunSpec) -> String {
    spec.descriptor
        .scene
        .preset
        .clone()
        .unwrap_or_else(|| "scene".into())
}

/// Groups in the order their first run comes in the plan.
pub fn groups(runs: &[&(RunSpec, RunOutput)]) -> Vec<Group> {
    // Bits, so that NaN (no fixed step) is one key.
    let key = |s: &RunSpec| {
        let run = &s.descriptor.run;
        let dt = run.dt.unwrap_or(f64::NAN);
        let duration = run.duration.unwrap_or(f64::NAN);
        (
            scene_of(s),
            run.integrator,
            dt.to_bits(),
            duration.to_bits(),
        )
    };
    (first_seen(runs.iter().copied(), |a, b| key(&a.0) == key(&b.0)).iter())
        .map(|rs| group(rs))
        .collect()
}

fn group(rs: &[&(RunSpec, RunOutput)]) -> Group {
    let (first, _) = rs[0];
    let run = &first.descriptor.run;
    let runs: Vec<&RunOutput> = rs.iter().map(|(_, o)| o).collect();
    let values = |name: &str| -> Vec<f64> {
        (runs.iter())
            .filter_map(|o| o.scalar(name))
            .filter(|v| v.is_finite())
            .collect()
    };
    let stats = |name: &str| Stats::of(&values(name));
    let max = |name: &str| values(name).into_iter().fold(f64::NAN, f64::max);
    let collisions: u64 = runs.iter().map(|o| o.collisions).sum();
    let repeats: f64 = values("repeat_collisions").iter().sum();
    let cpu: Vec<f64> = runs.iter().map(|o| o.cpu_seconds).collect();
    Group {
        scene: scene_of(first),
        integrator: run.integrator,
        dt: run.dt.unwrap_or(f64::NAN),
        duration: run.duration.unwrap_or(f64::NAN),
        // A run with a piston records its frequency (NaN if unmeasured).
        piston: runs.iter().any(|o| o.scalar("piston_frequency").is_some()),
        runs: runs.len(),
        pressure: stats("beta_pressure"),
        collision_rate: stats("collision_rate"),
        frequency: stats("piston_frequency"),
        energy_drift: stats("energy_drift").mean,
        depth_max: max("overlap_depth_max"),
        depth_mean: stats("overlap_depth_mean").mean,
        longest: max("overlap_steps_max"),
        stuck: stats("stuck_pairs").mean,
        repeat_share: repeats / (collisions.max(1) as f64),
        cpu: Stats::of(&cpu).mean,
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
