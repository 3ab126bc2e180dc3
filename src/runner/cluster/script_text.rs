//! What user text `study slurm` may write into a batch script, and how.
//! A script is read twice: by sbatch, which takes each `#SBATCH` line as
//! options in a syntax of its own (split at blanks; quotes and `\` removed;
//! an unquoted `#` ends the line; `hetjob` or `packjob` anywhere in it
//! splits the job in two; `%` starts a file name pattern in `--output`),
//! and by bash. So a control character is refused anywhere (a newline
//! would end the line and start a command), a path must be UTF-8 (the
//! script is text: a lossy path names another folder) and goes into shell
//! code as one quoted word, and an `#SBATCH` value keeps to an alphabet
//! sbatch reads literally, with `%` doubled in `--output`. Anything else is
//! bad input (exit 2), named by its flag, never echoed raw.

use crate::descriptor::errors::DescriptorError;
use std::path::Path;

/// Bytes of any one value a script holds (Linux's PATH_MAX).
pub const MAX_LEN: usize = 4096;

/// What the `#SBATCH` alphabet refuses in a path, beside control characters.
const NOT_IN_DIRECTIVES: &str = "\"'\\#";

/// Words that split a job wherever they are in an `#SBATCH` line.
const SPLITTERS: [&str; 2] = ["hetjob", "packjob"];

fn refuse(flag: &str, shown: impl std::fmt::Debug, what: String) -> DescriptorError {
    DescriptorError::new(flag, format!("{shown:?} {what}"))
}

/// The first control character of `text` (C0, DEL, C1), as "U+000A at byte 5".
fn control(text: &str) -> Option<String> {
    text.char_indices()
        .find(|(_, c)| c.is_control())
        .map(|(i, c)| format!("U+{:04X} at byte {i}", u32::from(c)))
}

fn splitter(text: &str) -> Option<&'static str> {
    let lower = text.to_ascii_lowercase();
    SPLITTERS.into_iter().find(|w| lower.contains(w))
}

/// `path` as script text: UTF-8, no control character, at most `MAX_LEN`
/// bytes. `flag` names where it came from (`--out`, `FILE`, ...).
pub fn path_text<'a>(flag: &str, path: &'a Path) -> Result<&'a str, DescriptorError> {
    let Some(text) = path.to_str() else {
        return Err(refuse(flag, path, "is not UTF-8 text".into()).hint(
            "the Slurm scripts name this path in text: rename it (or choose another) in UTF-8",
        ));
    };
    if let Some(at) = control(text) {
        return Err(
            refuse(flag, path, format!("has a control character ({at})")).hint(
                "a newline, tab, escape or other control character would break the Slurm script: choose a path without them",
            ),
        );
    }
    if text.len() > MAX_LEN {
        return Err(refuse(
            flag,
            format!("{}...", text.chars().take(60).collect::<String>()),
            format!("is {} bytes long", text.len()),
        )
        .hint(format!(
            "a path in a Slurm script has at most {MAX_LEN} bytes"
        )));
    }
    Ok(text)
}

/// `path` as the start of an `#SBATCH --output=` value: `path_text`, none
/// of the characters sbatch reads in a directive (blanks, quotes, `\`,
/// `#`), no `hetjob`/`packjob`; each `%` doubled, which sbatch's file name
/// pattern turns back into one.
pub fn directive_path(flag: &str, path: &Path) -> Result<String, DescriptorError> {
    let text = path_text(flag, path)?;
    if let Some(c) = text
        .chars()
        .find(|&c| c.is_whitespace() || NOT_IN_DIRECTIVES.contains(c))
    {
        return Err(refuse(
            flag,
            path,
            format!("has {c:?}, which sbatch reads in `#SBATCH --output=` (blanks, quotes, `\\` and `#` are its syntax)"),
        )
        .hint("choose a folder whose path has no blanks, quotes, `\\` or `#`"));
    }
    if let Some(w) = splitter(text) {
        return Err(refuse(
            flag,
            path,
            format!("has `{w}`, which splits a Slurm job wherever it is in an `#SBATCH` line"),
        )
        .hint(format!("choose a folder whose path has no `{w}`")));
    }
    Ok(text.replace('%', "%%"))
}

/// A flag's value for an `#SBATCH` line: ASCII letters and digits and the
/// characters of `also`, at most `MAX_LEN` bytes, no `hetjob`/`packjob`;
/// `example` is a value that would be right.
pub fn directive_value(
    flag: &str,
    value: &str,
    also: &str,
    example: &str,
) -> Result<(), DescriptorError> {
    let allowed = |c: char| c.is_ascii_alphanumeric() || also.contains(c);
    let alphabet = if also.is_empty() {
        "ASCII letters and digits only".to_string()
    } else {
        let extra: Vec<String> = also.chars().map(|c| format!("`{c}`")).collect();
        format!("ASCII letters, digits and {} only", extra.join(" "))
    };
    let hint = format!("{flag} takes {alphabet}, e.g. {flag} {example}");
    if value.is_empty() {
        return Err(refuse(flag, value, "is empty".into()).hint(hint));
    }
    if let Some(at) = control(value) {
        return Err(refuse(flag, value, format!("has a control character ({at})")).hint(hint));
    }
    if let Some(c) = value.chars().find(|&c| !allowed(c)) {
        return Err(refuse(
            flag,
            value,
            format!("has {c:?}, which has no place in an `#SBATCH` line"),
        )
        .hint(hint));
    }
    if value.len() > MAX_LEN {
        let start: String = value.chars().take(60).collect();
        return Err(
            refuse(flag, start, format!("is {} bytes long", value.len()))
                .hint(format!("{flag} has at most {MAX_LEN} bytes")),
        );
    }
    if let Some(w) = splitter(value) {
        return Err(refuse(
            flag,
            value,
            format!("has `{w}`, which splits a Slurm job wherever it is in an `#SBATCH` line"),
        )
        .hint(hint));
    }
    Ok(())
}

/// The Slurm job name for a study name: letters, digits, `_`, `.`, `-`
/// kept (all a valid study name has), anything else `_`, at most 64
/// characters; "study" for a name that leaves nothing or holds `hetjob` or
/// `packjob`. A name, not a flag: made safe here, refused at validate.
pub fn job_name(name: &str) -> String {
    let safe: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "_.-".contains(c) {
                c
            } else {
                '_'
            }
        })
        .take(64)
        .collect();
    if safe.is_empty() || splitter(&safe).is_some() {
        "study".to_string()
    } else {
        safe
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::OsStr;
    use std::os::unix::ffi::OsStrExt;

    #[test]
    fn paths_are_utf8_without_control_characters() {
        assert_eq!(
            path_text("--out", Path::new("/a b/$(x)'")),
            Ok("/a b/$(x)'")
        );
        for bad in [&b"/a\nb"[..], b"/a\rb", b"/a\x1bb", b"/a\x7fb", b"/a\xffb"] {
            let e = path_text("--out", Path::new(OsStr::from_bytes(bad))).unwrap_err();
            assert_eq!(e.file, "--out");
            assert!(!e.message.chars().any(char::is_control), "{e}");
        }
        let long = format!("/{}", "a".repeat(MAX_LEN));
        assert!(path_text("--out", Path::new(&long)).is_err());
    }

    #[test]
    fn directive_paths_double_percent_and_refuse_sbatch_syntax() {
        assert_eq!(
            directive_path("--out", Path::new("/s/50%a/%%")),
            Ok("/s/50%%a/%%%%".to_string())
        );
        assert_eq!(
            directive_path("--out", Path::new("/s/é$x;`y`")),
            Ok("/s/é$x;`y`".into())
        );
        for bad in [
            "/a b",
            "/a\tb",
            "/a'b",
            "/a\"b",
            "/a\\b",
            "/a#b",
            "/my-HetJob",
            "/packjob",
        ] {
            assert!(directive_path("--out", Path::new(bad)).is_err(), "{bad}");
        }
    }

    #[test]
    fn directive_values_keep_to_their_alphabet() {
        assert_eq!(directive_value("--mem", "4G", "", "4G"), Ok(()));
        assert_eq!(
            directive_value("--partition", "a_b-c.d,e", "_-.,", "debug"),
            Ok(())
        );
        for bad in [
            "",
            "4G\ntouch x",
            "4 G",
            "4G;x",
            "$(x)",
            "hetjob",
            "4G#",
            "é",
        ] {
            let e = directive_value("--mem", bad, "", "4G").unwrap_err();
            assert!(e.hints[0].contains("--mem 4G"), "{e}");
            assert!(!e.message.chars().any(char::is_control), "{e}");
        }
    }

    #[test]
    fn job_names_are_made_safe() {
        assert_eq!(job_name("piston-test"), "piston-test");
        assert_eq!(job_name("a b\n$(x)%"), "a_b___x__");
        assert_eq!(job_name(""), "study");
        assert_eq!(job_name("my hetjob"), "study");
        assert_eq!(job_name(&"x".repeat(100)).len(), 64);
    }
}
