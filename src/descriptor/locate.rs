//! Places in descriptor text: byte offset -> line:col, key path <-> offset.
//! Uses toml's spanned parse tree so messages can point at the exact key.

use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// 1-based line and column (in characters) of byte `offset` in `text`.
pub fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let col = before[line_start..].chars().count() + 1;
    (line, col)
}

/// Line:col of the key at dotted `path` (array items by index), or of its
/// deepest ancestor present in the text; None if the text does not parse.
pub fn position_of(text: &str, path: &str) -> Option<(usize, usize)> {
    position_of_keys(text, &path.split('.').collect::<Vec<_>>())
}

/// Like `position_of` with the keys given one by one, for keys that contain
/// dots themselves (sweep parameters are named by quoted key paths).
pub fn position_of_keys(text: &str, keys: &[&str]) -> Option<(usize, usize)> {
    deepest(text, keys).map(|(_, position)| position)
}

/// How many of `keys` the text has, in order, and the line:col of the last
/// one found; None if the text does not parse or has not even the first.
pub fn deepest(text: &str, keys: &[&str]) -> Option<(usize, (usize, usize))> {
    let root = DeTable::parse(text).ok()?;
    let mut best: Option<usize> = None;
    let mut depth = 0;
    let mut table: Option<&DeTable<'_>> = Some(root.get_ref());
    let mut array: Option<&[Spanned<DeValue<'_>>]> = None;
    for &segment in keys {
        let value = if let Some(t) = table.take() {
            let Some((key, value)) = t.iter().find(|(k, _)| k.get_ref() == segment) else {
                break;
            };
            best = Some(key.span().start);
            depth += 1;
            value
        } else if let Some(items) = array.take() {
            let Some(item) = segment.parse::<usize>().ok().and_then(|i| items.get(i)) else {
                break;
            };
            best = Some(item.span().start);
            depth += 1;
            item
        } else {
            break;
        };
        match value.get_ref() {
            DeValue::Table(t) => table = Some(t),
            DeValue::Array(a) => array = Some(a),
            _ => {}
        }
    }
    best.map(|offset| (depth, line_col(text, offset)))
}

/// Dotted key path of the deepest key or value whose span contains `offset`.
pub fn path_at(text: &str, offset: usize) -> Option<String> {
    let root = DeTable::parse(text).ok()?;
    let mut path = Vec::new();
    walk_table(root.get_ref(), offset, &mut path);
    (!path.is_empty()).then(|| path.join("."))
}

fn walk_table(table: &DeTable<'_>, offset: usize, path: &mut Vec<String>) -> bool {
    for (key, _) in table.iter() {
        if key.span().contains(&offset) {
            path.push(key.get_ref().to_string());
            return true;
        }
    }
    // A `[header]` table's value span does not cover its body, so search
    // every child rather than only the one whose span contains the offset.
    for (key, value) in table.iter() {
        path.push(key.get_ref().to_string());
        if walk_value(value.get_ref(), offset, path) || value.span().contains(&offset) {
            return true;
        }
        path.pop();
    }
    false
}

fn walk_value(value: &DeValue<'_>, offset: usize, path: &mut Vec<String>) -> bool {
    match value {
        DeValue::Table(t) => walk_table(t, offset, path),
        DeValue::Array(items) => items.iter().enumerate().any(|(i, item)| {
            path.push(i.to_string());
            let found = walk_value(item.get_ref(), offset, path) || item.span().contains(&offset);
            if !found {
                path.pop();
            }
            found
        }),
        _ => false,
    }
}
