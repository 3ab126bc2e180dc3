//! What the studies' runs and sections write the same way, beside charts:
//! named results, "mean ± se" cells and the section itself.

use crate::model::report::{Figure, ReportSection};
use crate::stats::format::pm;
use crate::stats::point_runs::PointRuns;

/// "mean ± standard error" of a result over a point's runs.
pub fn stat_pm(p: &PointRuns, name: &str) -> String {
    let s = p.stat(name);
    pm(s.mean, s.stderr)
}

/// Named results as a run's output holds them.
pub fn scalars<const N: usize>(values: [(&str, f64); N]) -> [(String, f64); N] {
    values.map(|(k, v)| (k.to_string(), v))
}

/// A study's section of the report, presenting every one of its `results`.
pub fn section(
    title: &str,
    markdown: String,
    figures: Vec<Figure>,
    results: &[&str],
) -> ReportSection {
    let presents = results.iter().map(|r| r.to_string()).collect();
    ReportSection {
        title: title.into(),
        markdown,
        figures,
        presents,
    }
}
