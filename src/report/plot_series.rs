//! Each time series: per sweep point (up to MAX_POINTS of them, evenly chosen)
//! the replica mean with a ±1 std band, over a few single runs drawn faintly.

use super::chart::{ChartSpec, Layer};
use super::labels::axis_label;
use super::plots::{Points, evenly, point_label};
use crate::model::chart::colour;
use crate::model::run_output::{RunOutput, Series};
use crate::model::run_spec::RunSpec;
use std::collections::BTreeSet;

const MAX_POINTS: usize = 6;
const TRACES_PER_POINT: usize = 2;

/// (observable, chart) for every observable a run of `points` recorded, sorted by name.
pub fn charts(runs: &[(RunSpec, RunOutput)], points: &Points) -> Vec<(String, ChartSpec)> {
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

fn chart(name: &str, runs: &[(RunSpec, RunOutput)], shown: &[u64], points: &Points) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, id) in shown.iter().enumerate() {
        let replicas: Vec<&Series> = runs
            .iter()
            .filter(|(s, _)| s.point_id == *id)
            .filter_map(|(_, o)| o.series(name))
            .filter(|s| !s.t.is_empty() && !s.value.is_empty())
            .collect();
        let Some(first) = replicas.first() else {
            continue;
        };
        let paint = colour(i);
        for trace in replicas.iter().take(TRACES_PER_POINT) {
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
        let (mean, std) = mean_std(&replicas);
        let t: Vec<f64> = first.t.iter().copied().take(mean.len()).collect();
        if replicas.len() >= 2 {
            layers.push(Layer::Band {
                x: t.clone(),
                lower: mean.iter().zip(&std).map(|(m, s)| m - s).collect(),
                upper: mean.iter().zip(&std).map(|(m, s)| m + s).collect(),
                paint: paint.faded(0.18),
            });
        }
        let params = points.get(id).map(Vec::as_slice).unwrap_or(&[]);
        layers.push(Layer::Line {
            points: t.into_iter().zip(mean).collect(),
            paint,
            width: 2,
            dashed: false,
            label: Some(format!(
                "{} (mean of {})",
                point_label(params),
                replicas.len()
            )),
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

/// Mean and sample std at each time index over replicas, truncated to the
/// shortest replica (they share a t grid); non-finite samples are skipped and
/// an index with none left is NaN (a gap in the line).
pub fn mean_std(replicas: &[&Series]) -> (Vec<f64>, Vec<f64>) {
    let len = replicas
        .iter()
        .map(|s| s.t.len().min(s.value.len()))
        .min()
        .unwrap_or(0);
    (0..len)
        .map(|i| {
            let v: Vec<f64> = replicas
                .iter()
                .map(|s| s.value[i])
                .filter(|v| v.is_finite())
                .collect();
            let n = v.len() as f64;
            let mean = if v.is_empty() {
                f64::NAN
            } else {
                v.iter().sum::<f64>() / n
            };
            let std = if v.len() < 2 {
                0.0
            } else {
                (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
            };
            (mean, std)
        })
        .unzip()
}
