//! The heat study's part of the report: the runs grouped by point and
//! handed to their experiment's part (relaxation, conduction, the 1D
//! chain), and what those parts share. The prose is in the Markdown files
//! beside this one.

use super::{Experiment, Gas, NAME, OPTIONS, RESULTS};
use crate::model::chart::{Layer, Paint};
use crate::model::descriptor::Descriptor;
use crate::model::report::ReportSection;
use crate::stats::ensemble::Runs as AllRuns;
use crate::stats::format::{num, pm};
use crate::stats::point_runs::{PointRuns, by_point};
use crate::stats::summary::{Stats, z_score};
use crate::studies::curves::polyline;
pub(super) use crate::studies::curves::{bar, figure, measured};
use crate::studies::options::value;

pub(super) const INTRO: &str = include_str!("intro.md");
pub(super) const METHODS: &str = include_str!("methods.md");
/// Captions and the findings' sentences, one per line.
pub(super) const CAPTIONS: &str = include_str!("captions.md");

/// The runs of one sweep point or case.
pub(super) type Runs<'a> = PointRuns<'a>;

/// "mean ± se (z = ..)" against `theory`.
pub(super) fn with_z(s: &Stats, theory: f64) -> String {
    match z_score(s, theory) {
        Some(z) => format!("{} (z = {:+.1})", pm(s.mean, s.stderr), z),
        None => pm(s.mean, s.stderr),
    }
}

/// A point's name: its case, or its sweep values.
pub(super) fn label(rs: &Runs, gas: &Gas) -> String {
    let what = format!("N = {}, φ = {}", num(gas.particles), num(gas.packing()));
    match &rs.spec.case {
        Some(c) => format!("{c} ({what})"),
        None => what,
    }
}

/// A dashed line of width 2: how this study draws its theories.
pub(super) fn dashed(points: Vec<(f64, f64)>, paint: Paint, label: String) -> Layer {
    polyline(points, paint, 2, true, Some(label))
}

pub fn section(d: &Descriptor, runs: &AllRuns) -> anyhow::Result<ReportSection> {
    let mut relaxing = Vec::new();
    let mut conducting = Vec::new();
    for rs in by_point(runs) {
        let Ok(gas) = Gas::of(&rs.spec.descriptor) else {
            continue;
        };
        match gas.experiment() {
            Ok(Experiment::Relax { wall }) => relaxing.push((gas, wall, rs)),
            Ok(Experiment::Conduct {
                hot,
                cold,
                hot_high,
            }) => conducting.push((gas, (hot, cold, hot_high), rs)),
            Err(_) => {}
        }
    }
    let mut md = String::from(INTRO);
    let mut figures = Vec::new();
    if !relaxing.is_empty() {
        let window = value(d, NAME, OPTIONS, "initial_window");
        md.push_str(&super::section_relax::part(window, &relaxing, &mut figures));
    }
    // Rods conduct anomalously: their own part.
    let (rods, balls): (Vec<_>, Vec<_>) = conducting.into_iter().partition(|p| p.0.dimension == 1);
    if !balls.is_empty() {
        let width = value(d, NAME, OPTIONS, "fit_width");
        md.push_str(&super::section_conduct::part(width, &balls, &mut figures));
    }
    if !rods.is_empty() {
        md.push_str(&super::chain::part(&rods, &mut figures));
    }
    md.push_str(METHODS);
    let title = "Heat transfer across the boundary";
    Ok(crate::studies::parts::section(title, md, figures, RESULTS))
}

#[cfg(test)]
mod tests {
    use super::super::{chain, section_conduct, section_relax};

    /// Each part fills every `{key}` of its text (with no points too).
    #[test]
    fn every_placeholder_is_filled() {
        let figures = &mut Vec::new();
        for text in [
            section_relax::part(0.1, &[], figures),
            section_conduct::part(0.5, &[], figures),
            chain::part(&[], figures),
        ] {
            assert!(crate::stats::fill::unfilled(&text).is_empty(), "{text}");
        }
    }
}
