//! Parse a study descriptor (TOML) into a `Descriptor`, with errors that point
//! at file:line:col, say what is wrong and what would be right.
//!
//! The descriptor is kept twice: as a `toml::Table` (so sweep values, `--quick`
//! and `--replicas` can be applied as key-path overrides) and typed.

use crate::descriptor::check::check;
use crate::descriptor::errors::DescriptorError;
use crate::descriptor::explain::{explain, toml_error};
use crate::model::descriptor::Descriptor;
use serde::Deserialize;
use std::io::Read;
use std::path::Path;

pub use crate::descriptor::explain::{closest, edit_distance};
pub use crate::descriptor::overrides::apply_overrides;

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
    let unreadable = |what: String| {
        DescriptorError::new(&file, what)
            .hint("give the path of a study descriptor, e.g. `studies/piston.toml`; `study list` shows the bundled ones")
    };
    let meta = std::fs::metadata(path)
        .map_err(|e| unreadable(format!("cannot read the descriptor: {e}")))?;
    // A device or a pipe would be read forever; a huge file is not a descriptor.
    if !meta.is_file() {
        return Err(unreadable(
            "is not a regular file (a folder, device or pipe); a descriptor is a TOML file".into(),
        ));
    }
    if meta.len() > MAX_DESCRIPTOR_BYTES {
        return Err(unreadable(format!(
            "is {} bytes; a descriptor is at most {MAX_DESCRIPTOR_BYTES} (sweep with ranges, not long lists)",
            meta.len()
        )));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_DESCRIPTOR_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| unreadable(format!("cannot read the descriptor: {e}")))?;
    if bytes.len() as u64 > MAX_DESCRIPTOR_BYTES {
        return Err(unreadable(format!(
            "grew past {MAX_DESCRIPTOR_BYTES} bytes while being read"
        )));
    }
    let text = utf8(&file, bytes)?;
    parse(&file, &text)
}

/// The descriptor's bytes as text; the first byte that is not UTF-8 is
/// placed at its line:col.
fn utf8(file: &str, bytes: Vec<u8>) -> Result<String, DescriptorError> {
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let before = String::from_utf8_lossy(&bytes[..at]);
        DescriptorError::new(
            file,
            format!(
                "byte 0x{:02X} is not UTF-8 text: a descriptor is TOML, which is UTF-8",
                bytes[at]
            ),
        )
        .at(Some(crate::descriptor::locate::line_col(&before, at)))
        .hint("save the file as UTF-8 (e.g. `iconv -f latin1 -t utf-8`)")
    })
}

/// Largest descriptor read (explicit positions of many particles fit).
pub const MAX_DESCRIPTOR_BYTES: u64 = 16 << 20;

/// Parse and validate descriptor `text`; `file` names it in messages.
pub fn parse(file: &str, text: &str) -> Result<Loaded, DescriptorError> {
    let table: toml::Table = toml::from_str(text).map_err(|e| toml_error(file, text, &e))?;
    crate::descriptor::text::printable(file, text, &table)?;
    let descriptor: Descriptor = toml::from_str(text).map_err(|e| toml_error(file, text, &e))?;
    let loaded = Loaded {
        file: file.to_string(),
        text: text.to_string(),
        table,
        descriptor,
        overrides: Vec::new(),
    };
    check(&loaded)?;
    // `[quick]` is checked now, not first when someone passes --quick.
    let overrides: Vec<_> = loaded.descriptor.quick.clone().into_iter().collect();
    if !overrides.is_empty() {
        apply_all(&loaded, &overrides, QUICK, Some("quick"))?;
    }
    Ok(loaded)
}

/// How messages name the `[quick]` overrides.
const QUICK: &str = "[quick] (applied by --quick)";

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
        source_table
            .and_then(|t| crate::descriptor::locate::position_of_keys(&loaded.text, &[t, path]))
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
        if source_table == Some("quick") {
            crate::descriptor::validate::quick_key(path).map_err(|p| {
                let mut out = fail(p.message);
                out.hints.extend(p.hint);
                out
            })?;
        }
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
    apply_all(loaded, &overrides, QUICK, Some("quick"))
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

/// Typed descriptor from a table (overrides applied). No source positions
/// exist for overridden values, so errors carry the key path instead.
pub fn from_table(file: &str, table: &toml::Table) -> Result<Descriptor, DescriptorError> {
    from_owned_table(file, table.clone())
}

/// `from_table` for a table the caller no longer needs (no copy is made).
pub fn from_owned_table(file: &str, table: toml::Table) -> Result<Descriptor, DescriptorError> {
    Descriptor::deserialize(toml::Value::Table(table)).map_err(|e| {
        let (message, hints) = explain(e.message());
        hints
            .into_iter()
            .fold(DescriptorError::new(file, message), DescriptorError::hint)
    })
}

/// A TOML value as the user would write it.
pub fn show(value: &toml::Value) -> String {
    // A message quotes at most this much of a value: long strings and lists
    // are cut, saying how long they are.
    const LONGEST: usize = 120;
    let text = written(value);
    if text.chars().count() <= LONGEST {
        return text;
    }
    let start: String = text.chars().take(LONGEST - 20).collect();
    format!("{start}… ({} characters)", text.chars().count())
}

fn written(value: &toml::Value) -> String {
    match value {
        toml::Value::String(s) => format!("{s:?}"),
        // `1e-300`, not three hundred digits (Rust's Debug form is valid TOML).
        toml::Value::Float(f) if f.is_finite() => format!("{f:?}"),
        toml::Value::Array(items) => {
            let items: Vec<String> = items.iter().map(written).collect();
            format!("[{}]", items.join(", "))
        }
        other => other.to_string(),
    }
}

fn prefix(mut e: DescriptorError, with: &str) -> DescriptorError {
    e.message = format!("{with}{}", e.message);
    e
}
