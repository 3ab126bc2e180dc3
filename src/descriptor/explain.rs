//! toml and serde errors turned into what a user can act on: placed at
//! line:col, the table named, Rust types said in TOML words, and the closest
//! valid name offered ("did you mean").

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::locate::{line_col, path_at};

/// A syntax or shape error from toml/serde, placed and explained.
pub fn toml_error(file: &str, text: &str, e: &toml::de::Error) -> DescriptorError {
    let (mut message, mut hints) = explain(e.message());
    let spanned = e.span().and_then(|s| text.get(s)).map(str::trim);
    // Say which key, and what a "map" was (toml reads a date-time as one).
    if message == "duplicate key"
        && let Some(key) = spanned
    {
        message = format!("duplicate key `{key}`: it is set twice in the same table");
        hints.push(format!("keep one `{key} = ...`"));
    }
    if message.starts_with("invalid type: map")
        && let Some(date) = spanned.filter(|s| s.parse::<toml::value::Datetime>().is_ok())
    {
        message = message.replacen("map", &format!("date-time {date}"), 1);
    }
    if e.span().is_none() && message.contains("recursion") {
        return nested_too_deeply(file, text);
    }
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

/// toml gives up on deep nesting without saying where: point at the first
/// line nested deepest (a `[a.b.c...]` header's dots, or brackets open).
fn nested_too_deeply(file: &str, text: &str) -> DescriptorError {
    let depth = |line: &str| {
        let line = line.trim_start();
        if line.starts_with('[') && !line.starts_with("[[") {
            return line.split('#').next().unwrap_or("").matches('.').count() + 1;
        }
        let (mut open, mut deepest) = (0usize, 0usize);
        for c in line.chars() {
            match c {
                '[' | '{' => open += 1,
                ']' | '}' => open = open.saturating_sub(1),
                _ => {}
            }
            deepest = deepest.max(open);
        }
        deepest
    };
    let (line, levels) = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, depth(l)))
        .fold((1, 0), |best, x| if x.1 > best.1 { x } else { best });
    DescriptorError::new(
        file,
        format!("nested too deeply ({levels} levels): more than the TOML reader follows"),
    )
    .at(Some((line, 1)))
    .hint("a descriptor's tables and lists are a few levels deep; see docs/descriptor.md")
}

/// Turn serde's terse messages into what a user can act on.
pub fn explain(raw: &str) -> (String, Vec<String>) {
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
    if raw.contains("untagged enum Drawn") {
        return (
            "must be a number or a range `[lo, hi]` of two numbers".to_string(),
            vec!["write e.g. `mass = 1.0` or `mass = [1.0, 9.0]` (`radius` likewise)".to_string()],
        );
    }
    (humanize_types(raw), Vec::new())
}

/// Serde names Rust types ("expected u32"); users write TOML.
fn humanize_types(raw: &str) -> String {
    let mut s = raw.to_string();
    for (rust, toml) in [
        ("expected f64", "expected a number"),
        // TOML integers stop at 2^63 - 1, below usize's and u64's limits.
        (
            "expected usize",
            "expected a whole number from 0 to 9223372036854775807",
        ),
        (
            "expected u64",
            "expected a whole number from 0 to 9223372036854775807",
        ),
        (
            "expected u32",
            "expected a whole number from 0 to 4294967295",
        ),
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
