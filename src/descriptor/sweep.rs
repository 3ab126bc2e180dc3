//! What a sweep expands to, as the descriptor says it: each parameter's
//! values, the points in order, and how many runs they make (with the
//! cases), before anything is planned.

use crate::descriptor::load::Loaded;
use crate::model::descriptor::{Scale, SweepMode, SweepSection, SweepValues};

/// More runs than this need `--yes`.
pub const CONFIRM_ABOVE: u64 = 100_000;
/// More runs than this are refused outright: a study's records, tables and
/// summaries grow with its runs (a plan of 2 million runs takes about half
/// a gigabyte to plan and a second to validate).
pub const HARD_LIMIT: u64 = 2_000_000;

/// The values a sweep parameter takes, in order.
pub fn expand_values(values: &SweepValues) -> Vec<toml::Value> {
    (0..len(values)).map(|i| value_at(values, i)).collect()
}

/// How many values a sweep parameter takes.
pub fn len(values: &SweepValues) -> usize {
    match values {
        SweepValues::List(v) => v.len(),
        SweepValues::Range(r) => r.steps,
    }
}

/// Value `i` (< `len`) of a sweep parameter, without expanding the others.
pub fn value_at(values: &SweepValues, i: usize) -> toml::Value {
    let r = match values {
        SweepValues::List(v) => return v[i].clone(),
        SweepValues::Range(r) => r,
    };
    let f = if r.steps == 1 {
        0.0
    } else {
        i as f64 / (r.steps - 1) as f64
    };
    let x = match (i, r.scale) {
        (0, _) => r.from,
        (i, _) if i + 1 == r.steps => r.to,
        (_, Scale::Linear) => r.from + (r.to - r.from) * f,
        (_, Scale::Log) => significant(r.from * (r.to / r.from).powf(f)),
    };
    number(x)
}

/// A parameter's values as `study validate` prints them: all of a short
/// list, the ends of a long one (`model::text::shortened`).
pub fn values_text(values: &SweepValues, show: impl Fn(&toml::Value) -> String) -> String {
    crate::model::text::shortened(len(values), |i| show(&value_at(values, i)))
}

/// Round to 12 significant digits, so a log range gives 100, not 99.99999999999999.
fn significant(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(11 - x.abs().log10().floor() as i32);
    (x * scale).round() / scale
}

/// Whole numbers become TOML integers so they also fit integer keys (counts);
/// serde reads an integer into a float key just as well.
fn number(x: f64) -> toml::Value {
    if x.fract() == 0.0 && x.abs() < 9.0e15 {
        toml::Value::Integer(x as i64)
    } else {
        toml::Value::Float(x)
    }
}

/// Sweep points in order: product (last key varies fastest) or zip.
pub fn points(sweep: Option<&SweepSection>) -> Vec<Vec<(String, toml::Value)>> {
    let Some(sweep) = sweep else {
        return vec![Vec::new()];
    };
    let axes: Vec<(String, Vec<toml::Value>)> = sweep
        .parameters
        .iter()
        .map(|(k, v)| (k.clone(), expand_values(v)))
        .collect();
    match sweep.mode {
        SweepMode::Zip => {
            let n = axes.iter().map(|(_, v)| v.len()).min().unwrap_or(0);
            (0..n)
                .map(|i| {
                    axes.iter()
                        .map(|(k, v)| (k.clone(), v[i].clone()))
                        .collect()
                })
                .collect()
        }
        SweepMode::Product => axes.iter().fold(vec![Vec::new()], |acc, (k, values)| {
            acc.iter()
                .flat_map(|prefix| {
                    values.iter().map(move |v| {
                        let mut p = prefix.clone();
                        p.push((k.clone(), v.clone()));
                        p
                    })
                })
                .collect()
        }),
    }
}

/// The sweep's points as a float: the product (or, zipped, the shortest)
/// of its parameters' lengths, without building them and without overflow.
pub fn size(sweep: &SweepSection) -> f64 {
    let lens = sweep.parameters.values().map(|v| match v {
        SweepValues::List(l) => l.len() as f64,
        SweepValues::Range(r) => r.steps as f64,
    });
    match sweep.mode {
        SweepMode::Zip => lens.fold(f64::INFINITY, f64::min).min(f64::MAX),
        SweepMode::Product => lens.product(),
    }
}

/// A count as a reader takes it: exact up to 10^7, then "about 1.2e21".
pub fn points_text(x: f64) -> String {
    if x < 1e7 {
        format!("{x:.0}")
    } else {
        format!("about {x:.1e}")
    }
}

/// (sweep points, runs) without building the plan; saturates instead of overflowing.
pub fn count(loaded: &Loaded) -> (u64, u64) {
    let d = &loaded.descriptor;
    let points = match &d.sweep {
        None => 1,
        Some(s) => {
            let lens = s.parameters.values().map(|v| match v {
                SweepValues::List(l) => l.len() as u64,
                SweepValues::Range(r) => r.steps as u64,
            });
            match s.mode {
                SweepMode::Zip => lens.min().unwrap_or(0),
                SweepMode::Product => lens.fold(1u64, u64::saturating_mul),
            }
        }
    };
    let sweep_runs = points.saturating_mul(u64::from(d.study.replicas));
    let case_runs = d
        .case
        .iter()
        .map(|c| u64::from(c.replicas.unwrap_or(d.study.replicas)))
        .fold(0u64, u64::saturating_add);
    (
        points.saturating_add(d.case.len() as u64),
        sweep_runs.saturating_add(case_runs),
    )
}

/// How a value's text writes numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Numbers {
    /// As they compare: an integer that a float holds exactly is written as
    /// that float and -0.0 as 0.0, so `10` and `10.0` give one text.
    Alike,
    /// As written, integers apart from floats (the seeds' form: it must
    /// never change, or every saved run's seed would).
    AsWritten,
}

/// A value's canonical text (floats in Rust's shortest round-trip form,
/// tables with sorted keys): two values with the same `Alike` text set a key
/// alike.
pub fn value_text(value: &toml::Value) -> String {
    let mut out = String::new();
    write_value(value, Numbers::Alike, &mut out);
    out
}

/// The text of a sweep point's (key, value) pairs, a line each.
pub fn point_text(params: &[(String, toml::Value)], numbers: Numbers) -> String {
    let mut out = String::new();
    for (key, value) in params {
        out.push_str(key);
        out.push('=');
        write_value(value, numbers, &mut out);
        out.push('\n');
    }
    out
}

fn write_value(value: &toml::Value, numbers: Numbers, out: &mut String) {
    use std::fmt::Write;
    let alike = numbers == Numbers::Alike;
    let _ = match value {
        toml::Value::Integer(i) if alike && i.unsigned_abs() <= 1 << 53 => {
            write!(out, "{:?}", *i as f64)
        }
        toml::Value::Float(f) if alike && *f == 0.0 => write!(out, "0.0"),
        toml::Value::Float(f) => write!(out, "{f:?}"),
        toml::Value::Integer(i) => write!(out, "{i}"),
        toml::Value::String(s) => write!(out, "{s:?}"),
        toml::Value::Boolean(b) => write!(out, "{b}"),
        toml::Value::Datetime(d) => write!(out, "{d}"),
        toml::Value::Array(items) => {
            out.push('[');
            for item in items {
                write_value(item, numbers, out);
                out.push(',');
            }
            write!(out, "]")
        }
        toml::Value::Table(t) => {
            out.push('{');
            let mut keys: Vec<&String> = t.keys().collect();
            keys.sort();
            for k in keys {
                let _ = write!(out, "{k:?}=");
                write_value(&t[k], numbers, out);
                out.push(',');
            }
            write!(out, "}}")
        }
    };
}
