//! The generic plots every study gets: each scalar result against the swept
//! parameter, each time series, each histogram. Builders live in their own
//! files; this one names, renders and writes them.

use super::chart::{self, ChartSpec};
use super::labels::{short_name, slug};
use super::{plot_hist, plot_scalars, plot_series, sampled};
use crate::files::write_atomic;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::model::summary::SummaryRow;
use crate::stats::ensemble::Runs;
use std::collections::{BTreeMap, BTreeSet, HashSet};
use std::path::Path;

/// A plot written into the out dir.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub file: String,
    pub caption: String,
}

/// Swept parameters of each point, as the planner gave them; a case's
/// point is labelled by its name (`case` = name).
pub type Points = BTreeMap<u64, Vec<(String, toml::Value)>>;

pub fn points(runs: &[(RunSpec, RunOutput)]) -> Points {
    let mut points = Points::new();
    for (spec, _) in runs {
        points
            .entry(spec.point_id)
            .or_insert_with(|| match &spec.case {
                Some(name) => vec![("case".into(), toml::Value::String(name.clone()))],
                None => spec.params.to_vec(),
            });
    }
    points
}

/// The generic figures written, in report order, and what the report says
/// about those it left out (`sampled.rs`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Figures {
    pub figures: Vec<Figure>,
    pub omitted: Vec<String>,
}

/// Render and write the generic plots of the sweep; returns them in report
/// order. A result a study presents in its own section gets no generic
/// plot, nor does `energy_drift` (the report gives its largest value in a
/// line); cases are their studies' to show. Many names are sampled
/// (`sampled.rs`); each chart gathers its data in one pass over the runs.
pub fn write_all(
    out_dir: &Path,
    presented: &[String],
    runs: &Runs,
    summary: &[SummaryRow],
) -> anyhow::Result<Figures> {
    let mut points = points(runs);
    let cases: HashSet<u64> = runs
        .iter()
        .filter(|(s, _)| s.case.is_some())
        .map(|(s, _)| s.point_id)
        .collect();
    points.retain(|id, _| !cases.contains(id));
    let presented: HashSet<&str> = presented.iter().map(String::as_str).collect();
    let mut charts: Vec<(String, ChartSpec, String)> = Vec::new();
    let mut files = FileNames::default();
    let mut omitted = Vec::new();
    let generic: Vec<&SummaryRow> = summary
        .iter()
        .filter(|r| r.result != "energy_drift" && !presented.contains(r.result.as_str()))
        .filter(|r| points.contains_key(&r.point_id))
        .collect();
    let names: BTreeSet<&str> = generic.iter().map(|r| r.result.as_str()).collect();
    let names: Vec<&str> = names.into_iter().collect();
    let (shown, notes) = sampled::chosen(&names, "Scalar results", "summary.parquet");
    omitted.extend(notes);
    for (name, spec) in plot_scalars::charts(&generic, &shown, &points) {
        let caption =
            format!("{name}: mean ± standard error per sweep point, with theory where known");
        charts.push((files.unique("scalar", &name), spec, caption));
    }
    let in_sweep = || {
        runs.iter()
            .filter(|(s, _)| points.contains_key(&s.point_id))
    };
    let names: BTreeSet<&str> = in_sweep()
        .flat_map(|(_, o)| o.series.iter().map(|s| s.observable.as_str()))
        .collect();
    let names: Vec<&str> = names.into_iter().collect();
    let (shown, notes) = sampled::chosen(&names, "Series", "series.parquet");
    omitted.extend(notes);
    for (name, spec) in plot_series::charts(runs, &shown, &points) {
        let caption =
            format!("{name} against time: mean over replicas with ±1 std band, and single runs");
        charts.push((files.unique("series", &name), spec, caption));
    }
    let names: BTreeSet<&str> = in_sweep()
        .flat_map(|(_, o)| o.histograms.iter().map(|h| h.observable.as_str()))
        .collect();
    let names: Vec<&str> = names.into_iter().collect();
    let (shown, notes) = sampled::chosen(&names, "Histograms", "histograms.parquet");
    omitted.extend(notes);
    for (name, spec) in plot_hist::charts(runs, &shown, &points) {
        let caption = format!("{name}: mean count per bin over replicas");
        charts.push((files.unique("hist", &name), spec, caption));
    }
    let mut figures = Vec::new();
    for (file, spec, caption) in charts {
        write_atomic(&out_dir.join(&file), chart::render(&spec).as_bytes())?;
        figures.push(Figure { file, caption });
    }
    Ok(Figures { figures, omitted })
}

/// SVG file names from result names. Slugs can collide ("a.b" and "a_b",
/// "A" and "a"): a later name gets `_2`, `_3`, ...; names come in a fixed
/// order, so each keeps its file from run to run.
#[derive(Default)]
pub struct FileNames {
    used: std::collections::HashSet<String>,
}

impl FileNames {
    pub fn unique(&mut self, prefix: &str, name: &str) -> String {
        let stem = format!("{prefix}_{}", slug(name));
        let mut file = format!("{stem}.svg");
        let mut k = 1;
        while !self.used.insert(file.clone()) {
            k += 1;
            file = format!("{stem}_{k}.svg");
        }
        file
    }
}

/// "mass=10, n=4" for a point's parameters ("all runs" when nothing is swept).
pub fn point_label(params: &[(String, toml::Value)]) -> String {
    if params.is_empty() {
        return "all runs".into();
    }
    params
        .iter()
        .map(|(k, v)| format!("{}={}", short_name(k), value_text(v)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// A TOML value without quotes around strings.
pub fn value_text(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Float(f) => crate::stats::format::num(*f),
        other => other.to_string(),
    }
}

/// At most `k` items spread evenly over `items`, first and last included.
pub fn evenly<T: Copy>(items: &[T], k: usize) -> Vec<T> {
    if items.len() <= k || k < 2 {
        return items.iter().copied().take(k).collect();
    }
    (0..k)
        .map(|i| items[(i * (items.len() - 1) + (k - 1) / 2) / (k - 1)])
        .collect()
}

/// True when positive values span more than 1.5 decades: then a log axis
/// shows the structure a linear one would squash.
pub fn wants_log(values: impl Iterator<Item = f64>) -> bool {
    let mut any = false;
    let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
    for v in values.filter(|v| v.is_finite()) {
        if v <= 0.0 {
            return false;
        }
        any = true;
        lo = lo.min(v);
        hi = hi.max(v);
    }
    any && (hi / lo).log10() > 1.5
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn even_choice_keeps_ends() {
        let v: Vec<u32> = (0..20).collect();
        let e = evenly(&v, 6);
        assert_eq!(e.len(), 6);
        assert_eq!((e[0], e[5]), (0, 19));
        assert_eq!(evenly(&[1, 2], 6), vec![1, 2]);
        assert!(evenly::<u32>(&[], 6).is_empty());
    }

    #[test]
    fn colliding_slugs_get_distinct_files() {
        let mut files = FileNames::default();
        assert_eq!(files.unique("scalar", "a.b"), "scalar_a_b.svg");
        assert_eq!(files.unique("scalar", "a_b"), "scalar_a_b_2.svg");
        assert_eq!(files.unique("scalar", "A.B"), "scalar_a_b_3.svg");
        assert_eq!(files.unique("series", "a.b"), "series_a_b.svg");
        // A name whose own slug looks like a numbered one still gets its own file.
        assert_eq!(files.unique("scalar", "a_b_2"), "scalar_a_b_2_2.svg");
    }

    #[test]
    fn log_only_for_wide_positive() {
        assert!(wants_log([1.0, 100.0].into_iter()));
        assert!(!wants_log([1.0, 10.0].into_iter()));
        assert!(!wants_log([-1.0, 100.0].into_iter()));
        assert!(!wants_log(std::iter::empty()));
    }
}
