//! What `study validate` says a plan's error bars will be, before it runs:
//! each named study's error model (`Study::error_model`) at each point of
//! the plan, for the replicas that point runs. Studies without a model,
//! and points a model does not cover, are said to be so.

use crate::model::run_spec::RunSpec;
use crate::studies::{self, ErrorModel};
use std::fmt::Write;

/// Per study: the predicted relative standard error of its headline result
/// at each point it covers, with that point's replicas, and its model.
struct Predicted {
    study: &'static str,
    points: Vec<(f64, u32, ErrorModel)>,
}

/// The lines `study validate` prints (empty when no named study has a model).
pub fn describe(specs: &[RunSpec]) -> String {
    let mut by_study: Vec<Predicted> = Vec::new();
    let mut total = 0usize;
    let mut i = 0;
    while i < specs.len() {
        let point = specs[i].point_id;
        let replicas = specs[i..]
            .iter()
            .take_while(|s| s.point_id == point)
            .count();
        total += 1;
        let n = u32::try_from(replicas).unwrap_or(u32::MAX);
        for (study, model) in studies::error_models(&specs[i].descriptor) {
            let at = match by_study.iter().position(|p| p.study == study) {
                Some(k) => k,
                None => {
                    by_study.push(Predicted {
                        study,
                        points: Vec::new(),
                    });
                    by_study.len() - 1
                }
            };
            by_study[at].points.push((model.stderr(n), n, model));
        }
        i += replicas;
    }
    let mut out = String::new();
    if by_study.is_empty() {
        return out;
    }
    out += "  error bars (the studies' error models, before running; docs/accuracy.md):\n";
    for p in &by_study {
        let _ = writeln!(out, "    {}", line(p, total));
    }
    out
}

fn line(p: &Predicted, total: usize) -> String {
    let se: Vec<f64> = p.points.iter().map(|x| x.0).collect();
    let lo = se.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = se.iter().copied().fold(0.0, f64::max);
    let reps: Vec<u32> = p.points.iter().map(|x| x.1).collect();
    let (rlo, rhi) = (
        reps.iter().min().copied().unwrap_or(0),
        reps.iter().max().copied().unwrap_or(0),
    );
    // The model of the point with the widest error bar speaks for the plan.
    let worst = p
        .points
        .iter()
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|x| &x.2)
        .expect("a study listed has a point");
    let bar = if hi <= lo * 1.05 {
        format!("±{} %", two_digits(100.0 * hi))
    } else {
        format!("±{}–{} %", two_digits(100.0 * lo), two_digits(100.0 * hi))
    };
    let replicas = if rlo == rhi {
        format!("{rlo} replicas")
    } else {
        format!("{rlo}–{rhi} replicas")
    };
    let covered = if p.points.len() == total {
        String::new()
    } else {
        format!(" ({} of {total} points have a model)", p.points.len())
    };
    let length = if worst.length_exponent == 0.0 {
        "; longer runs do not narrow it, more replicas do"
    } else {
        ""
    };
    format!(
        "{}: {} to about {bar} per point with {replicas}{covered}{length}; ±1 % would take ~{} replicas at the widest (model: {})",
        p.study,
        worst.label,
        replicas_text(worst.replicas_for(0.01)),
        worst.basis
    )
}

/// A replica count: exact below 100, else to two digits.
fn replicas_text(n: f64) -> String {
    if n < 100.0 {
        format!("{n:.0}")
    } else {
        two_digits(n)
    }
}

/// A number to two significant digits, as an error bar deserves
/// (0.01234 -> "0.012", 1.581 -> "1.6", 123.4 -> "120").
pub fn two_digits(x: f64) -> String {
    if !(x.is_finite() && x > 0.0) {
        return format!("{x}");
    }
    let exp = x.log10().floor() as i32;
    let scale = 10f64.powi(exp - 1);
    let rounded = (x / scale).round() * scale;
    // Rounding may carry into the next decade (9.96 -> 10).
    let decimals = (1 - rounded.log10().floor() as i32).max(0) as usize;
    format!("{rounded:.decimals$}")
}

#[cfg(test)]
mod tests {
    #[test]
    fn two_significant_digits() {
        assert_eq!(super::two_digits(0.01234), "0.012");
        assert_eq!(super::two_digits(1.581), "1.6");
        assert_eq!(super::two_digits(123.4), "120");
        assert_eq!(super::two_digits(9.96), "10");
    }
}
