//! The mixing study's part of the report: the 1D runs (rods, hot start) and
//! the 2D runs (two species started apart) each get their own half, from
//! the runs of the plan grouped by sweep point or case; and what the two
//! halves share. The prose is in the Markdown files beside this one.

use super::{section_disks, section_rods};
use crate::model::report::{Figure, ReportSection};
use crate::stats::ensemble::Runs;
use crate::stats::format::{num, pm};
use crate::stats::point_runs::{PointRuns, by_point};

const METHODS: &str = include_str!("methods.md");
/// The findings' sentences, one per outcome, and the figures' captions.
pub const SENTENCES: &str = include_str!("sentences.md");

/// The runs of one sweep point or case.
pub type Point<'a> = PointRuns<'a>;

/// How many runs of a point mixed within their length.
pub fn mixed(p: &Point) -> usize {
    (p.outs.iter())
        .filter(|o| o.scalar("mixed") == Some(1.0))
        .count()
}

pub fn all_mixed(p: &Point) -> bool {
    mixed(p) == p.outs.len()
}

/// A point's name: its values of the results named, each after its
/// symbol, and its case if it is one.
pub fn label(p: &Point, values: &[(&str, &str)]) -> String {
    let values = values
        .iter()
        .map(|(symbol, r)| format!("{symbol} = {}", num(p.first(r))));
    let what = values.collect::<Vec<_>>().join(", ");
    match &p.spec.case {
        Some(c) => format!("{what} (case {c})"),
        None => what,
    }
}

/// The mixing time over the runs that mixed: a lower bound when some did
/// not, only the run length when none did.
pub fn tau_text(p: &Point) -> String {
    let tau = p.stat("mixing_time");
    match mixed(p) {
        0 => format!(
            "> {} (none mixed)",
            num(p.spec.descriptor.run.duration.unwrap_or(f64::NAN))
        ),
        k if k < p.outs.len() => format!("{} (censored: a lower bound)", pm(tau.mean, tau.stderr)),
        _ => pm(tau.mean, tau.stderr),
    }
}

/// The distinct values of `value` over the points, in increasing order.
pub fn distinct<'a>(points: impl IntoIterator<Item = &'a Point<'a>>, value: &str) -> Vec<f64> {
    let mut v: Vec<f64> = points.into_iter().map(|p| p.first(value)).collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

pub fn section(runs: &Runs) -> anyhow::Result<ReportSection> {
    let (rods, disks): (Vec<Point>, Vec<Point>) = by_point(runs)
        .into_iter()
        .partition(|p| p.scene().and_then(|s| s.dimension().ok()) == Some(1));
    let mut markdown = String::new();
    let mut figures: Vec<Figure> = Vec::new();
    if !rods.is_empty() {
        markdown.push_str(&section_rods::part(&rods, &mut figures));
    }
    if !disks.is_empty() {
        markdown.push_str(&section_disks::part(&disks, &mut figures));
    }
    markdown.push_str(METHODS);
    let results = super::RESULTS;
    Ok(crate::studies::parts::section(
        "Mixing time",
        markdown,
        figures,
        results,
    ))
}

#[cfg(test)]
mod tests {
    use super::super::{section_disks, section_rods};
    use crate::stats::fill::unfilled;

    /// Each half fills every `{key}` of its text (with no points too), and
    /// the texts it fills only with data hold the keys it fills.
    #[test]
    fn every_placeholder_is_filled() {
        let figures = &mut Vec::new();
        for text in [
            section_rods::part(&[], figures),
            section_disks::part(&[], figures),
        ] {
            assert!(unfilled(&text).is_empty(), "{text}");
        }
        let widest = ["spread", "heaviest", "times", "verdict"];
        assert_eq!(unfilled(section_rods::WIDEST), widest);
        assert_eq!(unfilled(section_disks::BULK), ["verdict", "rows"]);
    }

    /// Every outcome and figure the halves name has its sentence.
    #[test]
    fn every_sentence_is_there() {
        let names: Vec<&str> = crate::stats::named::names(super::SENTENCES).collect();
        let outcomes = ["censored", "many", "few", "agree", "above", "below"];
        let captions = ["spread", "concentration", "sides", "density"];
        assert_eq!(names, [&outcomes[..], &captions].concat());
    }
}
