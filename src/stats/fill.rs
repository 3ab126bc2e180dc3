//! Prose with numbers in it: a study's methods text lives in Markdown beside
//! the study, with `{name}` where a measured number goes.

/// `text` with each `{key}` replaced by its value. A placeholder without a
/// value is left as it is, so a missing number shows in the report instead
/// of vanishing; a test of each study's text checks none is left.
pub fn fill(text: &str, values: &[(&str, String)]) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        let close = after.find('}');
        let key = close.map(|c| &after[..c]);
        match key.and_then(|k| values.iter().find(|(name, _)| *name == k)) {
            Some((k, v)) => {
                out.push_str(v);
                rest = &after[k.len() + 1..];
            }
            None => {
                out.push('{');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// The `{key}` placeholders `text` still holds after `fill`.
pub fn unfilled(text: &str) -> Vec<&str> {
    let mut keys = Vec::new();
    let mut rest = text;
    while let Some(open) = rest.find('{') {
        rest = &rest[open + 1..];
        match rest.find('}') {
            Some(c)
                if rest[..c]
                    .chars()
                    .all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
                    && c > 0 =>
            {
                keys.push(&rest[..c]);
                rest = &rest[c + 1..];
            }
            _ => {}
        }
    }
    keys
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fills_each_key_and_keeps_the_rest() {
        let v = [("tau", "2.5".to_string()), ("n", "40".to_string())];
        assert_eq!(
            fill("τ = {tau} at N = {n}, {tau}", &v),
            "τ = 2.5 at N = 40, 2.5"
        );
        assert_eq!(fill("a {missing} b", &v), "a {missing} b");
        assert_eq!(fill("set {x: 1} {", &v), "set {x: 1} {");
        assert_eq!(unfilled("a {missing} {x: 1} {tau}"), ["missing", "tau"]);
        assert!(unfilled(&fill("{tau}", &v)).is_empty());
    }
}
