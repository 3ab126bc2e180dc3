//! The report section: one sentence per finding, the error of each
//! quantity against CPU time with both integrators on one log-log chart,
//! and a table per scene.

use super::groups::{Group, error, groups};
use crate::model::chart::{Layer, Paint, colour};
use crate::model::descriptor::Integrator;
use crate::model::report::{Figure, ReportSection};
use crate::stats::ensemble::Runs;
use crate::stats::fill::fill;
use crate::stats::format::{num, pm};
use crate::stats::groups::first_seen;
use crate::stats::line::log_slope;
use crate::stats::named::named;
use crate::stats::summary::Stats;
use crate::stats::table::table_row;
use crate::studies::curves::{figure, markers, polyline};
use std::fmt::Write;

const INTRO: &str = include_str!("intro.md");
const COST: &str = include_str!("cost.md");
const FINDINGS: &str = include_str!("findings.md");
const METHODS: &str = include_str!("methods.md");
/// The header rows of the tables, by name.
const TABLES: &str = include_str!("tables.md");

/// The finding `name` of findings.md with its numbers.
fn finding(name: &str, values: &[(&str, String)]) -> String {
    fill(named(FINDINGS, name), values)
}

/// The head of the table named `name` in TABLES: its header row, filled,
/// and the rule under it.
pub fn head(name: &str, values: &[(&str, String)]) -> String {
    let row = fill(named(TABLES, name), values);
    format!(
        "{row}\n|{}\n",
        "---|".repeat(row.matches(" | ").count() + 1)
    )
}

pub fn section(runs: &Runs) -> ReportSection {
    let all = groups(runs);
    let scenes: Vec<String> = (first_seen(all.iter().map(|g| &g.scene), |a, b| a == b))
        .into_iter()
        .map(|v| v[0].clone())
        .collect();
    let mut md = String::from(INTRO);
    for line in findings(&all, &scenes) {
        let _ = writeln!(md, "- {line}");
    }
    let mut figures = Vec::new();
    let cost = cost_chart(&all, &scenes);
    if !cost.chart.layers.is_empty() {
        figures.push(cost);
        md.push_str(COST);
    }
    for scene in &scenes {
        md.push_str(&table(scene, &all));
    }
    md.push_str(&super::effort::effort(&all, &scenes));
    // The other studies' headline cases have a part of their own.
    let (part, effort) = super::headlines::part(runs);
    md.push_str(&part);
    figures.extend(effort.filter(|f| !f.chart.layers.is_empty()));
    md.push_str(METHODS);
    ReportSection {
        title: "What accuracy costs in time: fixed step against exact events".into(),
        markdown: md,
        figures,
        presents: super::RESULTS
            .iter()
            .chain(super::SHOWN)
            .map(|r| r.to_string())
            .collect(),
    }
}

/// The exact engine's runs a scene's fixed steps are measured against: those
/// as long as the fixed steps' runs (the study may add exact runs of other
/// lengths for the statistics).
pub fn exact<'a>(all: &'a [Group], scene: &str) -> Option<&'a Group> {
    let mut exact = all
        .iter()
        .filter(|g| g.scene == scene && g.integrator == Integrator::Exact);
    let stepped = all
        .iter()
        .find(|g| g.scene == scene && g.integrator != Integrator::Exact);
    match stepped {
        Some(s) => exact.find(|g| g.duration.to_bits() == s.duration.to_bits()),
        None => exact.next(),
    }
}

/// The fixed-step groups of a scene with `integrator`, by increasing dt.
fn steps<'a>(all: &'a [Group], scene: &str, integrator: Integrator) -> Vec<&'a Group> {
    let mut v: Vec<&Group> = all
        .iter()
        .filter(|g| g.scene == scene && g.integrator == integrator)
        .collect();
    v.sort_by(|a, b| a.dt.total_cmp(&b.dt));
    v
}

/// The quantity a scene's accuracy is judged by: the piston's frequency
/// where there is one, else the wall pressure.
pub fn headline(g: &Group) -> (&'static str, &Stats) {
    if g.piston {
        ("piston frequency", &g.frequency)
    } else {
        ("wall pressure βP", &g.pressure)
    }
}

/// Relative scatter of one run's headline result.
pub fn scatter(g: &Group) -> f64 {
    let (_, s) = headline(g);
    s.std / s.mean.abs()
}

fn findings(all: &[Group], scenes: &[String]) -> Vec<String> {
    let mut lines = Vec::new();
    for scene in scenes {
        let naive = steps(all, scene, Integrator::FixedStepNaive);
        let fixed = steps(all, scene, Integrator::FixedStep);
        lines.extend(sticking(scene, &naive, &fixed));
    }
    let fixed = all.iter().filter(|g| g.integrator == Integrator::FixedStep);
    let drift = fixed.clone().map(|g| g.energy_drift).fold(0.0, f64::max);
    if fixed.count() > 0 {
        // Round-off over a run's steps stays far below this.
        let kept = if drift < 1e-9 {
            "energy_kept"
        } else {
            "energy_lost"
        };
        lines.push(finding(kept, &[("drift", num(drift))]));
    }
    for scene in scenes {
        // A scene whose runs all start alike (explicit positions and
        // velocities) has no statistical error to weigh a bias against.
        let Some(reference) = exact(all, scene).filter(|r| scatter(r) > 1e-9) else {
            continue;
        };
        let pts = steps(all, scene, Integrator::FixedStep);
        if pts.is_empty() {
            continue;
        }
        lines.push(bias(scene, reference, &pts));
        lines.extend(budget(scene, reference, &pts, 1.0));
    }
    lines
}

/// The group with the most stuck pairs.
fn worst<'a>(groups: &[&'a Group]) -> Option<&'a Group> {
    (groups.iter().copied()).max_by(|a, b| a.stuck.total_cmp(&b.stuck))
}

/// At what dt the stepper without the approach check stops sticking.
fn sticking(scene: &str, naive: &[&Group], fixed: &[&Group]) -> Option<String> {
    let (first, last) = (naive.first()?, naive.last()?);
    let stuck = |g: &&Group| g.stuck > 0.0;
    let w = worst(naive)?;
    let clean = naive.iter().take_while(|g| !stuck(g)).last();
    let mut values = vec![
        ("scene", scene.to_string()),
        ("first", num(first.dt)),
        ("last", num(last.dt)),
        ("worst", num(w.stuck)),
        ("worst_dt", num(w.dt)),
        ("clean", clean.map_or(String::new(), |g| num(g.dt))),
    ];
    let naive_text = match (naive.iter().any(stuck), clean) {
        (false, _) => "naive_none",
        (true, None) => "naive_all",
        (true, Some(_)) => "naive_above",
    };
    let naive_text = finding(naive_text, &values);
    let fixed_text = match worst(fixed).filter(|w| w.stuck > 0.0) {
        Some(w) => {
            let first = fixed.iter().find(|g| stuck(g)).map_or(w.dt, |g| g.dt);
            let (first, worst, worst_dt) = (num(first), num(w.stuck), num(w.dt));
            let values = [("first", first), ("worst", worst), ("worst_dt", worst_dt)];
            finding("fixed_some", &values)
        }
        None => finding("fixed_none", &[]),
    };
    values.extend([("naive", naive_text), ("fixed", fixed_text)]);
    Some(finding("sticking", &values))
}

/// How the headline error grows with dt, and from which dt it stands out.
fn bias(scene: &str, reference: &Group, pts: &[&Group]) -> String {
    let (what, _) = headline(reference);
    let errs: Vec<(f64, f64, f64)> = pts
        .iter()
        .filter_map(|g| error(headline(g).1, headline(reference).1).map(|(e, se)| (g.dt, e, se)))
        .collect();
    let seen: Vec<&(f64, f64, f64)> = errs.iter().filter(|(_, e, se)| *e > 3.0 * se).collect();
    let mut values = vec![("scene", scene.to_string()), ("what", what.to_string())];
    let Some(&&(dt, e, se)) = seen.first() else {
        values.push(("last", num(pts[pts.len() - 1].dt)));
        return finding("bias_none", &values);
    };
    let growth: Vec<(f64, f64)> = seen.iter().map(|p| (p.0, p.1)).collect();
    let order = log_slope(&growth, 3).map(|p| format!("; from there it grows as dt^{}", num(p)));
    values.extend([
        ("dt", num(dt)),
        ("error", pm(100.0 * e, 100.0 * se)),
        ("order", order.unwrap_or_default()),
    ]);
    finding("bias", &values)
}

/// What error `seconds` of CPU buy each way: the exact engine's statistical
/// error at that cost, and the fixed step's best (bias and its own scatter).
fn budget(scene: &str, reference: &Group, pts: &[&Group], seconds: f64) -> Option<String> {
    let exact_error = scatter(reference) * (reference.cpu / seconds).sqrt();
    let best = pts
        .iter()
        .filter_map(|g| {
            // The bias as far as these runs can exclude it (two standard
            // errors above the measured difference).
            let (e, se) = error(headline(g).1, headline(reference).1)?;
            let bias = e + 2.0 * se;
            let total = (bias * bias + scatter(g).powi(2) * g.cpu / seconds).sqrt();
            total.is_finite().then_some((g.dt, total))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))?;
    // Runs too short for the CPU clock's ticks measure no cost.
    if !exact_error.is_finite() || reference.cpu <= 0.0 {
        return None;
    }
    let (what, _) = headline(reference);
    let values = [
        ("scene", scene.to_string()),
        ("what", what.to_string()),
        ("exact", num(100.0 * exact_error)),
        ("cpu", num(reference.cpu)),
        ("dt", num(best.0)),
        ("fixed", num(100.0 * best.1)),
    ];
    Some(finding("cost", &values))
}

fn cost_chart(all: &[Group], scenes: &[String]) -> Figure {
    let mut layers = Vec::new();
    for (k, scene) in scenes.iter().enumerate() {
        let Some(reference) = exact(all, scene) else {
            continue;
        };
        let paint = colour(k);
        // (CPU, error, resolved): an error within two standard errors of 0
        // is drawn at its upper bound, faded.
        let pts: Vec<(f64, f64, bool)> = steps(all, scene, Integrator::FixedStep)
            .iter()
            .filter_map(|g| {
                let (e, se) = error(headline(g).1, headline(reference).1)?;
                let resolved = e > 2.0 * se;
                Some((g.cpu, if resolved { e } else { e + 2.0 * se }, resolved))
            })
            .filter(|&(c, e, _)| c > 0.0 && e > 0.0)
            .collect();
        let (what, _) = headline(reference);
        let line = pts.iter().map(|&(c, e, _)| (c, e)).collect();
        layers.push(polyline(line, paint.faded(0.4), 1, false, None));
        for (resolved, label) in [
            (true, format!("{scene}: fixed step ({what})")),
            (false, format!("{scene}: fixed step, bound (not resolved)")),
        ] {
            let marked: Vec<(f64, f64)> = (pts.iter().filter(|p| p.2 == resolved))
                .map(|&(c, e, _)| (c, e))
                .collect();
            let paint = if resolved { paint } else { paint.faded(0.35) };
            if !marked.is_empty() {
                layers.push(markers(marked, paint, Some(label)));
            }
        }
        let s = scatter(reference);
        if s > 1e-9 && reference.cpu > 0.0 {
            let label = format!("{scene}: exact (statistical)");
            layers.push(replicas_line(reference.cpu, s, 20, paint, label));
        }
    }
    let labels = (
        "Error against CPU time".into(),
        "CPU seconds of one run",
        "relative error",
    );
    figure("accuracy_cost.svg", labels, (true, true), layers)
}

/// Dashed: one run's error `s` at its cost `c0`, falling as cost^(−1/2)
/// with replicas, over `fifths` fifths of a decade.
pub fn replicas_line(c0: f64, s: f64, fifths: u32, paint: Paint, label: String) -> Layer {
    let c = (0..=fifths).map(|i| c0 * 10f64.powf(i as f64 / 5.0));
    let points = c.map(|c| (c, s * (c0 / c).sqrt())).collect();
    polyline(points, paint, 2, true, Some(label))
}

fn table(scene: &str, all: &[Group]) -> String {
    let reference = exact(all, scene);
    let mut md = format!("\n### {scene}\n\n{}", head("scene", &[]));
    // The reference and the fixed steps; exact runs of other lengths are
    // the statistics part's.
    let mut rows: Vec<&Group> = all
        .iter()
        .filter(|g| {
            g.scene == scene
                && (g.integrator != Integrator::Exact
                    || reference.is_some_and(|r| std::ptr::eq(*g, r)))
        })
        .collect();
    rows.sort_by(|a, b| {
        (a.integrator as u8)
            .cmp(&(b.integrator as u8))
            .then(a.dt.total_cmp(&b.dt))
    });
    let err = |a: &Stats, b: Option<&Stats>| {
        let e = b.and_then(|b| error(a, b));
        e.map_or("–".into(), |(e, se)| {
            format!("{} %", pm(100.0 * e, 100.0 * se))
        })
    };
    let stat = |s: &Stats| match s.n {
        0 => "–".into(),
        _ => pm(s.mean, s.stderr),
    };
    let compared: [fn(&Group) -> &Stats; 3] =
        [|g| &g.pressure, |g| &g.collision_rate, |g| &g.frequency];
    for g in rows {
        let exact_row = g.integrator == Integrator::Exact;
        let r = reference.filter(|_| !exact_row);
        let mut cells = vec![
            g.integrator.name().to_string(),
            opt(g.dt),
            g.runs.to_string(),
        ];
        for of in compared {
            cells.extend([stat(of(g)), err(of(g), r.map(of))]);
        }
        let repeats = format!("{} %", num(100.0 * g.repeat_share));
        cells.extend([num(g.energy_drift), opt(g.depth_max), opt(g.depth_mean)]);
        cells.extend([opt(g.longest), opt(g.stuck)]);
        cells.extend([if exact_row { "–".into() } else { repeats }, num(g.cpu)]);
        md.push_str(&table_row(&cells));
    }
    md
}

fn opt(x: f64) -> String {
    if x.is_nan() { "–".into() } else { num(x) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::fill::unfilled;
    use crate::stats::named::names;

    /// Every placeholder of the findings and the verdicts is one of the
    /// keys the section fills.
    #[test]
    fn every_placeholder_is_filled() {
        let keys = [
            "scene", "naive", "fixed", "first", "last", "worst", "worst_dt", "clean", "drift",
            "what", "dt", "error", "order", "exact", "cpu", "p", "verdict", "name", "from", "to",
            "lo", "hi", "model", "length",
        ];
        let values = keys.map(|k| (k, "x".to_string()));
        for text in [FINDINGS, super::super::effort::VERDICTS] {
            for name in names(text) {
                let filled = fill(named(text, name), &values);
                assert!(unfilled(&filled).is_empty(), "{filled}");
            }
        }
        for text in [INTRO, COST, METHODS] {
            assert!(unfilled(text).is_empty());
        }
    }
}
