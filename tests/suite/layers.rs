//! The import rule of docs/design.md: every module imports only modules
//! below it in the layer order. Read from the source: each `crate::<module>`
//! path a file names (in `use` lines or inline), outside comments.

use std::path::{Path, PathBuf};

/// Bottom to top; modules on one line are one layer and may not import
/// each other (`model`, `files` and `pages` import nothing at all).
const LAYERS: &[&[&str]] = &[
    &["model", "files", "pages"],
    &["engine"],
    &["theory"],
    &["scene"],
    &["observe"],
    &["stats"],
    &["studies"],
    &["report"],
    &["descriptor"],
    &["runner"],
    &["cli"],
];

fn layer(module: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&module))
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("src is readable") {
        let path = entry.expect("directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The top-level module a source file belongs to (`src/runner/plan/mod.rs` ->
/// `runner`, `src/cli.rs` -> `cli`); None for the crate root and the binary.
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).ok()?;
    let first = rel.components().next()?.as_os_str().to_str()?;
    let name = first.strip_suffix(".rs").unwrap_or(first);
    (!matches!(name, "lib" | "main")).then(|| name.to_string())
}

/// Modules named as `crate::<name>` in code (line comments dropped).
fn imports(text: &str) -> Vec<(usize, String)> {
    names_after(text, "crate::")
}

/// Each name that follows `prefix` in code (line comments dropped), with
/// its line number.
fn names_after(text: &str, prefix: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(i) = rest.find(prefix) {
            let after = &rest[i + prefix.len()..];
            let name: String = after
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                found.push((n + 1, name));
            }
            rest = after;
        }
    }
    found
}

/// Study folders named by a file of the folder `own`: through the crate
/// root, or through `super` up to `src/studies/` (one step from a folder's
/// `mod.rs`, two from its other files).
fn other_studies(text: &str, own: &str, is_mod: bool, folders: &[String]) -> Vec<(usize, String)> {
    let up = if is_mod { "super::" } else { "super::super::" };
    let mut named = names_after(text, "crate::studies::");
    named.extend(
        names_after(text, up)
            .into_iter()
            .filter(|(_, n)| n != "super"),
    );
    named
        .into_iter()
        .filter(|(_, name)| name != own && folders.contains(name))
        .collect()
}

#[test]
fn no_study_folder_reaches_into_another() {
    let studies = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/studies");
    let mut folders: Vec<String> = std::fs::read_dir(&studies)
        .expect("src/studies is readable")
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.is_dir())
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    folders.sort();
    assert!(folders.len() > 5, "only {folders:?} under src/studies");
    let mut wrong = Vec::new();
    for own in &folders {
        let mut files = Vec::new();
        rust_files(&studies.join(own), &mut files);
        for file in &files {
            let text = std::fs::read_to_string(file).expect("source is readable");
            let is_mod = file.file_name().is_some_and(|n| n == "mod.rs");
            for (line, other) in other_studies(&text, own, is_mod, &folders) {
                wrong.push(format!(
                    "{}:{line}: `{own}` reaches into `{other}`",
                    file.display()
                ));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "study folders that import another (shared code belongs in stats):\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_folder_rule_sees_every_way_across() {
    let folders = ["heat".to_string(), "mixing".to_string()];
    let text = "use crate::studies::mixing::line;\nuse super::super::mixing::X;\nuse super::heat;";
    let from_file = other_studies(text, "heat", false, &folders);
    assert_eq!(
        from_file,
        vec![(1, "mixing".to_string()), (2, "mixing".to_string())]
    );
    let from_mod = other_studies(
        "use super::mixing; use super::Study;",
        "heat",
        true,
        &folders,
    );
    assert_eq!(from_mod, vec![(1, "mixing".to_string())]);
    assert!(other_studies("use crate::studies::heat::X;", "heat", false, &folders).is_empty());
}

#[test]
fn imports_point_down_the_layers() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files.sort();
    let mut wrong = Vec::new();
    let mut checked = 0;
    for file in &files {
        let Some(module) = module_of(&src, file) else {
            continue;
        };
        let own = layer(&module)
            .unwrap_or_else(|| panic!("{}: module `{module}` is in no layer", file.display()));
        let text = std::fs::read_to_string(file).expect("source is readable");
        for (line, target) in imports(&text) {
            checked += 1;
            if target == module {
                continue;
            }
            let ok = match layer(&target) {
                Some(l) => l < own,
                None => false,
            };
            if !ok {
                wrong.push(format!(
                    "{}:{line}: `{module}` imports `crate::{target}`",
                    file.display()
                ));
            }
        }
    }
    assert!(
        checked > 100,
        "only {checked} imports found: is src/ there?"
    );
    assert!(
        wrong.is_empty(),
        "imports that point up the layers (or across one):\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_rule_sees_an_upward_import() {
    let found = imports("use crate::runner::plan; // crate::cli\nlet x = crate::model::X;");
    assert_eq!(
        found,
        vec![(1, "runner".to_string()), (2, "model".to_string())]
    );
    assert!(layer("runner") > layer("studies"));
}
