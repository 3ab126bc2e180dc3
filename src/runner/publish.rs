//! A finished study's outputs are published as one set. Everything is written
//! into a staging folder `OUT/.staging-<pid>/` and synced to disk; then the previous
//! `manifest.json` is removed, the new files are moved into OUT, outputs of
//! an earlier study that this one did not make are deleted, and the new
//! `manifest.json`, which lists the set, comes last. So OUT never holds a
//! manifest beside files it does not describe, and never a stale table or
//! plot beside a new report.

use crate::files::{is_temporary, sync_dir};
use crate::runner::outdir::SMALL_LIMIT;
use anyhow::Context;
use std::fs::File;
use std::path::{Path, PathBuf};

pub const MANIFEST: &str = "manifest.json";

pub const STAGING_PREFIX: &str = ".staging-";

/// Tables a study writes (some only when it has the data).
const TABLES: [&str; 4] = [
    "runs.parquet",
    "series.parquet",
    "histograms.parquet",
    "summary.parquet",
];

/// The staging folder of this process; removed on drop if not published.
#[derive(Debug)]
pub struct Staging {
    dir: PathBuf,
    out: PathBuf,
}

impl Staging {
    pub fn create(out: &Path) -> anyhow::Result<Staging> {
        let dir = out.join(format!("{STAGING_PREFIX}{}", std::process::id()));
        // A link of this name is removed, never followed.
        if std::fs::symlink_metadata(&dir).is_ok() {
            std::fs::remove_dir_all(&dir)
                .with_context(|| format!("cannot remove {}", dir.display()))?;
        }
        std::fs::create_dir(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
        Ok(Staging {
            dir,
            out: out.to_path_buf(),
        })
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Names of the files staged so far, sorted.
    pub fn files(&self) -> anyhow::Result<Vec<String>> {
        let mut names: Vec<String> = std::fs::read_dir(&self.dir)
            .with_context(|| format!("cannot list {}", self.dir.display()))?
            .flatten()
            .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| !is_temporary(n))
            .collect();
        names.sort();
        Ok(names)
    }

    /// Move the staged set into OUT (see the module comment).
    pub fn publish(self) -> anyhow::Result<()> {
        let staged = self.files()?;
        for name in &staged {
            let path = self.dir.join(name);
            File::open(&path)
                .and_then(|f| f.sync_all())
                .with_context(|| format!("cannot sync {}", path.display()))?;
        }
        let previous = previous_outputs(&self.out);
        remove_if_present(&self.out.join(MANIFEST))?;
        sync_dir(&self.out)?;
        for name in staged.iter().filter(|n| *n != MANIFEST) {
            move_into(&self.dir, &self.out, name)?;
        }
        for name in previous.iter().filter(|n| !staged.contains(n)) {
            remove_if_present(&self.out.join(name))?;
        }
        if staged.iter().any(|n| n == MANIFEST) {
            move_into(&self.dir, &self.out, MANIFEST)?;
        }
        sync_dir(&self.out)
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

/// The files the previous study published in OUT: as its manifest lists
/// them; for a manifest of an earlier bonkers without the list, its tables,
/// plots and report; with no manifest, only the table names.
fn previous_outputs(out: &Path) -> Vec<String> {
    let manifest = out.join(MANIFEST);
    let Ok(text) = crate::runner::outdir::read_own_text(&manifest, SMALL_LIMIT) else {
        return TABLES.iter().map(|s| s.to_string()).collect();
    };
    let listed = serde_json::from_str::<serde_json::Value>(&text)
        .ok()
        .and_then(|m| m.get("outputs").cloned())
        .and_then(|o| serde_json::from_value::<Vec<String>>(o).ok());
    let names = listed.unwrap_or_else(|| {
        std::fs::read_dir(out)
            .map(|it| {
                it.flatten()
                    .map(|e| e.file_name().to_string_lossy().into_owned())
                    .filter(|n| {
                        n.ends_with(".svg")
                            || TABLES.contains(&n.as_str())
                            || n == "report.md"
                            || n == "index.html"
                    })
                    .collect()
            })
            .unwrap_or_default()
    });
    // A manifest is a file anyone can edit: only plain names in OUT itself,
    // of the kinds a study publishes.
    names
        .into_iter()
        .filter(|n| !n.is_empty() && !n.contains(['/', '\\']) && n != ".." && n != ".")
        .filter(|n| published_kind(n))
        .collect()
}

/// A name of the kind a study publishes: a table, a plot, the report.
fn published_kind(name: &str) -> bool {
    name.ends_with(".parquet")
        || name.ends_with(".svg")
        || ["report.md", "index.html", MANIFEST].contains(&name)
}

fn move_into(from: &Path, to: &Path, name: &str) -> anyhow::Result<()> {
    std::fs::rename(from.join(name), to.join(name))
        .with_context(|| format!("cannot move {name} into {}", to.display()))
}

fn remove_if_present(path: &Path) -> anyhow::Result<()> {
    match std::fs::remove_file(path) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            Err(e).with_context(|| format!("cannot remove {}", path.display()))
        }
        _ => Ok(()),
    }
}
