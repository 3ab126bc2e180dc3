//! Error against effort for the other studies' headline results: the
//! `headline-*` cases run small versions of each study's headline scene
//! (its analysis named in the case) at a few run lengths. Per result: one
//! run's relative scatter σ₁ at each length with its CPU cost; the standard
//! error against replicas, measured from the spread of means of disjoint
//! groups of k replicas; both fitted against cost; the study's error model
//! (`Study::error_model`) beside what was measured; and a planning table.

use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::error_model::{ErrorModel, scatter_uncertainty, scatter_uncertainty_of};
use crate::stats::format::{num, pm};
use crate::stats::line::{line, log_slope};
use crate::stats::summary::Stats;
use std::fmt::Write;

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
    /// Relative standard error of the mean of k runs, measured as the
    /// spread of the means of disjoint groups of k consecutive replicas
    /// (None with fewer than 4 groups).
    pub fn grouped(&self, k: usize) -> Option<(f64, usize)> {
        let groups = self.values.len() / k;
        if groups < 4 {
            return None;
        }
        let means: Vec<f64> = self
            .values
            .chunks_exact(k)
            .map(|c| c.iter().sum::<f64>() / k as f64)
            .collect();
        let s = Stats::of(&means);
        Some((s.std / self.stats().mean.abs(), groups))
    }
}

/// Whether a run belongs to a headline case: its descriptor names a study
/// other than this one that has an error model for it.
pub fn is_headline(spec: &RunSpec) -> bool {
    crate::studies::error_models(&spec.descriptor)
        .iter()
        .any(|(name, _)| *name != "accuracy")
}

/// The headline runs grouped by (study, run length), in plan order.
pub fn lengths<'a>(runs: &[&'a (RunSpec, RunOutput)]) -> Vec<Length<'a>> {
    let mut out: Vec<Length> = Vec::new();
    for &(spec, o) in runs {
        let Some((study, model)) = crate::studies::error_models(&spec.descriptor)
            .into_iter()
            .find(|(name, _)| *name != "accuracy")
        else {
            continue;
        };
        let duration = spec.descriptor.run.duration.unwrap_or(f64::NAN);
        let scene = format!("{:?}", spec.descriptor.scene);
        let at = out.iter().position(|l| {
            l.study == study && l.scene == scene && l.duration.to_bits() == duration.to_bits()
        });
        let l = match at {
            Some(i) => &mut out[i],
            None => {
                let case = spec.case.clone().unwrap_or_else(|| study.to_string());
                // "headline-piston-m100-n5-300" -> "m100-n5".
                let name = case
                    .trim_start_matches("headline-")
                    .trim_start_matches(study)
                    .trim_start_matches('-')
                    .rsplit_once('-')
                    .map_or(String::new(), |(a, _)| a.to_string());
                out.push(Length {
                    study,
                    name,
                    scene,
                    model,
                    duration,
                    values: Vec::new(),
                    runs: Vec::new(),
                    cpu: 0.0,
                });
                out.last_mut().expect("just pushed")
            }
        };
        if let Some(v) = o.scalar(l.model.result).filter(|v| v.is_finite()) {
            l.values.push(v);
        }
        l.runs.push(o);
    }
    for l in &mut out {
        let cpu: Vec<f64> = l
            .runs
            .iter()
            .map(|o| o.cpu_seconds)
            .filter(|c| c.is_finite())
            .collect();
        l.cpu = cpu.iter().sum::<f64>() / cpu.len().max(1) as f64;
    }
    out
}

/// The studies with headline runs, in plan order.
fn studies(all: &[Length]) -> Vec<&'static str> {
    all.iter().fold(Vec::new(), |mut v, l| {
        if !v.contains(&l.study) {
            v.push(l.study);
        }
        v
    })
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
    let mut v: Vec<&Length> = groups
        .iter()
        .copied()
        .filter(|g| g.scene == most.scene)
        .collect();
    v.sort_by(|a, b| a.duration.total_cmp(&b.duration));
    v
}

/// The length whose error costs least (σ₁² c smallest).
fn cheapest<'a, 'b>(lengths: &[&'a Length<'b>]) -> Option<&'a Length<'b>> {
    lengths
        .iter()
        .copied()
        .filter(|l| l.cpu > 0.0 && l.scatter() > 0.0)
        .min_by(|a, b| (a.scatter().powi(2) * a.cpu).total_cmp(&(b.scatter().powi(2) * b.cpu)))
}

/// The markdown part (empty without headline runs) and its chart.
pub fn part(runs: &[&(RunSpec, RunOutput)]) -> (String, Option<ChartSpec>) {
    let all = lengths(runs);
    let names = studies(&all);
    if names.is_empty() {
        return (String::new(), None);
    }
    let mut md = String::from(INTRO);
    md.push_str(
        "\n![Relative standard error of each study's headline result against the CPU seconds spent on it. \
         Solid markers: the error of the mean of k replicas at the cheapest run length, measured from the spread \
         of the means of disjoint groups of k (cost: k runs). Faded markers joined by a thin line: one run's \
         scatter at each run length (cost: one run). Dashed: the study's error model, falling as cost^(−1/2) \
         with replicas.](accuracy_effort.svg)\n",
    );
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
    let mut md = format!(
        "\n#### {study}: {label}\n\n| case | run length | runs | mean | one run's scatter σ₁ | model σ₁ | measured / model | CPU s/run | σ₁ √c |\n|---|---|---|---|---|---|---|---|---|\n"
    );
    for l in groups {
        let s = l.stats();
        let sigma = l.scatter();
        let u = scatter_uncertainty_of(&l.values);
        let _ = writeln!(
            md,
            "| {} | {} | {}{} | {} | {} % | {} % | {} | {} | {} |",
            l.name,
            num(l.duration),
            l.values.len(),
            if l.values.len() < l.runs.len() {
                format!(" of {}", l.runs.len())
            } else {
                String::new()
            },
            pm(s.mean, s.stderr),
            pm(100.0 * sigma, 100.0 * sigma * u),
            num(100.0 * l.model.scatter),
            pm(sigma / l.model.scatter, sigma / l.model.scatter * u),
            num(l.cpu),
            num(sigma * l.cpu.sqrt()),
        );
    }
    let _ = writeln!(md, "\nModel ({}): {}.", first.name, first.model.basis);
    let lengths = series(groups);
    if let Some(extra) = correlation(study, groups) {
        md.push_str(&extra);
    }
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
    let pts: Vec<(f64, f64)> = lengths
        .iter()
        .filter(|l| l.cpu > 0.0 && l.scatter() > 0.0)
        .map(|l| (l.cpu, l.scatter()))
        .collect();
    let (Some(lo), Some(hi)) = (pts.first(), pts.last()) else {
        return String::new();
    };
    if pts.len() < 2 {
        return String::new();
    }
    let name = lengths[0].name.as_str();
    if hi.0 < 1.5 * lo.0 {
        return format!(
            "\nAcross run lengths ({name}: {} to {}) the CPU time hardly changes ({} to {} s): these runs \
             cost what building the scene and analysing the run cost, so their length is free and no \
             exponent can be fitted.\n",
            num(lengths[0].duration),
            num(lengths[lengths.len() - 1].duration),
            num(lo.0),
            num(hi.0)
        );
    }
    let Some(p) = log_slope(&pts, 2) else {
        return String::new();
    };
    let verdict = if (p + 0.5).abs() < 0.15 {
        "as cost^(−1/2): a longer run buys error as replicas do"
    } else if p > -0.35 {
        "hardly or not at all: the result is read off part of the run (a transient, or a window of \
         fixed length), so a longer run costs more and buys nothing; only replicas buy error"
    } else {
        "faster than cost^(−1/2) (the scatter of a few replicas is itself uncertain)"
    };
    format!(
        "\nAcross run lengths ({name}: {} to {}) one run's scatter goes as cost^{} (the model: length^{}), \
         {verdict}.\n",
        num(lengths[0].duration),
        num(lengths[lengths.len() - 1].duration),
        num(p),
        num(model)
    )
}

/// The standard error of k replicas, measured from disjoint groups.
fn along_replicas(best: &Length) -> String {
    let mut rows = String::new();
    let mut pts = Vec::new();
    let mut k = 1;
    while let Some((se, groups)) = best.grouped(k) {
        let cost = k as f64 * best.cpu;
        let u = scatter_uncertainty(groups);
        pts.push((cost, se, u));
        let _ = writeln!(
            rows,
            "| {k} | {groups} | {} % | {} % | {} % | {} |",
            pm(100.0 * se, 100.0 * se * u),
            num(100.0 * best.scatter() / (k as f64).sqrt()),
            num(100.0 * best.model.stderr(k as u32)),
            num(cost)
        );
        k *= 2;
    }
    if rows.is_empty() {
        return rows;
    }
    let mut md = format!(
        "\nAgainst replicas ({}, run length {}; the spread of the means of disjoint groups of k):\n\n\
         | replicas k | groups | measured standard error | σ₁/√k | model | CPU s |\n|---|---|---|---|---|---|\n{rows}",
        best.name,
        num(best.duration)
    );
    if let Some((p, dp)) = weighted_slope(&pts) {
        let _ = writeln!(
            md,
            "\nFitted against cost along replicas (weighted by each point's uncertainty): exponent {} \
             (independent replicas: −1/2; the groups share replicas, so the ± is a rough guide).",
            pm(p, dp)
        );
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
    let w: Vec<f64> = pts.iter().map(|p| 1.0 / (p.2 * p.2)).collect();
    let x: Vec<f64> = pts.iter().map(|p| p.0.ln()).collect();
    let y: Vec<f64> = pts.iter().map(|p| p.1.ln()).collect();
    let (slope, se, _) = line(&x, &y, Some(&w));
    (!se.is_nan()).then_some((slope, se))
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
    let mut md = format!(
        "\n| for this error on the {} | you need (CPU s) | as replicas of length {} ({}) | the model: replicas | CPU s |\n|---|---|---|---|---|\n",
        best.model.label,
        num(best.duration),
        best.name
    );
    for x in targets {
        let n = (sigma / x).powi(2).ceil().max(2.0);
        let m = best.model.replicas_for(x);
        let _ = writeln!(
            md,
            "| {} % | {} | {} | {} | {} |",
            num(100.0 * x),
            num(n * best.cpu),
            n,
            m,
            num(m * best.cpu)
        );
    }
    md
}

/// The pressure's correlation time from the block analysis of each run,
/// and what it does to the error: shown, not hidden.
fn correlation(study: &str, groups: &[&Length]) -> Option<String> {
    if study != "pressure" {
        return None;
    }
    let mut md = String::from(
        "\n| case | run length | block length chosen | block error of one run, mean | replica scatter σ₁ (absolute) | ratio |\n|---|---|---|---|---|---|\n",
    );
    let mut single = true;
    for l in groups {
        let get = |name: &str| -> Vec<f64> {
            l.runs
                .iter()
                .filter_map(|o| o.scalar(name))
                .filter(|v| v.is_finite())
                .collect()
        };
        let block = Stats::of(&get("Z_block_stderr"));
        let time = Stats::of(&get("block_time"));
        let sigma = l.stats().std;
        let first = l.runs.iter().find_map(|o| spacing(o));
        single &= time.std == 0.0 && first.is_some_and(|dt| (time.mean - dt).abs() < 1e-9 * dt);
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} |",
            l.name,
            num(l.duration),
            pm(time.mean, time.stderr),
            num(block.mean),
            num(sigma),
            num(sigma / block.mean)
        );
    }
    md.push_str(
        "\nThe block analysis (Flyvbjerg–Petersen) within each run looks for the block length beyond which \
         block means of Z's samples are uncorrelated: the pressure's correlation time, rounded up to a \
         power of two samples. Its error bar for one run should match the scatter between runs (ratio ≈ 1). \
         The model's c is what correlations between collisions multiply the uncorrelated error by.",
    );
    md.push_str(if single {
        " Here every run settled on blocks of a single sample: Z's samples are already uncorrelated at the \
         sampling interval, so no correlation time makes the error worse at these densities, and c ≈ 1.\n"
    } else {
        " Where it chose longer blocks, the pressure stays correlated over them, and the error of a run is \
         that much larger than its sample count suggests.\n"
    });
    Some(md)
}

/// The sampling interval of a run's pressure series.
fn spacing(o: &RunOutput) -> Option<f64> {
    let s = o
        .series("virial_pressure")
        .or_else(|| o.series("wall_pressure"))?;
    (s.t.len() > 1).then(|| s.t[1] - s.t[0])
}

fn chart(all: &[Length], names: &[&'static str]) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, study) in names.iter().enumerate() {
        let lengths = series(&of(all, study));
        let Some(best) = cheapest(&lengths) else {
            continue;
        };
        let paint = colour(i);
        let mut pts = Vec::new();
        let mut k = 1;
        while let Some((se, _)) = best.grouped(k) {
            pts.push((k as f64 * best.cpu, se));
            k *= 2;
        }
        let label = best.model.label;
        layers.push(Layer::Markers {
            points: pts,
            paint,
            label: Some(format!("{study}: {label}, k replicas")),
        });
        let runs: Vec<(f64, f64)> = lengths
            .iter()
            .filter(|l| l.cpu > 0.0)
            .map(|l| (l.cpu, l.scatter()))
            .collect();
        layers.push(Layer::Line {
            points: runs.clone(),
            paint: paint.faded(0.5),
            width: 1,
            dashed: false,
            label: None,
        });
        layers.push(Layer::Markers {
            points: runs,
            paint: paint.faded(0.45),
            label: Some(format!("{study}: one run per length")),
        });
        let c0 = best.cpu;
        let s0 = best.model.scatter;
        layers.push(Layer::Line {
            points: (0..=15)
                .map(|j| {
                    let c = c0 * 10f64.powf(j as f64 / 5.0);
                    (c, s0 * (c0 / c).sqrt())
                })
                .collect(),
            paint,
            width: 2,
            dashed: true,
            label: Some(format!("{study}: model, replicas")),
        });
    }
    ChartSpec {
        title: "Headline results: error against CPU time".into(),
        x_label: "CPU seconds".into(),
        y_label: "relative standard error".into(),
        x_log: true,
        y_log: true,
        layers,
    }
}

const INTRO: &str = "\n### Error against effort: each study's headline result\n\n\
Every bundled study has one result its report leads with; the `headline-*` cases run small versions of its \
scene, with its analysis, at a few points and (for one of them) a few run lengths, 32 seeded replicas each. \
One run's relative scatter σ₁ (standard deviation over replicas over the mean) and its CPU cost c give the \
error of n replicas, σ₁/√n, at cost n c. Against replicas the error falls as cost^(−1/2) for independent \
runs; the table below each result measures it from groups of replicas rather than assuming it. Against run \
length it falls as cost^(−1/2) only for a time average over runs longer than its correlation time; a result \
read off a transient (a frequency over the first periods, a relaxation or mixing time) gains nothing from a \
longer run. Each study's error model (its `error.rs`) gives σ₁ from the descriptor before anything runs, \
and `study validate` prints the error bars it implies; its constants were measured from these cases, so \
the ratio measured / model checks the model's form where it is not a calibration point, and its constants \
when the cases are run with other seeds (the tests do). The ± of a scatter comes from the values' own \
fourth moment: 1/√(2(n−1)) of it for normal values, more for the heavy tails some of these results have.\n";
