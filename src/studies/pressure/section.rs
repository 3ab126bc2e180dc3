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
use crate::model::report::ReportSection;
use crate::stats::ensemble::Runs;
use crate::stats::fill::fill;
use crate::stats::format::{num, pm};
use crate::stats::mser;
use crate::stats::named::named;
use crate::stats::summary::{Stats, z_score};
use crate::stats::table::table_row;
use crate::studies::curves::show;
use std::fmt::Write;

const INTRO: &str = include_str!("intro.md");
/// One line per figure, in the order `section` draws them.
const CAPTIONS: &str = include_str!("captions.md");
const FINITE_N: &str = include_str!("finite_n.md");
const WALLS: &str = include_str!("walls.md");
const FINITE_SIZE: &str = include_str!("finite_size.md");
const LOOP: &str = include_str!("loop.md");
const METHODS: &str = include_str!("methods.md");
/// The sentences and cells that carry numbers, one per line by name.
const SENTENCES: &str = include_str!("sentences.md");

/// A point's |drift| (second half against first, in error units) above
/// which it is flagged as still relaxing.
const DRIFT: f64 = 4.0;

/// Standard errors from which a loop's height counts as resolved.
const RESOLVED: f64 = 4.0;

pub fn section(runs: &Runs) -> anyhow::Result<ReportSection> {
    let all = points::points(runs);
    let fits = finite_size::fits(&all);
    let dense = dense_disks(&all);
    let examples = time_examples(&all);
    let drawn = [
        (!all.is_empty()).then(|| charts::z_chart(&all)),
        charts::deviation_chart(&all),
        (!examples.is_empty()).then(|| charts::time_chart(&examples)),
        (!fits.is_empty()).then(|| charts::finite_size_chart(&fits)),
        (dense.len() >= 3).then(|| charts::dense_disks_chart(&dense)),
    ];
    let mut md = format!("\n{INTRO}");
    let mut figures = Vec::new();
    for (figure, caption) in drawn.into_iter().zip(CAPTIONS.lines()) {
        if let Some(figure) = figure {
            md.push_str(&show(&mut figures, figure, caption));
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

/// The sentence of SENTENCES named `name` with its numbers.
fn sentence(name: &str, values: &[(&str, String)]) -> String {
    fill(named(SENTENCES, name), values)
}

/// The smallest and largest of `v`, as the report writes them.
fn range(v: &[f64]) -> [String; 2] {
    let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
    [num(lo), num(v.iter().copied().fold(0.0, f64::max))]
}

/// Up to four runs for the pressure-against-time figure: a rod point, the
/// walled disks (wall pressure), a disk and a sphere point.
fn time_examples(all: &[Point]) -> Vec<(&Point, &str)> {
    let pick = |label, f: fn(&Point) -> bool| Some((all.iter().rfind(|p| f(p))?, label));
    let picks = [
        pick("rods, walls", |p| p.dimension == 1),
        pick("disks, walls", |p| p.dimension == 2 && p.walls),
        pick("disks, virial", |p| {
            p.dimension == 2 && !p.walls && p.particles < 1000
        }),
        pick("spheres, virial", |p| {
            p.dimension == 3 && phases::is_fluid(3, p.eta)
        }),
    ];
    picks.into_iter().flatten().collect()
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
    let fluid: Vec<&Point> = (all.iter())
        .filter(|p| p.bulk() && phases::is_fluid(p.dimension, p.eta) && p.reference_holds())
        .collect();
    if fluid.is_empty() {
        return String::new();
    }
    let rel: Vec<f64> = fluid.iter().map(|p| p.error().0 / p.z.mean).collect();
    let [lo, hi] = range(&rel);
    let values = [
        ("points", fluid.len().to_string()),
        ("lo", lo),
        ("hi", hi),
        (
            "reach",
            rel.iter().filter(|r| **r <= 1.05e-4).count().to_string(),
        ),
        ("cpu", num(fluid.iter().map(|p| p.cpu_seconds).sum())),
        ("total", num(all.iter().map(|p| p.cpu_seconds).sum())),
    ];
    sentence("precision", &values) + "\n"
}

/// z of `stats` against `theory` to one decimal, "–" without one.
fn z_text(stats: &Stats, theory: f64) -> String {
    z_score(stats, theory).map_or("–".into(), |z| format!("{z:+.1}"))
}

/// One dimension's points: Z against each of its equations.
fn table(d: usize, pts: &[&Point]) -> String {
    let eqs = equations::of(d);
    let heads: Vec<String> = eqs.iter().map(|e| format!("{} (z)", e.name)).collect();
    let head = sentence("table", &[("equations", heads.join(" | "))]);
    let rule = "---|".repeat(13 + eqs.len());
    let mut md = format!("\n### {}\n\n{head}\n|{rule}\n", NAMES[d - 1]);
    for p in pts {
        let (err, from) = p.error();
        let start = match p.start {
            "compressed" => format!(
                "compressed ({} coll./particle)",
                num(p.prepare_per_particle)
            ),
            other => other.to_string(),
        };
        let mut cells = vec![
            num(p.eta),
            p.particles.to_string(),
            start,
            phases::label(d, p.eta).into(),
            pm(p.z.mean, err),
            format!("{from} ({})", p.z.n),
            num(err / p.z.mean),
            block(p),
            discarded(p),
            num(p.cut),
            num(p.drift),
        ];
        cells.extend(eqs.iter().map(|e| {
            let theory = (e.z)(p.eta);
            format!("{} ({})", num(theory), z_text(&p.z_stats(), theory))
        }));
        cells.extend([num(p.cpu_seconds), note(eqs, p)]);
        md.push_str(&table_row(&cells));
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
    let beyond: Vec<&str> = (eqs.iter().filter(|e| p.eta > e.holds_below))
        .map(|e| e.name)
        .collect();
    let values = [
        ("phase", phases::label(p.dimension, p.eta).to_string()),
        ("beyond", beyond.join(", ")),
        ("drift", num(p.drift)),
        ("n", p.z.n.to_string()),
        ("stderr", num(p.z.stderr)),
    ];
    let notes = [
        ("not_fluid", !phases::is_fluid(p.dimension, p.eta)),
        ("beyond", !beyond.is_empty()),
        ("drifting", p.drift > DRIFT),
        ("own_error", p.error().1 != "replicas"),
    ];
    let notes: Vec<String> = (notes.iter().filter(|(_, shown)| *shown))
        .map(|(name, _)| sentence(name, &values))
        .collect();
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
                format!(
                    "{} {} ({:+.1})",
                    e.name,
                    num(t),
                    (f.z_inf - t) / f.z_inf_err
                )
            })
            .collect();
        let mut chi2 = match f.dof {
            0 => "– (0)".into(),
            dof => format!("{} ({dof})", num(f.chi2)),
        };
        for &(n, c, dof) in &f.left_out {
            let values = [
                ("n", n.to_string()),
                ("chi2", num(c)),
                ("dof", dof.to_string()),
            ];
            chi2 += &sentence("left_out", &values);
        }
        md.push_str(&table_row(&[
            f.dimension.to_string(),
            num(f.eta),
            data.join("; "),
            pm(f.z_inf, f.z_inf_err),
            pm(f.slope, f.slope_err),
            chi2,
            eqs.join("; "),
        ]));
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
        md.push_str(&table_row(&[
            num(q.eta),
            phases::label(2, q.eta).into(),
            pm(v, e),
            format!("{} ({})", q.error().1, q.z.n),
            num(q.equilibrate),
            num(q.cut),
            num(q.drift),
            num(q.cpu_seconds),
        ]));
    }
    // The first of the largest falls, from a point to a denser one.
    let falls = (0..pts.len()).flat_map(|i| (i + 1..pts.len()).map(move |j| (i, j)));
    let best = (falls.map(|(i, j)| (i, j, pressure(pts[i]).0 - pressure(pts[j]).0)))
        .filter(|f| f.2 > 0.0)
        .reduce(|a, b| if b.2 > a.2 { b } else { a });
    let errors: Vec<f64> = pts.iter().map(|q| pressure(q).1).collect();
    let [lo, hi] = range(&errors);
    let mut values = vec![("lo", lo), ("hi", hi), ("flag", num(DRIFT))];
    let said = match best {
        Some((i, j, drop)) => {
            let err = pressure(pts[i]).1.hypot(pressure(pts[j]).1);
            let at = |q: &Point| {
                let (v, e) = pressure(q);
                format!("{} at η = {}", pm(v, e), num(q.eta))
            };
            let drift = pts[i].drift.max(pts[j].drift);
            values.extend([
                ("from", at(pts[i])),
                ("to", at(pts[j])),
                ("drop", pm(drop, err)),
                ("sigmas", num(drop / err)),
                ("points", pts.len().to_string()),
                ("drift", num(drift)),
            ]);
            let resolved = if drop / err >= RESOLVED {
                "resolved"
            } else {
                "noise"
            };
            let steady = match drift {
                d if d > DRIFT => "loop_drifts",
                d if d > 0.0 => "loop_steady",
                _ => "",
            };
            vec!["height", resolved, steady]
        }
        None => vec!["rises"],
    };
    let text: Vec<String> = (said.into_iter().chain(["error_bars"]))
        .filter(|name| !name.is_empty())
        .map(|name| sentence(name, &values))
        .collect();
    let _ = writeln!(md, "\n{}", text.join(" "));
    md
}

#[cfg(test)]
mod tests {
    use crate::stats::fill::{fill, unfilled};
    use crate::stats::named::{named, names};

    #[test]
    fn every_placeholder_is_filled() {
        assert!(unfilled(&super::methods()).is_empty());
        let text = fill(super::LOOP, &[("n", "1024".into())]);
        assert!(unfilled(&text).is_empty());
        for text in [
            super::INTRO,
            super::FINITE_N,
            super::WALLS,
            super::FINITE_SIZE,
        ] {
            assert!(unfilled(text).is_empty());
        }
        let keys = [
            "points",
            "lo",
            "hi",
            "reach",
            "cpu",
            "total",
            "equations",
            "phase",
            "beyond",
            "drift",
            "n",
            "stderr",
            "from",
            "to",
            "drop",
            "sigmas",
            "flag",
            "chi2",
            "dof",
        ];
        let values = keys.map(|k| (k, "x".to_string()));
        for name in names(super::SENTENCES) {
            let filled = fill(named(super::SENTENCES, name), &values);
            assert!(unfilled(&filled).is_empty(), "{filled}");
        }
    }
}
