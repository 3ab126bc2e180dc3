//! Each time series: per sweep point (up to MAX_POINTS of them, evenly chosen)
//! the replica mean with a ±1 std band, over a few single runs drawn faintly.

use super::chart::{ChartSpec, Layer};
use super::labels::axis_label;
use super::plots::{Points, evenly, point_label};
use crate::model::chart::colour;
use crate::model::run_output::Series;
use crate::stats::ensemble::Runs;
use crate::stats::summary::Stats;
use std::collections::{HashMap, HashSet};

const MAX_POINTS: usize = 6;
const TRACES_PER_POINT: usize = 2;

/// (observable, chart) for each of `names`, in that order. The single runs
/// drawn are gathered in one pass over the runs of the points shown.
pub fn charts(runs: &Runs, names: &[&str], points: &Points) -> Vec<(String, ChartSpec)> {
    let ids: Vec<u64> = points.keys().copied().collect();
    let shown = evenly(&ids, MAX_POINTS);
    let column: HashMap<&str, usize> = names.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let mut traces: HashMap<(usize, u64), Vec<&Series>> = HashMap::new();
    for (spec, out) in runs.iter().filter(|(s, _)| shown.contains(&s.point_id)) {
        let mut seen = HashSet::new();
        for series in &out.series {
            let Some(&i) = column.get(series.observable.as_str()) else {
                continue;
            };
            // The first series of a name in a run, as `RunOutput::series` reads it.
            let kept = traces.entry((i, spec.point_id)).or_default();
            if seen.insert(i) && kept.len() < TRACES_PER_POINT {
                kept.push(series);
            }
        }
    }
    names
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let chart = chart(name, runs, &shown, points, &|id| {
                traces.get(&(i, id)).map_or(&[][..], Vec::as_slice)
            });
            (name.to_string(), chart)
        })
        .collect()
}

fn chart<'a>(
    name: &str,
    runs: &Runs,
    shown: &[u64],
    points: &Points,
    traces: &dyn Fn(u64) -> &'a [&'a Series],
) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, id) in shown.iter().enumerate() {
        let Some((t, stats)) = runs.mean(*id, name).filter(|(t, _)| !t.is_empty()) else {
            continue;
        };
        let paint = colour(i);
        for trace in traces(*id) {
            layers.push(Layer::Line {
                points: trace
                    .t
                    .iter()
                    .copied()
                    .zip(trace.value.iter().copied())
                    .collect(),
                paint: paint.faded(0.3),
                width: 1,
                dashed: false,
                label: None,
            });
        }
        let replicas = stats.iter().map(|s| s.n).max().unwrap_or(0);
        if replicas >= 2 {
            // One std either side (not the standard error): the spread of single runs.
            let spread = |s: &Stats| if s.n < 2 { 0.0 } else { s.std };
            layers.push(Layer::Band {
                x: t.clone(),
                lower: stats.iter().map(|s| s.mean - spread(s)).collect(),
                upper: stats.iter().map(|s| s.mean + spread(s)).collect(),
                paint: paint.faded(0.18),
            });
        }
        let params = points.get(id).map(Vec::as_slice).unwrap_or(&[]);
        layers.push(Layer::Line {
            points: t.into_iter().zip(stats.iter().map(|s| s.mean)).collect(),
            paint,
            width: 2,
            dashed: false,
            label: Some(format!("{} (mean of {replicas})", point_label(params),)),
        });
    }
    ChartSpec {
        title: format!("{name} against time"),
        x_label: axis_label("t"),
        y_label: axis_label(name),
        x_log: false,
        y_log: false,
        layers,
    }
}
