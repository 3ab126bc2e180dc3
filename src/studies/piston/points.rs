//! The piston sweep, point by point: each point's runs summarised (the
//! statistics of every result the report shows, its cost), and the points
//! grouped by dimension and by the parameters other than the piston's mass.

use super::RESULTS;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::decay::decay_bound;
use crate::stats::groups::first_seen;
use crate::stats::summary::Stats;
use std::collections::BTreeMap;

const MASS_KEY: &str = "scene.piston.mass";
const PRESET_KEY: &str = "scene.preset";

/// One sweep point's runs, summarised.
pub struct Point {
    pub id: u64,
    pub dimension: usize,
    /// Swept parameters other than the piston mass and the preset
    /// ("energy=10, per_side=5").
    pub group: String,
    pub mass: f64,
    pub runs: usize,
    pub duration: f64,
    pub sample_every: f64,
    stats: BTreeMap<&'static str, Stats>,
    /// 1/N_free.
    pub equipartition: f64,
    pub seconds: f64,
    pub collisions: u64,
}

/// The sweep's points in order of their ids (cases are not the sweep's).
pub fn points(runs: &[(RunSpec, RunOutput)]) -> Vec<Point> {
    let mut by_id: BTreeMap<u64, Vec<&(RunSpec, RunOutput)>> = BTreeMap::new();
    for r in runs.iter().filter(|(s, _)| s.case.is_none()) {
        by_id.entry(r.0.point_id).or_default().push(r);
    }
    by_id
        .into_iter()
        .map(|(id, rs)| {
            let spec = &rs[0].0;
            let group: Vec<String> = spec
                .params
                .iter()
                .filter(|(k, _)| k != MASS_KEY && k != PRESET_KEY)
                .map(|(k, v)| format!("{}={v}", k.rsplit('.').next().unwrap_or(k)))
                .collect();
            let stats = RESULTS
                .iter()
                .map(|&name| {
                    let v: Vec<f64> = rs
                        .iter()
                        .filter_map(|r| r.1.scalar(name))
                        .filter(|v| v.is_finite())
                        .collect();
                    (name, Stats::of(&v))
                })
                .collect();
            Point {
                id,
                dimension: crate::scene::resolve(&spec.descriptor.scene)
                    .ok()
                    .and_then(|s| s.dimension)
                    .unwrap_or(0),
                group: group.join(", "),
                mass: rs[0].1.scalar("mass_ratio").unwrap_or(f64::NAN),
                runs: rs.len(),
                duration: spec.descriptor.run.duration.unwrap_or(f64::NAN),
                sample_every: spec.descriptor.run.sample_every.unwrap_or(f64::NAN),
                stats,
                equipartition: super::theory(&spec.descriptor, "piston_share").unwrap_or(f64::NAN),
                seconds: rs.iter().map(|r| r.1.wall_seconds).sum(),
                collisions: rs.iter().map(|r| r.1.collisions).sum(),
            }
        })
        .collect()
}

impl Point {
    pub fn stat(&self, name: &str) -> Stats {
        self.stats.get(name).copied().unwrap_or(Stats::of(&[]))
    }

    /// "M=100, energy=10, per_side=5" (the mass alone when nothing else is swept).
    pub fn label(&self) -> String {
        let mass = format!("M={}", crate::stats::format::num(self.mass));
        if self.group.is_empty() {
            mass
        } else {
            // Swept values may be any text (a species' name): shown literally.
            format!("{mass}, {}", crate::model::text::text(&self.group))
        }
    }

    /// Every run reached 1/e of its excess.
    pub fn relaxed(&self) -> bool {
        self.stat("relaxation_time").n as usize == self.runs
    }

    /// Lower bound on the mean relaxation time of a point whose runs did not
    /// all reach 1/e: the mean of min(tau, T) over its runs (runs that did not
    /// reach it within T took longer), or, if larger, the bound from what is
    /// left of the excess (at 2 standard errors above the mean, so it errs low).
    pub fn tau_bound(&self) -> f64 {
        let tau = self.stat("relaxation_time");
        let reached = if tau.n > 0 {
            tau.mean * tau.n as f64
        } else {
            0.0
        };
        let censored =
            (reached + (self.runs - tau.n as usize) as f64 * self.duration) / self.runs as f64;
        let left = self.stat("excess_left");
        let from_left = decay_bound(self.duration, left.mean + 2.0 * left.stderr.max(0.0));
        if from_left.is_finite() {
            censored.max(from_left)
        } else {
            censored
        }
    }
}

/// The points of each dimension, in order of dimension.
pub fn by_dimension(points: &[Point]) -> Vec<(usize, Vec<&Point>)> {
    let mut out: BTreeMap<usize, Vec<&Point>> = BTreeMap::new();
    for p in points {
        out.entry(p.dimension).or_default().push(p);
    }
    out.into_iter().collect()
}

/// Groups of points (same parameters but the mass), in first-seen order.
pub fn groups<'a>(points: &[&'a Point]) -> Vec<(String, Vec<&'a Point>)> {
    first_seen(points.iter().copied(), |a, b| a.group == b.group)
        .into_iter()
        .map(|g| (g[0].group.clone(), g))
        .collect()
}
