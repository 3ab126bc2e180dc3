//! How the piston gives its excess energy to the gases, across the sweep:
//! the relaxation time against the piston's mass, its power law, and in 2D
//! the time the gases' lag in sharing a compression predicts.

use super::SWEEP;
use crate::model::chart::{Layer, colour};
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::line_fit::fit_line;
use crate::stats::named::named;
use crate::stats::table::table_row;
use crate::studies::curves::{bar, figure, markers, measured, polyline};
use crate::studies::piston::points::{Point, groups};
use std::fmt::Write;

const ONE_AXIS: &str = include_str!("text/relaxation_1d.md");
const ACROSS_X: &str = include_str!("text/relaxation_2d.md");

/// omega tau_x below which the exchange theory's relaxation time is compared.
const SLOW_SWING: f64 = 0.5;

/// The relaxation section of one dimension's points (figure named by the dimension).
pub fn relaxation(points: &[&Point], dimension: usize, figures: &mut Vec<Figure>) -> String {
    let across = dimension > 1;
    let mut layers = Vec::new();
    let fits: String = (groups(points).into_iter().enumerate())
        .map(|(i, ps)| one_group(i, &ps, across, &mut layers))
        .collect();
    let name = format!("piston_relaxation_time_{dimension}d.svg");
    let title = format!("{dimension}D: time for the piston to give away 63% of its excess energy");
    let labels = (title, "piston mass M [m]", "relaxation time τ");
    figures.push(figure(&name, labels, (true, true), layers));
    let text = if dimension == 1 { ONE_AXIS } else { ACROSS_X };
    let values = [("dimension", dimension.to_string()), ("figure", name)];
    let mut md = fill(text, &values);
    if fits.is_empty() {
        md = md + named(SWEEP, "no_fit") + "\n\n";
    } else {
        let compared = if across { named(SWEEP, "compared") } else { "" };
        let intro = fill(named(SWEEP, "fit"), &[("compared", compared.into())]);
        let head = named(SWEEP, if across { "columns_across" } else { "columns" });
        let rule = "---|".repeat(if across { 8 } else { 7 });
        let _ = write!(md, "{intro}\n\n{head}\n|{rule}\n{fits}\n");
    }
    md + &unrelaxed(points)
}

/// One group's layers (pushed onto `layers`, in colour `i`) and its row of
/// the fit table (empty without a fit).
fn one_group(i: usize, ps: &[&Point], across: bool, layers: &mut Vec<Layer>) -> String {
    let relaxed: Vec<&Point> = ps.iter().copied().filter(|p| p.relaxed()).collect();
    let tau = |p: &Point| p.stat("relaxation_time");
    let logs: Vec<(f64, f64, f64)> = relaxed
        .iter()
        .map(|p| (p.mass.ln(), tau(p).mean.ln(), tau(p).stderr / tau(p).mean))
        .filter(|(_, y, e)| y.is_finite() && *e > 0.0)
        .collect();
    // On the log axis, an error bar's lower end at least a tenth of its mean.
    let bars = (relaxed.iter().map(|p| bar(p.mass, &tau(p))))
        .map(|(x, low, mean, high)| (x, low.max(mean / 10.0), mean, high));
    layers.extend(measured(bars, colour(i), &ps[0].group));
    // Unrelaxed points: lower bounds, drawn faded.
    let unrelaxed = ps
        .iter()
        .filter(|p| !p.relaxed() && p.tau_bound().is_finite());
    let bounds = unrelaxed.map(|p| (p.mass, p.tau_bound())).collect();
    layers.push(markers(bounds, colour(i).faded(0.35), None));
    let exchange = |p: &Point| p.stat("relaxation_time_exchange").mean;
    if across {
        // The exchange theory's prediction, point by point.
        let line = ps.iter().map(|p| (p.mass, exchange(p))).collect();
        let label = (i == 0).then(|| "x–y exchange theory (thin lines)".to_string());
        layers.push(polyline(line, colour(i).faded(0.6), 1, false, label));
    }
    let Some((b, se, a, chi2)) = fit_line(&logs) else {
        return String::new();
    };
    let (lo, hi) = (relaxed[0].mass, relaxed[relaxed.len() - 1].mass);
    let fitted = |m: f64| (m, (a + b * m.ln()).exp());
    let ends = vec![fitted(lo), fitted(hi)];
    layers.push(polyline(ends, colour(i), 1, true, None));
    let range = format!("{}–{}", num(lo), num(hi));
    let mut cells = vec![
        ps[0].group.clone(),
        range,
        logs.len().to_string(),
        pm(b, se),
        num(chi2),
    ];
    if across {
        // Where the exchange is fast next to the swing, as the theory
        // assumes (it is a small-omega-tau expansion).
        let ratios: Vec<f64> = relaxed
            .iter()
            .filter(|p| p.stat("omega_tau").mean < SLOW_SWING)
            .map(|p| tau(p).mean / exchange(p))
            .filter(|r| r.is_finite())
            .collect();
        let lo = ratios.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = ratios.iter().copied().fold(0.0, f64::max);
        cells.push(match ratios.len() {
            0 => "—".into(),
            n => format!("{}–{} ({n})", num(lo), num(hi)),
        });
    }
    let seconds: f64 = relaxed.iter().map(|p| p.seconds).sum();
    cells.push(format!("{seconds:.1}"));
    cells.push(count(relaxed.iter().map(|p| p.of.collisions()).sum()));
    table_row(&cells)
}

/// How many points did not relax, and the bound at the heaviest of them.
fn unrelaxed(points: &[&Point]) -> String {
    let unrelaxed: Vec<&&Point> = points.iter().filter(|p| !p.relaxed()).collect();
    let Some(p) = unrelaxed.iter().max_by(|a, b| a.mass.total_cmp(&b.mass)) else {
        return String::new();
    };
    let left = p.stat("excess_left");
    let values = [
        ("unrelaxed", unrelaxed.len().to_string()),
        ("points", points.len().to_string()),
        ("label", p.label()),
        ("left", pm(left.mean, left.stderr)),
        ("duration", num(p.duration)),
        ("bound", num(p.tau_bound())),
    ];
    fill(named(SWEEP, "unrelaxed"), &values) + "\n\n"
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::fill::unfilled;

    #[test]
    fn every_placeholder_is_filled() {
        let values = [("dimension", "1".into()), ("figure", "f.svg".into())];
        for text in [ONE_AXIS, ACROSS_X] {
            assert!(unfilled(&fill(text, &values)).is_empty());
        }
    }
}
