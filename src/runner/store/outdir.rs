//! What bonkers touches in an output folder (OUT), and how it reads there.
//!
//! An output folder may be shared with the user's own files, and anyone who
//! can write into it can plant links. So bonkers:
//! - writes only names it makes itself: `.study.lock`, `.shard-K-of-N.lock`,
//!   `.study.json`, `runs/` with `run-<digits>.json` and `run-<digits>.ckpt`
//!   in it, `slurm/`, `.staging-<digits>/`, `.outputs` and `.outputs-<n>/`,
//!   its temporary files `.<name>.<digits>-<digits>.tmp`, and the outputs a
//!   study publishes (tables, plots, report, `manifest.json`: `publish.rs`);
//! - takes a folder as a study's only if bonkers marked it so: its
//!   `.study.json` (every `study run` writes one before it runs), or the
//!   `manifest.json` of a bonkers from before `.study.json`; a name pattern
//!   is no proof. Any other non-empty folder (bar one holding only the
//!   locks bonkers leaves) is refused unless the user says `--force`
//!   (`check`);
//! - removes only its own leftovers, by exact name: temporary files, and
//!   staging and set folders only if they hold the marker bonkers made in
//!   them and no live process holds it, and then only the names it wrote
//!   there (`publish::clear`); records and checkpoints of runs a plan does
//!   not have only with `--prune` (`run.rs`);
//! - never follows a symbolic link inside OUT: a link where a folder or lock
//!   of its own belongs is refused, a link where a file it replaces belongs
//!   (a record, a checkpoint, a table) is replaced by a rename, never written
//!   through; files are read with no-follow opens and a size limit
//!   (`read_own`), so a link to `/dev/zero` or a pipe cannot hang a run.
//!   (The published names are bonkers' own links into the current set:
//!   `publish.rs`.)

use crate::descriptor::errors::DescriptorError;
use crate::files::is_temporary;
use crate::runner::plan::origin::ORIGIN_FILE;
use crate::runner::store::lock::LOCK_FILE;
use crate::runner::store::publish::{self, CURRENT, MANIFEST, STAGING_PREFIX};
use anyhow::Context;
use std::fs::{File, OpenOptions};
use std::io::Read;
use std::path::Path;

/// The folder of run records and checkpoints, and of the Slurm scripts.
pub const RUNS: &str = "runs";
pub const SLURM: &str = "slurm";

/// Larger than any record bonkers writes (series are thinned to 4000
/// points per run), small enough to read into memory.
pub const RECORD_LIMIT: u64 = 1 << 30;
/// `.study.json`, `manifest.json`, the Slurm scripts.
pub const SMALL_LIMIT: u64 = 64 << 20;
/// A checkpoint holds the whole engine state: particles times ~100 bytes.
pub const CHECKPOINT_LIMIT: u64 = 16 << 30;

fn digits(s: &str) -> bool {
    !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit())
}

/// `run-<digits>.json`: a run record.
pub fn is_record(name: &str) -> bool {
    name.strip_prefix("run-")
        .and_then(|n| n.strip_suffix(".json"))
        .is_some_and(digits)
}

/// `run-<digits>.ckpt`: a run's checkpoint.
pub fn is_checkpoint(name: &str) -> bool {
    name.strip_prefix("run-")
        .and_then(|n| n.strip_suffix(".ckpt"))
        .is_some_and(digits)
}

/// A name bonkers makes in `OUT/runs/`: a record, a checkpoint, or a
/// temporary file of one.
pub fn is_run_file(name: &str) -> bool {
    is_record(name) || is_checkpoint(name) || is_temporary(name)
}

/// `.staging-<digits>`: the staging folder of a process (`publish.rs`).
pub fn is_staging(name: &str) -> bool {
    name.strip_prefix(STAGING_PREFIX).is_some_and(digits)
}

/// `.shard-K-of-N.lock`.
fn is_shard_lock(name: &str) -> bool {
    name.strip_prefix(".shard-")
        .and_then(|n| n.strip_suffix(".lock"))
        .and_then(|n| n.split_once("-of-"))
        .is_some_and(|(k, n)| digits(k) && digits(n))
}

/// Names of OUT's own folders and locks: a link there is refused, since
/// bonkers would write through it.
fn is_structural(name: &str) -> bool {
    [LOCK_FILE, ORIGIN_FILE, RUNS, SLURM].contains(&name) || is_shard_lock(name)
}

/// A lock file as bonkers leaves one: a small regular file of a lock's name
/// (it holds a process id). A folder holding only these is as good as
/// empty: bonkers deletes nothing there, and a lock keeps its file.
fn is_own_lock(out: &Path, name: &str) -> bool {
    (name == LOCK_FILE || is_shard_lock(name))
        && std::fs::symlink_metadata(out.join(name)).is_ok_and(|m| m.is_file() && m.len() <= 64)
}

/// Check OUT before a command writes there: no links where its own folders
/// and locks belong, no folder where a record belongs, and, unless `force`,
/// no non-empty folder that is not a study's output (see the module
/// comment). A folder that does not exist yet is fine.
pub fn check(out: &Path, force: bool) -> Result<(), DescriptorError> {
    let names = match std::fs::read_dir(out) {
        Ok(entries) => entries
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect::<Vec<_>>(),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(_) if out.exists() && !out.is_dir() => {
            return Err(
                refuse(out, "is not a folder").hint("give a folder (new or empty) as --out")
            );
        }
        Err(e) => return Err(refuse(out, &format!("cannot be listed: {e}"))),
    };
    for name in names.iter().filter(|n| is_structural(n)) {
        let path = out.join(name);
        let Ok(meta) = std::fs::symlink_metadata(&path) else {
            continue;
        };
        if meta.file_type().is_symlink() {
            return Err(link(&path));
        }
        let folder = name == RUNS || name == SLURM;
        if folder != meta.is_dir() || !(folder || meta.is_file()) {
            let what = if folder {
                "is not a folder: bonkers keeps its own files there"
            } else {
                "is not a regular file: bonkers keeps its own state there"
            };
            return Err(refuse(&path, what).hint("move it away, or give another --out"));
        }
    }
    let current = out.join(CURRENT);
    if std::fs::symlink_metadata(&current).is_ok_and(|m| !m.file_type().is_symlink()) {
        return Err(refuse(
            &current,
            "is not the link bonkers keeps there (to the current set of outputs)",
        )
        .hint("move it away, or give another --out"));
    }
    check_runs(&out.join(RUNS))?;
    if force || is_study_output(out) {
        return Ok(());
    }
    let mut foreign: Vec<&String> = names.iter().filter(|n| !is_own_lock(out, n)).collect();
    if foreign.is_empty() {
        return Ok(());
    }
    foreign.sort();
    let shown: Vec<String> = foreign.iter().take(3).map(|n| format!("`{n}`")).collect();
    let more = match foreign.len() {
        n if n > 3 => format!(" and {} more", n - 3),
        _ => String::new(),
    };
    Err(refuse(
        out,
        &format!(
            "is not empty and is not the output folder of a study (it has no {ORIGIN_FILE}, which every study writes first): it holds {}{more}",
            shown.join(", ")
        ),
    )
    .hint("give a new or empty --out, or pass --force to write there anyway: bonkers then writes only names it makes itself and removes nothing it did not write (docs/descriptor.md, \"What bonkers touches in OUT\")"))
}

/// No folder where a record or checkpoint belongs: bonkers would neither
/// replace nor remove it, so its run could never be saved.
fn check_runs(runs: &Path) -> Result<(), DescriptorError> {
    let Ok(entries) = std::fs::read_dir(runs) else {
        return Ok(());
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if (is_record(&name) || is_checkpoint(&name)) && entry.file_type().is_ok_and(|t| t.is_dir())
        {
            return Err(refuse(
                &entry.path(),
                "is a folder named like a run's file; bonkers neither replaces nor removes it",
            )
            .hint("move it away (its run is then made again), or give another --out"));
        }
    }
    Ok(())
}

/// A study made OUT: it has a `.study.json` (every `study run` writes one
/// first), or the `manifest.json` of a bonkers that wrote none.
fn is_study_output(out: &Path) -> bool {
    let regular = |name: &str| {
        std::fs::symlink_metadata(out.join(name)).is_ok_and(|m| m.file_type().is_file())
    };
    if regular(ORIGIN_FILE) {
        return true;
    }
    read_own(&out.join(MANIFEST), SMALL_LIMIT)
        .ok()
        .and_then(|bytes| serde_json::from_slice::<serde_json::Value>(&bytes).ok())
        .is_some_and(|m| m.get("bonkers_version").is_some())
}

fn refuse(path: &Path, what: &str) -> DescriptorError {
    DescriptorError::new(&path.display().to_string(), what)
}

fn link(path: &Path) -> DescriptorError {
    refuse(
        path,
        "is a symbolic link; bonkers never follows links inside its output folder (it would write or delete where the link points)",
    )
    .hint(format!(
        "remove the link (`rm {}`), or give another --out",
        crate::runner::pipeline::shell_word(&path.to_string_lossy())
    ))
}

/// Why a file of OUT cannot be read as one of bonkers' own.
#[derive(Debug)]
pub enum Unusable {
    Missing,
    /// The path and what is wrong, e.g. "OUT/runs/run-5.json is a symbolic link".
    Refused(String),
}

impl std::fmt::Display for Unusable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unusable::Missing => f.write_str("no such file"),
            Unusable::Refused(why) => f.write_str(why),
        }
    }
}

/// Set no-follow on `options` (and non-blocking, so opening a pipe does not
/// wait for a writer): opening a symbolic link then fails.
pub fn no_follow(options: &mut OpenOptions) -> &mut OpenOptions {
    #[cfg(unix)]
    {
        use rustix::fs::OFlags;
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags((OFlags::NOFOLLOW | OFlags::NONBLOCK).bits() as i32);
    }
    options
}

/// Open `path` with `options` without following a link in its last
/// component, and insist on a regular file.
pub fn open_own(path: &Path, options: &OpenOptions) -> Result<File, Unusable> {
    let mut options = options.clone();
    let shown = path.display();
    let meta = std::fs::symlink_metadata(path);
    if meta.as_ref().is_ok_and(|m| m.file_type().is_symlink()) {
        return Err(Unusable::Refused(format!(
            "{shown} is a symbolic link, which bonkers does not follow in its output folder"
        )));
    }
    let file = match no_follow(&mut options).open(path) {
        Ok(file) => file,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Err(Unusable::Missing),
        Err(e) => return Err(Unusable::Refused(format!("cannot open {shown}: {e}"))),
    };
    let meta = file
        .metadata()
        .map_err(|e| Unusable::Refused(format!("cannot read {shown}: {e}")))?;
    if meta.is_dir() {
        return Err(Unusable::Refused(format!(
            "{shown} is a folder, not a file"
        )));
    }
    if !meta.is_file() {
        return Err(Unusable::Refused(format!(
            "{shown} is not a regular file (a device, pipe or socket)"
        )));
    }
    Ok(file)
}

/// The bytes of the regular file `path` (a link, folder, device or pipe is
/// refused, so is a file above `limit` bytes).
pub fn read_own(path: &Path, limit: u64) -> Result<Vec<u8>, Unusable> {
    let mut file = open_own(path, OpenOptions::new().read(true))?;
    let too_large = || {
        Unusable::Refused(format!(
            "{} is larger than {} MiB, more than bonkers writes there",
            path.display(),
            limit >> 20
        ))
    };
    let size = file.metadata().map_or(0, |m| m.len());
    if size > limit {
        return Err(too_large());
    }
    let mut bytes = Vec::with_capacity(size as usize);
    (&mut file)
        .take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Unusable::Refused(format!("cannot read {}: {e}", path.display())))?;
    if bytes.len() as u64 > limit {
        return Err(too_large());
    }
    Ok(bytes)
}

/// `read_own` as text.
pub fn read_own_text(path: &Path, limit: u64) -> Result<String, Unusable> {
    String::from_utf8(read_own(path, limit)?)
        .map_err(|_| Unusable::Refused(format!("{} is not UTF-8 text", path.display())))
}

/// Remove what an interrupted or killed run left in OUT: its temporary
/// files and links of a staging folder's name (the link, never what it
/// points at), its staging folders and sets no longer current as
/// `publish::clear` allows, and links of outputs the current set lacks.
/// Only call this holding OUT's lock.
pub fn remove_leftovers(out: &Path) -> anyhow::Result<()> {
    let entries =
        std::fs::read_dir(out).with_context(|| format!("cannot list {}", out.display()))?;
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let path = entry.path();
        let Ok(kind) = entry.file_type() else {
            continue;
        };
        if is_staging(&name) && (kind.is_dir() || kind.is_symlink()) {
            publish::clear(&path)?;
        } else if is_temporary(&name) && !kind.is_dir() {
            remove_if_present(&path)?;
        }
    }
    publish::tidy(out)
}

/// Remove the file (or link) `path`, if there is one.
pub fn remove_if_present(path: &Path) -> anyhow::Result<()> {
    match std::fs::remove_file(path) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            Err(e).with_context(|| format!("cannot remove {}", path.display()))
        }
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_bonkers_makes_are_told_apart_from_others() {
        for ours in ["run-0.json", "run-18446744073709551615.json"] {
            assert!(is_record(ours), "{ours}");
        }
        for other in [
            "run-.json",
            "run-notes.json",
            "run-5.json.bak",
            "run-5.JSON",
        ] {
            assert!(!is_record(other), "{other}");
        }
        assert!(is_checkpoint("run-7.ckpt") && !is_checkpoint("run-7.ckpt.old"));
        assert!(is_staging(".staging-123") && !is_staging(".staging-backup"));
        assert!(is_shard_lock(".shard-2-of-8.lock") && !is_shard_lock(".shard-x-of-8.lock"));
        for ours in [".run-5.json.123-0.tmp", ".summary.parquet.4000000-3.tmp"] {
            assert!(is_run_file(ours) || is_temporary(ours), "{ours}");
        }
        for other in [
            "thesis.tmp",
            "cache.tmp",
            "run-5.json.tmp",
            "..1-2.tmp",
            ".x.1-.tmp",
        ] {
            assert!(!is_temporary(other), "{other}");
        }
    }
}
