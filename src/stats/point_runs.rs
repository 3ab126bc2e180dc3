//! The runs of one sweep point or case, and statistics over them.

use super::ensemble::Runs;
use super::summary::{Stats, scalar};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::model::scene::SceneSpec;
use std::collections::BTreeMap;

/// The runs of one point (they share its descriptor).
pub struct PointRuns<'a> {
    pub spec: &'a RunSpec,
    pub outs: Vec<&'a RunOutput>,
    /// Every run of the plan, for the point's series means.
    all: &'a Runs,
}

/// The runs grouped by point, in the order of the points' ids (sweep
/// points and cases are numbered apart, in plan order).
pub fn by_point(runs: &Runs) -> Vec<PointRuns<'_>> {
    let mut points: BTreeMap<u64, PointRuns> = BTreeMap::new();
    for (spec, out) in runs.iter() {
        points
            .entry(spec.point_id)
            .or_insert_with(|| PointRuns {
                spec,
                outs: Vec::new(),
                all: runs,
            })
            .outs
            .push(out);
    }
    points.into_values().collect()
}

impl PointRuns<'_> {
    /// A scalar over the runs, finite values only.
    pub fn stat(&self, name: &str) -> Stats {
        scalar(self.outs.iter().copied(), name)
    }
    /// A scalar's value in the first run (for one that is the same in
    /// every run of a point).
    pub fn first(&self, name: &str) -> f64 {
        self.outs
            .first()
            .and_then(|o| o.scalar(name))
            .unwrap_or(f64::NAN)
    }
    pub fn cpu(&self) -> f64 {
        self.outs.iter().map(|o| o.cpu_seconds).sum()
    }
    pub fn collisions(&self) -> u64 {
        self.outs.iter().map(|o| o.collisions).sum()
    }
    /// The ensemble mean of a series at each sample time, with its standard
    /// error over the runs; empty if no run recorded it.
    pub fn mean_curve(&self, name: &str) -> (Vec<f64>, Vec<Stats>) {
        self.all.mean(self.spec.point_id, name).unwrap_or_default()
    }
    /// The point's scene, its preset applied.
    pub fn scene(&self) -> Option<SceneSpec> {
        crate::scene::resolve(&self.spec.descriptor.scene).ok()
    }
}
