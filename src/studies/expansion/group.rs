//! The runs of one sweep point or case, with what the report needs of them:
//! the scene as the theory sees it, how its velocities were drawn and the
//! ensemble-mean left fraction.

use super::measure::{Draw, Gas, draw};
use crate::stats::ensemble::Runs;
use crate::stats::format::num;
use crate::stats::passage::first_passage;
use crate::stats::point_runs::{PointRuns, by_point};
use crate::stats::summary::Stats;
use crate::theory::expansion_rods::Collisionless;
use std::ops::Deref;

pub struct Group<'a> {
    pub runs: PointRuns<'a>,
    pub gas: Option<Gas>,
    pub draw: Option<Draw>,
    /// Sample times and the ensemble's left fraction at each.
    pub t: Vec<f64>,
    pub mean: Vec<Stats>,
}

/// The points' runs, as their statistics and series.
impl<'a> Deref for Group<'a> {
    type Target = PointRuns<'a>;
    fn deref(&self) -> &PointRuns<'a> {
        &self.runs
    }
}

/// Runs grouped by sweep point (in order), then by case (in name order).
pub fn groups(runs: &Runs) -> Vec<Group<'_>> {
    let mut points = by_point(runs);
    points.sort_by_key(|p| p.spec.case.clone());
    (points.into_iter())
        .map(|runs| {
            let d = &runs.spec.descriptor;
            let (t, mean) = runs.mean_curve("left_fraction");
            let (gas, draw) = (Gas::of_descriptor(d), draw(d));
            Group {
                runs,
                gas,
                draw,
                t,
                mean,
            }
        })
        .collect()
}

impl Group<'_> {
    pub fn free(&self) -> Option<Collisionless> {
        Some(self.gas.as_ref()?.free(self.draw?))
    }

    /// Free particles with Maxwellian velocities at the start's kT: where
    /// collisions have made the velocities Maxwellian without yet changing
    /// the flight, a non-Maxwellian start tends to this curve (None for a
    /// Maxwellian start, whose own curve it is).
    pub fn free_thermal(&self) -> Option<Collisionless> {
        let gas = self.gas.as_ref()?;
        match self.draw? {
            Draw::Maxwell(_) => None,
            d => Some(gas.free(Draw::Maxwell(gas.temperature(d)))),
        }
    }

    pub fn tau_free(&self) -> f64 {
        self.free().map_or(f64::NAN, |f| f.relaxation_time())
    }

    /// The first passage of the ensemble-mean curve.
    pub fn tau_of_mean(&self) -> f64 {
        let curve: Vec<f64> = self.mean.iter().map(|s| s.mean).collect();
        first_passage(&self.t, &curve, 0.5)
    }

    pub fn dimension(&self) -> usize {
        self.gas.as_ref().map_or(0, |g| g.dimension)
    }

    pub fn particles(&self) -> f64 {
        self.gas.as_ref().map_or(f64::NAN, |g| g.particles as f64)
    }

    pub fn radius(&self) -> f64 {
        self.gas.as_ref().map_or(f64::NAN, |g| g.diameter / 2.0)
    }

    /// p_max of a uniform start (NaN for a Maxwellian one).
    pub fn p_max(&self) -> f64 {
        match self.draw {
            Some(Draw::Uniform(p)) => p,
            _ => f64::NAN,
        }
    }

    /// "p_max = 2" or "Maxwell kT = 1".
    pub fn start_text(&self) -> String {
        match self.draw {
            Some(Draw::Uniform(p)) => format!("p_max = {}", num(p)),
            Some(Draw::Maxwell(kt)) => format!("Maxwell kT = {}", num(kt)),
            None => "other".into(),
        }
    }

    /// "case: 100 disks, radius 0.5, p_max = 1".
    pub fn label(&self) -> String {
        let what = ["disks", "rods", "disks", "spheres"][self.dimension().min(3)];
        let case = (self.spec.case.as_ref()).map_or(String::new(), |c| format!("{c}: "));
        let (n, r) = (self.particles(), num(self.radius()));
        format!("{case}{n} {what}, radius {r}, {}", self.start_text())
    }
}
