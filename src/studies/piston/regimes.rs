//! Across the sweep: where the adiabatic theory holds, in terms of the
//! piston's mass over the gases' and its speed over theirs (and in 2D the
//! gases' collisions per radian of the swing); how the relaxation time grows
//! with M; the long-time share against equipartition; each with its cost.
//! One part per dimension the sweep holds.

use super::Options;
use crate::model::chart::{ChartSpec, Layer, Paint, colour};
use crate::model::report::Figure;
use crate::stats::ensemble::Runs;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::summary::Stats;
use crate::studies::piston::points::{Point, by_dimension, groups, marked, points};
use crate::studies::piston::relaxation::relaxation;
use std::f64::consts::{PI, TAU};
use std::fmt::Write;

const PARAMETERS: &str = include_str!("text/parameters.md");
const PARAMETERS_ACROSS: &str = include_str!("text/parameters_2d.md");
const TABLE: &str = include_str!("text/table.md");
const TABLE_ACROSS: &str = include_str!("text/table_2d.md");
const EQUIPARTITION: &str = include_str!("text/equipartition.md");

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
    for (dimension, points) in by_dimension(&all) {
        let heading = match dimension {
            1 => "Rods (1D)",
            2 => "Disks beside a wall (2D)",
            _ => "Spheres beside a wall (3D)",
        };
        let across = dimension > 1;
        let _ = writeln!(md, "\n### {heading}: where the adiabatic theory holds\n");
        md.push_str(&boundaries(&points, across));
        let name = frequency_figure(&points, dimension, figures);
        let _ = writeln!(
            md,
            "![{dimension}D: measured frequency over the nonlinear adiabatic prediction against the piston's mass over the gases' mass (mean ± standard error per sweep point); the curve is the gases'-inertia correction sqrt(M/(M + M_gas/3)) for small oscillations.]({name})\n"
        );
        md.push_str(&resolution(&points));
        md.push_str(&table(&points, across));
        let _ = writeln!(md, "\n### {heading}: how the piston relaxes\n");
        md.push_str(&relaxation(&points, dimension, figures));
        let _ = writeln!(md, "\n### {heading}: the long-time share\n");
        md.push_str(&equipartition(&points, o.late));
    }
    md
}

/// Where the theory holds and breaks down, in terms of M/M_gas, the speed
/// ratio and (across x) omega tau.
fn boundaries(points: &[&Point], across: bool) -> String {
    let mut md = String::new();
    let judged_results = [
        (
            "frequency_ratio",
            "The adiabatic frequency (piston alone as the inertia)",
        ),
        (
            "frequency_ratio_inertia",
            "With a third of the gases' mass added to the piston's, the adiabatic frequency",
        ),
        (
            "frequency_ratio_exchange",
            "With the gases' inertia and their lag in sharing the compression (exchange theory), the frequency",
        ),
    ];
    for (result, what) in &judged_results[..if across { 3 } else { 2 }] {
        md.push_str(&boundary(points, result, what, across));
    }
    md.push('\n');
    md.push_str(&prose(PARAMETERS, PARAMETERS_ACROSS, across));
    md.push_str("\n\n");
    md
}

/// A text, and where the gas has axes across x, what it adds there.
fn prose(text: &str, across_text: &str, across: bool) -> String {
    let mut md = text.trim_end().to_string();
    if across {
        md.push(' ');
        md.push_str(across_text.trim_end());
    }
    md
}

/// One bullet: at how many points `result` holds, from which M/M_gas on,
/// up to which piston speed (and omega tau), and how the others fail.
fn boundary(points: &[&Point], result: &str, what: &str, across: bool) -> String {
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
        judged
            .iter()
            .filter(|j| j.3 == Verdict::Holds)
            .map(f)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let count_of = |v: Verdict| judged.iter().filter(|j| j.3 == v).count();
    let mut md = format!(
        "- {what} holds within 1% (two standard errors to spare) at {} of {} points",
        count_of(Verdict::Holds),
        judged.len()
    );
    if holds_from.is_finite() {
        let _ = write!(md, ", at every point with M/M_gas ≥ {}", num(holds_from));
    }
    let fastest = holding(|j| j.1);
    if fastest.is_finite() {
        let _ = write!(
            md,
            " (piston speed up to {} of the gases' thermal speed",
            num(fastest)
        );
        let wt = holding(|j| j.2);
        if across && wt.is_finite() {
            let _ = write!(md, ", ωτ_x up to {}", num(wt));
        }
        md.push(')');
    }
    for (verdict, label) in [
        (
            Verdict::Agrees,
            "agrees within an error bar that would show 5%",
        ),
        (Verdict::Small, "small deviations (< 5%)"),
        (Verdict::Breaks, "breaks down (> 5%)"),
    ] {
        let n = count_of(verdict);
        if n > 0 {
            let s = if n == 1 { "" } else { "s" };
            let _ = write!(md, "; {label} at {n} point{s}");
        }
    }
    if breaks_to.is_finite() {
        let _ = write!(md, ", at every point with M/M_gas ≤ {}", num(breaks_to));
    }
    md.push_str(".\n");
    md
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
    if !worst.0.is_finite() {
        return String::new();
    }
    format!(
        "Sampling: at least {:.0} samples per measured period at every point, so interpolating the \
         crossings limits the frequency to {:.1e} relative, at most {:.0}% of a point's standard error.\n\n",
        worst.0,
        worst.1,
        100.0 * worst.2
    )
}

/// A column of the per-point table: its header, whether only a gas with
/// axes across x has it, the result it shows and its cell.
type Column = (&'static str, bool, &'static str, fn(&Point, &str) -> String);

/// A result's mean ± standard error.
fn both(p: &Point, name: &str) -> String {
    pm(p.stat(name).mean, p.stat(name).stderr)
}

fn mean(p: &Point, name: &str) -> String {
    num(p.stat(name).mean)
}

const COLUMNS: &[Column] = &[
    ("point", false, "", |p, _| p.id.to_string()),
    ("parameters", false, "", |p, _| p.label()),
    ("M/M_gas", false, "mass_over_gas", mean),
    ("v_piston/v_gas", false, "speed_ratio", mean),
    ("ωτ_x", true, "omega_tau", mean),
    (
        "ω/ω_adiabatic (n)",
        false,
        "frequency_ratio",
        |p, name| format!("{} ({}/{})", both(p, name), p.stat(name).n, p.runs),
    ),
    ("ω/ω_ad+inertia", false, "frequency_ratio_inertia", both),
    ("ω/ω_exchange", true, "frequency_ratio_exchange", both),
    ("ω/ω_γ=3", true, "frequency_ratio_collisionless", both),
    ("ω/ω_isothermal", false, "frequency_ratio_isothermal", both),
    ("adiabatic", false, "frequency_ratio", |p, name| {
        verdict_text(&p.stat(name))
    }),
    ("τ relax (n)", false, "relaxation_time", |p, name| {
        let tau = p.stat(name);
        if p.relaxed() {
            format!("{} ({}/{})", pm(tau.mean, tau.stderr), tau.n, p.runs)
        } else {
            format!(
                "> {} ({}/{} reached 1/e)",
                num(p.tau_bound()),
                tau.n,
                p.runs
            )
        }
    }),
    ("τ exchange", true, "relaxation_time_exchange", mean),
    ("excess left", false, "excess_left", both),
    (
        "piston share / 1/N_free",
        false,
        "piston_share",
        |p, name| format!("{} / {}", both(p, name), num(p.equipartition)),
    ),
    ("CPU s", false, "", |p, _| format!("{:.2}", p.seconds)),
    ("collisions", false, "", |p, _| count(p.collisions)),
];

/// Every point's results, one row each.
fn table(points: &[&Point], across: bool) -> String {
    let columns: Vec<&Column> = COLUMNS.iter().filter(|c| across || !c.1).collect();
    let mut md = prose(TABLE, TABLE_ACROSS, across);
    let headers: Vec<&str> = columns.iter().map(|c| c.0).collect();
    let _ = write!(
        md,
        "\n\n| {} |\n|{}\n",
        headers.join(" | "),
        "---|".repeat(columns.len())
    );
    for p in points {
        let cells: Vec<String> = columns.iter().map(|c| (c.3)(p, c.2)).collect();
        let _ = writeln!(md, "| {} |", cells.join(" | "));
    }
    md
}

fn frequency_figure(points: &[&Point], dimension: usize, figures: &mut Vec<Figure>) -> String {
    let mut layers = Vec::new();
    for (i, (group, ps)) in groups(points).into_iter().enumerate() {
        let at: Vec<(f64, Stats)> = (ps.iter())
            .map(|p| (p.stat("mass_over_gas").mean, p.stat("frequency_ratio")))
            .collect();
        layers.extend(marked(&at, None, colour(i), group));
    }
    let mus: Vec<f64> = points
        .iter()
        .map(|p| p.stat("mass_over_gas").mean)
        .filter(|m| m.is_finite() && *m > 0.0)
        .collect();
    let lo = mus.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = mus.iter().copied().fold(0.0, f64::max);
    if hi > lo {
        layers.push(Layer::Line {
            points: (0..=100)
                .map(|k| {
                    let mu = lo * (hi / lo).powf(k as f64 / 100.0);
                    (mu, (mu / (mu + 1.0 / 3.0)).sqrt())
                })
                .collect(),
            paint: Paint::solid((0, 0, 0)),
            width: 1,
            dashed: true,
            label: Some("gas inertia: sqrt(M/(M + M_gas/3))".into()),
        });
    }
    let name = format!("piston_frequency_ratio_{dimension}d.svg");
    figures.push(Figure {
        file: name.clone(),
        chart: ChartSpec {
            title: format!("{dimension}D: measured over adiabatic frequency"),
            x_label: "piston mass / gas mass, M/M_gas".into(),
            y_label: "ω / ω_adiabatic".into(),
            x_log: true,
            layers,
            ..Default::default()
        },
    });
    name
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
    let mut md = fill(EQUIPARTITION, &values);
    if settled.is_empty() {
        return md;
    }
    md.push_str(
        "| point | parameters | piston share | 1/N_free | share × N_free | z | oscillator share (× N_free) | CPU s |\n|---|---|---|---|---|---|---|---|\n",
    );
    let mut within = 0;
    let mut oscillator = 0.0;
    for p in &settled {
        let share = p.stat("piston_share");
        let z = (share.mean - p.equipartition) / share.stderr;
        within += usize::from(z.abs() < 4.0);
        let osc = p.stat("oscillator_share");
        oscillator += osc.mean / p.equipartition / settled.len() as f64;
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {:+.1} | {} | {:.2} |",
            p.id,
            p.label(),
            pm(share.mean, share.stderr),
            num(p.equipartition),
            pm(share.mean / p.equipartition, share.stderr / p.equipartition),
            z,
            pm(osc.mean / p.equipartition, osc.stderr / p.equipartition),
            p.seconds
        );
    }
    let _ = writeln!(
        md,
        "\n{within} of {} agree with 1/N_free within four standard errors. The oscillator share (its kinetic \
         plus adiabatic potential energy, per 1/N_free) averages {} degrees of freedom over these points (a \
         harmonic oscillator's is two); the summary table sets it beside its microcanonical mean.\n",
        settled.len(),
        num(oscillator)
    );
    md
}

#[cfg(test)]
mod tests {
    use super::*;

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
        assert!(crate::stats::fill::unfilled(&fill(EQUIPARTITION, &values)).is_empty());
    }
}
