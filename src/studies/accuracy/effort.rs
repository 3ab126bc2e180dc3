//! The statistics half: the exact engine's error on a scene's headline
//! result against the effort spent, by replicas and by run length. One
//! run's relative scatter σ at CPU cost c gives, over n replicas, an error
//! σ/√n at cost n c: error ∝ cost^(−1/2) along replicas by construction.
//! Along run length it holds only while runs outlast the result's
//! correlation time, so the section measures the exponent across lengths
//! and plans with the length that buys error cheapest.

use super::groups::Group;
use super::section::{head, headline, scatter};
use crate::model::descriptor::Integrator;
use crate::stats::fill::fill;
use crate::stats::format::num;
use crate::stats::line::log_slope;
use crate::stats::named::named;
use crate::stats::table::table_row;
use std::fmt::Write;

const INTRO: &str = include_str!("effort.md");
/// What the fits of error against effort say, one line per outcome.
pub const VERDICTS: &str = include_str!("verdicts.md");

/// What an exponent of one run's scatter against its cost says.
pub fn exponent(p: f64) -> &'static str {
    let name = match p {
        p if (p + 0.5).abs() < 0.15 => "as_replicas",
        p if p > -0.35 => "no_gain",
        _ => "faster",
    };
    named(VERDICTS, name)
}

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
    let parts: String = (scenes.iter())
        .map(|scene| (scene, lengths(all, scene)))
        .filter(|(_, runs)| runs.len() >= 2)
        .map(|(scene, runs)| one(scene, &runs))
        .collect();
    if parts.is_empty() {
        return parts;
    }
    INTRO.to_string() + &parts
}

fn one(scene: &str, runs: &[&Group]) -> String {
    let (what, _) = headline(runs[0]);
    let mut md = format!("\n#### {scene}: {what}\n\n{}", head("lengths", &[]));
    for g in runs {
        let s = scatter(g);
        md.push_str(&table_row(&[
            num(g.duration),
            g.runs.to_string(),
            num(s),
            num(g.cpu),
            num(s * g.cpu.sqrt()),
        ]));
    }
    let points: Vec<(f64, f64)> = runs.iter().map(|g| (g.cpu, scatter(g))).collect();
    if let Some(p) = log_slope(&points, 2) {
        let values = [("p", num(p)), ("verdict", exponent(p).to_string())];
        let _ = writeln!(md, "\n{}", fill(named(VERDICTS, "effort_fit"), &values));
    }
    // Plan with the length whose error costs least.
    let cost = |g: &Group| scatter(g).powi(2) * g.cpu;
    let best = (runs.iter())
        .min_by(|a, b| cost(a).total_cmp(&cost(b)))
        .expect("two lengths at least");
    let values = [("what", what.to_string()), ("length", num(best.duration))];
    let table = plan(scatter(best), best.cpu, &TARGETS, |_| Vec::new());
    md + "\n" + &head("runs_plan", &values) + &table
}

/// A planning table's rows: per target relative error x, the CPU seconds
/// and the runs of `cpu` seconds each that one run's relative scatter
/// `sigma` needs, n = (σ / x)² (at least 2, for an error bar), then the
/// cells `more` adds for x.
pub fn plan(sigma: f64, cpu: f64, targets: &[f64], more: impl Fn(f64) -> Vec<String>) -> String {
    let row = |x: f64| {
        let n = (sigma / x).powi(2).ceil().max(2.0);
        let mut cells = vec![format!("{} %", num(100.0 * x)), num(n * cpu), n.to_string()];
        cells.extend(more(x));
        table_row(&cells)
    };
    targets.iter().map(|&x| row(x)).collect()
}
