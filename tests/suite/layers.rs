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

/// The top-level module a source file belongs to (`src/runner/plan.rs` ->
/// `runner`, `src/cli.rs` -> `cli`); None for the crate root and the binary.
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).ok()?;
    let first = rel.components().next()?.as_os_str().to_str()?;
    let name = first.strip_suffix(".rs").unwrap_or(first);
    (!matches!(name, "lib" | "main")).then(|| name.to_string())
}

/// Modules named as `crate::<name>` in code (line comments dropped).
fn imports(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(i) = rest.find("crate::") {
            let after = &rest[i + "crate::".len()..];
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
