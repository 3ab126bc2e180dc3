//! The report's contents list and the anchors its links point to. Anchors
//! follow GitHub's rule for headings (lower case, punctuation dropped,
//! spaces as hyphens, a repeat numbered), so the links work in report.md on
//! a forge and in index.html alike.

use std::collections::HashMap;
use std::fmt::Write;

/// The anchors of a page's headings, handed out in page order.
#[derive(Default)]
pub struct Anchors(HashMap<String, usize>);

impl Anchors {
    /// The anchor of the next heading, whose Markdown text is `heading`.
    pub fn next(&mut self, heading: &str) -> String {
        let slug = slug(heading);
        let seen = self.0.entry(slug.clone()).or_insert(0);
        *seen += 1;
        match *seen {
            1 => slug,
            n => format!("{slug}-{}", n - 1),
        }
    }
}

/// GitHub's anchor of a heading: its visible text (escapes and code or
/// emphasis marks dropped) in lower case, letters, digits, `-` and `_`
/// kept, spaces as hyphens.
fn slug(heading: &str) -> String {
    let mut out = String::new();
    let mut chars = heading.chars().peekable();
    while let Some(c) = chars.next() {
        let c = match c {
            '\\' => match chars.next() {
                Some(escaped) => escaped,
                None => break,
            },
            c => c,
        };
        if c == ' ' {
            out.push('-');
        } else if c.is_alphanumeric() || c == '-' || c == '_' {
            out.extend(c.to_lowercase());
        }
    }
    out
}

/// (level, text) of a Markdown heading line.
pub fn heading(line: &str) -> Option<(usize, &str)> {
    let t = line.trim();
    let level = t.chars().take_while(|&c| c == '#').count();
    let rest = t.get(level..)?;
    ((1..=6).contains(&level) && rest.starts_with(' ')).then(|| (level, rest.trim()))
}

/// The headings of `md` outside fenced code, in order.
fn headings(md: &str) -> Vec<(usize, &str)> {
    let mut fenced = false;
    let mut found = Vec::new();
    for line in md.lines() {
        if line.trim().starts_with("```") {
            fenced = !fenced;
        } else if let Some(h) = heading(line).filter(|_| !fenced) {
            found.push(h);
        }
    }
    found
}

/// Under its own heading, a list of the sections of `after` (levels 2 and 3, each section's
/// subsections on its line), linked to the anchors the page gives them
/// when `before` stands above `after`.
pub fn contents(before: &str, after: &str) -> String {
    let mut anchors = Anchors::default();
    let mut md = String::from("## Contents\n");
    for (_, text) in headings(&(before.to_string() + &md)) {
        anchors.next(text);
    }
    let mut subsections = 0;
    for (level, text) in headings(after) {
        let link = format!("[{text}](#{})", anchors.next(text));
        match level {
            2 => {
                let _ = write!(md, "\n- {link}");
                subsections = 0;
            }
            3 => {
                md += if subsections == 0 { ": " } else { " · " };
                md += &link;
                subsections += 1;
            }
            _ => {}
        }
    }
    md + "\n\n"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn anchors_are_githubs() {
        let mut a = Anchors::default();
        assert_eq!(
            a.next("Piston: oscillation and dissipation"),
            "piston-oscillation-and-dissipation"
        );
        assert_eq!(
            a.next("MacKay's case: at what frequency?"),
            "mackays-case-at-what-frequency"
        );
        assert_eq!(a.next("The dimple in P(v₁)"), "the-dimple-in-pv₁");
        assert_eq!(a.next("`rod\\_piston` 1D"), "rod_piston-1d");
        assert_eq!(
            a.next("How each number is measured"),
            "how-each-number-is-measured"
        );
        assert_eq!(
            a.next("How each number is measured"),
            "how-each-number-is-measured-1"
        );
    }

    #[test]
    fn sections_list_their_subsections() {
        let before = "# study\n\n## Findings\n";
        let after = "## A\n\n### B\n\n```\n## not a heading\n```\n### B\n\n## Findings\n";
        assert_eq!(
            contents(before, after),
            "## Contents\n\n- [A](#a): [B](#b) · [B](#b-1)\n- [Findings](#findings-1)\n\n"
        );
    }
}
