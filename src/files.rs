//! Files written whole or not at all: a temporary sibling, then a rename.
//! The bottom of the crate beside `model`: every layer that writes uses it.

use anyhow::Context;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Write `bytes` to `path` via a temporary sibling and a rename: a reader
/// sees the old file or the new one, never half. Atomic, not synced: a
/// study's outputs are synced once, together, when they are published
/// (`publish.rs`); a run file that a power cut tore does not parse, so it is
/// simply run again, and a sync per run would cost more than many runs.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    write_via_temp(path, |file| {
        file.write_all(bytes)?;
        Ok(())
    })
}

/// `write` fills a fresh temporary file, which is renamed to `path`.
pub fn write_via_temp(
    path: &Path,
    write: impl FnOnce(&mut File) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let tmp = temp_name(path);
    let result = create_new(&tmp)
        .map_err(anyhow::Error::from)
        .and_then(|mut file| write(&mut file))
        .with_context(|| format!("cannot write {}", tmp.display()))
        .and_then(|()| {
            std::fs::rename(&tmp, path)
                .with_context(|| format!("cannot move {} into place", path.display()))
        });
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// A new file at `tmp`. Never an existing one: a link planted there is not
/// followed (`create_new` opens with O_EXCL). A file of that name can only
/// be the leftover of a killed process that had our id, so it goes.
fn create_new(tmp: &Path) -> std::io::Result<File> {
    let open = || File::options().write(true).create_new(true).open(tmp);
    match open() {
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
            std::fs::remove_file(tmp)?;
            open()
        }
        other => other,
    }
}

/// Make renames and removals in `dir` durable (Unix; elsewhere a rename is
/// as durable as the file system makes it).
pub fn sync_dir(dir: &Path) -> anyhow::Result<()> {
    #[cfg(unix)]
    {
        let dir = if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            dir
        };
        File::open(dir)
            .and_then(|d| d.sync_all())
            .with_context(|| format!("cannot sync {}", dir.display()))?;
    }
    #[cfg(not(unix))]
    let _ = dir;
    Ok(())
}

/// `.<name>.<pid>-<n>.tmp` beside `path`: unique per process and write, so
/// two writers never share a temporary file.
pub fn temp_name(path: &Path) -> PathBuf {
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    path.with_file_name(format!(".{name}.{}-{n}{TEMP_SUFFIX}", std::process::id()))
}

const TEMP_SUFFIX: &str = ".tmp";

/// A temporary file of `write_atomic`, by its exact form
/// `.<name>.<digits>-<digits>.tmp`: a user's `notes.tmp` is not one.
pub fn is_temporary(file_name: &str) -> bool {
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    file_name
        .strip_prefix('.')
        .and_then(|r| r.strip_suffix(TEMP_SUFFIX))
        .and_then(|r| r.rsplit_once('.'))
        .and_then(|(name, tag)| Some((name, tag.split_once('-')?)))
        .is_some_and(|(name, (pid, n))| !name.is_empty() && digits(pid) && digits(n))
}
