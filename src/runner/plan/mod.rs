//! Sweep x replicas -> one `RunSpec` per simulation, each with the descriptor
//! as it applies to its sweep point and its own seed, derived from (study
//! seed, the point's swept values, replica). A point's replicas share its
//! descriptor, and points share the base's long lists (`descriptor::point`),
//! so planning is linear in the plan's size.

pub mod confirm;
pub mod error_bars;
pub mod estimate;
pub mod origin;
pub mod seeds;
pub mod trajectory;

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::{Loaded, show};
use crate::descriptor::point::{PointBase, PointError};
use crate::descriptor::sweep::{HARD_LIMIT, Numbers, count, point_text, points};
use crate::descriptor::validate;
use crate::model::descriptor::Descriptor;
use crate::model::run_spec::RunSpec;
use crate::runner::plan::seeds::{point_key, run_seed};
use std::collections::{HashMap, HashSet};
use std::sync::Arc;

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
    let mut specs = Vec::with_capacity(usize::try_from(runs).unwrap_or(0));
    let mut seen: HashMap<u64, u64> = HashMap::new();
    let mut same: HashMap<String, u64> = HashMap::new();
    let base = PointBase::new(&loaded.file, &loaded.table, d);
    let mut checks = validate::Points::default();
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
        let descriptor = Arc::new(point_descriptor(&base, &mut checks, &params, &fail)?);
        let key = point_key(&params);
        // 10 and 10.0 are one value: the same point, though not the same seeds.
        let repeat = match seen.insert(key, point_id) {
            Some(other) => Some((other, "seeds")),
            None => same
                .insert(point_text(&params, Numbers::Alike), point_id)
                .map(|o| (o, "settings")),
        };
        if let Some((other, what)) = repeat {
            return Err(fail(
                format!("has the same values as point {other}"),
                Some(format!(
                    "remove the repeat: both points would run with the same {what}"
                )),
            ));
        }
        let params = Arc::new(params);
        for replica in 0..replicas {
            specs.push(RunSpec {
                run_id: point_id * u64::from(replicas) + u64::from(replica),
                point_id,
                replica,
                seed: run_seed(d.study.seed, key, replica),
                params: Arc::clone(&params),
                case: None,
                descriptor: Arc::clone(&descriptor),
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
    let base = PointBase::new(&loaded.file, &loaded.table, d);
    let mut checks = validate::Points::default();
    let no_params = Arc::new(Vec::new());
    let mut named = HashSet::new();
    for (i, case) in d.case.iter().enumerate() {
        let at = format!("case.{i}");
        let fail = |message: String, hint: Option<String>| {
            let err =
                DescriptorError::new(&loaded.file, format!("case \"{}\": {message}", case.name))
                    .at(crate::descriptor::locate::position_of(&loaded.text, &at))
                    .key(&at);
            hint.into_iter().fold(err, DescriptorError::hint)
        };
        validate::case(d, i, &mut named)
            .map_err(|p| fail(format!("`{}`: {}", p.key, p.message), p.hint))?;
        let settings: Vec<(String, toml::Value)> = case
            .set
            .iter()
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect();
        let descriptor = Arc::new(point_descriptor(&base, &mut checks, &settings, &fail)?);
        let point_id = specs.last().map_or(0, |s| s.point_id + 1);
        let key = point_key(&[("case".to_string(), toml::Value::String(case.name.clone()))]);
        for replica in 0..case.replicas.unwrap_or(d.study.replicas) {
            specs.push(RunSpec {
                run_id: specs.len() as u64,
                point_id,
                replica,
                seed: run_seed(d.study.seed, key, replica),
                params: Arc::clone(&no_params),
                case: Some(case.name.clone()),
                descriptor: Arc::clone(&descriptor),
            });
        }
    }
    Ok(())
}

/// The descriptor of one point: the base with `settings` (key path, value)
/// applied, typed and checked as it will run; problems go through `fail`,
/// which says which point they belong to.
fn point_descriptor(
    base: &PointBase<'_>,
    checks: &mut validate::Points,
    settings: &[(String, toml::Value)],
    fail: &dyn Fn(String, Option<String>) -> DescriptorError,
) -> Result<Descriptor, DescriptorError> {
    let descriptor = base.descriptor(settings).map_err(|e| match e {
        PointError::Apply(n, m) => fail(format!("`{}`: {m}", settings[n].0), None),
        PointError::Typed(e) => {
            let mut err = fail(e.message, None);
            err.hints = e.hints;
            err
        }
    })?;
    checks
        .point(&descriptor)
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
