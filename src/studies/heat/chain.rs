//! Rods between a hot and a cold wall: a 1D gas of unequal masses conducts
//! anomalously, its conductivity growing with N as momentum is conserved
//! in the bulk (fluctuating hydrodynamics: N^(1/3)). The report's part:
//! conductivity against N, on log axes, with a fitted power.

use super::Gas;
use super::section::{Runs, dashed, figure, measured, with_z};
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::goodness::chi_square_tail;
use crate::stats::line::{chi_square, line};
use crate::stats::table::table_row;

const TEXT: &str = include_str!("chain.md");

/// Weighted least squares of y on x, weights 1/sigma^2: (slope, its
/// standard error, the fit's χ² on points - 2 degrees of freedom); NaN with
/// fewer than three points.
pub fn power_fit(points: &[(f64, f64, f64)]) -> (f64, f64, f64) {
    if points.len() < 3 {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let x: Vec<f64> = points.iter().map(|p| p.0).collect();
    let y: Vec<f64> = points.iter().map(|p| p.1).collect();
    let w: Vec<f64> = points.iter().map(|p| 1.0 / (p.2 * p.2)).collect();
    let (slope, se, intercept) = line(&x, &y, Some(&w));
    (slope, se, chi_square(points, slope, intercept))
}

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
        return format!("Over {over} no exponent was fitted (fewer than three N).");
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

/// (ln N, ln mean, relative error) of a conductivity, where it has one.
fn log_point(n: f64, s: &crate::stats::summary::Stats) -> Option<(f64, f64, f64)> {
    (s.mean > 0.0 && s.stderr > 0.0).then(|| (n.ln(), s.mean.ln(), s.stderr / s.mean))
}

pub fn part(points: &[(Gas, (f64, f64, bool), Runs)], figures: &mut Vec<Figure>) -> String {
    let order = if points.iter().all(|p| p.0.alternating) {
        "alternating along the line: the diatomic hard-point chain"
    } else {
        "in the random order the placement gives: a disordered mass chain"
    };
    let mut rows = String::new();
    let mut logs = Vec::new();
    let mut bulk_logs = Vec::new();
    for (gas, (hot, cold, _), rs) in points {
        let eff = rs.stat("conductivity_effective");
        let bulk = rs.stat("conductivity");
        logs.extend(log_point(gas.particles, &eff));
        bulk_logs.extend(log_point(gas.particles, &bulk));
        let flux = rs.stat("flux_in");
        rows.push_str(&table_row(&[
            num(gas.particles),
            num(gas.size[0]),
            format!("{} / {}", num(*hot), num(*cold)),
            rs.outs.len().to_string(),
            pm(flux.mean, flux.stderr),
            with_z(&rs.stat("flux_imbalance"), 0.0),
            pm(eff.mean, eff.stderr),
            pm(bulk.mean, bulk.stderr),
            num(rs.cpu()),
            count(rs.collisions()),
        ]));
    }
    let (alpha, se, chi2) = power_fit(&logs);
    let (alpha_bulk, se_bulk, chi2_bulk) = power_fit(&bulk_logs);
    let upper = &logs[logs.len().saturating_sub(1) / 2..];
    let (alpha_upper, se_upper, _) = power_fit(upper);
    let dof = logs.len().saturating_sub(2);
    let p = chi_square_tail(chi2, dof);
    let fits = if p < 0.05 {
        "one power does not fit the whole range, the effective exponent drifts with N"
    } else {
        "one power fits the whole range within the error bars"
    };
    let fit_verdict = match p.is_nan() {
        true => String::new(),
        false => format!(
            "A χ² this large comes by chance with probability {}: {fits}.",
            num(p)
        ),
    };
    let alpha_verdict = format!(
        "{} {}",
        against_theory("all N", alpha, se),
        against_theory("the larger N", alpha_upper, se_upper)
    );
    let mut figure_text = String::new();
    if !logs.is_empty() {
        figure_text = chart(&logs, &bulk_logs, alpha, figures);
    }
    fill(
        TEXT,
        &[
            ("order", order.into()),
            ("rows", rows),
            ("alpha", pm(alpha, se)),
            ("chi2", num(chi2)),
            ("dof", dof.to_string()),
            ("alpha_bulk", pm(alpha_bulk, se_bulk)),
            ("chi2_bulk", num(chi2_bulk)),
            ("fit_verdict", fit_verdict),
            ("local", local_slopes(&logs)),
            (
                "from",
                num(upper.first().map_or(f64::NAN, |p| p.0.exp().round())),
            ),
            ("alpha_upper", pm(alpha_upper, se_upper)),
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
    alpha: f64,
    figures: &mut Vec<Figure>,
) -> String {
    let file = "heat_chain_conductivity.svg";
    let bars = |v: &[(f64, f64, f64)]| -> Vec<(f64, f64, f64, f64)> {
        v.iter()
            .map(|&(x, y, r)| {
                let (n, k) = (x.exp(), y.exp());
                (n, k * (1.0 - r), k, k * (1.0 + r))
            })
            .collect()
    };
    let mut layers = measured(
        bars(logs),
        colour(0),
        "κ = J L / ΔT (mean ± standard error)",
    )
    .to_vec();
    layers.extend(measured(
        bars(bulk_logs),
        colour(2),
        "κ bulk (mean ± standard error)",
    ));
    if alpha.is_finite() {
        // The fitted line through the weighted centroid.
        let w: f64 = logs.iter().map(|p| 1.0 / (p.2 * p.2)).sum();
        let cx = logs.iter().map(|p| p.0 / (p.2 * p.2)).sum::<f64>() / w;
        let cy = logs.iter().map(|p| p.1 / (p.2 * p.2)).sum::<f64>() / w;
        let ends = [logs[0].0, logs[logs.len() - 1].0];
        layers.push(dashed(
            ends.iter()
                .map(|&x| (x.exp(), (cy + alpha * (x - cx)).exp()))
                .collect(),
            colour(1),
            format!("fit: N^{}", num(alpha)),
        ));
    }
    figures.push(figure(
        file,
        (
            "Conductivity of the 1D gas of unequal masses against N".into(),
            "N (particles; density 1)",
            "κ [k √(kT/m) σ⁰]",
        ),
        (true, true),
        layers,
    ));
    format!(
        "![The 1D gas's conductivity against N on log axes, with the fitted power (dashed).]({file})\n"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_power_law_is_fitted_exactly() {
        let pts: Vec<(f64, f64, f64)> = [10.0f64, 20.0, 40.0, 80.0]
            .iter()
            .map(|&n| (n.ln(), (2.0 * n.powf(0.3)).ln(), 0.01))
            .collect();
        let (a, se, chi2) = power_fit(&pts);
        assert!((a - 0.3).abs() < 1e-12 && se > 0.0 && chi2 < 1e-18);
        assert_eq!(local_slopes(&pts), "0.3, 0.3, 0.3");
        assert!(against_theory("all N", a, 0.001).contains("differs from 1/3"));
    }
}
