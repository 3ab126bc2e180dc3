//! Across the sweep: where the adiabatic theory holds, in terms of the
//! piston's mass over the gases' and its speed over theirs (and in 2D the
//! gases' collisions per radian of the swing); how the relaxation time grows
//! with M; the long-time share against equipartition; each with its cost.
//! One part per dimension the sweep holds.

use super::{CAPTIONS, Options, SWEEP};
use crate::model::chart::{Paint, colour};
use crate::model::report::Figure;
use crate::stats::ensemble::Runs;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::named::named;
use crate::stats::summary::Stats;
use crate::stats::table::table_row;
use crate::studies::curves::{bar, figure, measured, polyline, show};
use crate::studies::piston::points::{Point, by_dimension, groups, points};
use crate::studies::piston::relaxation::relaxation;
use std::f64::consts::{PI, TAU};
use std::fmt::Write;

/// How a frequency ratio compares with 1: holds (within 1% with two
/// standard errors to spare), small deviation (significant, below 5%),
/// breaks down (significant, above 5%), agrees within an error bar that
/// would show a 5% deviation, or too uncertain to tell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Verdict {
    Holds,
    Small,
    Breaks,
    Agrees,
    Unclear,
}

fn verdict(s: &Stats) -> Verdict {
    let gap = (s.mean - 1.0).abs();
    if !s.mean.is_finite() || !s.stderr.is_finite() {
        Verdict::Unclear
    } else if gap + 2.0 * s.stderr < 0.01 {
        Verdict::Holds
    } else if gap > 3.0 * s.stderr && gap < 0.05 {
        Verdict::Small
    } else if gap > 3.0 * s.stderr {
        Verdict::Breaks
    } else if gap + 3.0 * s.stderr < 0.05 {
        Verdict::Agrees
    } else {
        Verdict::Unclear
    }
}

fn verdict_text(s: &Stats) -> String {
    let gap = 100.0 * (s.mean - 1.0);
    match verdict(s) {
        Verdict::Holds => format!("holds ({gap:+.2}%)"),
        Verdict::Small => format!("small deviation ({gap:+.1}%)"),
        Verdict::Breaks => format!("breaks down ({gap:+.0}%)"),
        Verdict::Agrees => format!("agrees (±{:.1}%)", 100.0 * s.stderr),
        Verdict::Unclear => "error too large".into(),
    }
}

/// The regime summary, tables and figures, one part per dimension.
pub fn regimes(runs: &Runs, o: &Options, figures: &mut Vec<Figure>) -> String {
    let all = points(runs);
    let mut md = String::new();
    for points in by_dimension(&all) {
        let dimension = points[0].dimension;
        let heading = match dimension {
            1 => "Rods (1D)",
            2 => "Disks beside a wall (2D)",
            _ => "Spheres beside a wall (3D)",
        };
        let across = dimension > 1;
        let _ = writeln!(md, "\n### {heading}: where the adiabatic theory holds\n");
        let judged = [
            "frequency_ratio",
            "frequency_ratio_inertia",
            "frequency_ratio_exchange",
        ];
        for result in &judged[..if across { 3 } else { 2 }] {
            md += &boundary(&points, result, across);
        }
        md = md + "\n" + &prose("parameters", across) + "\n\n";
        let values = [("dimension", dimension.to_string())];
        let caption = fill(named(CAPTIONS, "frequency"), &values);
        md += &show(figures, frequency_figure(&points, dimension), &caption);
        md += &resolution(&points);
        md += &table(&points, across);
        let _ = writeln!(md, "\n### {heading}: how the piston relaxes\n");
        md += &relaxation(&points, dimension, figures);
        let _ = writeln!(md, "\n### {heading}: the long-time share\n");
        md += &equipartition(&points, o.late);
    }
    md
}

/// A sweep text, and where the gas has axes across x, what it adds there.
fn prose(name: &str, across: bool) -> String {
    let mut md = named(SWEEP, name).to_string();
    if across {
        md = md + " " + named(SWEEP, &format!("{name}_across"));
    }
    md
}

/// One bullet: at how many points `result` holds, from which M/M_gas on,
/// up to which piston speed (and omega tau), and how the others fail.
fn boundary(points: &[&Point], result: &str, across: bool) -> String {
    // (M/M_gas, speed ratio, omega tau, verdict) per point.
    let judged: Vec<(f64, f64, f64, Verdict)> = points
        .iter()
        .map(|p| {
            let [mu, speed, wt] =
                ["mass_over_gas", "speed_ratio", "omega_tau"].map(|n| p.stat(n).mean);
            (mu, speed, wt, verdict(&p.stat(result)))
        })
        .filter(|(mu, ..)| mu.is_finite())
        .collect();
    // The smallest M/M_gas above every point that does not hold, and the
    // largest below every point that does not break down.
    let masses =
        |v: Verdict, is: bool| (judged.iter().filter(move |j| (j.3 == v) == is)).map(|j| j.0);
    let last_other = masses(Verdict::Holds, false).fold(f64::NEG_INFINITY, f64::max);
    let holds_from =
        (masses(Verdict::Holds, true).filter(|&mu| mu > last_other)).fold(f64::INFINITY, f64::min);
    let first_other = masses(Verdict::Breaks, false).fold(f64::INFINITY, f64::min);
    let breaks_to = (masses(Verdict::Breaks, true).filter(|&mu| mu < first_other))
        .fold(f64::NEG_INFINITY, f64::max);
    let holding = |f: fn(&(f64, f64, f64, Verdict)) -> f64| {
        (judged.iter().filter(|j| j.3 == Verdict::Holds))
            .map(f)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let count_of = |v: Verdict| judged.iter().filter(|j| j.3 == v).count();
    // The part of the sentence named `name`, where its number x is finite.
    let part = |name: &str, x: f64, more: String| match x.is_finite() {
        true => fill(named(SWEEP, name), &[("x", num(x)), ("more", more)]),
        false => String::new(),
    };
    let wt = if across { holding(|j| j.2) } else { f64::NAN };
    let speed = part(
        "speed",
        holding(|j| j.1),
        part("omega_tau", wt, String::new()),
    );
    // Each verdict's phrase is the line of its name.
    let others: String = [Verdict::Agrees, Verdict::Small, Verdict::Breaks]
        .into_iter()
        .map(|v| (count_of(v), named(SWEEP, &format!("{v:?}"))))
        .filter(|(n, _)| *n > 0)
        .map(|(n, phrase)| format!("; {phrase} at {n} point{}", if n == 1 { "" } else { "s" }))
        .collect();
    let values = [
        ("what", named(SWEEP, result).to_string()),
        ("held", count_of(Verdict::Holds).to_string()),
        ("judged", judged.len().to_string()),
        ("from", part("from", holds_from, String::new())),
        ("speed", speed),
        ("others", others),
        ("to", part("to", breaks_to, String::new())),
    ];
    fill(named(SWEEP, "bullet"), &values) + "\n"
}

/// How well the sampling resolves the frequency at the worst point: linear
/// interpolation between samples dt apart places a crossing within
/// (omega dt)^2 / (8 omega), so K periods give omega to (omega dt)^2/(8 pi K)
/// relative (the bound `piston_estimators` tests).
fn resolution(points: &[&Point]) -> String {
    // (samples per period, relative bound, bound over the relative error bar)
    let worst = points
        .iter()
        .map(|p| {
            let omega = p.stat("frequency");
            let periods = p.stat("frequency_periods").mean.max(1.0);
            let step = omega.mean * p.sample_every;
            let bound = step * step / (8.0 * PI * periods);
            (TAU / step, bound, bound / (omega.stderr / omega.mean))
        })
        .filter(|w| w.0.is_finite())
        .fold((f64::INFINITY, 0.0f64, 0.0f64), |w, v| {
            (w.0.min(v.0), w.1.max(v.1), w.2.max(v.2))
        });
    let values = [
        ("per_period", format!("{:.0}", worst.0)),
        ("bound", format!("{:.1e}", worst.1)),
        ("share", format!("{:.0}", 100.0 * worst.2)),
    ];
    match worst.0.is_finite() {
        true => fill(named(SWEEP, "resolution"), &values) + "\n\n",
        false => String::new(),
    }
}

/// A column of the per-point table: its header, whether only a gas with
/// axes across x has it, the result it shows and its cell.
type Column = (&'static str, bool, &'static str, fn(&Point, &str) -> String);

/// A result's mean ± standard error.
fn both(p: &Point, name: &str) -> String {
    pm(p.stat(name).mean, p.stat(name).stderr)
}

/// With the runs that gave it, n of N.
fn counted(p: &Point, name: &str) -> String {
    format!("{} ({}/{})", both(p, name), p.stat(name).n, p.runs)
}

fn mean(p: &Point, name: &str) -> String {
    num(p.stat(name).mean)
}

/// The relaxation time, or where the runs ended first its lower bound.
fn relaxation_cell(p: &Point, name: &str) -> String {
    let (bound, n, runs) = (num(p.tau_bound()), p.stat(name).n, p.runs);
    match p.relaxed() {
        true => counted(p, name),
        false => format!("> {bound} ({n}/{runs} reached 1/e)"),
    }
}

const COLUMNS: &[Column] = &[
    ("point", false, "", |p, _| p.of.spec.point_id.to_string()),
    ("parameters", false, "", |p, _| p.label()),
    ("M/M_gas", false, "mass_over_gas", mean),
    ("v_piston/v_gas", false, "speed_ratio", mean),
    ("ωτ_x", true, "omega_tau", mean),
    ("ω/ω_adiabatic (n)", false, "frequency_ratio", counted),
    ("ω/ω_ad+inertia", false, "frequency_ratio_inertia", both),
    ("ω/ω_exchange", true, "frequency_ratio_exchange", both),
    ("ω/ω_γ=3", true, "frequency_ratio_collisionless", both),
    ("ω/ω_isothermal", false, "frequency_ratio_isothermal", both),
    ("adiabatic", false, "frequency_ratio", |p, name| {
        verdict_text(&p.stat(name))
    }),
    ("τ relax (n)", false, "relaxation_time", relaxation_cell),
    ("τ exchange", true, "relaxation_time_exchange", mean),
    ("excess left", false, "excess_left", both),
    (
        "piston share / 1/N_free",
        false,
        "piston_share",
        |p, name| format!("{} / {}", both(p, name), num(p.equipartition)),
    ),
    ("CPU s", false, "", |p, _| format!("{:.2}", p.seconds)),
    ("collisions", false, "", |p, _| count(p.of.collisions())),
];

/// Every point's results, one row each.
fn table(points: &[&Point], across: bool) -> String {
    let columns: Vec<&Column> = COLUMNS.iter().filter(|c| across || !c.1).collect();
    let row = |cell: &dyn Fn(&Column) -> String| {
        table_row(&columns.iter().map(|c| cell(c)).collect::<Vec<_>>())
    };
    let mut md = prose("table", across) + "\n\n" + &row(&|c| c.0.to_string());
    md = md + "|" + &"---|".repeat(columns.len()) + "\n";
    for p in points {
        md += &row(&|c| (c.3)(p, c.2));
    }
    md
}

/// Measured over adiabatic frequency against M/M_gas, a colour per group,
/// with the gases'-inertia correction across the masses swept.
fn frequency_figure(points: &[&Point], dimension: usize) -> Figure {
    let mut layers = Vec::new();
    for (i, ps) in groups(points).into_iter().enumerate() {
        let at = |p: &&Point| bar(p.stat("mass_over_gas").mean, &p.stat("frequency_ratio"));
        layers.extend(measured(ps.iter().map(at), colour(i), &ps[0].group));
    }
    let (lo, hi) = (points.iter().map(|p| p.stat("mass_over_gas").mean))
        .filter(|m| m.is_finite() && *m > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(l, h), m| (l.min(m), h.max(m)));
    if hi > lo {
        let mus = (0..=100).map(|k| lo * (hi / lo).powf(k as f64 / 100.0));
        let curve = mus.map(|mu| (mu, (mu / (mu + 1.0 / 3.0)).sqrt())).collect();
        let label = Some("gas inertia: sqrt(M/(M + M_gas/3))".into());
        layers.push(polyline(curve, Paint::solid((0, 0, 0)), 1, true, label));
    }
    let name = format!("piston_frequency_ratio_{dimension}d.svg");
    let title = format!("{dimension}D: measured over adiabatic frequency");
    let labels = (title, "piston mass / gas mass, M/M_gas", "ω / ω_adiabatic");
    figure(&name, labels, (true, false), layers)
}

/// The piston's late share of the kinetic energy against 1/N_free, at the
/// points whose runs all relaxed within a tenth of the run (so the late
/// part is at equilibrium), with its cost.
fn equipartition(points: &[&Point], late: f64) -> String {
    let settled: Vec<&&Point> = points
        .iter()
        .filter(|p| p.relaxed() && p.stat("relaxation_time").mean < 0.1 * p.duration)
        .collect();
    let values = [
        ("late", num(100.0 * late)),
        ("settled", settled.len().to_string()),
        ("points", points.len().to_string()),
    ];
    let mut md = fill(named(SWEEP, "equipartition"), &values) + "\n\n";
    if settled.is_empty() {
        return md;
    }
    md = md + named(SWEEP, "shares") + "\n|" + &"---|".repeat(8) + "\n";
    let (mut within, mut oscillator) = (0, 0.0);
    for p in &settled {
        let (share, osc) = (p.stat("piston_share"), p.stat("oscillator_share"));
        let z = (share.mean - p.equipartition) / share.stderr;
        within += usize::from(z.abs() < 4.0);
        oscillator += osc.mean / p.equipartition / settled.len() as f64;
        let per_free = |s: &Stats| pm(s.mean / p.equipartition, s.stderr / p.equipartition);
        md += &table_row(&[
            p.of.spec.point_id.to_string(),
            p.label(),
            pm(share.mean, share.stderr),
            num(p.equipartition),
            per_free(&share),
            format!("{z:+.1}"),
            per_free(&osc),
            format!("{:.2}", p.seconds),
        ]);
    }
    let values = [
        ("within", within.to_string()),
        ("settled", settled.len().to_string()),
        ("dof", num(oscillator)),
    ];
    md + "\n" + &fill(named(SWEEP, "agreement"), &values) + "\n\n"
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::fill::unfilled;

    #[test]
    fn verdicts() {
        let s = |mean, stderr| Stats {
            n: 8,
            mean,
            std: f64::NAN,
            stderr,
            ci_low: f64::NAN,
            ci_high: f64::NAN,
        };
        assert_eq!(verdict(&s(1.002, 0.001)), Verdict::Holds);
        assert_eq!(verdict(&s(0.98, 0.002)), Verdict::Small);
        assert_eq!(verdict(&s(0.8, 0.01)), Verdict::Breaks);
        assert_eq!(verdict(&s(0.99, 0.01)), Verdict::Agrees);
        assert_eq!(verdict(&s(0.98, 0.02)), Verdict::Unclear);
    }

    #[test]
    fn every_placeholder_is_filled() {
        let values = [
            ("late", "50".into()),
            ("settled", "1".into()),
            ("points", "2".into()),
        ];
        assert!(unfilled(&fill(named(SWEEP, "equipartition"), &values)).is_empty());
    }
}
