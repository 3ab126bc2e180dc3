//! User text as it may be shown: control characters made visible, and
//! Markdown's markup escaped. Names reach messages, plots and report.md
//! from every layer, so the rules live at the bottom.

/// `s` with each control character written as its escape (`\u{1b}`).
pub fn visible(s: &str) -> String {
    s.chars()
        .map(|c| {
            if control(c) {
                c.escape_unicode().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

/// A character no key or string may hold: Unicode's control characters
/// (C0, DEL and C1).
pub fn control(c: char) -> bool {
    c.is_control()
}

/// User text (a description, a name, a value, a message) as Markdown shows
/// it, character for character: one line; each character that Markdown or
/// inline HTML reads as markup backslash-escaped (CommonMark lets any ASCII
/// punctuation be), a heading, quote or list marker at its start too;
/// control characters written as escapes.
pub fn text(s: &str) -> String {
    escaped(s, "")
}

/// `text`, with the characters of `also` escaped too.
pub fn escaped(s: &str, also: &str) -> String {
    let s = visible(&one_line(s));
    let chars: Vec<char> = s.chars().collect();
    let word = |i: Option<usize>| {
        i.and_then(|i| chars.get(i))
            .is_some_and(|c| c.is_alphanumeric())
    };
    // A list marker "12. " or "12) " at the start.
    let digits = chars.iter().take_while(|c| c.is_ascii_digit()).count();
    let marker = digits > 0 && chars.get(digits + 1).is_none_or(|c| c.is_whitespace());
    let mut out = String::with_capacity(s.len());
    for (i, &c) in chars.iter().enumerate() {
        let markup = match c {
            '\\' | '`' | '*' | '[' | ']' | '<' | '>' | '&' | '|' | '~' => true,
            // Intraword underscores (`p_max`) are no emphasis.
            '_' => !(word(i.checked_sub(1)) && word(Some(i + 1))),
            '#' | '-' | '+' | '=' => i == 0,
            '.' | ')' if i == digits && marker => true,
            c => also.contains(c),
        };
        if markup {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

/// Newlines folded to spaces (headings, captions and list items are one line).
pub fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Items of a long list shown before "…" (and the last after it).
pub const LIST_HEAD: usize = 5;

/// A list of `len` items, `item(i)` each, joined by commas: whole if short,
/// else the first `LIST_HEAD`, "…", the last and the count, so that a list
/// of a million values prints a line, not megabytes.
pub fn shortened(len: usize, item: impl Fn(usize) -> String) -> String {
    if len <= 2 * LIST_HEAD {
        return (0..len).map(item).collect::<Vec<_>>().join(", ");
    }
    let head: Vec<String> = (0..LIST_HEAD).map(&item).collect();
    format!("{}, …, {} ({len} values)", head.join(", "), item(len - 1))
}
