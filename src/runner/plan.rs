//! Sweep x replicas -> one `RunSpec` per simulation, each with the descriptor
//! as it applies to its sweep point and its own seed, derived from (study
//! seed, the point's swept values, replica).

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::{Loaded, apply_overrides, from_table, show};
use crate::descriptor::sweep::{HARD_LIMIT, count, points};
use crate::descriptor::validate;
use crate::model::descriptor::Descriptor;
use crate::model::run_spec::RunSpec;
use crate::runner::seeds::{point_key, run_seed};
use std::collections::HashMap;

/// Expand the descriptor into runs: the sweep's (run_id = point_id *
/// replicas + replica), then each case's, numbered on. Every point is
/// checked as it will run, so a study fails here, before anything runs,
/// rather than run by run.
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
        let descriptor = point_descriptor(loaded, &loaded.table, &params, &fail)?;
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
                case: None,
                descriptor: descriptor.clone(),
            });
        }
    }
    cases(loaded, &mut specs)?;
    Ok(specs)
}

/// Each `[[case]]`: the descriptor without its sweep and cases, the case's
/// keys set, its own replicas. Its seeds come from its name as a sweep
/// point's come from its values, so cases never share seeds with the sweep
/// or with each other.
fn cases(loaded: &Loaded, specs: &mut Vec<RunSpec>) -> Result<(), DescriptorError> {
    let d = &loaded.descriptor;
    let mut base = loaded.table.clone();
    base.remove("sweep");
    base.remove("case");
    for (i, case) in d.case.iter().enumerate() {
        let at = format!("case.{i}");
        let fail = |message: String, hint: Option<String>| {
            let err =
                DescriptorError::new(&loaded.file, format!("case \"{}\": {message}", case.name))
                    .at(crate::descriptor::locate::position_of(&loaded.text, &at))
                    .key(&at);
            hint.into_iter().fold(err, DescriptorError::hint)
        };
        validate::case(d, i).map_err(|p| fail(format!("`{}`: {}", p.key, p.message), p.hint))?;
        let settings: Vec<(String, toml::Value)> = case
            .set
            .iter()
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect();
        let descriptor = point_descriptor(loaded, &base, &settings, &fail)?;
        let point_id = specs.last().map_or(0, |s| s.point_id + 1);
        let key = point_key(&[("case".to_string(), toml::Value::String(case.name.clone()))]);
        for replica in 0..case.replicas.unwrap_or(d.study.replicas) {
            specs.push(RunSpec {
                run_id: specs.len() as u64,
                point_id,
                replica,
                seed: run_seed(d.study.seed, key, replica),
                params: Vec::new(),
                case: Some(case.name.clone()),
                descriptor: descriptor.clone(),
            });
        }
    }
    Ok(())
}

/// The descriptor of one point: `base` with `settings` (key path, value)
/// applied, typed and checked as it will run; problems go through `fail`,
/// which says which point they belong to.
fn point_descriptor(
    loaded: &Loaded,
    base: &toml::Table,
    settings: &[(String, toml::Value)],
    fail: &dyn Fn(String, Option<String>) -> DescriptorError,
) -> Result<Descriptor, DescriptorError> {
    let mut table = base.clone();
    for (key, value) in settings {
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
    Ok(descriptor)
}

/// "`scene.piston.mass` = 10.0, `run.duration` = 5.0".
fn shown(params: &[(String, toml::Value)]) -> String {
    params
        .iter()
        .map(|(k, v)| format!("`{k}` = {}", show(v)))
        .collect::<Vec<_>>()
        .join(", ")
}
