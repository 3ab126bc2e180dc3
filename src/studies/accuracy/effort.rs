//! The statistics half: the exact engine's error on a scene's headline
//! result against the effort spent, by replicas and by run length. One
//! run's relative scatter σ at CPU cost c gives, over n replicas, an error
//! σ/√n at cost n c: error ∝ cost^(−1/2) along replicas by construction.
//! Along run length it holds only while runs outlast the result's
//! correlation time, so the section measures the exponent across lengths
//! and plans with the length that buys error cheapest.

use super::groups::Group;
use super::section::{headline, scatter};
use crate::model::descriptor::Integrator;
use crate::stats::format::num;
use crate::stats::line::log_slope;
use std::fmt::Write;

/// Relative errors the planning table is asked for.
const TARGETS: [f64; 4] = [0.1, 0.03, 0.01, 0.001];

/// The exact runs of a scene at each run length, shortest first (those
/// without measurable scatter or cost left out).
fn lengths<'a>(all: &'a [Group], scene: &str) -> Vec<&'a Group> {
    let mut v: Vec<&Group> = all
        .iter()
        .filter(|g| {
            g.scene == scene
                && g.integrator == Integrator::Exact
                && g.runs > 1
                && g.duration.is_finite()
                && scatter(g) > 1e-9
                && g.cpu > 0.0
        })
        .collect();
    v.sort_by(|a, b| a.duration.total_cmp(&b.duration));
    v
}

/// The section's statistics part for every scene with exact runs of at
/// least two lengths (empty if there is none).
pub fn effort(all: &[Group], scenes: &[String]) -> String {
    let mut md = String::new();
    for scene in scenes {
        let runs = lengths(all, scene);
        if runs.len() < 2 {
            continue;
        }
        if md.is_empty() {
            md.push_str(INTRO);
        }
        md.push_str(&one(scene, &runs));
    }
    md
}

fn one(scene: &str, runs: &[&Group]) -> String {
    let (what, _) = headline(runs[0]);
    let mut md = format!(
        "\n#### {scene}: {what}\n\n| run length | runs | relative scatter of one run σ | CPU s/run c | σ √c |\n|---|---|---|---|---|\n"
    );
    for g in runs {
        let s = scatter(g);
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} |",
            num(g.duration),
            g.runs,
            num(s),
            num(g.cpu),
            num(s * g.cpu.sqrt())
        );
    }
    let points: Vec<(f64, f64)> = runs.iter().map(|g| (g.cpu, scatter(g))).collect();
    if let Some(p) = log_slope(&points, 2) {
        let verdict = if (p + 0.5).abs() < 0.15 {
            "as cost^(−1/2): these runs outlast the result's correlation time, so length and replicas buy \
             error alike"
                .to_string()
        } else if p > -0.35 {
            "more slowly than cost^(−1/2): a longer run does not buy its share of error (the result is \
             measured over part of the run, or correlated over times near the run length); replicas do"
                .to_string()
        } else {
            "faster than cost^(−1/2) (with few replicas per length the scatter is itself uncertain)"
                .to_string()
        };
        let _ = writeln!(
            md,
            "\nAcross run lengths, one run's scatter falls as cost^{}, {verdict}.",
            num(p)
        );
    }
    // Plan with the length whose error costs least: n = (σ / X)^2 runs.
    let best = runs
        .iter()
        .min_by(|a, b| (scatter(a).powi(2) * a.cpu).total_cmp(&(scatter(b).powi(2) * b.cpu)))
        .expect("two lengths at least");
    let _ = write!(
        md,
        "\n| for this error on the {what} | you need (CPU s) | as runs of length {} |\n|---|---|---|\n",
        num(best.duration)
    );
    for x in TARGETS {
        let n = (scatter(best) / x).powi(2).ceil().max(2.0);
        let _ = writeln!(
            md,
            "| {} % | {} | {} |",
            num(100.0 * x),
            num(n * best.cpu),
            n
        );
    }
    md
}

const INTRO: &str = "\n### Error against effort: the statistics\n\n\
The exact engine's only error is statistical, and it is bought with CPU time two ways: more replicas (n runs \
give σ/√n, exactly cost^(−1/2)) or longer runs (cost^(−1/2) only while a run outlasts the correlation time of \
what it measures). Each table gives one run's relative scatter σ (standard deviation over independent \
replicas, relative to the mean) at each run length with its CPU cost c; σ √c is the error one CPU-second \
buys, constant where length and replicas are worth the same. The planning tables use the length whose σ² c \
is least: n = (σ / X)² runs (at least 2, for an error bar) of c each. Costs are this machine's, one core; the \
CPU clock ticks every few milliseconds, so the shortest runs' c is a mean over replicas of coarse readings.\n";
