//! Text in a descriptor: every key and string goes into messages, file and
//! column names, SVG plots (XML, which cannot hold most control characters)
//! and report.md (where ESC would reach a terminal). A control character is
//! refused wherever it is, before the typed parse can quote it raw.

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::show;
use crate::descriptor::locate::position_of_keys;
pub use crate::model::text::{control, visible};

/// The first key or string of `table` that holds a control character (the
/// description may break lines and use tabs), placed at its key in `text`.
pub fn printable(file: &str, text: &str, table: &toml::Table) -> Result<(), DescriptorError> {
    let mut path = Vec::new();
    let Some(found) = first_in_table(table, &mut path) else {
        return Ok(());
    };
    let keys: Vec<&str> = path.iter().map(String::as_str).collect();
    let dotted = visible(&keys.join("."));
    let (what, shown, c) = match found {
        Found::Key(k, c) => ("the key", k, c),
        Found::Value(v, c) => ("the text", v, c),
    };
    Err(DescriptorError::new(
        file,
        format!(
            "`{dotted}`: {what} {} holds the control character U+{:04X}; names and \
             text go into file names, plots and the report",
            show(&toml::Value::String(shown)),
            c as u32
        ),
    )
    .at(position_of_keys(text, &keys))
    .key(dotted)
    .hint(
        "remove it: any printable character may be used (docs/descriptor.md, \"Names and text\")",
    ))
}

/// A key or a string and the first control character in it.
enum Found {
    Key(String, char),
    Value(String, char),
}

fn first_in_table(table: &toml::Table, path: &mut Vec<String>) -> Option<Found> {
    for (key, value) in table {
        path.push(key.clone());
        if let Some(c) = key.chars().find(|&c| control(c)) {
            return Some(Found::Key(key.clone(), c));
        }
        if let Some(found) = first_in_value(value, path) {
            return Some(found);
        }
        path.pop();
    }
    None
}

fn first_in_value(value: &toml::Value, path: &mut Vec<String>) -> Option<Found> {
    match value {
        toml::Value::String(s) => {
            // Free text: line breaks and tabs are folded to spaces where it is shown.
            let description = path.len() == 2 && path[0] == "study" && path[1] == "description";
            let bad = |c: char| control(c) && !(description && "\n\r\t".contains(c));
            s.chars()
                .find(|&c| bad(c))
                .map(|c| Found::Value(s.clone(), c))
        }
        toml::Value::Array(items) => items.iter().enumerate().find_map(|(i, item)| {
            path.push(i.to_string());
            let found = first_in_value(item, path);
            if found.is_none() {
                path.pop();
            }
            found
        }),
        toml::Value::Table(t) => first_in_table(t, path),
        _ => None,
    }
}
