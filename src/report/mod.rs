//! SVG plots, report.md and a self-contained index.html.
//!
//! The report is written from one markdown text (`markdown.rs`); `html.rs`
//! renders that same text with the SVGs inlined, so the two never disagree.

pub mod chart;
pub mod contents;
mod findings;
pub mod html;
pub mod labels;
pub mod markdown;
pub mod movie;
mod plot_hist;
mod plot_scalars;
mod plot_series;
pub mod plots;
pub mod sampled;

pub use labels::axis_label;

use crate::files::write_atomic;
use crate::model::descriptor::Descriptor;
use crate::model::report::ReportSection;
use crate::model::summary::SummaryRow;
use crate::stats::ensemble::Runs;
use anyhow::Context;
use std::path::Path;

/// How the study was run, for the report's header, cost and failure sections.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReportMeta {
    pub command: String,
    pub threads: usize,
    pub started: String,
    pub finished: String,
    pub version: String,
    /// Wall time of the whole study (runs, tables, analyses; not this report).
    pub total_wall_seconds: f64,
    /// Wall time this invocation spent running runs.
    pub runs_wall_seconds: f64,
    /// Runs reused from an earlier invocation (their cost was paid then).
    pub resumed_runs: usize,
    /// Runs the plan has (failed ones included; 0: as many as were given).
    pub planned_runs: usize,
    /// (run id, error message) of runs that did not finish.
    pub failed_runs: Vec<(u64, String)>,
}

/// Write the generic plots, `report.md` and `index.html` into `out_dir`
/// (created if missing), and the figures of the studies' `sections`, which
/// come first, in order.
pub fn write(
    out_dir: &Path,
    descriptor: &Descriptor,
    runs: &Runs,
    summary: &[SummaryRow],
    sections: &[ReportSection],
    meta: &ReportMeta,
) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)
        .with_context(|| format!("creating report folder {}", out_dir.display()))?;
    for figure in sections.iter().flat_map(|s| &s.figures) {
        let svg = chart::render(&figure.chart);
        write_atomic(&out_dir.join(&figure.file), svg.as_bytes())?;
    }
    let presented: Vec<String> = sections.iter().flat_map(|s| s.presents.clone()).collect();
    let figures = plots::write_all(out_dir, &presented, runs, summary)?;
    let points = plots::points(runs);
    let md = markdown::render(&markdown::Inputs {
        descriptor,
        runs,
        summary,
        sections,
        meta,
        figures: &figures.figures,
        omitted: &figures.omitted,
        points: &points,
    });
    write_atomic(&out_dir.join("report.md"), md.as_bytes())?;
    let page = html::page(&descriptor.study.name, &md, out_dir);
    write_atomic(&out_dir.join("index.html"), page.as_bytes())
}
