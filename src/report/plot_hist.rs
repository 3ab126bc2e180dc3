//! Each histogram: the mean count per bin over replicas, as a step outline per
//! sweep point (outlines stay readable when several points overlap).

use super::chart::{ChartSpec, Layer};
use super::labels::axis_label;
use super::plots::{Points, evenly, point_label};
use crate::model::chart::colour;
use crate::model::run_output::{Histogram, RunOutput};
use crate::model::run_spec::RunSpec;
use std::collections::{HashMap, HashSet};

const MAX_POINTS: usize = 6;

/// (observable, chart) for each of `names`, in that order; the histograms
/// are gathered in one pass over the runs of the points shown.
pub fn charts(
    runs: &[(RunSpec, RunOutput)],
    names: &[&str],
    points: &Points,
) -> Vec<(String, ChartSpec)> {
    let ids: Vec<u64> = points.keys().copied().collect();
    let shown = evenly(&ids, MAX_POINTS);
    let column: HashMap<&str, usize> = names.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let mut found: HashMap<(usize, u64), Vec<&Histogram>> = HashMap::new();
    for (spec, out) in runs.iter().filter(|(s, _)| shown.contains(&s.point_id)) {
        let mut seen = HashSet::new();
        for h in &out.histograms {
            // The first histogram of a name in a run counts.
            if let Some(&i) = column.get(h.observable.as_str())
                && seen.insert(i)
            {
                found.entry((i, spec.point_id)).or_default().push(h);
            }
        }
    }
    names
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let chart = chart(name, &shown, points, &|id| {
                found.get(&(i, id)).map_or(&[][..], Vec::as_slice)
            });
            (name.to_string(), chart)
        })
        .collect()
}

fn chart<'a>(
    name: &str,
    shown: &[u64],
    points: &Points,
    histograms: &dyn Fn(u64) -> &'a [&'a Histogram],
) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, id) in shown.iter().enumerate() {
        let hists = histograms(*id);
        let Some((mean, n)) = mean_counts(hists) else {
            continue;
        };
        let bins = hists[0];
        let mut outline = Vec::with_capacity(2 * mean.len());
        for ((lo, hi), c) in bins.lo.iter().zip(&bins.hi).zip(&mean) {
            outline.push((*lo, *c));
            outline.push((*hi, *c));
        }
        let params = points.get(id).map(Vec::as_slice).unwrap_or(&[]);
        layers.push(Layer::Line {
            points: outline,
            paint: colour(i),
            width: 2,
            dashed: false,
            label: Some(format!("{} (mean of {n})", point_label(params))),
        });
    }
    ChartSpec {
        title: format!("histogram of {name}"),
        x_label: axis_label(name),
        y_label: "mean count per bin".into(),
        x_log: false,
        y_log: false,
        layers,
    }
}

/// Mean count per bin over the histograms that share the first one's bins
/// (others are left out rather than misaligned), and how many were averaged.
pub fn mean_counts(hists: &[&Histogram]) -> Option<(Vec<f64>, usize)> {
    let first = hists.first()?;
    let bins = first.lo.len().min(first.hi.len()).min(first.count.len());
    if bins == 0 {
        return None;
    }
    let same: Vec<&&Histogram> = hists
        .iter()
        .filter(|h| h.lo.len() >= bins && h.count.len() >= bins && h.lo[..bins] == first.lo[..bins])
        .collect();
    let n = same.len() as f64;
    let mean = (0..bins)
        .map(|b| same.iter().map(|h| h.count[b]).sum::<f64>() / n)
        .collect();
    Some((mean, same.len()))
}
