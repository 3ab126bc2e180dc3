//! The report's first screen: each result that has a theory, how many
//! points agree with it and the one furthest from it, and what the study
//! cost. The point-by-point table is under "Measurements and theory".

use super::markdown::{Inputs, Z_FLAG, cell, code, contrast, params_text};
use crate::model::summary::SummaryRow;
use crate::stats::format::{count, num, pm};
use std::fmt::Write;

pub fn findings(inp: &Inputs) -> String {
    let mut md = String::from("## Findings\n\n");
    let tested = |r: &&SummaryRow| r.theory.is_some();
    let (contrasts, laws): (Vec<&SummaryRow>, Vec<&SummaryRow>) = (inp.summary.iter())
        .filter(tested)
        .partition(|r| contrast(inp, r));
    let results = distinct(&laws);
    if results.is_empty() {
        md += "No result here has a theory to compare with.\n\n";
    } else {
        let _ = writeln!(
            md,
            "| result | theory | points with \\|z\\| ≤ {Z_FLAG} | furthest from theory |\n|---|---:|---:|---|"
        );
        for result in results {
            let rows: Vec<&&SummaryRow> = laws.iter().filter(|r| r.result == result).collect();
            md += &row(result, &rows, inp);
        }
        md.push('\n');
    }
    let shown: Vec<String> = distinct(&contrasts).into_iter().map(code).collect();
    if !shown.is_empty() {
        let _ = writeln!(
            md,
            "Set beside a contrast, a theory that shows where the physics leaves it rather than a \
             law the runs must obey: {}.\n",
            shown.join(", ")
        );
    }
    let cpu: f64 = inp.runs.iter().map(|(_, o)| o.cpu_seconds).sum();
    let collisions: u64 = inp.runs.iter().map(|(_, o)| o.collisions).sum();
    let _ = writeln!(
        md,
        "{} runs, {} CPU s, {} collisions. Every point is under \
         [Measurements and theory](#measurements-and-theory), its cost under [Cost](#cost).\n",
        inp.runs.len(),
        num(cpu),
        count(collisions)
    );
    md
}

/// The results of `rows`, each once, in order.
fn distinct<'a>(rows: &[&'a SummaryRow]) -> Vec<&'a str> {
    let mut results: Vec<&str> = Vec::new();
    for r in rows {
        if !results.contains(&r.result.as_str()) {
            results.push(&r.result);
        }
    }
    results
}

/// One result's line: its theory (one value, or the range over points),
/// how many points agree, and the worst.
fn row(result: &str, rows: &[&&SummaryRow], inp: &Inputs) -> String {
    let theories = rows.iter().filter_map(|r| r.theory);
    let (lo, hi) = theories.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), t| {
        (lo.min(t), hi.max(t))
    });
    let theory = if lo == hi {
        num(lo)
    } else {
        format!("{} – {}", num(lo), num(hi))
    };
    let judged: Vec<(&&SummaryRow, f64)> = rows.iter().filter_map(|r| Some((*r, r.z?))).collect();
    let within = judged.iter().filter(|(_, z)| z.abs() <= Z_FLAG).count();
    let mut agree = format!("{within} of {}", judged.len());
    if judged.len() < rows.len() {
        let _ = write!(
            agree,
            " ({} without an error bar)",
            rows.len() - judged.len()
        );
    }
    let worst = judged.iter().max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()));
    let furthest = worst.map_or("—".into(), |(r, z)| {
        // A point by its parameters where they fit the cell.
        let label = params_text(inp.points, r.point_id);
        let point = match label.chars().count() {
            ..=60 => cell(&label),
            _ => format!("point {}", r.point_id),
        };
        format!("{} (z = {z:.1}) at {point}", pm(r.mean, r.stderr))
    });
    format!("| {} | {theory} | {agree} | {furthest} |\n", code(result))
}
