//! Parse a study descriptor (TOML) into a `Descriptor`, with errors that point
//! at file:line:col, say what is wrong and what would be right.
//!
//! The descriptor is kept twice: as a `toml::Table` (so sweep values, `--quick`
//! and `--replicas` can be applied as key-path overrides) and typed.

use super::descriptor_types::Descriptor;
use super::errors::DescriptorError;
use super::locate::{line_col, path_at, position_of};
use super::validate;
use serde::Deserialize;
use std::path::Path;

/// A parsed and validated descriptor together with its source.
#[derive(Debug, Clone, PartialEq)]
pub struct Loaded {
    /// The file name as the user gave it (used in messages).
    pub file: String,
    /// The source text as read.
    pub text: String,
    /// The descriptor as run: source plus any overrides.
    pub table: toml::Table,
    pub descriptor: Descriptor,
    /// Overrides applied on top of the source, in order (key path, value).
    pub overrides: Vec<(String, toml::Value)>,
}

impl Loaded {
    /// TOML text of the descriptor as run (the source if nothing was overridden).
    pub fn text_as_run(&self) -> String {
        if self.overrides.is_empty() {
            self.text.clone()
        } else {
            toml::to_string(&self.table).unwrap_or_else(|_| self.text.clone())
        }
    }
}

/// Read and parse the descriptor at `path`.
pub fn load(path: &Path) -> Result<Loaded, DescriptorError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| {
        DescriptorError::new(&file, format!("cannot read the descriptor: {e}"))
            .hint("give the path of a study descriptor, e.g. `studies/piston.toml`; `study list` shows the bundled ones")
    })?;
    parse(&file, &text)
}

/// Parse and validate descriptor `text`; `file` names it in messages.
pub fn parse(file: &str, text: &str) -> Result<Loaded, DescriptorError> {
    let table: toml::Table = toml::from_str(text).map_err(|e| toml_error(file, text, &e))?;
    let descriptor: Descriptor = toml::from_str(text).map_err(|e| toml_error(file, text, &e))?;
    let loaded = Loaded {
        file: file.to_string(),
        text: text.to_string(),
        table,
        descriptor,
        overrides: Vec::new(),
    };
    check(&loaded)?;
    Ok(loaded)
}

/// Apply overrides (key path -> value) and re-validate. `origin` says where
/// they came from (e.g. "--quick") so messages can name it.
pub fn with_overrides(
    loaded: &Loaded,
    overrides: &[(String, toml::Value)],
    origin: &str,
) -> Result<Loaded, DescriptorError> {
    apply_all(loaded, overrides, origin, None)
}

/// `with_overrides`; if the overrides come from a table of the source (`[quick]`),
/// errors point at the entry that caused them.
fn apply_all(
    loaded: &Loaded,
    overrides: &[(String, toml::Value)],
    origin: &str,
    source_table: Option<&str>,
) -> Result<Loaded, DescriptorError> {
    let place = |path: &str| {
        source_table.and_then(|t| super::locate::position_of_keys(&loaded.text, &[t, path]))
    };
    let mut table = loaded.table.clone();
    let mut descriptor = loaded.descriptor.clone();
    // One at a time, so an error names the override that caused it.
    for (path, value) in overrides {
        let fail = |message: String| {
            DescriptorError::new(
                &loaded.file,
                format!("{origin}: `{path}` = {}: {message}", show(value)),
            )
            .at(place(path))
            .key(path.clone())
        };
        apply_overrides(&mut table, path, value.clone()).map_err(&fail)?;
        descriptor = from_table(&loaded.file, &table).map_err(|e| {
            let mut out = fail(e.message);
            out.hints = e.hints;
            out
        })?;
    }
    let mut all = loaded.overrides.clone();
    all.extend(overrides.iter().cloned());
    let next = Loaded {
        file: loaded.file.clone(),
        text: loaded.text.clone(),
        table,
        descriptor,
        overrides: all,
    };
    check(&next).map_err(|mut e| {
        // A problem at an overridden key was caused by the override.
        if let Some((path, _)) = overrides
            .iter()
            .find(|(p, _)| e.key.as_deref().is_some_and(|k| k.starts_with(p.as_str())))
        {
            e.position = place(path);
        }
        prefix(e, &format!("after applying {origin}: "))
    })?;
    Ok(next)
}

/// `--quick`: apply the descriptor's `[quick]` overrides.
pub fn quick(loaded: &Loaded) -> Result<Loaded, DescriptorError> {
    let overrides: Vec<_> = loaded.descriptor.quick.clone().into_iter().collect();
    if overrides.is_empty() {
        return Err(DescriptorError::new(&loaded.file, "--quick: this descriptor has no [quick] table")
            .hint("add e.g. `[quick]` with `\"study.replicas\" = 2` and `\"run.duration\" = 100.0`, or drop --quick"));
    }
    apply_all(loaded, &overrides, "[quick] (--quick)", Some("quick"))
}

/// `--replicas N`: override `study.replicas`.
pub fn with_replicas(loaded: &Loaded, replicas: u32) -> Result<Loaded, DescriptorError> {
    let value = toml::Value::Integer(i64::from(replicas));
    with_overrides(
        loaded,
        &[("study.replicas".to_string(), value)],
        "--replicas",
    )
}

/// Set the dotted key `path` of `doc` to `value`, creating tables on the way.
/// A numeric segment indexes an array (`scene.species.0.count`); below
/// `sweep.parameters.` the rest of the path is one key (a swept key path).
pub fn apply_overrides(
    doc: &mut toml::Table,
    path: &str,
    value: toml::Value,
) -> Result<(), String> {
    // Sweep parameters are themselves named by key paths: the rest is one key.
    let segments: Vec<&str> = match path.strip_prefix("sweep.parameters.") {
        Some(key) => vec!["sweep", "parameters", key],
        None => path.split('.').collect(),
    };
    if segments.iter().any(|s| s.trim().is_empty()) {
        return Err(format!(
            "`{path}` is not a key path; write keys separated by dots, e.g. `scene.piston.mass`"
        ));
    }
    let (last, parents) = segments.split_last().ok_or("empty key path")?;
    let mut slot = Slot::Table(doc);
    let mut walked = String::new();
    for segment in parents {
        slot = slot.child(segment, &walked)?;
        if !walked.is_empty() {
            walked.push('.');
        }
        walked.push_str(segment);
    }
    slot.set(last, &walked, value)
}

/// A container being walked by `apply_overrides`.
enum Slot<'a> {
    Table(&'a mut toml::Table),
    Array(&'a mut Vec<toml::Value>),
}

impl<'a> Slot<'a> {
    fn child(self, segment: &str, walked: &str) -> Result<Slot<'a>, String> {
        let value = match self {
            Slot::Table(t) => t
                .entry(segment.to_string())
                .or_insert_with(|| toml::Value::Table(toml::Table::new())),
            Slot::Array(a) => {
                let len = a.len();
                index(segment, walked, len)
                    .and_then(|i| a.get_mut(i).ok_or_else(|| out_of_range(i, walked, len)))?
            }
        };
        match value {
            toml::Value::Table(t) => Ok(Slot::Table(t)),
            toml::Value::Array(a) => Ok(Slot::Array(a)),
            other => Err(format!(
                "`{}` is a {}, not a table, so it has no key `{segment}`",
                join(walked, segment),
                other.type_str()
            )),
        }
    }

    fn set(self, segment: &str, walked: &str, value: toml::Value) -> Result<(), String> {
        match self {
            Slot::Table(t) => {
                t.insert(segment.to_string(), value);
                Ok(())
            }
            Slot::Array(a) => {
                let len = a.len();
                let i = index(segment, walked, len)?;
                let item = a.get_mut(i).ok_or_else(|| out_of_range(i, walked, len))?;
                *item = value;
                Ok(())
            }
        }
    }
}

fn join(walked: &str, segment: &str) -> String {
    if walked.is_empty() {
        segment.to_string()
    } else {
        format!("{walked}.{segment}")
    }
}

fn index(segment: &str, walked: &str, len: usize) -> Result<usize, String> {
    segment.parse::<usize>().map_err(|_| {
        format!(
            "`{walked}` is a list of {len}; index it by number (`{walked}.0`), not by `{segment}`"
        )
    })
}

fn out_of_range(i: usize, walked: &str, len: usize) -> String {
    format!("`{walked}` has {len} item(s), so index {i} does not exist; use 0..{len}")
}

/// Typed descriptor from a table (overrides applied). No source positions
/// exist for overridden values, so errors carry the key path instead.
pub fn from_table(file: &str, table: &toml::Table) -> Result<Descriptor, DescriptorError> {
    Descriptor::deserialize(toml::Value::Table(table.clone())).map_err(|e| {
        let (message, hints) = explain(e.message());
        hints
            .into_iter()
            .fold(DescriptorError::new(file, message), DescriptorError::hint)
    })
}

/// Semantic checks; errors are placed at their key in the source if present.
fn check(loaded: &Loaded) -> Result<(), DescriptorError> {
    let problem = match validate::descriptor(&loaded.descriptor) {
        Ok(()) => return check_sweep(loaded),
        Err(p) => p,
    };
    // Sweep keys are quoted key paths: locate them as one key.
    let position = match problem.key.strip_prefix("sweep.parameters.") {
        Some(key) => super::locate::position_of_keys(&loaded.text, &["sweep", "parameters", key]),
        None => position_of(&loaded.text, &problem.key),
    };
    let mut err = DescriptorError::new(
        &loaded.file,
        format!("`{}`: {}", problem.key, problem.message),
    )
    .at(position)
    .key(problem.key);
    if let Some(h) = problem.hint {
        err = err.hint(h);
    }
    Err(err)
}

/// Every sweep value must fit its key: apply each alone and check the result.
fn check_sweep(loaded: &Loaded) -> Result<(), DescriptorError> {
    let Some(sweep) = &loaded.descriptor.sweep else {
        return Ok(());
    };
    for (key, values) in &sweep.parameters {
        let place = super::locate::position_of_keys(&loaded.text, &["sweep", "parameters", key]);
        let fail = |message: String| {
            DescriptorError::new(&loaded.file, format!("sweep parameter `{key}`: {message}"))
                .at(place)
                .key(format!("sweep.parameters.{key}"))
        };
        validate::sweep_key(key).map_err(|p| {
            let e = fail(p.message);
            match p.hint {
                Some(h) => e.hint(h),
                None => e,
            }
        })?;
        for value in representatives(values) {
            let mut table = loaded.table.clone();
            apply_overrides(&mut table, key, value.clone()).map_err(&fail)?;
            let shown = show(&value);
            let descriptor = from_table(&loaded.file, &table).map_err(|e| {
                let mut out = fail(format!("value {shown}: {}", e.message));
                out.hints = e.hints;
                out
            })?;
            if let Err(p) = validate::descriptor(&descriptor) {
                let e = fail(format!(
                    "value {shown} makes `{}` invalid: {}",
                    p.key, p.message
                ));
                return Err(match p.hint {
                    Some(h) => e.hint(h),
                    None => e,
                });
            }
        }
    }
    Ok(())
}

/// The values of a sweep parameter worth checking: all of a list; of a
/// (monotonic) range its ends and its first non-whole value, which between
/// them meet every key's type and bounds that the range meets.
fn representatives(values: &super::descriptor_types::SweepValues) -> Vec<toml::Value> {
    let all = super::plan::expand_values(values);
    if matches!(values, super::descriptor_types::SweepValues::List(_)) {
        return all;
    }
    let mut picked: Vec<toml::Value> = all.first().into_iter().chain(all.last()).cloned().collect();
    if let Some(f) = all.iter().find(|v| v.is_float()) {
        picked.push(f.clone());
    }
    picked
}

/// A TOML value as the user would write it.
pub fn show(value: &toml::Value) -> String {
    match value {
        toml::Value::String(s) => format!("{s:?}"),
        other => other.to_string(),
    }
}

fn prefix(mut e: DescriptorError, with: &str) -> DescriptorError {
    e.message = format!("{with}{}", e.message);
    e
}

/// A syntax or shape error from toml/serde, placed and explained.
fn toml_error(file: &str, text: &str, e: &toml::de::Error) -> DescriptorError {
    let (mut message, hints) = explain(e.message());
    let offset = e.span().map(|s| s.start);
    if let Some(path) = offset.and_then(|o| path_at(text, o)) {
        message = match path.rsplit_once('.') {
            // "unknown key `x`" at `a.b.x`: name the table it sits in.
            Some((table, last)) if message.contains(&format!("`{last}`")) => {
                format!("{message} in [{table}]")
            }
            None if message.contains(&format!("`{path}`")) => message,
            _ => format!("`{path}`: {message}"),
        };
    }
    let err = DescriptorError::new(file, message).at(offset.map(|o| line_col(text, o)));
    hints.into_iter().fold(err, DescriptorError::hint)
}

/// Turn serde's terse messages into what a user can act on.
fn explain(raw: &str) -> (String, Vec<String>) {
    let raw = raw.trim();
    let quoted = backticked(raw);
    if let Some(rest) = raw.strip_prefix("unknown field ") {
        let unknown = quoted.first().cloned().unwrap_or_default();
        let valid = &quoted[1.min(quoted.len())..];
        let mut hints = Vec::new();
        if let Some(best) = closest(&unknown, valid) {
            hints.push(format!("did you mean `{best}`?"));
        }
        if rest.contains("there are no fields") || valid.is_empty() {
            hints.push("this table takes no keys".to_string());
        } else {
            hints.push(format!("valid keys here: {}", list(valid)));
        }
        return (format!("unknown key `{unknown}`"), hints);
    }
    if raw.starts_with("unknown variant ") {
        let unknown = quoted.first().cloned().unwrap_or_default();
        let valid = &quoted[1.min(quoted.len())..];
        let mut hints = Vec::new();
        if let Some(best) = closest(&unknown, valid) {
            hints.push(format!("did you mean \"{best}\"?"));
        }
        hints.push(format!("valid values: {}", list(valid)));
        return (format!("unknown value \"{unknown}\""), hints);
    }
    if raw.starts_with("missing field ") {
        let missing = quoted.first().cloned().unwrap_or_default();
        let hint = if missing == "kind" {
            "say which kind, e.g. `kind = \"random\"`".to_string()
        } else {
            format!("add `{missing} = ...` to this table (see docs/descriptor.md)")
        };
        return (format!("missing required key `{missing}`"), vec![hint]);
    }
    if raw.contains("untagged enum SweepValues") {
        return (
            "a sweep parameter must be a list of values or a range".to_string(),
            vec!["write e.g. `[1.0, 2.0, 4.0]` or `{ from = 1.0, to = 100.0, steps = 5, scale = \"log\" }`".to_string()],
        );
    }
    if raw.contains("untagged enum Mass") {
        return (
            "`mass` must be a number or a range `[lo, hi]`".to_string(),
            vec!["write e.g. `mass = 1.0` or `mass = [1.0, 9.0]`".to_string()],
        );
    }
    (humanize_types(raw), Vec::new())
}

/// Serde names Rust types ("expected u32"); users write TOML.
fn humanize_types(raw: &str) -> String {
    let mut s = raw.to_string();
    for (rust, toml) in [
        ("expected f64", "expected a number"),
        ("expected usize", "expected a whole number >= 0"),
        ("expected u64", "expected a whole number >= 0"),
        ("expected u32", "expected a whole number >= 0"),
        ("expected a sequence", "expected a list `[...]`"),
        ("expected a map", "expected a table"),
    ] {
        s = s.replace(rust, toml);
    }
    s
}

fn backticked(s: &str) -> Vec<String> {
    s.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

fn list(items: &[String]) -> String {
    items
        .iter()
        .map(|k| format!("`{k}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The valid name closest to `word`, if it is close enough to be a typo.
pub fn closest(word: &str, valid: &[String]) -> Option<String> {
    let limit = (word.chars().count() / 3).max(2);
    valid
        .iter()
        .map(|v| (edit_distance(&word.to_lowercase(), &v.to_lowercase()), v))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, _)| *d)
        .map(|(_, v)| v.clone())
}

/// Levenshtein distance over chars.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diag = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1)
                .min(row[j] + 1)
                .min(diag + usize::from(ca != *cb));
            diag = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}
