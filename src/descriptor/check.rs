//! Semantic checks of a parsed descriptor, placed at their key in the
//! source: the descriptor as its sweep points will run, a value that does not
//! fit its key at that sweep key, a value a preset supplied at the preset.

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::{Loaded, show};
use crate::descriptor::point::{PointBase, PointError};
use crate::descriptor::validate;
use crate::model::descriptor::{Descriptor, SweepMode, SweepValues};

/// Semantic checks; errors are placed at their key in the source if present.
/// With a sweep, the descriptor is checked as its sweep points will run:
/// the first point, and each key's representative values within a point.
pub fn check(loaded: &Loaded) -> Result<(), DescriptorError> {
    let d = &loaded.descriptor;
    preset_lists(loaded)?;
    validate::study(d)
        .and_then(|()| validate::sweep(d))
        .map_err(|p| located(loaded, p))?;
    let Some(sweep) = &d.sweep else {
        return validate::point(d).map_err(|p| located(loaded, p));
    };
    let axes: Vec<(&String, Vec<toml::Value>, Vec<usize>)> = sweep
        .parameters
        .iter()
        .map(|(k, v)| {
            let values = crate::descriptor::sweep::expand_values(v);
            let picked = representatives(v, &values);
            (k, values, picked)
        })
        .collect();
    let base = PointBase::new(&loaded.file, &loaded.table, d);
    // Each value must fit its key's type (alone: types do not interact).
    for (key, values, picked) in &axes {
        validate::sweep_key(key).map_err(|p| sweep_error(loaded, key, p.message, p.hint))?;
        for &i in picked {
            point_descriptor(loaded, &base, &[((*key).clone(), values[i].clone())])?;
        }
    }
    // Then whole points: the first, and each representative value in the
    // point it belongs to (zip: its row; product: the others at their first).
    let at = |row: usize, only: Option<(usize, usize)>| -> Vec<(String, toml::Value)> {
        axes.iter()
            .enumerate()
            .map(|(a, (k, v, _))| {
                let i = match (only, sweep.mode) {
                    (Some((b, i)), _) if a == b => i,
                    (_, SweepMode::Zip) => row,
                    _ => 0,
                };
                ((*k).clone(), v[i].clone())
            })
            .collect()
    };
    let mut checks = validate::Points::default();
    check_point(loaded, &base, &mut checks, &at(0, None), None)?;
    for (a, (_, _, picked)) in axes.iter().enumerate() {
        for &i in picked {
            check_point(loaded, &base, &mut checks, &at(i, Some((a, i))), Some(a))?;
        }
    }
    Ok(())
}

/// A list given empty beside a preset: the typed scene cannot tell it from
/// a list left out, which keeps the preset's, so it is refused rather than
/// ignored.
fn preset_lists(loaded: &Loaded) -> Result<(), DescriptorError> {
    let Some(name) = &loaded.descriptor.scene.preset else {
        return Ok(());
    };
    let scene = loaded.table.get("scene").and_then(toml::Value::as_table);
    for (list, what) in [
        ("species", "the scene would have no particles"),
        ("thermal_walls", "the preset's walls cannot be removed"),
    ] {
        let empty = scene
            .and_then(|s| s.get(list))
            .and_then(toml::Value::as_array)
            .is_some_and(Vec::is_empty);
        if empty {
            let key = format!("scene.{list}");
            return Err(DescriptorError::new(
                &loaded.file,
                format!("`{key}` is empty: {what}"),
            )
            .at(crate::descriptor::locate::position_of(&loaded.text, &key))
            .key(key)
            .hint(format!(
                "leave `{list}` out to keep those of preset \"{name}\", or list at least one"
            )));
        }
    }
    Ok(())
}

/// The descriptor with `params` applied; a key that does not take its value
/// is reported at that sweep key.
fn point_descriptor(
    loaded: &Loaded,
    base: &PointBase<'_>,
    params: &[(String, toml::Value)],
) -> Result<Descriptor, DescriptorError> {
    base.descriptor(params).map_err(|e| match e {
        PointError::Apply(n, m) => {
            let (key, value) = &params[n];
            sweep_error(loaded, key, format!("value {}: {m}", show(value)), None)
        }
        PointError::Typed(e) => {
            let (key, value) = &params[0];
            let mut err = sweep_error(
                loaded,
                key,
                format!("value {}: {}", show(value), e.message),
                None,
            );
            err.hints = e.hints;
            err
        }
    })
}

/// Check one sweep point. A problem at (or around) a swept key, or one that
/// the value of key `blamed` caused, is reported at that sweep key; one the
/// descriptor has without its sweep, at its own key.
fn check_point(
    loaded: &Loaded,
    base: &PointBase<'_>,
    checks: &mut validate::Points,
    params: &[(String, toml::Value)],
    blamed: Option<usize>,
) -> Result<(), DescriptorError> {
    let d = point_descriptor(loaded, base, params)?;
    let Err(p) = checks.point(&d) else {
        return Ok(());
    };
    let related = |k: &str| k == p.key || p.key.starts_with(&format!("{k}."));
    let culprit = params.iter().position(|(k, _)| related(k)).or(blamed);
    if let Some(c) = culprit {
        let (key, value) = &params[c];
        return Err(sweep_error(
            loaded,
            key,
            format!(
                "value {} makes `{}` invalid: {}",
                show(value),
                p.key,
                p.message
            ),
            p.hint,
        ));
    }
    let shown: Vec<String> = params
        .iter()
        .map(|(k, v)| format!("`{k}` = {}", show(v)))
        .collect();
    // A problem of the descriptor without its sweep is placed at its key;
    // if the sweep changed its numbers, the point is named too.
    match validate::point(&loaded.descriptor) {
        Err(base) if base == p => return Err(located(loaded, p)),
        Err(base) if base.key == p.key => {
            let mut err = located(loaded, p);
            err.message += &format!(" (at sweep point {})", shown.join(", "));
            return Err(err);
        }
        _ => {}
    }
    let mut err = DescriptorError::new(
        &loaded.file,
        format!(
            "at sweep point ({}): `{}`: {}",
            shown.join(", "),
            p.key,
            p.message
        ),
    )
    .at(crate::descriptor::locate::position_of(
        &loaded.text,
        "sweep.parameters",
    ))
    .key(p.key);
    if let Some(h) = p.hint {
        err = err.hint(h);
    }
    Err(err)
}

/// An error at sweep parameter `key`.
fn sweep_error(
    loaded: &Loaded,
    key: &str,
    message: String,
    hint: Option<String>,
) -> DescriptorError {
    let place =
        crate::descriptor::locate::position_of_keys(&loaded.text, &["sweep", "parameters", key]);
    let err = DescriptorError::new(&loaded.file, format!("sweep parameter `{key}`: {message}"))
        .at(place)
        .key(format!("sweep.parameters.{key}"));
    hint.into_iter().fold(err, DescriptorError::hint)
}

/// A problem placed at its key in the source. A scene key that the preset
/// supplied (absent from the file) is placed at `preset`, saying so.
fn located(loaded: &Loaded, p: validate::Problem) -> DescriptorError {
    let keys: Vec<&str> = match p.key.strip_prefix("sweep.parameters.") {
        Some(key) => vec!["sweep", "parameters", key],
        None => p.key.split('.').collect(),
    };
    let found = crate::descriptor::locate::deepest(&loaded.text, &keys);
    let mut position = found.map(|(_, at)| at);
    let mut from_preset = None;
    if keys.len() >= 2
        && keys[0] == "scene"
        && found.is_none_or(|(depth, _)| depth < 2)
        && let Some(name) = &loaded.descriptor.scene.preset
    {
        position =
            crate::descriptor::locate::position_of(&loaded.text, "scene.preset").or(position);
        from_preset = Some(format!(
            "`{}` comes from preset \"{name}\"; set it in [scene] to override the preset",
            keys[..2].join(".")
        ));
    }
    let err = DescriptorError::new(&loaded.file, format!("`{}`: {}", p.key, p.message))
        .at(position)
        .key(p.key);
    p.hint
        .into_iter()
        .chain(from_preset)
        .fold(err, DescriptorError::hint)
}

/// Indices of the values of a sweep parameter worth checking: all of a
/// list; of a (monotonic) range its ends and its first non-whole value,
/// which between them meet every key's type and bounds that the range meets.
fn representatives(sweep: &SweepValues, values: &[toml::Value]) -> Vec<usize> {
    if matches!(sweep, SweepValues::List(_)) {
        return (0..values.len()).collect();
    }
    let mut picked = vec![0, values.len().saturating_sub(1)];
    if let Some(f) = values.iter().position(toml::Value::is_float) {
        picked.push(f);
    }
    picked.sort_unstable();
    picked.dedup();
    picked.retain(|&i| i < values.len());
    picked
}
