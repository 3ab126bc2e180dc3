//! Error against effort for the other studies' headline results: the
//! `headline-*` cases run small versions of each study's headline scene
//! (its analysis named in the case) at a few run lengths. Per result: one
//! run's relative scatter σ₁ at each length with its CPU cost; the standard
//! error against replicas, measured from the spread of means of disjoint
//! groups of k replicas; both fitted against cost; the study's error model
//! (`Study::error_model`) beside what was measured; and a planning table.

use super::effort::{VERDICTS, exponent, plan};
use super::section::{head, replicas_line};
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::ensemble::Runs;
use crate::stats::error_model::{ErrorModel, scatter_uncertainty, scatter_uncertainty_of};
use crate::stats::fill::fill;
use crate::stats::format::{num, pm};
use crate::stats::groups::first_seen;
use crate::stats::line::{Sums, log_slope};
use crate::stats::named::named;
use crate::stats::point_runs::by_point;
use crate::stats::summary::{Stats, scalar};
use crate::stats::table::table_row;
use crate::studies::curves::{figure, markers, polyline};
use std::fmt::Write;

const INTRO: &str = include_str!("headlines.md");

/// The runs of one headline result at one run length.
pub struct Length<'a> {
    pub study: &'static str,
    /// The case's name without its length, and its scene as a key.
    pub name: String,
    pub scene: String,
    pub model: ErrorModel,
    pub duration: f64,
    /// The result of each run, in replica order (non-finite left out).
    pub values: Vec<f64>,
    pub runs: Vec<&'a RunOutput>,
    /// Mean CPU seconds of one run.
    pub cpu: f64,
}

impl Length<'_> {
    pub fn stats(&self) -> Stats {
        Stats::of(&self.values)
    }
    /// One run's relative scatter σ₁ (standard deviation over |mean|).
    pub fn scatter(&self) -> f64 {
        let s = self.stats();
        s.std / s.mean.abs()
    }
    /// For k = 1, 2, 4, ... while there are at least 4 groups: k, the
    /// relative standard error of the mean of k runs, measured as the
    /// spread of the means of disjoint groups of k consecutive replicas,
    /// and the number of groups.
    pub fn by_replicas(&self) -> Vec<(usize, f64, usize)> {
        let mean = self.stats().mean.abs();
        let k = (0..).map(|i| 1usize << i);
        (k.take_while(|k| self.values.len() / k >= 4))
            .map(|k| {
                let means: Vec<f64> = (self.values.chunks_exact(k))
                    .map(|c| c.iter().sum::<f64>() / k as f64)
                    .collect();
                (k, Stats::of(&means).std / mean, self.values.len() / k)
            })
            .collect()
    }
}

/// The study other than this one with an error model for a run's
/// descriptor, and the model: a run with one belongs to a headline case.
pub fn model_of(spec: &RunSpec) -> Option<(&'static str, ErrorModel)> {
    (crate::studies::error_models(&spec.descriptor).into_iter())
        .find(|(name, _)| *name != "accuracy")
}

/// The headline cases' points, in plan order.
pub fn lengths(runs: &Runs) -> Vec<Length<'_>> {
    (by_point(runs).into_iter())
        .filter_map(|p| {
            let (study, model) = model_of(p.spec)?;
            let case = p.spec.case.clone().unwrap_or_else(|| study.to_string());
            // "headline-piston-m100-n5-300" -> "m100-n5".
            let name = (case.trim_start_matches("headline-"))
                .trim_start_matches(study)
                .trim_start_matches('-')
                .rsplit_once('-')
                .map_or(String::new(), |(a, _)| a.to_string());
            let values = (p.outs.iter().filter_map(|o| o.scalar(model.result)))
                .filter(|v| v.is_finite())
                .collect();
            let cpu: Vec<f64> = (p.outs.iter().map(|o| o.cpu_seconds))
                .filter(|c| c.is_finite())
                .collect();
            Some(Length {
                study,
                name,
                scene: format!("{:?}", p.spec.descriptor.scene),
                model,
                duration: p.spec.descriptor.run.duration.unwrap_or(f64::NAN),
                values,
                runs: p.outs,
                cpu: cpu.iter().sum::<f64>() / cpu.len().max(1) as f64,
            })
        })
        .collect()
}

/// The groups of one study with at least two values, in plan order.
fn of<'a, 'b>(all: &'a [Length<'b>], study: &str) -> Vec<&'a Length<'b>> {
    all.iter()
        .filter(|l| l.study == study && l.values.len() > 1)
        .collect()
}

/// The groups of the scene run at the most lengths, shortest first: the
/// run-length series.
fn series<'a, 'b>(groups: &[&'a Length<'b>]) -> Vec<&'a Length<'b>> {
    let same = |a: &Length| groups.iter().filter(|g| g.scene == a.scene).count();
    let Some(most) = groups.iter().max_by_key(|g| same(g)) else {
        return Vec::new();
    };
    let mut v = groups.to_vec();
    v.retain(|g| g.scene == most.scene);
    v.sort_by(|a, b| a.duration.total_cmp(&b.duration));
    v
}

/// The length whose error costs least (σ₁² c smallest).
fn cheapest<'a, 'b>(lengths: &[&'a Length<'b>]) -> Option<&'a Length<'b>> {
    let cost = |l: &Length| l.scatter().powi(2) * l.cpu;
    (lengths.iter().copied())
        .filter(|l| l.cpu > 0.0 && l.scatter() > 0.0)
        .min_by(|a, b| cost(a).total_cmp(&cost(b)))
}

/// The markdown part (empty without headline runs) and its figure.
pub fn part(runs: &Runs) -> (String, Option<Figure>) {
    let all = lengths(runs);
    // The studies with headline runs, in plan order.
    let studies = first_seen(all.iter().map(|l| l.study), |a, b| a == b);
    let names: Vec<&str> = studies.into_iter().map(|g| g[0]).collect();
    if names.is_empty() {
        return (String::new(), None);
    }
    let mut md = String::from(INTRO);
    for study in &names {
        md.push_str(&one(study, &of(&all, study)));
    }
    (md, Some(chart(&all, &names)))
}

fn one(study: &str, groups: &[&Length]) -> String {
    let Some(first) = groups.first() else {
        return String::new();
    };
    let label = first.model.label;
    let mut md = format!("\n#### {study}: {label}\n\n{}", head("headline", &[]));
    for l in groups {
        let (s, sigma) = (l.stats(), l.scatter());
        let u = scatter_uncertainty_of(&l.values);
        let mut runs = l.values.len().to_string();
        if l.values.len() < l.runs.len() {
            let _ = write!(runs, " of {}", l.runs.len());
        }
        let ratio = sigma / l.model.scatter;
        md.push_str(&table_row(&[
            l.name.clone(),
            num(l.duration),
            runs,
            pm(s.mean, s.stderr),
            format!("{} %", pm(100.0 * sigma, 100.0 * sigma * u)),
            format!("{} %", num(100.0 * l.model.scatter)),
            pm(ratio, ratio * u),
            num(l.cpu),
            num(sigma * l.cpu.sqrt()),
        ]));
    }
    let _ = writeln!(md, "\nModel ({}): {}.", first.name, first.model.basis);
    let lengths = series(groups);
    md.push_str(&correlation(study, groups));
    md.push_str(&along_length(&lengths, first.model.length_exponent));
    let Some(best) = cheapest(&lengths) else {
        return md;
    };
    md.push_str(&along_replicas(best));
    md.push_str(&planning(best));
    md
}

/// One run's scatter against its cost across run lengths, fitted.
fn along_length(lengths: &[&Length], model: f64) -> String {
    let pts: Vec<(f64, f64)> = (lengths.iter().filter(|l| l.cpu > 0.0 && l.scatter() > 0.0))
        .map(|l| (l.cpu, l.scatter()))
        .collect();
    if pts.len() < 2 {
        return String::new();
    }
    let (lo, hi) = (pts[0], pts[pts.len() - 1]);
    let mut values = vec![
        ("name", lengths[0].name.clone()),
        ("from", num(lengths[0].duration)),
        ("to", num(lengths[lengths.len() - 1].duration)),
        ("lo", num(lo.0)),
        ("hi", num(hi.0)),
    ];
    if hi.0 < 1.5 * lo.0 {
        return format!("\n{}\n", fill(named(VERDICTS, "length_free"), &values));
    }
    let Some(p) = log_slope(&pts, 2) else {
        return String::new();
    };
    values.extend([
        ("p", num(p)),
        ("model", num(model)),
        ("verdict", exponent(p).to_string()),
    ]);
    format!("\n{}\n", fill(named(VERDICTS, "length_fit"), &values))
}

/// The standard error of k replicas, measured from disjoint groups.
fn along_replicas(best: &Length) -> String {
    let mut rows = String::new();
    let mut pts = Vec::new();
    for (k, se, groups) in best.by_replicas() {
        let cost = k as f64 * best.cpu;
        let u = scatter_uncertainty(groups);
        pts.push((cost, se, u));
        rows.push_str(&table_row(&[
            k.to_string(),
            groups.to_string(),
            format!("{} %", pm(100.0 * se, 100.0 * se * u)),
            format!("{} %", num(100.0 * best.scatter() / (k as f64).sqrt())),
            format!("{} %", num(100.0 * best.model.stderr(k as u32))),
            num(cost),
        ]));
    }
    if rows.is_empty() {
        return rows;
    }
    let values = [("name", best.name.clone()), ("length", num(best.duration))];
    let against = fill(named(VERDICTS, "replicas"), &values);
    let mut md = format!("\n{against}\n\n{}{rows}", head("replicas", &[]));
    if let Some((p, dp)) = weighted_slope(&pts) {
        let fit = fill(named(VERDICTS, "replicas_fit"), &[("p", pm(p, dp))]);
        let _ = writeln!(md, "\n{fit}");
    }
    md
}

/// Slope of ln(error) against ln(cost), each point weighted by 1/u² (u its
/// relative uncertainty, the error of its logarithm), with the slope's
/// standard error; None for fewer than three points.
fn weighted_slope(pts: &[(f64, f64, f64)]) -> Option<(f64, f64)> {
    if pts.len() < 3 || pts.iter().any(|p| !(p.0 > 0.0 && p.1 > 0.0 && p.2 > 0.0)) {
        return None;
    }
    let sums = Sums::of_errors(pts.iter().map(|p| (p.0.ln(), p.1.ln(), p.2)));
    let se = sums.slope_error();
    se.is_finite().then(|| (sums.slope(), se))
}

/// For X % error, the replicas and CPU seconds: measured σ₁ and the model's.
fn planning(best: &Length) -> String {
    let sigma = best.scatter();
    // The four round targets that need more than two replicas.
    let targets: Vec<f64> = [0.3, 0.1, 0.03, 0.01, 0.003, 0.001, 3e-4, 1e-4, 3e-5, 1e-5]
        .into_iter()
        .filter(|&x| x < sigma / 2f64.sqrt())
        .take(4)
        .collect();
    let values = [
        ("what", best.model.label.to_string()),
        ("length", num(best.duration)),
        ("name", best.name.clone()),
    ];
    let rows = plan(sigma, best.cpu, &targets, |x| {
        let m = best.model.replicas_for(x);
        vec![m.to_string(), num(m * best.cpu)]
    });
    format!("\n{}{rows}", head("replicas_plan", &values))
}

/// The pressure's correlation time from the block analysis of each run,
/// and what it does to the error: shown, not hidden.
fn correlation(study: &str, groups: &[&Length]) -> String {
    if study != "pressure" {
        return String::new();
    }
    let mut md = format!("\n{}", head("blocks", &[]));
    let mut single = true;
    for l in groups {
        let block = scalar(l.runs.iter().copied(), "Z_block_stderr");
        let time = scalar(l.runs.iter().copied(), "block_time");
        let sigma = l.stats().std;
        let first = l.runs.iter().find_map(|o| spacing(o));
        single &= time.std == 0.0 && first.is_some_and(|dt| (time.mean - dt).abs() < 1e-9 * dt);
        md.push_str(&table_row(&[
            l.name.clone(),
            num(l.duration),
            pm(time.mean, time.stderr),
            num(block.mean),
            num(sigma),
            num(sigma / block.mean),
        ]));
    }
    let blocks = if single {
        "blocks_single"
    } else {
        "blocks_longer"
    };
    let (what, here) = (named(VERDICTS, "blocks"), named(VERDICTS, blocks));
    let _ = writeln!(md, "\n{what} {here}");
    md
}

/// The sampling interval of a run's pressure series.
fn spacing(o: &RunOutput) -> Option<f64> {
    let s = o
        .series("virial_pressure")
        .or_else(|| o.series("wall_pressure"))?;
    (s.t.len() > 1).then(|| s.t[1] - s.t[0])
}

fn chart(all: &[Length], names: &[&'static str]) -> Figure {
    let mut layers = Vec::new();
    for (i, study) in names.iter().enumerate() {
        let lengths = series(&of(all, study));
        let Some(best) = cheapest(&lengths) else {
            continue;
        };
        let paint = colour(i);
        let label = best.model.label;
        let replicas = (best.by_replicas().iter())
            .map(|&(k, se, _)| (k as f64 * best.cpu, se))
            .collect();
        layers.push(markers(
            replicas,
            paint,
            Some(format!("{study}: {label}, k replicas")),
        ));
        let runs: Vec<(f64, f64)> = (lengths.iter().filter(|l| l.cpu > 0.0))
            .map(|l| (l.cpu, l.scatter()))
            .collect();
        layers.push(polyline(runs.clone(), paint.faded(0.5), 1, false, None));
        let label = Some(format!("{study}: one run per length"));
        layers.push(markers(runs, paint.faded(0.45), label));
        let label = format!("{study}: model, replicas");
        let model = best.model.scatter;
        layers.push(replicas_line(best.cpu, model, 15, paint, label));
    }
    let labels = (
        "Headline results: error against CPU time".into(),
        "CPU seconds",
        "relative standard error",
    );
    figure("accuracy_effort.svg", labels, (true, true), layers)
}
