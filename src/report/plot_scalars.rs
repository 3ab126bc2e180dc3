//! Each scalar result against the main swept numeric parameter: mean ± stderr
//! per point, one line per combination of the other swept parameters, theory
//! dashed beside it.

use super::chart::{ChartSpec, Layer, Paint};
use super::labels::{axis_label, short_name};
use super::plots::{Points, point_label, wants_log};
use crate::model::chart::colour;
use crate::model::summary::SummaryRow;
use std::collections::{BTreeMap, HashMap};

const THEORY: Paint = Paint {
    rgb: (30, 30, 30),
    alpha: 1.0,
};

/// (result name, chart) for each of `names`, in that order; the rows are
/// grouped by result in one pass.
pub fn charts(
    summary: &[&SummaryRow],
    names: &[&str],
    points: &Points,
) -> Vec<(String, ChartSpec)> {
    let mut by_result: HashMap<&str, Vec<&SummaryRow>> = HashMap::new();
    for r in summary {
        by_result.entry(r.result.as_str()).or_default().push(r);
    }
    let x_key = x_parameter(summary);
    names
        .iter()
        .filter_map(|&name| {
            let rows = by_result.get(name)?;
            Some((
                name.to_string(),
                chart(name, rows, x_key.as_deref(), points),
            ))
        })
        .collect()
}

/// The numeric swept parameter with the most distinct values (the sweep's
/// main axis; ties go to the first); None when nothing numeric is swept
/// (then x is the point id).
fn x_parameter(summary: &[&SummaryRow]) -> Option<String> {
    let first = summary.first()?;
    let distinct = |k: &str| {
        let mut v: Vec<u64> = summary.iter().map(|r| param(r, k).to_bits()).collect();
        v.sort_unstable();
        v.dedup();
        v.len()
    };
    let mut best: Option<(&str, usize)> = None;
    for (k, _) in &first.params {
        if summary.iter().all(|r| param(r, k).is_finite()) {
            let n = distinct(k);
            if best.is_none_or(|(_, m)| n > m) {
                best = Some((k, n));
            }
        }
    }
    best.map(|(k, _)| k.to_string())
}

fn param(row: &SummaryRow, key: &str) -> f64 {
    row.params
        .iter()
        .find(|(k, _)| k == key)
        .map_or(f64::NAN, |(_, v)| *v)
}

fn chart(name: &str, rows: &[&SummaryRow], x_key: Option<&str>, points: &Points) -> ChartSpec {
    let x_of = |r: &SummaryRow| x_key.map_or(r.point_id as f64, |k| param(r, k));
    // One line per combination of the parameters other than x.
    let mut groups: BTreeMap<String, Vec<&SummaryRow>> = BTreeMap::new();
    for r in rows {
        let others: Vec<(String, toml::Value)> = points
            .get(&r.point_id)
            .map(|p| {
                p.iter()
                    .filter(|(k, _)| Some(k.as_str()) != x_key)
                    .cloned()
                    .collect()
            })
            .unwrap_or_default();
        groups.entry(point_label(&others)).or_default().push(r);
    }
    let single = groups.len() == 1;
    let mut layers = Vec::new();
    // Theory goes last: drawn over the measurements, listed last in the legend.
    let mut theories = Vec::new();
    let mut theory_labelled = false;
    for (i, (label, mut group)) in groups.into_iter().enumerate() {
        group.sort_by(|a, b| x_of(a).total_cmp(&x_of(b)));
        let paint = colour(i);
        let means: Vec<(f64, f64)> = group.iter().map(|r| (x_of(r), r.mean)).collect();
        layers.push(Layer::ErrorBars {
            bars: group
                .iter()
                .filter(|r| r.stderr.is_finite())
                .map(|r| (x_of(r), r.mean - r.stderr, r.mean, r.mean + r.stderr))
                .collect(),
            paint,
        });
        layers.push(Layer::Line {
            points: means.clone(),
            paint,
            width: 2,
            dashed: false,
            label: None,
        });
        layers.push(Layer::Markers {
            points: means,
            paint,
            label: Some(if single {
                "measured (mean ± stderr)".into()
            } else {
                label
            }),
        });
        let theory: Vec<(f64, f64)> = group
            .iter()
            .filter_map(|r| r.theory.map(|t| (x_of(r), t)))
            .collect();
        if !theory.is_empty() {
            // One dark theory style for every line, so the legend needs one entry.
            theories.push(theory_layer(theory, THEORY, !theory_labelled));
            theory_labelled = true;
        }
    }
    layers.extend(theories);
    let xs = rows.iter().map(|r| x_of(r));
    let ys = rows.iter().flat_map(|r| {
        [
            r.mean - r.stderr,
            r.mean + r.stderr,
            r.mean,
            r.theory.unwrap_or(r.mean),
        ]
    });
    let x_label = x_key.map_or("sweep point".to_string(), axis_label);
    ChartSpec {
        title: format!("{name} vs {}", x_key.map_or("sweep point", short_name)),
        x_label,
        y_label: axis_label(name),
        x_log: x_key.is_some() && wants_log(xs),
        y_log: wants_log(ys),
        layers,
    }
}

/// Theory as a dashed line (and small markers, so a single point still shows).
fn theory_layer(points: Vec<(f64, f64)>, paint: Paint, labelled: bool) -> Layer {
    if points.len() == 1 {
        return Layer::Markers {
            points,
            paint: paint.faded(0.6),
            label: labelled.then(|| "theory".to_string()),
        };
    }
    Layer::Line {
        points,
        paint,
        width: 2,
        dashed: true,
        label: labelled.then(|| "theory (dashed)".to_string()),
    }
}
