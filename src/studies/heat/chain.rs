//! Rods between a hot and a cold wall: a 1D gas of unequal masses conducts
//! anomalously, its conductivity growing with N as momentum is conserved
//! in the bulk (fluctuating hydrodynamics: N^(1/3)). The report's part:
//! conductivity against N, on log axes, with a fitted power.

use super::Gas;
use super::section::{CAPTIONS, Runs, dashed, figure, measured, with_z};
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::goodness::chi_square_tail;
use crate::stats::named::named;
use crate::stats::power_law::{PowerLaw, log_point};
use crate::stats::table::table_row;
use crate::studies::parts::stat_pm;

const TEXT: &str = include_str!("chain.md");

/// Slopes of y on x between neighbouring points: the local exponents.
fn local_slopes(points: &[(f64, f64, f64)]) -> String {
    let slopes: Vec<String> = points
        .windows(2)
        .map(|w| num((w[1].1 - w[0].1) / (w[1].0 - w[0].0)))
        .collect();
    slopes.join(", ")
}

/// Whether `alpha` ± `se` agrees (|z| < 4) with the exponents theory names.
fn against_theory(over: &str, alpha: f64, se: f64) -> String {
    if !(alpha.is_finite() && se > 0.0) {
        return fill(named(CAPTIONS, "chain_none"), &[("over", over.into())]);
    }
    let each = [
        ("1/3", 1.0 / 3.0),
        ("a normal conductor's 0", 0.0),
        ("the ballistic 1", 1.0),
    ]
    .map(|(name, a)| {
        let z = (alpha - a) / se;
        let word = if z.abs() < 4.0 {
            "agrees with"
        } else {
            "differs from"
        };
        format!("{word} {name} (z = {z:+.1})")
    });
    format!("Over {over}, α = {} {}.", pm(alpha, se), each.join(", "))
}

pub fn part(points: &[(Gas, (f64, f64, bool), Runs)], figures: &mut Vec<Figure>) -> String {
    let order = match points.iter().all(|p| p.0.alternating) {
        true => named(CAPTIONS, "order_alternating"),
        false => named(CAPTIONS, "order_random"),
    };
    let mut rows = String::new();
    let (mut logs, mut bulk_logs) = (Vec::new(), Vec::new());
    for (gas, (hot, cold, _), rs) in points {
        logs.extend(log_point(gas.particles, &rs.stat("conductivity_effective")));
        bulk_logs.extend(log_point(gas.particles, &rs.stat("conductivity")));
        rows.push_str(&table_row(&[
            num(gas.particles),
            num(gas.size[0]),
            format!("{} / {}", num(*hot), num(*cold)),
            rs.outs.len().to_string(),
            stat_pm(rs, "flux_in"),
            with_z(&rs.stat("flux_imbalance"), 0.0),
            stat_pm(rs, "conductivity_effective"),
            stat_pm(rs, "conductivity"),
            num(rs.cpu()),
            count(rs.collisions()),
        ]));
    }
    let upper = &logs[logs.len().saturating_sub(1) / 2..];
    let [fit, bulk, fit_upper] = [&logs[..], &bulk_logs, upper].map(|p| PowerLaw::fit(p, 3));
    let dof = logs.len().saturating_sub(2);
    let p = chi_square_tail(fit.chi2, dof);
    let fits = named(
        CAPTIONS,
        if p < 0.05 {
            "chain_drifts"
        } else {
            "chain_fits"
        },
    );
    let fit_verdict = match p.is_nan() {
        true => String::new(),
        false => fill(fits, &[("p", num(p))]),
    };
    let alpha_verdict = format!(
        "{} {}",
        against_theory("all N", fit.exponent, fit.error),
        against_theory("the larger N", fit_upper.exponent, fit_upper.error)
    );
    let mut figure_text = String::new();
    if !logs.is_empty() {
        figure_text = chart(&logs, &bulk_logs, &fit, figures);
    }
    fill(
        TEXT,
        &[
            ("order", order.into()),
            ("rows", rows),
            ("alpha", pm(fit.exponent, fit.error)),
            ("chi2", num(fit.chi2)),
            ("dof", dof.to_string()),
            ("alpha_bulk", pm(bulk.exponent, bulk.error)),
            ("chi2_bulk", num(bulk.chi2)),
            ("fit_verdict", fit_verdict),
            ("local", local_slopes(&logs)),
            (
                "from",
                num(upper.first().map_or(f64::NAN, |p| p.0.exp().round())),
            ),
            ("alpha_upper", pm(fit_upper.exponent, fit_upper.error)),
            ("alpha_verdict", alpha_verdict),
            ("figure", figure_text),
        ],
    )
}

/// κ against N on log axes, both measures, with the fitted power; the
/// figure's Markdown.
fn chart(
    logs: &[(f64, f64, f64)],
    bulk_logs: &[(f64, f64, f64)],
    fit: &PowerLaw,
    figures: &mut Vec<Figure>,
) -> String {
    let file = "heat_chain_conductivity.svg";
    // Back from the logs: N and κ with its error bar.
    let bars = |v: &[(f64, f64, f64)]| -> Vec<(f64, f64, f64, f64)> {
        v.iter()
            .map(|&(x, y, r)| (x.exp(), y.exp() * (1.0 - r), y.exp(), y.exp() * (1.0 + r)))
            .collect()
    };
    let label = "κ = J L / ΔT (mean ± standard error)";
    let mut layers = measured(bars(logs), colour(0), label).to_vec();
    let label = "κ bulk (mean ± standard error)";
    layers.extend(measured(bars(bulk_logs), colour(2), label));
    if fit.exponent.is_finite() {
        let ends = [logs[0].0, logs[logs.len() - 1].0];
        let line = ends.map(|x| (x.exp(), (fit.intercept + fit.exponent * x).exp()));
        let label = format!("fit: N^{}", num(fit.exponent));
        layers.push(dashed(line.to_vec(), colour(1), label));
    }
    let axes = ("N (particles; density 1)", "κ [k √(kT/m) σ⁰]");
    let title = "Conductivity of the 1D gas of unequal masses against N".into();
    figures.push(figure(file, (title, axes.0, axes.1), (true, true), layers));
    format!("![{}]({file})\n", named(CAPTIONS, "chain_figure"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn local_exponents_and_verdicts() {
        let pts: Vec<(f64, f64, f64)> = [10.0f64, 20.0, 40.0, 80.0]
            .iter()
            .map(|&n| (n.ln(), (2.0 * n.powf(0.3)).ln(), 0.01))
            .collect();
        assert_eq!(local_slopes(&pts), "0.3, 0.3, 0.3");
        assert!(against_theory("all N", 0.3, 0.001).contains("differs from 1/3"));
        assert!(against_theory("all N", f64::NAN, 0.001).contains("no exponent"));
    }
}
