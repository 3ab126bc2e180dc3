//! Who may write into an output directory. A whole `study run` and
//! `study collect` hold an exclusive advisory lock on `OUT/.study.lock`;
//! the parts of a plan (`--shard K/N`, `--runs`) hold it shared, so any
//! number of them can add records side by side while none of them can
//! overlap a whole run or a collect. A shard also holds
//! `OUT/.shard-K-of-N.lock` exclusively, so the same shard never runs twice
//! at once (a requeued array task whose first copy still runs fails fast).
//! Each lock file names the process id of its last exclusive owner. The
//! system drops the locks when the process ends, however it ends, so a
//! killed run leaves nothing to clean up. The files stay: deleting a lock
//! file races with a process about to lock it. flock-style locks also work
//! on NFS and Lustre (Linux emulates them with POSIX locks there).

use crate::runner::store::outdir::open_own;
use anyhow::{Context, anyhow, bail};
use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Seek, Write};
use std::path::{Path, PathBuf};

pub const LOCK_FILE: &str = ".study.lock";

/// Held while a study writes into its output directory.
#[derive(Debug)]
pub struct OutLock {
    _files: Vec<File>,
}

impl OutLock {
    /// The whole directory, for a whole run or a collect.
    pub fn acquire(out_dir: &Path) -> anyhow::Result<OutLock> {
        let path = out_dir.join(LOCK_FILE);
        let mut file = open(&path)?;
        match file.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => bail!(
                "another `study run`{} (or a shard of one) is writing to {}; wait for it to finish, or give this one another --out",
                owner(&mut file),
                out_dir.display()
            ),
            Err(TryLockError::Error(e)) => {
                return Err(e).with_context(|| format!("cannot lock {}", path.display()));
            }
        }
        name_owner(&mut file, &path)?;
        Ok(OutLock { _files: vec![file] })
    }

    /// A part of the plan: shared with other parts; `shard` ("K-of-N")
    /// also locks that shard's own file.
    pub fn shared(out_dir: &Path, shard: Option<&str>) -> anyhow::Result<OutLock> {
        let path = out_dir.join(LOCK_FILE);
        let mut file = open(&path)?;
        match file.try_lock_shared() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => bail!(
                "a whole `study run` or a `study collect`{} is using {}; run this part when it has finished",
                owner(&mut file),
                out_dir.display()
            ),
            Err(TryLockError::Error(e)) => {
                return Err(e).with_context(|| format!("cannot lock {}", path.display()));
            }
        }
        let mut files = vec![file];
        if let Some(shard) = shard {
            let path = shard_lock(out_dir, shard);
            let mut own = open(&path)?;
            match own.try_lock() {
                Ok(()) => {}
                Err(TryLockError::WouldBlock) => bail!(
                    "shard {} is already running{} in {}; it goes on there, so this copy stops",
                    shard.replace("-of-", "/"),
                    owner(&mut own),
                    out_dir.display()
                ),
                Err(TryLockError::Error(e)) => {
                    return Err(e).with_context(|| format!("cannot lock {}", path.display()));
                }
            }
            name_owner(&mut own, &path)?;
            files.push(own);
        }
        Ok(OutLock { _files: files })
    }
}

/// `OUT/.shard-K-of-N.lock`.
pub fn shard_lock(out_dir: &Path, shard: &str) -> PathBuf {
    out_dir.join(format!(".shard-{shard}.lock"))
}

/// The process holding a shard's lock, if one does: its id, or "" if the
/// file does not name it. None when nobody holds it (or it cannot be read).
pub fn holder(path: &Path) -> Option<String> {
    let mut file = open_own(path, OpenOptions::new().read(true)).ok()?;
    match file.try_lock_shared() {
        Err(TryLockError::WouldBlock) => {
            let mut pid = String::new();
            let _ = file.read_to_string(&mut pid);
            Some(pid.trim().to_string())
        }
        _ => None,
    }
}

/// The lock file at `path`, created if need be; a link there is not
/// followed (the lock would write its process id where it points), nor is
/// anything but a regular file used (`outdir::check` refuses both first).
fn open(path: &Path) -> anyhow::Result<File> {
    let mut options = OpenOptions::new();
    options.read(true).write(true).create(true).truncate(false);
    open_own(path, &options).map_err(|e| anyhow!("cannot use the lock file: {e}"))
}

/// " (process 123)" as the lock file says, or "".
fn owner(file: &mut File) -> String {
    let mut owner = String::new();
    let _ = file.read_to_string(&mut owner);
    match owner.trim() {
        "" => String::new(),
        pid => format!(" (process {pid})"),
    }
}

fn name_owner(file: &mut File, path: &Path) -> anyhow::Result<()> {
    file.set_len(0)
        .and_then(|()| file.rewind())
        .and_then(|()| writeln!(file, "{}", std::process::id()))
        .with_context(|| format!("cannot write {}", path.display()))
}
