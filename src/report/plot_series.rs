//! Each time series: per sweep point (up to MAX_POINTS of them, evenly chosen)
//! the replica mean with a ±1 std band, over a few single runs drawn faintly.

use super::chart::{ChartSpec, Layer};
use super::labels::axis_label;
use super::plots::{Points, evenly, point_label};
use crate::model::chart::colour;
use crate::stats::ensemble::Runs;
use crate::stats::summary::Stats;
use std::collections::BTreeSet;

const MAX_POINTS: usize = 6;
const TRACES_PER_POINT: usize = 2;

/// (observable, chart) for every observable a run of `points` recorded, sorted by name.
pub fn charts(runs: &Runs, points: &Points) -> Vec<(String, ChartSpec)> {
    let names: BTreeSet<&str> = runs
        .iter()
        .filter(|(s, _)| points.contains_key(&s.point_id))
        .flat_map(|(_, o)| o.series.iter().map(|s| s.observable.as_str()))
        .collect();
    let ids: Vec<u64> = points.keys().copied().collect();
    let shown = evenly(&ids, MAX_POINTS);
    names
        .into_iter()
        .map(|name| (name.to_string(), chart(name, runs, &shown, points)))
        .collect()
}

fn chart(name: &str, runs: &Runs, shown: &[u64], points: &Points) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, id) in shown.iter().enumerate() {
        let Some((t, stats)) = runs.mean(*id, name).filter(|(t, _)| !t.is_empty()) else {
            continue;
        };
        let paint = colour(i);
        let traces = runs
            .iter()
            .filter(|(s, _)| s.point_id == *id)
            .filter_map(|(_, o)| o.series(name))
            .take(TRACES_PER_POINT);
        for trace in traces {
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
