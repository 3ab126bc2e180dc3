//! The report section: one sentence per finding, the error of each
//! quantity against CPU time with both integrators on one log-log chart,
//! and a table per scene.

use super::groups::{Group, error, groups};
use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::descriptor::Integrator;
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::format::{num, pm};
use crate::stats::line::log_slope;
use crate::stats::summary::Stats;
use std::fmt::Write;

pub fn section(runs: &[(RunSpec, RunOutput)]) -> ReportSection {
    // The other studies' headline cases have a part of their own.
    let (headline, own): (Vec<_>, Vec<_>) = runs
        .iter()
        .partition(|(s, _)| super::headlines::is_headline(s));
    let all = groups(&own);
    let scenes: Vec<String> = all.iter().fold(Vec::new(), |mut v, g| {
        if !v.contains(&g.scene) {
            v.push(g.scene.clone());
        }
        v
    });
    let mut md = String::from(INTRO);
    md.push_str("\n### Findings\n\n");
    for line in findings(&all, &scenes) {
        let _ = writeln!(md, "- {line}");
    }
    let mut figures = Vec::new();
    let chart = cost_chart(&all, &scenes);
    if !chart.layers.is_empty() {
        figures.push(Figure {
            file: "accuracy_cost.svg".into(),
            chart,
        });
        md.push_str(
            "\n![Relative error of the wall pressure βP (the piston's frequency for the piston scene) \
             against the CPU seconds of one run. Markers joined by a line: the fixed step, one marker per dt \
             (largest dt cheapest); its error is its bias against the exact engine's mean, drawn faded at its \
             upper bound (difference plus two standard errors) where these runs do not resolve it. Dashed lines: \
             the exact engine, whose only error is statistical: one run's scatter at one run's cost, falling as \
             cost^(-1/2) with more runs.](accuracy_cost.svg)\n",
        );
    }
    for scene in &scenes {
        md.push_str(&table(scene, &all));
    }
    md.push_str(&super::effort::effort(&all, &scenes));
    let (part, chart) = super::headlines::part(&headline);
    md.push_str(&part);
    if let Some(chart) = chart.filter(|c| !c.layers.is_empty()) {
        figures.push(Figure {
            file: "accuracy_effort.svg".into(),
            chart,
        });
    }
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
        if let Some(line) = sticking(scene, &naive, &steps(all, scene, Integrator::FixedStep)) {
            lines.push(line);
        }
    }
    let fixed: Vec<&Group> = all
        .iter()
        .filter(|g| g.integrator == Integrator::FixedStep)
        .collect();
    let drift = fixed.iter().map(|g| g.energy_drift).fold(0.0, f64::max);
    if !fixed.is_empty() {
        lines.push(format!(
            "Energy: the fixed step's bounces are elastic, so it conserves energy to round-off at every \
             step tried (largest relative drift over a run {}), however wrong its trajectories; \
             energy conservation says nothing about its accuracy.",
            num(drift)
        ));
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
        if let Some(line) = budget(scene, reference, &pts, 1.0) {
            lines.push(line);
        }
    }
    lines
}

/// At what dt the stepper without the approach check stops sticking.
fn sticking(scene: &str, naive: &[&Group], fixed: &[&Group]) -> Option<String> {
    let first = naive.first()?;
    let last = naive[naive.len() - 1];
    let stuck = |g: &&Group| g.stuck > 0.0;
    let clean_below = naive.iter().take_while(|g| !stuck(g)).last();
    let worst = naive.iter().max_by(|a, b| a.stuck.total_cmp(&b.stuck))?;
    let naive_text = match (naive.iter().any(stuck), clean_below) {
        (false, _) => format!(
            "no pair stuck at any dt from {} to {}",
            num(first.dt),
            num(last.dt)
        ),
        (true, None) => format!(
            "pairs stuck at every dt tried, down to {} ({} stuck pairs per run at dt = {})",
            num(first.dt),
            num(worst.stuck),
            num(worst.dt)
        ),
        (true, Some(ok)) => format!(
            "pairs stuck above dt = {} and none at or below it ({} stuck pairs per run at dt = {})",
            num(ok.dt),
            num(worst.stuck),
            num(worst.dt)
        ),
    };
    let fixed_worst = fixed.iter().max_by(|a, b| a.stuck.total_cmp(&b.stuck));
    let fixed_text = if let Some(w) = fixed_worst.filter(|w| w.stuck > 0.0) {
        let first = fixed.iter().find(|g| g.stuck > 0.0).map_or(w.dt, |g| g.dt);
        format!(
            "with it, none below dt = {}, but still up to {} per run (at dt = {}), where overlaps \
             deeper than a step's travel are pushed back in by third particles",
            num(first),
            num(w.stuck),
            num(w.dt)
        )
    } else {
        "with it, none at any dt".to_string()
    };
    Some(format!(
        "Sticking, {scene}: without the approach check (the seeds' first version) {naive_text}; {fixed_text}."
    ))
}

/// How the headline error grows with dt, and from which dt it stands out.
fn bias(scene: &str, reference: &Group, pts: &[&Group]) -> String {
    let (what, _) = headline(reference);
    let errs: Vec<(f64, f64, f64)> = pts
        .iter()
        .filter_map(|g| error(headline(g).1, headline(reference).1).map(|(e, se)| (g.dt, e, se)))
        .collect();
    let seen: Vec<&(f64, f64, f64)> = errs.iter().filter(|(_, e, se)| *e > 3.0 * se).collect();
    let Some((dt, e, se)) = seen.first() else {
        return format!(
            "Bias, {scene}: the fixed step's {what} agrees with the exact engine's within three standard errors \
             at every dt tried, up to {}: any bias is below the statistics of these runs.",
            num(pts[pts.len() - 1].dt)
        );
    };
    let order = slope(&seen)
        .map(|p| format!("; from there it grows as dt^{}", num(p)))
        .unwrap_or_default();
    format!(
        "Bias, {scene}: the fixed step's {what} differs from the exact engine's by more than three standard \
         errors from dt = {} on ({} %){order}; below, it is within the statistics of these runs.",
        num(*dt),
        pm(100.0 * e, 100.0 * se)
    )
}

/// Least-squares slope of log error against log dt, over at least 3 points.
fn slope(pts: &[&(f64, f64, f64)]) -> Option<f64> {
    let xy: Vec<(f64, f64)> = pts.iter().map(|(dt, e, _)| (*dt, *e)).collect();
    log_slope(&xy, 3)
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
    Some(format!(
        "Cost, {scene}: one CPU-second buys the exact engine a {what} within {} % (its statistical \
         error, from runs of {} s each); the fixed step's best use of it, dt = {}, is within {} % at most \
         (its bias, bounded by these runs at two standard errors, and its own scatter).",
        num(100.0 * exact_error),
        num(reference.cpu),
        num(best.0),
        num(100.0 * best.1)
    ))
}

fn cost_chart(all: &[Group], scenes: &[String]) -> ChartSpec {
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
        layers.push(Layer::Line {
            points: pts.iter().map(|&(c, e, _)| (c, e)).collect(),
            paint: paint.faded(0.4),
            width: 1,
            dashed: false,
            label: None,
        });
        for (resolved, label) in [
            (true, format!("{scene}: fixed step ({what})")),
            (false, format!("{scene}: fixed step, bound (not resolved)")),
        ] {
            let marked: Vec<(f64, f64)> = pts
                .iter()
                .filter(|p| p.2 == resolved)
                .map(|&(c, e, _)| (c, e))
                .collect();
            if !marked.is_empty() {
                layers.push(Layer::Markers {
                    points: marked,
                    paint: if resolved { paint } else { paint.faded(0.35) },
                    label: Some(label),
                });
            }
        }
        let s = scatter(reference);
        if s > 1e-9 && reference.cpu > 0.0 {
            let c0 = reference.cpu;
            layers.push(Layer::Line {
                points: (0..=20)
                    .map(|i| {
                        let c = c0 * 10f64.powf(i as f64 / 5.0);
                        (c, s * (c0 / c).sqrt())
                    })
                    .collect(),
                paint,
                width: 2,
                dashed: true,
                label: Some(format!("{scene}: exact (statistical)")),
            });
        }
    }
    ChartSpec {
        title: "Error against CPU time".into(),
        x_label: "CPU seconds of one run".into(),
        y_label: "relative error".into(),
        x_log: true,
        y_log: true,
        layers,
    }
}

fn table(scene: &str, all: &[Group]) -> String {
    let reference = exact(all, scene);
    let mut md = format!(
        "\n### {scene}\n\n| integrator | dt | runs | βP | error | collision rate | error | \
         piston frequency | error | energy drift | deepest overlap | mean overlap | longest overlap (steps) | \
         stuck pairs/run | repeat collisions | CPU s/run |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
    );
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
    let err = |a: &Stats, b: Option<&Stats>| match b.and_then(|b| error(a, b)) {
        Some((e, se)) => format!("{} %", pm(100.0 * e, 100.0 * se)),
        None => "–".into(),
    };
    let stat = |s: &Stats| {
        if s.n == 0 {
            "–".to_string()
        } else {
            pm(s.mean, s.stderr)
        }
    };
    let exact_row = |g: &Group| g.integrator == Integrator::Exact;
    for g in rows {
        let r = reference.filter(|_| !exact_row(g));
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            g.integrator.name(),
            if g.dt.is_nan() {
                "–".into()
            } else {
                num(g.dt)
            },
            g.runs,
            stat(&g.pressure),
            err(&g.pressure, r.map(|r| &r.pressure)),
            stat(&g.collision_rate),
            err(&g.collision_rate, r.map(|r| &r.collision_rate)),
            stat(&g.frequency),
            err(&g.frequency, r.map(|r| &r.frequency)),
            num(g.energy_drift),
            opt(g.depth_max),
            opt(g.depth_mean),
            opt(g.longest),
            opt(g.stuck),
            if exact_row(g) {
                "–".into()
            } else {
                format!("{} %", num(100.0 * g.repeat_share))
            },
            num(g.cpu),
        );
    }
    md
}

fn opt(x: f64) -> String {
    if x.is_nan() { "–".into() } else { num(x) }
}

const INTRO: &str = "\nThe Imperial project's simulation moves every particle by a fixed step dt, bounces what \
overlaps a wall, and collides overlapping pairs, only if they approach (its fix for particles that stick \
together). The exact engine instead finds every collision's time. Both drive the same observers here, on the \
same scenes, so their results can be compared directly: each fixed step's error is its difference from the \
exact engine's ensemble, set beside the CPU time it took.\n";

const METHODS: &str = "\n### How it is measured\n\n\
Each scene runs with the exact engine (the reference) and with the fixed step at each dt, with and without the \
approach check, in independent replicas. **Errors** are relative differences of ensemble means, |fixed / exact − 1|, \
with the standard error of both ensembles combined; an error within about two standard errors is noise, not \
bias. **Wall pressure** is the momentum the walls receive per unit time and wall length, over each run's own \
kT = 2K/f (βP: every run draws its own energy, and the pressure follows it); the fixed step reflects a \
wall overlap at the step's end, so its impulses are right but late. **Collision rate** is pair collisions per unit \
time: a fixed step misses pairs that cross without overlapping at a step end (both move more than a diameter \
relative to each other in one step) and makes repeat collisions of a pair still overlapping from the step \
before. **Overlaps** are measured at step ends, as a fraction of the contact distance (deepest over the runs, \
mean over every overlap seen); the longest overlap counts the step ends in a row one pair spent overlapping, and \
a pair is **stuck** once it has overlapped longer than it would take to pass clean through its partner at their \
relative speed (two contact distances over that speed). **Piston frequency** uses the piston study's estimator (first four full \
periods). **CPU time** is the thread's CPU time for one run, scene building included. The exact engine's \
error at equal cost is its statistical error: one run's relative scatter at one run's cost, shrinking as \
cost^(−1/2) with more runs (or longer ones, as long as they are longer than the correlation time).\n";
