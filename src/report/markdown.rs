//! report.md: what was run, the plots, measurement beside theory, the cost,
//! the study's own sections, failures, and how to read the tables.
//! `html.rs` renders this same text, so the two never disagree.

use super::ReportMeta;
use super::contents::contents;
use super::findings::findings;
use super::plots::{Figure, Points, point_label, value_text};
use crate::model::descriptor::{Descriptor, SweepValues};
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::model::summary::SummaryRow;
use crate::stats::format::{count, num, pm};
use std::collections::BTreeMap;
use std::fmt::Write;

pub use crate::model::text::{one_line, shortened, text};

/// |z| above this is flagged: more than three standard errors from theory.
pub const Z_FLAG: f64 = 3.0;

pub struct Inputs<'a> {
    pub descriptor: &'a Descriptor,
    pub runs: &'a [(RunSpec, RunOutput)],
    pub summary: &'a [SummaryRow],
    pub sections: &'a [ReportSection],
    pub meta: &'a ReportMeta,
    pub figures: &'a [Figure],
    /// What the generic figures leave out, a line each (`sampled.rs`).
    pub omitted: &'a [String],
    pub points: &'a Points,
}

/// The header and the findings on the first screen, the contents list
/// under them, then the rest.
pub fn render(inp: &Inputs) -> String {
    let mut top = String::new();
    header(&mut top, inp);
    top += &findings(inp);
    let rest = rest(inp);
    top.clone() + &contents(&top, &rest) + &rest
}

fn rest(inp: &Inputs) -> String {
    let mut md = String::new();
    what_was_run(&mut md, inp);
    energy_drift(&mut md, inp.runs);
    // The study's own sections first: they answer its questions.
    for s in inp.sections {
        let _ = writeln!(
            md,
            "## {}\n\n{}\n",
            one_line(&s.title),
            s.markdown.trim_end()
        );
    }
    theory_table(&mut md, inp);
    plots(&mut md, inp.figures, inp.omitted);
    cost(&mut md, inp);
    failures(&mut md, inp.meta);
    footer(&mut md, inp.runs);
    md
}

fn header(md: &mut String, inp: &Inputs) {
    let study = &inp.descriptor.study;
    let _ = writeln!(md, "# {}\n", text(&study.name));
    // The description is the user's prose, shown as typed: its paragraphs
    // kept, any markup in it shown as characters.
    for paragraph in study.description.split("\n\n").map(text) {
        if !paragraph.is_empty() {
            let _ = writeln!(md, "{paragraph}\n");
        }
    }
    let m = inp.meta;
    let _ = writeln!(
        md,
        "Made by {} (bonkers {}) on {} thread{}, from {} to {}; wall time {} s.\n",
        code(&m.command.replace('`', "'")),
        m.version,
        m.threads,
        if m.threads == 1 { "" } else { "s" },
        m.started,
        m.finished,
        num(m.total_wall_seconds)
    );
}

fn what_was_run(md: &mut String, inp: &Inputs) {
    let d = inp.descriptor;
    md.push_str("## What was run\n\n");
    if let Some(sweep) = &d.sweep {
        let mode = format!("{:?}", sweep.mode).to_lowercase();
        let _ = writeln!(md, "Sweep ({mode}):\n\n| parameter | values |\n|---|---|");
        for (key, values) in &sweep.parameters {
            let text = match values {
                SweepValues::List(v) => shortened(v.len(), |i| value_text(&v[i])),
                SweepValues::Range(r) => format!(
                    "{} to {} in {} {:?} steps",
                    num(r.from),
                    num(r.to),
                    r.steps,
                    r.scale
                )
                .to_lowercase(),
            };
            let _ = writeln!(md, "| {} | {} |", code(key), cell(&text));
        }
        md.push('\n');
    } else {
        md.push_str("No sweep: one point.\n\n");
    }
    let run = &d.run;
    // A `[run]` key the sweep sets is in the table above, not here.
    let fixed = |key: &str| {
        d.sweep
            .as_ref()
            .is_none_or(|s| !s.parameters.contains_key(&format!("run.{key}")))
    };
    let mut length = Vec::new();
    if let Some(t) = run.duration.filter(|_| fixed("duration")) {
        length.push(format!("duration {}", num(t)));
    }
    if let Some(c) = run.collisions.filter(|_| fixed("collisions")) {
        length.push(format!("{} collisions", count(c)));
    }
    if run.equilibrate > 0.0 && fixed("equilibrate") {
        length.push(format!("after equilibrating for {}", num(run.equilibrate)));
    }
    if let Some(s) = run.sample_every.filter(|_| fixed("sample_every")) {
        length.push(format!("sampled every {}", num(s)));
    }
    let swept_run = d
        .sweep
        .as_ref()
        .is_some_and(|s| s.parameters.keys().any(|k| k.starts_with("run.")));
    if swept_run {
        length.push("`[run]` keys of the sweep as in its table".into());
    }
    let planned = inp.meta.planned_runs.max(inp.runs.len());
    let case_runs =
        |c: &crate::model::descriptor::CaseSection| c.replicas.unwrap_or(d.study.replicas) as usize;
    let cases: usize = d.case.iter().map(case_runs).sum();
    let sweep = planned.saturating_sub(cases);
    let seeds = inp.runs.iter().map(|(s, _)| s.seed);
    let (lo, hi) = seeds.fold((u64::MAX, 0), |(lo, hi), s| (lo.min(s), hi.max(s)));
    let _ = writeln!(
        md,
        "{} points × {} replicas = {} runs (each: {}). Study seed {}; every run has its \
         own seed{}, derived from (study seed, the point's swept values, replica): the `seed` \
         column of `runs.parquet`.\n",
        sweep / d.study.replicas.max(1) as usize,
        d.study.replicas,
        sweep,
        if length.is_empty() {
            "as the scene says".into()
        } else {
            length.join(", ")
        },
        d.study.seed,
        if inp.runs.is_empty() {
            String::new()
        } else {
            format!(" ({lo} to {hi})")
        },
    );
    if !d.case.is_empty() {
        let list: Vec<String> = d
            .case
            .iter()
            .map(|c| format!("{} ({} runs)", code(&c.name), case_runs(c)))
            .collect();
        let _ = writeln!(
            md,
            "Beside the sweep, {} case(s) the study presents in its own section: {}; each \
             is the descriptor without its sweep, with the case's keys set \
             (`[[case]]` in the descriptor), seeded from its name.\n",
            d.case.len(),
            list.join(", ")
        );
    }
}

/// The conservation check every run without thermal walls makes.
fn energy_drift(md: &mut String, runs: &[(RunSpec, RunOutput)]) {
    let drifts: Vec<f64> = runs
        .iter()
        .filter_map(|(_, o)| o.scalar("energy_drift"))
        .collect();
    if let Some(worst) = drifts.iter().copied().reduce(f64::max) {
        let _ = writeln!(
            md,
            "Energy is conserved: over the measured time the kinetic energy of no run changed by \
             more than {} of itself (round-off; `energy_drift` in `runs.parquet`, {} runs).\n",
            num(worst),
            drifts.len()
        );
    }
}

fn plots(md: &mut String, figures: &[Figure], omitted: &[String]) {
    if figures.is_empty() {
        return;
    }
    md.push_str("## Plots\n\n");
    for line in omitted {
        let _ = writeln!(md, "- {line}");
    }
    if !omitted.is_empty() {
        md.push('\n');
    }
    for f in figures {
        let _ = writeln!(md, "![{}]({})\n", caption(&f.caption), f.file);
    }
}

/// Every result that has a theory to compare with, point by point (all
/// results, with or without theory, are in summary.parquet).
fn theory_table(md: &mut String, inp: &Inputs) {
    md.push_str("## Measurements and theory\n\n");
    let compared: Vec<&SummaryRow> = inp.summary.iter().filter(|r| r.theory.is_some()).collect();
    if compared.is_empty() {
        let _ = writeln!(
            md,
            "No result here has a theory to compare with. Every result of every point, with its \
             n, mean, standard error and 95% interval, is in `summary.parquet`.\n"
        );
        return;
    }
    let runs_per_point = runs_per_point(inp.runs);
    let contrast = |r: &SummaryRow| contrast(inp, r);
    let flagged = (compared.iter())
        .filter(|r| !contrast(r) && r.z.is_some_and(|z| z.abs() > Z_FLAG))
        .count();
    let _ = writeln!(
        md,
        "The results with a theory to compare with; every result of every point is in \
         `summary.parquet`. Mean ± standard error over replicas; the 95% interval uses \
         Student's t. z = (mean − theory) / stderr; rows with |z| > {Z_FLAG} are marked ⚠ \
         ({flagged} of {}), except a *contrast*: a theory set beside the measurement to show \
         where it stops holding. n counts runs that measured the result (NaN results are left \
         out).\n",
        compared.len()
    );
    md.push_str("| point | parameters | result | n | mean ± stderr | 95% CI | theory | z |\n");
    md.push_str("|---:|---|---|---:|---:|---:|---:|---:|\n");
    for r in compared {
        let total = runs_per_point.get(&r.point_id).copied().unwrap_or(0);
        let n = if r.n as usize == total {
            r.n.to_string()
        } else {
            format!("{} of {total}", r.n)
        };
        let ci = if r.ci_low.is_finite() {
            format!("[{}, {}]", num(r.ci_low), num(r.ci_high))
        } else {
            "—".into()
        };
        let z = match (r.z, r.theory) {
            (Some(z), _) if contrast(r) => format!("{z:.2} (contrast)"),
            (Some(z), _) if z.abs() > Z_FLAG => format!("**{z:.2}** ⚠"),
            (Some(z), _) => format!("{z:.2}"),
            (None, Some(_)) if r.n >= 2 && r.stderr == 0.0 => "— (no spread)".into(),
            _ => "—".into(),
        };
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} |",
            r.point_id,
            cell(&params_text(inp.points, r.point_id)),
            code(&r.result),
            n,
            pm(r.mean, r.stderr),
            ci,
            r.theory.map_or("—".into(), num),
            z
        );
    }
    md.push('\n');
}

/// The cost behind each point: CPU seconds of the threads that ran its runs
/// (wall seconds of the runs where the platform does not report CPU time),
/// collisions, and the rate.
fn cost(md: &mut String, inp: &Inputs) {
    md.push_str("## Cost\n\n");
    let cpu_known = inp.runs.iter().all(|(_, o)| o.cpu_seconds.is_finite());
    let seconds = |o: &RunOutput| {
        finite_or_zero(if cpu_known {
            o.cpu_seconds
        } else {
            o.wall_seconds
        })
    };
    let mut per: BTreeMap<u64, (usize, f64, u64)> = BTreeMap::new();
    for (s, o) in inp.runs {
        let e = per.entry(s.point_id).or_default();
        e.0 += 1;
        e.1 += seconds(o);
        e.2 += o.collisions;
    }
    let unit = if cpu_known { "CPU s" } else { "run wall s" };
    let _ = writeln!(
        md,
        "| point | parameters | runs | {unit} | collisions | collisions / {unit} |"
    );
    md.push_str("|---:|---|---:|---:|---:|---:|\n");
    let (mut runs, mut secs, mut colls) = (0, 0.0, 0);
    for (id, (n, s, c)) in &per {
        let _ = writeln!(
            md,
            "| {id} | {} | {n} | {} | {} | {} |",
            cell(&params_text(inp.points, *id)),
            num(*s),
            count(*c),
            rate(*c, *s)
        );
        (runs, secs, colls) = (runs + n, secs + s, colls + c);
    }
    let _ = writeln!(
        md,
        "| **total** | | **{runs}** | **{}** | **{}** | **{}** |\n",
        num(secs),
        count(colls),
        rate(colls, secs)
    );
    if !cpu_known {
        md.push_str(
            "CPU time is not measured on this platform: the seconds are each run's wall time.\n\n",
        );
    }
    let m = inp.meta;
    let what = if cpu_known { "CPU" } else { "run" };
    if m.resumed_runs > 0 {
        let _ = writeln!(
            md,
            "{} of the {runs} runs were done by an earlier invocation and resumed; their cost is \
             counted above. This invocation took {} s of wall time, {} s of it running runs \
             on {} threads.\n",
            m.resumed_runs,
            num(m.total_wall_seconds),
            num(m.runs_wall_seconds),
            m.threads
        );
    } else if m.runs_wall_seconds > 0.0 && secs > 0.0 {
        let _ = writeln!(
            md,
            "The runs took {} {what} seconds in {} s of wall time on {} threads (parallel \
             speed-up {}); the whole study, with tables, plots and analyses, took {} s.\n",
            num(secs),
            num(m.runs_wall_seconds),
            m.threads,
            num(secs / m.runs_wall_seconds),
            num(m.total_wall_seconds)
        );
    }
}

fn failures(md: &mut String, meta: &ReportMeta) {
    if meta.failed_runs.is_empty() {
        return;
    }
    let _ = writeln!(
        md,
        "## Failed runs\n\n{} runs failed; they are absent from the statistics above.\n",
        meta.failed_runs.len()
    );
    for (id, msg) in &meta.failed_runs {
        let _ = writeln!(md, "- run {id}: {}", text(msg));
    }
    md.push('\n');
}

/// The tables beside the report; series and histograms only when some run
/// produced them (the store writes them only then).
fn footer(md: &mut String, runs: &[(RunSpec, RunOutput)]) {
    md.push_str(
        "## How to read the tables\n\n\
         The tables are tidy Parquet files beside this report (polars, pandas, DuckDB, R):\n\n\
         - `runs.parquet`: one row per simulation: `run_id`, `point_id`, `replica`, `seed`, \
         the swept parameters as columns, one column per scalar result (prefixed `result.` \
         if its name is taken), the cost (`events`, `collisions`, `wall_seconds`, \
         `cpu_seconds`, and `prepare_seconds` of those spent compressing the start) and `status`.\n",
    );
    if runs.iter().any(|(_, o)| !o.series.is_empty()) {
        md.push_str("- `series.parquet`: long form `run_id`, `t`, `observable`, `value`.\n");
    }
    if runs.iter().any(|(_, o)| !o.histograms.is_empty()) {
        md.push_str(
            "- `histograms.parquet`: long form `run_id`, `observable`, `lo`, `hi`, `count` \
             (bins are [lo, hi)).\n",
        );
    }
    md.push_str(
        "- `summary.parquet`: per point and result: `point_id`, the parameters, `result`, `n`, \
         `mean`, `std`, `stderr`, `ci_low`, `ci_high`, `theory`, `z`, `cpu_seconds`, \
         `wall_seconds`, `collisions`.\n\n\
         Column names contain dots (`scene.piston.mass`): quote them in SQL, e.g. in DuckDB \
         `SELECT \"scene.piston.mass\", mean FROM 'summary.parquet'`.\n\n\
         Units are reduced: lengths in σ, masses in m, energies in kT, time in σ√(m/kT).\n",
    );
}

/// Whether a row's theory is a contrast at its point (`Study::contrast`).
pub(super) fn contrast(inp: &Inputs, row: &SummaryRow) -> bool {
    let run = inp.runs.iter().find(|(s, _)| s.point_id == row.point_id);
    run.is_some_and(|(s, _)| crate::studies::contrast(&s.descriptor, &row.result))
}

fn runs_per_point(runs: &[(RunSpec, RunOutput)]) -> BTreeMap<u64, usize> {
    let mut m = BTreeMap::new();
    for (s, _) in runs {
        *m.entry(s.point_id).or_insert(0) += 1;
    }
    m
}

pub(super) fn params_text(points: &Points, id: u64) -> String {
    points.get(&id).map_or(String::new(), |p| point_label(p))
}

fn rate(collisions: u64, seconds: f64) -> String {
    let r = collisions as f64 / seconds;
    if !(seconds > 0.0 && r.is_finite()) {
        "—".into()
    } else if r >= 1000.0 {
        count(r.round() as u64)
    } else {
        num(r)
    }
}

fn finite_or_zero(x: f64) -> f64 {
    if x.is_finite() { x } else { 0.0 }
}

/// Text safe inside a table cell: `text`, whose pipes are escaped.
pub fn cell(s: &str) -> String {
    text(s)
}

/// A name in a code span, or as `text` where a backtick or pipe would end it.
pub fn code(s: &str) -> String {
    let line = one_line(s);
    if line.is_empty() || line.contains(['`', '|']) || line.chars().any(char::is_control) {
        text(s)
    } else {
        format!("`{line}`")
    }
}

/// An image's caption: `text`, with parentheses escaped too, so that no
/// `](` inside it ends the caption early.
fn caption(s: &str) -> String {
    crate::model::text::escaped(s, "()")
}
