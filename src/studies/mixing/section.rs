//! The mixing study's part of the report: the 1D runs (rods, hot start) and
//! the 2D runs (two species started apart) each get their own half, from
//! the runs of the plan grouped by sweep point or case.

use super::{section_disks, section_rods};
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::ensemble::Runs;
use crate::stats::summary::Stats;
use std::collections::BTreeMap;

/// The runs of one sweep point or case.
pub struct Point<'a> {
    pub spec: &'a RunSpec,
    pub outs: Vec<&'a RunOutput>,
    /// Every run of the plan, for the point's series means.
    all: &'a Runs,
}

impl Point<'_> {
    /// A scalar over the runs, finite values only.
    pub fn stat(&self, name: &str) -> Stats {
        crate::stats::summary::scalar(self.outs.iter().copied(), name)
    }
    /// A scalar's value in the first run (the same in every run of a point).
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
    /// How many runs mixed within their length.
    pub fn mixed(&self) -> usize {
        self.outs
            .iter()
            .filter(|o| o.scalar("mixed") == Some(1.0))
            .count()
    }
    /// The ensemble mean of a series at each sample time, with its standard
    /// error over the runs (runs of a point share their sample times; a
    /// shorter record ends the curve).
    pub fn mean_curve(&self, name: &str) -> (Vec<f64>, Vec<Stats>) {
        self.all.mean(self.spec.point_id, name).unwrap_or_default()
    }
}

fn dimension(spec: &RunSpec) -> usize {
    crate::scene::resolve(&spec.descriptor.scene)
        .ok()
        .and_then(|s| s.dimension().ok())
        .unwrap_or(0)
}

pub fn section(runs: &Runs) -> anyhow::Result<ReportSection> {
    let mut by_point: BTreeMap<u64, Point> = BTreeMap::new();
    for (spec, out) in runs.iter() {
        by_point
            .entry(spec.point_id)
            .or_insert_with(|| Point {
                spec,
                outs: Vec::new(),
                all: runs,
            })
            .outs
            .push(out);
    }
    let (rods, disks): (Vec<Point>, Vec<Point>) =
        by_point.into_values().partition(|p| dimension(p.spec) == 1);
    let mut markdown = String::new();
    let mut figures: Vec<Figure> = Vec::new();
    if !rods.is_empty() {
        section_rods::write(&rods, &mut markdown, &mut figures);
    }
    if !disks.is_empty() {
        section_disks::write(&disks, &mut markdown, &mut figures);
    }
    markdown.push_str(METHODS);
    Ok(ReportSection {
        title: "Mixing time".into(),
        markdown,
        figures,
        presents: super::RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

const METHODS: &str = "\n### How each number is measured\n\n\
docs/mixing.md gives the definitions and why. In short: **1D** runs start with all the kinetic energy \
in one rod (the scene's piston rod; the gas at rest), between walls. The energy concentration \
Y = Σ(Kᵢ/K)² (`energy_concentration`) is 1 then; at equilibrium the energy shares are \
Dirichlet(½, …, ½) whatever the masses, and Y averages 3/(N + 2). The **mixing time** (`mixing_time`) \
is the first time the excess Y − 3/(N + 2) falls to 1/e of its start, interpolated between samples; \
`mixing_collisions` is the same time on the collision clock (collisions per rod, from the run's mean \
collision rate). A run whose Y never gets there within its length is **not mixed** (`mixed` = 0): it \
enters no mean, and a point with such runs is listed as censored and left out of every fit. \
`late_concentration_ratio` is Y over the last half of the run over 3/(N + 2) (1 when mixed); \
`concentration_change` the largest |Y(t) − Y(0)| (0 to rounding for equal masses: their collisions \
only swap velocities); `hot_share_ratio` the hot species' energy share over the last half over its \
count / N (equipartition: 1). **2D** runs start species A in the left half and B in the right of a \
box with walls along x and periodic along y. The fraction of the disks still in their own half \
starts at 1 and mixes to ½; its excess over ½ falling to 1/e is the mixing time. The self-diffusion \
coefficient D (`diffusion`) is measured in a periodic box of the same packing fraction and mass \
ratio: the slope over 2 of the mean-squared displacement (unwrapped) against lag, over both axes, \
fitted from a quarter of the longest lag on (`memory_ratio`: how many velocity-memory times D m/kT \
the fit starts after; above 5 the start's curvature biases D by under 1 %). The diffusion equation \
between walls from a step gives the fraction in its own half as ½ + Σ_odd 4/(πk)² exp(−k² t/τ_D), \
τ_D = L²/(π² D), L the centres' room along x; its 1/e time is the diffusive mixing time. Enskog's D \
for one kind of disk (`diffusion_enskog`) is (1/(2nσ)) √(kT/(π m)) / g(σ), g(σ) from Henderson's equation of state.\n";
