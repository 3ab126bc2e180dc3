//! How the piston gives its excess energy to the gases, across the sweep:
//! the relaxation time against the piston's mass, its power law, and in 2D
//! the time the gases' lag in sharing a compression predicts.

use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::line_fit::fit_line;
use crate::stats::summary::Stats;
use crate::studies::piston::points::{Point, groups, marked};
use std::fmt::Write;

const ONE_AXIS: &str = include_str!("text/relaxation_1d.md");
const ACROSS_X: &str = include_str!("text/relaxation_2d.md");

/// omega tau_x below which the exchange theory's relaxation time is compared.
const SLOW_SWING: f64 = 0.5;

/// The relaxation section of one dimension's points (figure named by the dimension).
pub fn relaxation(points: &[&Point], dimension: usize, figures: &mut Vec<Figure>) -> String {
    let mut layers = Vec::new();
    let mut fits = String::new();
    for (i, (group, ps)) in groups(points).into_iter().enumerate() {
        fits.push_str(&one_group(i, &group, &ps, dimension > 1, &mut layers));
    }
    let name = format!("piston_relaxation_time_{dimension}d.svg");
    figures.push(Figure {
        file: name.clone(),
        chart: ChartSpec {
            title: format!(
                "{dimension}D: time for the piston to give away 63% of its excess energy"
            ),
            x_label: "piston mass M [m]".into(),
            y_label: "relaxation time τ".into(),
            x_log: true,
            y_log: true,
            layers,
        },
    });
    let text = if dimension == 1 { ONE_AXIS } else { ACROSS_X };
    let values = [("dimension", dimension.to_string()), ("figure", name)];
    let mut md = fill(text, &values);
    if fits.is_empty() {
        md.push_str("Too few relaxed points (three needed per group) to fit a power law.\n\n");
    } else {
        let (extra, rule, compared) = if dimension > 1 {
            (
                " τ / τ_exchange |",
                "---|",
                ", and the measured time over the exchange theory's at those of them where the disks share \
                 the compression quickly, ωτ_x < 0.5 (lowest–highest, number of points)",
            )
        } else {
            ("", "", "")
        };
        let _ = write!(
            md,
            "Power law τ ∝ M^b fitted (weighted least squares in log–log, error scaled by sqrt(χ²/dof) where \
             the points scatter more than their error bars) over the points where every run relaxed{compared}:\n\n\
             | group | M from–to | points | exponent b | χ²/dof |{extra} CPU s | collisions |\n\
             |---|---|---|---|---|{rule}---|---|\n{fits}\n",
        );
    }
    md.push_str(&unrelaxed(points));
    md
}

/// One group's layers (pushed onto `layers`, in colour `i`) and its row of
/// the fit table (empty without a fit).
fn one_group(
    i: usize,
    group: &str,
    ps: &[&Point],
    across: bool,
    layers: &mut Vec<Layer>,
) -> String {
    let relaxed: Vec<&Point> = ps.iter().copied().filter(|p| p.relaxed()).collect();
    let tau = |p: &Point| p.stat("relaxation_time");
    let logs: Vec<(f64, f64, f64)> = relaxed
        .iter()
        .map(|p| (p.mass.ln(), tau(p).mean.ln(), tau(p).stderr / tau(p).mean))
        .filter(|(_, y, e)| y.is_finite() && *e > 0.0)
        .collect();
    let at: Vec<(f64, Stats)> = relaxed.iter().map(|p| (p.mass, tau(p))).collect();
    layers.extend(marked(&at, Some(10.0), colour(i), group.to_string()));
    // Unrelaxed points: lower bounds, drawn faded.
    layers.push(Layer::Markers {
        points: ps
            .iter()
            .filter(|p| !p.relaxed() && p.tau_bound().is_finite())
            .map(|p| (p.mass, p.tau_bound()))
            .collect(),
        paint: colour(i).faded(0.35),
        label: None,
    });
    if across {
        // The exchange theory's prediction, point by point.
        layers.push(Layer::Line {
            points: ps
                .iter()
                .map(|p| (p.mass, p.stat("relaxation_time_exchange").mean))
                .collect(),
            paint: colour(i).faded(0.6),
            width: 1,
            dashed: false,
            label: (i == 0).then(|| "x–y exchange theory (thin lines)".to_string()),
        });
    }
    let Some((b, se, a, chi2)) = fit_line(&logs) else {
        return String::new();
    };
    let (lo, hi) = (relaxed[0].mass, relaxed[relaxed.len() - 1].mass);
    layers.push(Layer::Line {
        points: vec![(lo, (a + b * lo.ln()).exp()), (hi, (a + b * hi.ln()).exp())],
        paint: colour(i),
        width: 1,
        dashed: true,
        label: None,
    });
    let mut row = format!(
        "| {group} | {}–{} | {} | {} | {} |",
        num(lo),
        num(hi),
        logs.len(),
        pm(b, se),
        num(chi2),
    );
    if across {
        // Where the exchange is fast next to the swing, as the theory
        // assumes (it is a small-omega-tau expansion).
        let ratios: Vec<f64> = relaxed
            .iter()
            .filter(|p| p.stat("omega_tau").mean < SLOW_SWING)
            .map(|p| tau(p).mean / p.stat("relaxation_time_exchange").mean)
            .filter(|r| r.is_finite())
            .collect();
        let lo = ratios.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = ratios.iter().copied().fold(0.0, f64::max);
        let _ = match ratios.len() {
            0 => write!(row, " — |"),
            n => write!(row, " {}–{} ({n}) |", num(lo), num(hi)),
        };
    }
    let seconds: f64 = relaxed.iter().map(|p| p.seconds).sum();
    let collisions = relaxed.iter().map(|p| p.collisions).sum();
    let _ = writeln!(row, " {seconds:.1} | {} |", count(collisions));
    row
}

/// How many points did not relax, and the bound at the heaviest of them.
fn unrelaxed(points: &[&Point]) -> String {
    let unrelaxed: Vec<&&Point> = points.iter().filter(|p| !p.relaxed()).collect();
    let Some(p) = unrelaxed.iter().max_by(|a, b| a.mass.total_cmp(&b.mass)) else {
        return String::new();
    };
    let left = p.stat("excess_left");
    format!(
        "{} of {} points did not relax within their runs; at {} the piston still holds {} of its \
         starting excess after {} time units, so τ > {}.\n\n",
        unrelaxed.len(),
        points.len(),
        p.label(),
        pm(left.mean, left.stderr),
        num(p.duration),
        num(p.tau_bound())
    )
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
