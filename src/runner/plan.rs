//! Sweep x replicas -> one `RunSpec` per simulation, each with the descriptor
//! as it applies to its sweep point and its own seed, derived from (study
//! seed, the point's swept values, replica).

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::{Loaded, apply_overrides, from_table, show};
use crate::descriptor::validate;
use crate::model::descriptor::{Scale, SweepMode, SweepSection, SweepValues};
use crate::model::run_spec::RunSpec;
use crate::runner::seeds::{point_key, run_seed};
use std::collections::HashMap;

/// More runs than this need `--yes`.
pub const CONFIRM_ABOVE: u64 = 100_000;
/// More runs than this are refused outright: every planned run carries its
/// own descriptor, so the plan alone would not fit in memory.
pub const HARD_LIMIT: u64 = 2_000_000;

/// The values a sweep parameter takes, in order.
pub fn expand_values(values: &SweepValues) -> Vec<toml::Value> {
    match values {
        SweepValues::List(v) => v.clone(),
        SweepValues::Range(r) => (0..r.steps)
            .map(|i| {
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
            })
            .collect(),
    }
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
    (points, points.saturating_mul(u64::from(d.study.replicas)))
}

/// Expand the descriptor into runs: run_id = point_id * replicas + replica.
/// Every point is checked as it will run, so a study fails here, before
/// anything runs, rather than run by run.
pub fn plan(loaded: &Loaded) -> Result<Vec<RunSpec>, DescriptorError> {
    let (_, runs) = count(loaded);
    if runs > HARD_LIMIT {
        let at = if loaded.descriptor.sweep.is_some() {
            "sweep"
        } else {
            "study.replicas"
        };
        return Err(DescriptorError::new(
            &loaded.file,
            format!("the plan has {runs} runs, more than the {HARD_LIMIT} one study can hold"),
        )
        .at(crate::descriptor::locate::position_of(&loaded.text, at))
        .key(at)
        .hint(
            "sweep fewer values or fewer replicas, or split the study into several descriptors",
        ));
    }
    let d = &loaded.descriptor;
    let replicas = d.study.replicas;
    let mut specs = Vec::new();
    let mut seen: HashMap<u64, u64> = HashMap::new();
    for (point_id, params) in points(d.sweep.as_ref()).into_iter().enumerate() {
        let point_id = point_id as u64;
        let fail = |message: String, hint: Option<String>| {
            let err = DescriptorError::new(
                &loaded.file,
                format!("sweep point {point_id} ({}): {message}", shown(&params)),
            )
            .at(crate::descriptor::locate::position_of(
                &loaded.text,
                "sweep.parameters",
            ))
            .key("sweep.parameters");
            hint.into_iter().fold(err, DescriptorError::hint)
        };
        let mut table = loaded.table.clone();
        for (key, value) in &params {
            apply_overrides(&mut table, key, value.clone())
                .map_err(|m| fail(format!("`{key}`: {m}"), None))?;
        }
        let descriptor = from_table(&loaded.file, &table).map_err(|e| {
            let mut err = fail(e.message, None);
            err.hints = e.hints;
            err
        })?;
        validate::point(&descriptor)
            .map_err(|p| fail(format!("`{}`: {}", p.key, p.message), p.hint))?;
        let key = point_key(&params);
        if let Some(other) = seen.insert(key, point_id) {
            return Err(fail(
                format!("has the same values as point {other}"),
                Some("remove the repeat: both points would run with the same seeds".into()),
            ));
        }
        for replica in 0..replicas {
            specs.push(RunSpec {
                run_id: point_id * u64::from(replicas) + u64::from(replica),
                point_id,
                replica,
                seed: run_seed(d.study.seed, key, replica),
                params: params.clone(),
                descriptor: descriptor.clone(),
            });
        }
    }
    Ok(specs)
}

/// "`scene.piston.mass` = 10.0, `run.duration` = 5.0".
fn shown(params: &[(String, toml::Value)]) -> String {
    params
        .iter()
        .map(|(k, v)| format!("`{k}` = {}", show(v)))
        .collect::<Vec<_>>()
        .join(", ")
}
