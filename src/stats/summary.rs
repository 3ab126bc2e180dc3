//! Ensemble statistics per sweep point and scalar result (`summary.parquet`).
//!
//! A run that could not measure a result reports NaN (or omits it); such values
//! are left out of `n`, the mean and the error bar rather than poisoning them.
//! The report shows "n of N runs" wherever that happened.

use crate::model::descriptor::Descriptor;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::model::summary::SummaryRow;
use statrs::distribution::{ContinuousCDF, StudentsT};
use std::collections::{BTreeMap, HashSet};

/// Two-sided confidence level of `ci_low..ci_high`.
pub const CONFIDENCE: f64 = 0.95;

/// One row per (point_id, result), ordered by point_id then result name.
/// `theory(descriptor, result)` is asked once per row with the point's descriptor.
pub fn summarize(
    runs: &[(RunSpec, RunOutput)],
    theory: &dyn Fn(&Descriptor, &str) -> Option<f64>,
) -> Vec<SummaryRow> {
    let mut points: BTreeMap<u64, Vec<&(RunSpec, RunOutput)>> = BTreeMap::new();
    for run in runs {
        points.entry(run.0.point_id).or_default().push(run);
    }
    let mut rows = Vec::new();
    for (point_id, point_runs) in points {
        let spec = &point_runs[0].0;
        let params = numeric_params(&spec.params);
        let seconds: f64 = point_runs.iter().map(|(_, o)| o.wall_seconds).sum();
        let collisions: u64 = point_runs.iter().map(|(_, o)| o.collisions).sum();
        for (name, values) in values_by_name(&point_runs) {
            let stats = Stats::of(&values);
            let theory = theory(&spec.descriptor, name).filter(|t| t.is_finite());
            rows.push(SummaryRow {
                point_id,
                params: params.clone(),
                result: name.to_string(),
                n: stats.n,
                mean: stats.mean,
                std: stats.std,
                stderr: stats.stderr,
                ci_low: stats.ci_low,
                ci_high: stats.ci_high,
                theory,
                z: theory.and_then(|t| z_score(&stats, t)),
                seconds,
                collisions,
            });
        }
    }
    rows
}

/// Each scalar name of `runs` (sorted) with its finite values, in run
/// order: one pass over every run's scalars, so a run of many names costs
/// its size, not its size squared. A name a run reports twice counts once,
/// its first value (as `RunOutput::scalar` reads it).
fn values_by_name<'a>(runs: &[&'a (RunSpec, RunOutput)]) -> BTreeMap<&'a str, Vec<f64>> {
    let mut values: BTreeMap<&str, Vec<f64>> = BTreeMap::new();
    let mut seen: HashSet<&str> = HashSet::new();
    for (_, o) in runs {
        seen.clear();
        for (name, v) in &o.scalars {
            let list = values.entry(name.as_str()).or_default();
            if seen.insert(name.as_str()) && v.is_finite() {
                list.push(*v);
            }
        }
    }
    values
}

/// Swept parameters as numbers: integers and floats as themselves, booleans as
/// 0/1, anything else (strings, tables) as NaN.
pub fn numeric_params(params: &[(String, toml::Value)]) -> Vec<(String, f64)> {
    params
        .iter()
        .map(|(k, v)| (k.clone(), toml_number(v)))
        .collect()
}

/// A TOML value as f64, NaN when it is not a number.
pub fn toml_number(v: &toml::Value) -> f64 {
    match v {
        toml::Value::Integer(i) => *i as f64,
        toml::Value::Float(f) => *f,
        toml::Value::Boolean(b) => f64::from(u8::from(*b)),
        _ => f64::NAN,
    }
}

/// Sample statistics of finite values; NaN where undefined (no values, or a
/// spread from a single value).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stats {
    pub n: u64,
    pub mean: f64,
    /// Sample standard deviation (n - 1 in the denominator).
    pub std: f64,
    pub stderr: f64,
    pub ci_low: f64,
    pub ci_high: f64,
}

impl Stats {
    pub fn of(values: &[f64]) -> Stats {
        let n = values.len() as u64;
        let mean = if n == 0 {
            f64::NAN
        } else {
            values.iter().sum::<f64>() / n as f64
        };
        let ss: f64 = values.iter().map(|v| (v - mean).powi(2)).sum();
        Stats::from_moments(n, mean, ss, t_quantile(n.saturating_sub(1)))
    }

    /// The statistics of the values times `factor` (> 0).
    pub fn scaled(&self, factor: f64) -> Stats {
        Stats {
            n: self.n,
            mean: self.mean * factor,
            std: self.std * factor,
            stderr: self.stderr * factor,
            ci_low: self.ci_low * factor,
            ci_high: self.ci_high * factor,
        }
    }

    /// From the count, the mean, the sum of squared deviations from it and
    /// the Student quantile for n - 1 degrees of freedom (given, so that a
    /// curve of many samples with one n computes it once).
    pub fn from_moments(n: u64, mean: f64, ss: f64, quantile: f64) -> Stats {
        let (std, stderr, half) = if n < 2 {
            (f64::NAN, f64::NAN, f64::NAN)
        } else {
            let std = (ss / (n - 1) as f64).sqrt();
            let stderr = std / (n as f64).sqrt();
            (std, stderr, quantile * stderr)
        };
        Stats {
            n,
            mean,
            std,
            stderr,
            ci_low: mean - half,
            ci_high: mean + half,
        }
    }
}

/// A scalar result over runs, from those that measured it finite.
pub fn scalar<'a>(outs: impl IntoIterator<Item = &'a RunOutput>, name: &str) -> Stats {
    let values: Vec<f64> = outs
        .into_iter()
        .filter_map(|o| o.scalar(name))
        .filter(|v| v.is_finite())
        .collect();
    Stats::of(&values)
}

/// The two-sided `CONFIDENCE` quantile of Student's t with `dof` degrees of freedom.
pub fn t_quantile(dof: u64) -> f64 {
    match StudentsT::new(0.0, 1.0, dof as f64) {
        Ok(t) => t.inverse_cdf(0.5 + CONFIDENCE / 2.0),
        Err(_) => f64::NAN,
    }
}

/// (mean - theory) / stderr, or None when the error bar cannot say anything:
/// fewer than two values, or no spread at all. With zero spread a disagreement
/// has no statistical scale (it is systematic, not noise), so no z is claimed;
/// exact agreement (to round-off) is reported as z = 0 because the deviation
/// is zero in any unit.
pub fn z_score(stats: &Stats, theory: f64) -> Option<f64> {
    if stats.n < 2 || !stats.mean.is_finite() || !stats.stderr.is_finite() {
        return None;
    }
    let diff = stats.mean - theory;
    if stats.stderr > 0.0 {
        return Some(diff / stats.stderr);
    }
    let roundoff = 1e-12 * theory.abs().max(stats.mean.abs()).max(f64::MIN_POSITIVE);
    (diff.abs() <= roundoff).then_some(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    #[test]
    fn one_to_four() {
        let s = Stats::of(&[1.0, 2.0, 3.0, 4.0]);
        assert_eq!(s.n, 4);
        assert!(close(s.mean, 2.5, 1e-12));
        assert!(close(s.std, 1.290_994, 1e-6));
        assert!(close(s.stderr, 0.645_497, 1e-6));
        assert!(close(t_quantile(3), 3.182_446, 1e-5));
        assert!(close(s.ci_high - s.mean, 3.182_446 * 0.645_497, 1e-5));
    }

    #[test]
    fn degenerate_samples() {
        let empty = Stats::of(&[]);
        assert_eq!(empty.n, 0);
        assert!(empty.mean.is_nan() && empty.stderr.is_nan());
        let one = Stats::of(&[7.0]);
        assert_eq!(one.mean, 7.0);
        assert!(one.std.is_nan() && one.ci_low.is_nan());
        assert_eq!(z_score(&one, 7.0), None);
    }

    #[test]
    fn z_with_zero_spread() {
        let flat = Stats::of(&[2.0, 2.0, 2.0]);
        assert_eq!(flat.stderr, 0.0);
        assert_eq!((flat.ci_low, flat.ci_high), (2.0, 2.0));
        assert_eq!(z_score(&flat, 2.0), Some(0.0));
        assert_eq!(z_score(&flat, 2.5), None);
    }

    #[test]
    fn z_is_deviation_in_stderr() {
        let s = Stats::of(&[1.0, 2.0, 3.0, 4.0]);
        let z = z_score(&s, 1.0).unwrap_or(f64::NAN);
        assert!(close(z, 1.5 / 0.645_497, 1e-5));
    }
}
