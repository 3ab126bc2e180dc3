//! How the piston gives its excess energy to the gases, across the sweep:
//! the relaxation time against the piston's mass, its power law, and in 2D
//! the time the gases' lag in sharing a compression predicts.

use crate::model::chart::colour;
use crate::model::chart::{ChartSpec, Layer};
use crate::model::report::Figure;
use crate::stats::format::{count, num, pm};
use crate::stats::line::{Sums, chi_square};
use crate::studies::piston::points::{Point, groups};
use std::fmt::Write;

/// Weighted least-squares line through (x, y ± e): slope, its standard
/// error (scaled up by sqrt(chi^2/dof) when the scatter exceeds the error
/// bars), and chi^2/dof.
fn fit_line(points: &[(f64, f64, f64)]) -> Option<(f64, f64, f64, f64)> {
    if points.len() < 3 {
        return None;
    }
    let sums = Sums::of_errors(points.iter().copied());
    let det = sums.det();
    if det.is_nan() || det <= 0.0 {
        return None;
    }
    let (slope, intercept) = (sums.slope(), sums.intercept());
    let chi2 = chi_square(points, slope, intercept) / (points.len() - 2) as f64;
    let se = sums.slope_error() * chi2.max(1.0).sqrt();
    Some((slope, se, intercept, chi2))
}

/// omega tau_x below which the exchange theory's relaxation time is compared.
const SLOW_SWING: f64 = 0.5;

/// The relaxation section of one dimension's points (figure named by the dimension).
pub fn relaxation(
    points: &[&Point],
    dimension: usize,
    figures: &mut Vec<Figure>,
) -> anyhow::Result<String> {
    let mut md = String::new();
    let mut layers = Vec::new();
    let mut fits = String::new();
    for (i, (group, ps)) in groups(points).into_iter().enumerate() {
        let relaxed: Vec<&Point> = ps.iter().copied().filter(|p| p.relaxed()).collect();
        let logs: Vec<(f64, f64, f64)> = relaxed
            .iter()
            .map(|p| {
                let s = p.stat("relaxation_time");
                (p.mass.ln(), s.mean.ln(), s.stderr / s.mean)
            })
            .filter(|(_, y, e)| y.is_finite() && *e > 0.0)
            .collect();
        layers.push(Layer::ErrorBars {
            bars: relaxed
                .iter()
                .map(|p| {
                    let s = p.stat("relaxation_time");
                    (
                        p.mass,
                        (s.mean - s.stderr).max(s.mean / 10.0),
                        s.mean,
                        s.mean + s.stderr,
                    )
                })
                .collect(),
            paint: colour(i),
        });
        layers.push(Layer::Markers {
            points: relaxed
                .iter()
                .map(|p| (p.mass, p.stat("relaxation_time").mean))
                .collect(),
            paint: colour(i),
            label: Some(group.clone()),
        });
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
        if dimension > 1 {
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
        if let Some((b, se, a, chi2)) = fit_line(&logs) {
            let masses: Vec<f64> = relaxed.iter().map(|p| p.mass).collect();
            let (lo, hi) = (masses[0], masses[masses.len() - 1]);
            layers.push(Layer::Line {
                points: vec![(lo, (a + b * lo.ln()).exp()), (hi, (a + b * hi.ln()).exp())],
                paint: colour(i),
                width: 1,
                dashed: true,
                label: None,
            });
            let _ = write!(
                fits,
                "| {group} | {}–{} | {} | {} | {} |",
                num(lo),
                num(hi),
                logs.len(),
                pm(b, se),
                num(chi2),
            );
            if dimension > 1 {
                // Where the exchange is fast next to the swing, as the
                // theory assumes (it is a small-omega-tau expansion).
                let ratios: Vec<f64> = relaxed
                    .iter()
                    .filter(|p| p.stat("omega_tau").mean < SLOW_SWING)
                    .map(|p| {
                        p.stat("relaxation_time").mean / p.stat("relaxation_time_exchange").mean
                    })
                    .filter(|r| r.is_finite())
                    .collect();
                let (lo, hi) = ratios
                    .iter()
                    .fold((f64::INFINITY, 0.0f64), |(a, b), &r| (a.min(r), b.max(r)));
                let _ = match ratios.len() {
                    0 => write!(fits, " — |"),
                    n => write!(fits, " {}–{} ({n}) |", num(lo), num(hi)),
                };
            }
            let _ = writeln!(
                fits,
                " {:.1} | {} |",
                relaxed.iter().map(|p| p.seconds).sum::<f64>(),
                count(relaxed.iter().map(|p| p.collisions).sum()),
            );
        }
    }
    let name = format!("piston_relaxation_time_{dimension}d.svg");
    let chart = ChartSpec {
        title: format!("{dimension}D: time for the piston to give away 63% of its excess energy"),
        x_label: "piston mass M [m]".into(),
        y_label: "relaxation time τ".into(),
        x_log: true,
        y_log: true,
        layers,
    };
    figures.push(Figure {
        file: name.to_string(),
        chart,
    });
    md.push_str(if dimension == 1 { ONE_AXIS } else { ACROSS_X });
    md.push_str(
        "Solid markers: every run reached 1/e of its excess (mean ± standard error); faded markers: lower \
         bounds from what was left of the excess when the runs ended; dashed lines: power-law fits",
    );
    md.push_str(if dimension > 1 {
        "; thin lines: the exchange theory's τ.\n\n"
    } else {
        ".\n\n"
    });
    let _ = writeln!(
        md,
        "![{dimension}D: relaxation time against piston mass, with power-law fits over the points where every run relaxed, and lower bounds (faded) where the runs ended first.]({name})\n"
    );
    if fits.is_empty() {
        md.push_str("Too few relaxed points (three needed per group) to fit a power law.\n\n");
    } else {
        let (extra, rule) = if dimension > 1 {
            (" τ / τ_exchange |", "---|")
        } else {
            ("", "")
        };
        let _ = write!(
            md,
            "Power law τ ∝ M^b fitted (weighted least squares in log–log, error scaled by sqrt(χ²/dof) where \
             the points scatter more than their error bars) over the points where every run relaxed{}:\n\n\
             | group | M from–to | points | exponent b | χ²/dof |{extra} CPU s | collisions |\n\
             |---|---|---|---|---|{rule}---|---|\n{fits}\n",
            if dimension > 1 {
                ", and the measured time over the exchange theory's at those of them where the disks share \
                 the compression quickly, ωτ_x < 0.5 (lowest–highest, number of points)"
            } else {
                ""
            }
        );
    }
    let unrelaxed: Vec<&&Point> = points.iter().filter(|p| !p.relaxed()).collect();
    if !unrelaxed.is_empty() {
        let worst = unrelaxed
            .iter()
            .max_by(|a, b| a.mass.total_cmp(&b.mass))
            .map(|p| {
                let left = p.stat("excess_left");
                format!(
                    "at {} the piston still holds {} of its starting excess after {} time units, so τ > {}",
                    p.label(),
                    pm(left.mean, left.stderr),
                    num(p.duration),
                    num(p.tau_bound())
                )
            })
            .unwrap_or_default();
        let _ = writeln!(
            md,
            "{} of {} points did not relax within their runs; {worst}.\n",
            unrelaxed.len(),
            points.len()
        );
    }
    Ok(md)
}

const ONE_AXIS: &str = "A heavy piston moves slowly, so each gas follows its adiabat: every particle bouncing between a wall \
and the piston keeps its action v·X, and the energy the piston puts into a gas while compressing it comes back \
while the gas expands. Only the departures from that reversible picture dissipate: particles that meet the \
piston at different phases of its swing, and collisions inside each gas that share the energy out. A heavier \
piston is slower next to the gas particles (its speed falls as 1/sqrt(M)) and departs less from the adiabat, so \
its relaxation time grows steeply with M: a very heavy piston loses its energy only through these ever smaller \
non-adiabatic effects, and in practice keeps it for as long as we can watch. ";

const ACROSS_X: &str = "In 2D the piston squeezes each gas along x only: the x-motion heats first, and collisions between \
disks share the heat with y in about a mean free time τ_x. While compressing, the gas is hotter along x than \
its adiabat says and pushes back harder; while expanding, the reverse: the loop does not close, and the piston \
loses energy every swing. A compression along x alone is partly a shear, and dilute hard disks (whose bulk \
viscosity is zero) resist it by their shear viscosity η (σ_xx = η ε̇ in 2D); 1D has nothing like it (a line has \
no other axis). Treating each gas as a relaxing spring (Debye: stiffness k (1 + ½ iωτ_x/(1 + iωτ_x)) in 2D), the \
oscillator's energy decays in 1/(ω Im k/Re k) ≈ 2/(ω²τ_x) for ωτ_x ≪ 1: a heavier piston is slower, \
dissipates less per swing, but only in proportion, so τ grows about linearly with M, not as M² as in 1D. The \
thin lines are this prediction with τ_x = η/p from the Chapman–Enskog viscosity of hard disks (no fitted \
parameter; its start state, small-amplitude). It is meant for heavy pistons, ωτ_x ≪ 1; light ones \
(ωτ_x ≳ 1) lose their energy within a few swings by the routes they have in 1D as well (a compression \
neither slow nor uniform), far faster than it says. ";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_fit_recovers_a_power_law() {
        let pts: Vec<(f64, f64, f64)> = [10.0f64, 100.0, 1000.0]
            .iter()
            .map(|m| (m.ln(), (3.0 * m.powf(1.5)).ln(), 0.1))
            .collect();
        let (b, se, a, chi2) = fit_line(&pts).expect("fits");
        assert!((b - 1.5).abs() < 1e-12 && (a - 3f64.ln()).abs() < 1e-12);
        assert!(chi2 < 1e-20);
        // Error of the slope from the error bars alone: 0.1 / sqrt(sum (x - xbar)^2).
        let spread = 2.0 * (10f64.ln()).powi(2);
        assert!((se - 0.1 / spread.sqrt()).abs() < 1e-12);
    }
}
