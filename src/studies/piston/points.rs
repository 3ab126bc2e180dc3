//! The piston sweep, point by point: each point's runs summarised (the
//! statistics of every result the report shows, its cost), and the points
//! grouped by dimension and by the parameters other than the piston's mass.

use crate::stats::decay::decay_bound;
use crate::stats::ensemble::Runs;
use crate::stats::groups::first_seen;
use crate::stats::point_runs::{PointRuns, by_point};
use crate::stats::summary::Stats;

const MASS_KEY: &str = "scene.piston.mass";
const PRESET_KEY: &str = "scene.preset";

/// One sweep point's runs, summarised.
pub struct Point<'a> {
    pub dimension: usize,
    /// Swept parameters other than the piston mass and the preset
    /// ("energy=10, per_side=5").
    pub group: String,
    pub mass: f64,
    pub runs: usize,
    pub duration: f64,
    pub sample_every: f64,
    /// 1/N_free.
    pub equipartition: f64,
    pub seconds: f64,
    pub of: PointRuns<'a>,
}

/// The sweep's points in order of their ids (cases are not the sweep's).
pub fn points(runs: &Runs) -> Vec<Point<'_>> {
    (by_point(runs).into_iter())
        .filter(|p| p.spec.case.is_none())
        .map(|of| {
            let spec = of.spec;
            let group: Vec<String> = (spec.params.iter())
                .filter(|(k, _)| k != MASS_KEY && k != PRESET_KEY)
                .map(|(k, v)| format!("{}={v}", k.rsplit('.').next().unwrap_or(k)))
                .collect();
            let run = &spec.descriptor.run;
            Point {
                dimension: of.scene().and_then(|s| s.dimension).unwrap_or(0),
                group: group.join(", "),
                mass: of.first("mass_ratio"),
                runs: of.outs.len(),
                duration: run.duration.unwrap_or(f64::NAN),
                sample_every: run.sample_every.unwrap_or(f64::NAN),
                equipartition: super::theory(&spec.descriptor, "piston_share").unwrap_or(f64::NAN),
                seconds: of.outs.iter().map(|o| o.wall_seconds).sum(),
                of,
            }
        })
        .collect()
}

impl Point<'_> {
    pub fn stat(&self, name: &str) -> Stats {
        self.of.stat(name)
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
pub fn by_dimension<'a, 'b>(points: &'a [Point<'b>]) -> Vec<Vec<&'a Point<'b>>> {
    let mut all = first_seen(points, |a, b| a.dimension == b.dimension);
    all.sort_by_key(|d| d[0].dimension);
    all
}

/// Groups of points (same parameters but the mass), in first-seen order.
pub fn groups<'a, 'b>(points: &[&'a Point<'b>]) -> Vec<Vec<&'a Point<'b>>> {
    first_seen(points.iter().copied(), |a, b| a.group == b.group)
}
