//! The report section: Z against packing fraction with the equations of
//! state, per dimension a table of the points (error bars and where they
//! come from, how each start was made and equilibrated, the phase, z-scores),
//! wall against virial pressure, the 1/N extrapolation, pressure against
//! time and the dense disks' loop. The prose is in the Markdown beside it.

use super::charts::{self, NAMES};
use super::equations::{self, Equation};
use super::finite_size::{self, Fit};
use super::phases;
use super::points::{self, Point, TRUSTED_REPLICAS};
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::fill::fill;
use crate::stats::format::{num, pm};
use crate::stats::mser;
use crate::stats::summary::{Stats, z_score};
use crate::stats::table::table_row;
use std::fmt::Write;

const INTRO: &str = include_str!("intro.md");
/// One line per figure, in the order `section` draws them.
const CAPTIONS: &str = include_str!("captions.md");
const FINITE_N: &str = include_str!("finite_n.md");
const WALLS: &str = include_str!("walls.md");
const FINITE_SIZE: &str = include_str!("finite_size.md");
const LOOP: &str = include_str!("loop.md");
const METHODS: &str = include_str!("methods.md");

/// A point's |drift| (second half against first, in error units) above
/// which it is flagged as still relaxing.
const DRIFT: f64 = 4.0;

/// Standard errors from which a loop's height counts as resolved.
const RESOLVED: f64 = 4.0;

pub fn section(runs: &[(RunSpec, RunOutput)]) -> anyhow::Result<ReportSection> {
    let all = points::points(runs);
    let fits = finite_size::fits(&all);
    let dense = dense_disks(&all);
    let mut md = format!("\n{INTRO}");
    let examples = time_examples(&all);
    let charts = [
        (
            "pressure_z",
            (!all.is_empty()).then(|| charts::z_chart(&all)),
        ),
        ("pressure_deviation", charts::deviation_chart(&all)),
        (
            "pressure_time",
            (!examples.is_empty()).then(|| charts::time_chart(&examples)),
        ),
        (
            "pressure_finite_size",
            (!fits.is_empty()).then(|| charts::finite_size_chart(&fits)),
        ),
        (
            "pressure_dense_disks",
            (dense.len() >= 3).then(|| charts::dense_disks_chart(&dense)),
        ),
    ];
    let mut figures = Vec::new();
    for ((name, chart), caption) in charts.into_iter().zip(CAPTIONS.lines()) {
        if let Some(chart) = chart {
            let file = format!("{name}.svg");
            let _ = writeln!(md, "![{caption}]({file})\n");
            figures.push(Figure { file, chart });
        }
    }
    md.push_str(&headline(&all));
    md.push_str(FINITE_N);
    for d in 1..=3 {
        let pts = charts::bulk(&all, d);
        if !pts.is_empty() {
            md.push_str(&table(d, &pts));
        }
    }
    md.push_str(&walls_table(&all));
    md.push_str(&finite_size_table(&fits));
    if dense.len() >= 3 {
        md.push_str(&loop_text(&dense));
    }
    md.push_str(&methods());
    Ok(ReportSection {
        title: "Pressure against density: the equation of state".into(),
        markdown: md,
        figures,
        presents: super::RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

fn methods() -> String {
    fill(
        METHODS,
        &[
            ("batch", mser::BATCH.to_string()),
            ("significant", num(mser::SIGNIFICANT)),
            ("drift", num(DRIFT)),
            ("trusted", TRUSTED_REPLICAS.to_string()),
        ],
    )
}

/// Up to four runs for the pressure-against-time figure: a rod point, the
/// walled disks (wall pressure), a disk and a sphere point.
fn time_examples(all: &[Point]) -> Vec<(&Point, &str)> {
    let pick = |f: &dyn Fn(&Point) -> bool| all.iter().filter(|p| f(p)).last();
    [
        (pick(&|p| p.dimension == 1), "rods, walls"),
        (pick(&|p| p.dimension == 2 && p.walls), "disks, walls"),
        (
            pick(&|p| p.dimension == 2 && !p.walls && p.particles < 1000),
            "disks, virial",
        ),
        (
            pick(&|p| p.dimension == 3 && phases::is_fluid(3, p.eta)),
            "spheres, virial",
        ),
    ]
    .into_iter()
    .filter_map(|(p, label)| Some((p?, label)))
    .collect()
}

/// The periodic disks of the largest N with at least 1000 disks, from
/// eta = 0.68 on, by packing fraction.
fn dense_disks(all: &[Point]) -> Vec<&Point> {
    let dense = |p: &&Point| p.dimension == 2 && !p.walls && p.eta >= 0.68 && p.particles >= 1000;
    let n = all.iter().filter(dense).map(|p| p.particles).max();
    let mut pts: Vec<&Point> = (all.iter().filter(dense))
        .filter(|p| Some(p.particles) == n)
        .collect();
    pts.sort_by(|a, b| a.eta.total_cmp(&b.eta));
    pts
}

/// How precise the fluid points are and what they cost.
fn headline(all: &[Point]) -> String {
    let fluid: Vec<&Point> = all
        .iter()
        .filter(|p| {
            (p.dimension == 1 || !p.walls)
                && phases::is_fluid(p.dimension, p.eta)
                && p.eta <= equations::of(p.dimension)[0].holds_below
        })
        .collect();
    if fluid.is_empty() {
        return String::new();
    }
    let rel: Vec<f64> = fluid.iter().map(|p| p.error().0 / p.z.mean).collect();
    let total: f64 = all.iter().map(|p| p.cpu_seconds).sum();
    format!(
        "**Precision.** At the {} fluid points where a reference equation holds, the relative standard error of Z is {} to {}; {} of them reach 1e-4. They cost {} CPU seconds of the study's {}.\n",
        fluid.len(),
        num(rel.iter().copied().fold(f64::INFINITY, f64::min)),
        num(rel.iter().copied().fold(0.0, f64::max)),
        rel.iter().filter(|r| **r <= 1.05e-4).count(),
        num(fluid.iter().map(|p| p.cpu_seconds).sum()),
        num(total)
    )
}

/// z of `stats` against `theory` to one decimal, "–" without one.
fn z_text(stats: &Stats, theory: f64) -> String {
    z_score(stats, theory).map_or("–".into(), |z| format!("{z:+.1}"))
}

/// One dimension's points: Z against each of its equations.
fn table(d: usize, pts: &[&Point]) -> String {
    let eqs = equations::of(d);
    let mut md = format!(
        "\n### {}\n\n| η | N | start | phase | Z | error from | rel. error | runs' own error (block; ×2 ratio) | discarded | MSER cut | max \\|drift\\| |",
        NAMES[d - 1]
    );
    for e in eqs {
        let _ = write!(md, " {} (z) |", e.name);
    }
    let _ = writeln!(md, " CPU s | note |\n|{}", "---|".repeat(13 + eqs.len()));
    for p in pts {
        let (err, from) = p.error();
        let start = match p.start {
            "compressed" => format!(
                "compressed ({} coll./particle)",
                num(p.prepare_per_particle)
            ),
            other => other.to_string(),
        };
        let _ = write!(
            md,
            "| {} | {} | {start} | {} | {} | {from} ({}) | {} | {} | {} | {} | {} |",
            num(p.eta),
            p.particles,
            phases::label(d, p.eta),
            pm(p.z.mean, err),
            p.z.n,
            num(err / p.z.mean),
            block(p),
            discarded(p),
            num(p.cut),
            num(p.drift),
        );
        for e in eqs {
            let theory = (e.z)(p.eta);
            let _ = write!(md, " {} ({}) |", num(theory), z_text(&p.z_stats(), theory));
        }
        let _ = writeln!(md, " {} | {} |", num(p.cpu_seconds), note(eqs, p));
    }
    md
}

/// "±s (t; r)": the block-average error, block length and doubling ratio;
/// for rods the wall-hit model's error instead.
fn block(p: &Point) -> String {
    if p.run_basis == "wall hits" && p.run_stderr.is_finite() {
        let (own, blocks) = (num(p.run_stderr), num(p.block_stderr));
        return format!("±{own} (wall hits; blocks ±{blocks}, not valid here)");
    }
    if !p.block_stderr.is_finite() {
        return "–".into();
    }
    let ratio = if p.block_doubling.is_finite() {
        num(p.block_doubling)
    } else {
        "no plateau".into()
    };
    format!("±{} ({}; {ratio})", num(p.block_stderr), num(p.block_time))
}

/// Time discarded before recording, and about how many collisions per
/// particle that was (at the measured rate).
fn discarded(p: &Point) -> String {
    if p.equilibrate == 0.0 {
        return "0".into();
    }
    let collisions = num(p.equilibrate * p.collision_rate);
    format!("{} (~{collisions} coll./particle)", num(p.equilibrate))
}

/// The phase, equations beyond their range, and any sign of a run not in
/// equilibrium.
fn note(eqs: &[Equation], p: &Point) -> String {
    let mut notes = Vec::new();
    if !phases::is_fluid(p.dimension, p.eta) {
        let phase = phases::label(p.dimension, p.eta);
        notes.push(format!(
            "not the stable fluid ({phase}): no fluid equation applies"
        ));
    }
    let beyond: Vec<&str> = (eqs.iter().filter(|e| p.eta > e.holds_below))
        .map(|e| e.name)
        .collect();
    if !beyond.is_empty() {
        notes.push(format!("beyond the range of {}", beyond.join(", ")));
    }
    if p.drift > DRIFT {
        let drift = num(p.drift);
        notes.push(format!(
            "drifting: a run's halves differ by {drift} error bars"
        ));
    }
    if p.error().1 != "replicas" {
        notes.push(format!(
            "the {} replicas scatter less than their runs' own error ({}): that error used",
            p.z.n,
            num(p.z.stderr)
        ));
    }
    notes.join("; ")
}

fn walls_table(all: &[Point]) -> String {
    let stats = |s: Option<&Stats>| s.map_or("–".into(), |s| pm(s.mean, s.stderr));
    let rows: String = (all.iter())
        .filter_map(|p| Some((p, p.wall_minus_virial.as_ref()?)))
        .map(|(p, diff)| {
            table_row(&[
                p.dimension.to_string(),
                num(p.eta),
                p.particles.to_string(),
                stats(p.z_wall.as_ref()),
                stats(p.z_virial.as_ref()),
                pm(diff.mean, diff.stderr),
                z_text(diff, 0.0),
            ])
        })
        .collect();
    if rows.is_empty() {
        rows
    } else {
        WALLS.to_string() + &rows
    }
}

fn finite_size_table(fits: &[Fit]) -> String {
    if fits.is_empty() {
        return String::new();
    }
    let mut md = FINITE_SIZE.to_string();
    for f in fits {
        let data: Vec<String> = (f.data.iter())
            .map(|&(n, z, e)| format!("{n}: {}", pm(z, e)))
            .collect();
        let eqs: Vec<String> = (equations::of(f.dimension).iter())
            .map(|e| {
                let t = (e.z)(f.eta);
                let z = (f.z_inf - t) / f.z_inf_err;
                format!("{} {} ({z:+.1})", e.name, num(t))
            })
            .collect();
        let mut chi2 = if f.dof > 0 {
            format!("{} ({})", num(f.chi2), f.dof)
        } else {
            "– (0)".into()
        };
        for (n, c, dof) in &f.left_out {
            let c = num(*c);
            let _ = write!(
                chi2,
                "; N = {n} left out (the line through it: χ² {c} for {dof}, beyond its 99 % point)"
            );
        }
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {chi2} | {} |",
            f.dimension,
            num(f.eta),
            data.join("; "),
            pm(f.z_inf, f.z_inf_err),
            pm(f.slope, f.slope_err),
            eqs.join("; ")
        );
    }
    md
}

/// βPσ² = Z ρ of a point and its error.
fn pressure(q: &Point) -> (f64, f64) {
    let rho = 4.0 * q.eta / std::f64::consts::PI;
    (q.z.mean * rho, q.error().0 * rho)
}

/// The dense disks' table, and whether their pressure falls anywhere as
/// the density grows (the finite-size loop of the liquid-hexatic
/// coexistence): the loop's height is the largest fall of βPσ² from a
/// point to a denser one, with the two points' errors combined, resolved
/// from `RESOLVED` standard errors on and with its two points' drift told.
fn loop_text(pts: &[&Point]) -> String {
    let mut md = fill(LOOP, &[("n", pts[0].particles.to_string())]);
    for q in pts {
        let (v, e) = pressure(q);
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} ({}) | {} | {} | {} | {} |",
            num(q.eta),
            phases::label(2, q.eta),
            pm(v, e),
            q.error().1,
            q.z.n,
            num(q.equilibrate),
            num(q.cut),
            num(q.drift),
            num(q.cpu_seconds)
        );
    }
    let mut best: Option<(usize, usize, f64, f64)> = None;
    for i in 0..pts.len() {
        for j in i + 1..pts.len() {
            let ((pi, ei), (pj, ej)) = (pressure(pts[i]), pressure(pts[j]));
            if pi - pj > 0.0 && best.is_none_or(|b| pi - pj > b.2) {
                best = Some((i, j, pi - pj, ei.hypot(ej)));
            }
        }
    }
    md.push('\n');
    match best {
        Some((i, j, drop, err)) => {
            let at =
                |q: &Point| format!("{} at η = {}", pm(pressure(q).0, pressure(q).1), num(q.eta));
            let _ = write!(
                md,
                "**Loop height.** βPσ² falls from {} to {}, by {}: {} standard errors, the largest fall between any two of the {} points (a pure-noise curve would show a fall of a standard error or two). ",
                at(pts[i]),
                at(pts[j]),
                pm(drop, err),
                num(drop / err),
                pts.len()
            );
            md.push_str(if drop / err >= RESOLVED {
                "The loop is resolved."
            } else {
                "That is within the noise: no loop is resolved."
            });
            let drift = pts[i].drift.max(pts[j].drift);
            if drift > DRIFT {
                let _ = write!(
                    md,
                    " Its points drift (max |drift| {}, over the flag at {}): they still relax, and the height is less certain than its error bar.",
                    num(drift),
                    num(DRIFT)
                );
            } else if drift > 0.0 {
                let _ = write!(
                    md,
                    " Both its points pass the drift test (max |drift| {}, under the flag at {}).",
                    num(drift),
                    num(DRIFT)
                );
            }
        }
        None => md.push_str("Here βPσ² rises at every step: no loop is resolved."),
    }
    let errors: Vec<f64> = pts.iter().map(|q| pressure(q).1).collect();
    let _ = writeln!(
        md,
        " The error bars of βPσ² are {} to {}.",
        num(errors.iter().copied().fold(f64::INFINITY, f64::min)),
        num(errors.iter().copied().fold(0.0, f64::max))
    );
    md
}

#[cfg(test)]
mod tests {
    use crate::stats::fill::unfilled;

    #[test]
    fn every_placeholder_is_filled() {
        assert!(unfilled(&super::methods()).is_empty());
        let text = crate::stats::fill::fill(super::LOOP, &[("n", "1024".into())]);
        assert!(unfilled(&text).is_empty());
        for text in [
            super::INTRO,
            super::FINITE_N,
            super::WALLS,
            super::FINITE_SIZE,
        ] {
            assert!(unfilled(text).is_empty());
        }
    }
}
