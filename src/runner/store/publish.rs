//! A finished study's outputs are published as one set, switched in by one
//! atomic rename: a reader of OUT, or OUT after a kill at any instant, finds
//! the previous set whole or the new set whole, never a mix.
//!
//! Layout: each set is a folder `OUT/.outputs-<n>/`; the link `OUT/.outputs`
//! names the current one; each published name at the top of OUT
//! (`OUT/index.html`, `OUT/runs.parquet`, ...) is a link to `.outputs/<name>`,
//! which never changes. Publishing a set:
//! 1. it is written into `OUT/.staging-<pid>/` and each file synced;
//! 2. the staging folder is renamed `.outputs-<n>` (n above any there);
//! 3. each name of the new set gets its link if it has none (until the
//!    switch it resolves in the old set, or nowhere: a name the old set
//!    lacks is absent, as it should be);
//! 4. the switch: a new link renamed over `.outputs`, naming `.outputs-<n>`;
//! 5. the links of names only the old set had (dangling now) and the old
//!    set's folder are removed (`tidy`).
//!
//! A kill before 4 leaves the old set, after it the new one; `tidy`, which
//! every command holding OUT's lock runs first, removes what is left over.
//! An OUT of an older bonkers holds its outputs as plain files: they are
//! first adopted as a set (hard links in a set folder, then each file
//! replaced by its link, its content unchanged), so that switch is atomic
//! too.
//!
//! Ownership: a staging or set folder holds `.bonkers`, which bonkers
//! creates in it first, and which the process that makes it holds locked
//! (flock) while it lives. A folder named like one is removed only if it
//! has that marker and nobody holds it; then only the names a set holds
//! (`published_kind`, temporary files, the marker) are removed, and the
//! folder only once empty: a file someone else put there stays, and so
//! does the folder (`clear`).
//!
//! Test hook: with `BONKERS_PUBLISH_EXIT_AT=k` in the environment the
//! process exits, as a kill would leave OUT, before the k-th change
//! publishing makes (k = 0, 1, ...).

use crate::files::{is_temporary, sync_dir, temp_name};
use crate::runner::store::outdir::{SMALL_LIMIT, open_own, read_own_text};
use anyhow::{Context, bail};
use std::fs::{File, OpenOptions, TryLockError};
use std::io::Write;
use std::path::{Path, PathBuf};

pub const MANIFEST: &str = "manifest.json";

pub const STAGING_PREFIX: &str = ".staging-";

/// The link naming the current set, and the prefix of the sets' folders.
pub const CURRENT: &str = ".outputs";
pub const SET_PREFIX: &str = ".outputs-";

/// Made first in every staging and set folder, and held locked by its maker.
pub const MARKER: &str = ".bonkers";

/// The staging folder of this process; cleared on drop if not published.
#[derive(Debug)]
pub struct Staging {
    dir: PathBuf,
    out: PathBuf,
    /// The marker, locked while this process lives.
    marker: Option<File>,
}

impl Staging {
    pub fn create(out: &Path) -> anyhow::Result<Staging> {
        let dir = out.join(format!("{STAGING_PREFIX}{}", std::process::id()));
        if std::fs::symlink_metadata(&dir).is_ok() {
            clear(&dir)?;
            if std::fs::symlink_metadata(&dir).is_ok() {
                bail!(
                    "cannot stage the outputs in {}: it is there already (another process's, or holding files bonkers did not write); move it away",
                    dir.display()
                );
            }
        }
        std::fs::create_dir(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
        let marker = make_marker(&dir)?;
        marker
            .lock()
            .with_context(|| format!("cannot lock {}", dir.join(MARKER).display()))?;
        Ok(Staging {
            dir,
            out: out.to_path_buf(),
            marker: Some(marker),
        })
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Names of the outputs staged so far, sorted.
    pub fn files(&self) -> anyhow::Result<Vec<String>> {
        let mut names: Vec<String> = std::fs::read_dir(&self.dir)
            .with_context(|| format!("cannot list {}", self.dir.display()))?
            .flatten()
            .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| published_kind(n))
            .collect();
        names.sort();
        Ok(names)
    }

    /// Switch the staged set in (see the module comment).
    pub fn publish(self) -> anyhow::Result<()> {
        let staged = self.files()?;
        for name in &staged {
            let path = self.dir.join(name);
            File::open(&path)
                .and_then(|f| f.sync_all())
                .with_context(|| format!("cannot sync {}", path.display()))?;
        }
        sync_dir(&self.dir)?;
        let out = &self.out;
        let mut steps = Steps::from_env();
        adopt(out, &staged, &mut steps)?;
        let set = format!("{SET_PREFIX}{}", next_id(out)?);
        steps.next();
        std::fs::rename(&self.dir, out.join(&set))
            .with_context(|| format!("cannot move {} into place", self.dir.display()))?;
        sync_dir(out)?;
        for name in &staged {
            link_output(out, name, &mut steps)?;
        }
        sync_dir(out)?;
        switch(out, &set, &mut steps)?;
        tidy_with(out, &mut steps)
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        self.marker.take();
        let _ = clear(&self.dir);
    }
}

/// A name of the kind a study publishes: a table, a plot, the report, the
/// manifest.
pub fn published_kind(name: &str) -> bool {
    let plain = !name.starts_with('.') && !name.contains(['/', '\\']);
    plain
        && (name.ends_with(".parquet")
            || name.ends_with(".svg")
            || ["report.md", "index.html", MANIFEST].contains(&name))
}

/// `.outputs-<digits>`.
pub fn is_set(name: &str) -> bool {
    name.strip_prefix(SET_PREFIX)
        .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}

/// The target of a published name's link.
fn link_target(name: &str) -> PathBuf {
    Path::new(CURRENT).join(name)
}

/// Whether `path` is the link bonkers makes for the output `name`.
fn is_own_link(path: &Path, name: &str) -> bool {
    std::fs::read_link(path).is_ok_and(|t| t == link_target(name))
}

/// The current set's folder name, if `.outputs` is a link to an existing
/// `.outputs-<digits>` folder beside it (anything else names no set).
pub fn current_set(out: &Path) -> Option<String> {
    let target = std::fs::read_link(out.join(CURRENT)).ok()?;
    let name = target.to_str()?;
    let folder = std::fs::symlink_metadata(out.join(name)).is_ok_and(|m| m.is_dir());
    (is_set(name) && folder).then(|| name.to_string())
}

/// One above the largest `n` of the `.outputs-<n>` there (of any kind).
fn next_id(out: &Path) -> anyhow::Result<u64> {
    let entries =
        std::fs::read_dir(out).with_context(|| format!("cannot list {}", out.display()))?;
    let top = entries
        .flatten()
        .filter_map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            is_set(&name)
                .then(|| name[SET_PREFIX.len()..].parse::<u64>().ok())
                .flatten()
        })
        .max()
        .unwrap_or(0);
    Ok(top.saturating_add(1))
}

/// Create the marker in a new folder `dir` (it names the process).
fn make_marker(dir: &Path) -> anyhow::Result<File> {
    let path = dir.join(MARKER);
    let mut file = File::options()
        .read(true)
        .write(true)
        .create_new(true)
        .open(&path)
        .with_context(|| format!("cannot create {}", path.display()))?;
    writeln!(file, "{}", std::process::id())
        .with_context(|| format!("cannot write {}", path.display()))?;
    Ok(file)
}

/// Make `OUT/<name>` the link to `.outputs/<name>`, unless it is already:
/// a new link renamed over whatever is there (a link or a file is replaced,
/// never followed; a folder is refused by the rename).
fn link_output(out: &Path, name: &str, steps: &mut Steps) -> anyhow::Result<()> {
    let path = out.join(name);
    if is_own_link(&path, name) {
        return Ok(());
    }
    replace_with_link(&path, &link_target(name), steps)
}

/// The switch: `.outputs` names `set` from now on.
fn switch(out: &Path, set: &str, steps: &mut Steps) -> anyhow::Result<()> {
    replace_with_link(&out.join(CURRENT), Path::new(set), steps)?;
    sync_dir(out)
}

/// A link to `target` at `path`, made beside it and renamed over it.
fn replace_with_link(path: &Path, target: &Path, steps: &mut Steps) -> anyhow::Result<()> {
    let tmp = temp_name(path);
    let _ = std::fs::remove_file(&tmp);
    steps.next();
    symlink(target, &tmp).with_context(|| format!("cannot create {}", tmp.display()))?;
    steps.next();
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        anyhow::anyhow!("cannot publish {}: {e}", path.display())
    })
}

#[cfg(unix)]
fn symlink(target: &Path, link: &Path) -> std::io::Result<()> {
    std::os::unix::fs::symlink(target, link)
}

#[cfg(windows)]
fn symlink(target: &Path, link: &Path) -> std::io::Result<()> {
    if target.extension().is_some() {
        std::os::windows::fs::symlink_file(target, link)
    } else {
        std::os::windows::fs::symlink_dir(target, link)
    }
}

#[cfg(not(any(unix, windows)))]
fn symlink(_: &Path, _: &Path) -> std::io::Result<()> {
    Err(std::io::ErrorKind::Unsupported.into())
}

/// OUT of an older bonkers (no `.outputs`) with its outputs as plain files:
/// make them the current set, unchanged, before the new one is switched in
/// (`adopt_plain`); then each plain file of a name the current set has is
/// replaced by its link (the same content: this also finishes an adoption
/// a kill interrupted).
fn adopt(out: &Path, staged: &[String], steps: &mut Steps) -> anyhow::Result<()> {
    if std::fs::symlink_metadata(out.join(CURRENT)).is_err() {
        adopt_plain(out, staged, steps)?;
    }
    let Some(set) = current_set(out) else {
        return Ok(());
    };
    let mut names: Vec<String> = std::fs::read_dir(out)
        .with_context(|| format!("cannot list {}", out.display()))?
        .flatten()
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| published_kind(n))
        .filter(|n| std::fs::symlink_metadata(out.join(&set).join(n)).is_ok_and(|m| m.is_file()))
        .collect();
    names.sort();
    for name in &names {
        link_output(out, name, steps)?;
    }
    sync_dir(out)
}

/// The plain outputs as a set: the regular files the older manifest lists
/// (all of a published kind for a manifest without the list), and those
/// the new set replaces, hard-linked (or copied) into a set folder, which
/// `.outputs` then names.
fn adopt_plain(out: &Path, staged: &[String], steps: &mut Steps) -> anyhow::Result<()> {
    let regular = |name: &str| std::fs::symlink_metadata(out.join(name)).is_ok_and(|m| m.is_file());
    let listed = legacy_listed(out);
    let mut names: Vec<String> = std::fs::read_dir(out)
        .with_context(|| format!("cannot list {}", out.display()))?
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| published_kind(n) && regular(n))
        .filter(|n| staged.contains(n) || listed.as_ref().is_some_and(|l| l.accepts(n)))
        .collect();
    names.sort();
    if names.is_empty() {
        return Ok(());
    }
    let set = format!("{SET_PREFIX}{}", next_id(out)?);
    let dir = out.join(&set);
    steps.next();
    std::fs::create_dir(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    make_marker(&dir)?;
    for name in &names {
        let (from, to) = (out.join(name), dir.join(name));
        if std::fs::hard_link(&from, &to).is_err() {
            std::fs::copy(&from, &to).with_context(|| format!("cannot copy {}", from.display()))?;
        }
    }
    sync_dir(&dir)?;
    switch(out, &set, steps)
}

/// What an older manifest says it published.
enum Listed {
    Names(Vec<String>),
    /// A manifest of a bonkers that did not list its outputs: every file of
    /// a published kind was its.
    All,
}

impl Listed {
    fn accepts(&self, name: &str) -> bool {
        match self {
            Listed::Names(names) => names.iter().any(|n| n == name),
            Listed::All => true,
        }
    }
}

/// The outputs the plain `manifest.json` of an older bonkers lists (a file
/// anyone can edit: only names of published kinds count), itself included.
fn legacy_listed(out: &Path) -> Option<Listed> {
    let text = read_own_text(&out.join(MANIFEST), SMALL_LIMIT).ok()?;
    let manifest = serde_json::from_str::<serde_json::Value>(&text).ok()?;
    manifest.get("bonkers_version")?;
    match manifest
        .get("outputs")
        .cloned()
        .and_then(|o| serde_json::from_value::<Vec<String>>(o).ok())
    {
        Some(mut names) => {
            names.push(MANIFEST.to_string());
            Some(Listed::Names(names))
        }
        None => Some(Listed::All),
    }
}

/// Remove what publishing leaves behind: sets other than the current one
/// (`clear`), links of outputs the current set does not have, a `.outputs`
/// naming no set. Only call this holding OUT's lock.
pub fn tidy(out: &Path) -> anyhow::Result<()> {
    tidy_with(out, &mut Steps::default())
}

fn tidy_with(out: &Path, steps: &mut Steps) -> anyhow::Result<()> {
    let current = current_set(out);
    let entries =
        std::fs::read_dir(out).with_context(|| format!("cannot list {}", out.display()))?;
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let path = entry.path();
        if is_set(&name) && current.as_deref() != Some(name.as_str()) {
            steps.next();
            clear(&path)?;
        } else if published_kind(&name) && is_own_link(&path, &name) {
            let present = current.as_ref().is_some_and(|set| {
                std::fs::symlink_metadata(out.join(set).join(&name)).is_ok_and(|m| m.is_file())
            });
            if !present {
                steps.next();
                remove_file(&path)?;
            }
        } else if name == CURRENT
            && current.is_none()
            && entry.file_type().is_ok_and(|t| t.is_symlink())
        {
            steps.next();
            remove_file(&path)?;
        }
    }
    sync_dir(out)
}

/// Remove the staging or set folder `dir` if bonkers made it and no live
/// process holds it (see the module comment); a link of that name is
/// removed, never followed. A folder that stays is said on stderr.
pub fn clear(dir: &Path) -> anyhow::Result<()> {
    let Ok(meta) = std::fs::symlink_metadata(dir) else {
        return Ok(());
    };
    if meta.file_type().is_symlink() {
        return remove_file(dir);
    }
    if !meta.is_dir() {
        return Ok(());
    }
    let shown = dir.display();
    let marker = dir.join(MARKER);
    let Ok(lock) = open_own(&marker, OpenOptions::new().read(true).write(true)) else {
        eprintln!("study: left {shown} in place: bonkers did not make it (it has no {MARKER})");
        return Ok(());
    };
    match lock.try_lock() {
        Ok(()) => {}
        Err(TryLockError::WouldBlock) => return Ok(()),
        Err(TryLockError::Error(e)) => {
            return Err(e).with_context(|| format!("cannot lock {}", marker.display()));
        }
    }
    let mut others = Vec::new();
    for entry in std::fs::read_dir(dir)
        .with_context(|| format!("cannot list {shown}"))?
        .flatten()
    {
        let name = entry.file_name().to_string_lossy().into_owned();
        let folder = entry.file_type().is_ok_and(|t| t.is_dir());
        if name == MARKER {
            continue;
        }
        if !folder && (published_kind(&name) || is_temporary(&name)) {
            remove_file(&entry.path())?;
        } else {
            others.push(name);
        }
    }
    if !others.is_empty() {
        others.sort();
        eprintln!(
            "study: left {shown} in place: it holds files bonkers did not write ({})",
            others.join(", ")
        );
        return Ok(());
    }
    remove_file(&marker)?;
    drop(lock);
    std::fs::remove_dir(dir).with_context(|| format!("cannot remove {shown}"))
}

fn remove_file(path: &Path) -> anyhow::Result<()> {
    match std::fs::remove_file(path) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            Err(e).with_context(|| format!("cannot remove {}", path.display()))
        }
        _ => Ok(()),
    }
}

/// Counts the changes publishing makes, for the test hook (module comment).
#[derive(Debug, Default)]
struct Steps {
    done: usize,
    exit_at: Option<usize>,
}

impl Steps {
    fn from_env() -> Steps {
        Steps {
            done: 0,
            exit_at: std::env::var("BONKERS_PUBLISH_EXIT_AT")
                .ok()
                .and_then(|k| k.parse().ok()),
        }
    }

    /// Before each change.
    fn next(&mut self) {
        if self.exit_at == Some(self.done) {
            std::process::exit(137);
        }
        self.done += 1;
    }
}
