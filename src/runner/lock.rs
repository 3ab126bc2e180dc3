//! One `study run` per output directory. The run that owns a directory holds
//! an advisory lock on `OUT/.study.lock` (which also names its process id);
//! a second run on the same directory fails at once, rather than mixing its
//! files with the first's. The system drops the lock when its process ends,
//! however it ends, so a killed run leaves nothing to clean up. The file
//! itself stays: deleting a lock file races with a process about to lock it.

use anyhow::{Context, bail};
use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Seek, Write};
use std::path::Path;

pub const LOCK_FILE: &str = ".study.lock";

/// Held while a study writes into its output directory.
#[derive(Debug)]
pub struct OutLock {
    _file: File,
}

impl OutLock {
    pub fn acquire(out_dir: &Path) -> anyhow::Result<OutLock> {
        let path = out_dir.join(LOCK_FILE);
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&path)
            .with_context(|| format!("cannot open the lock file {}", path.display()))?;
        match file.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => {
                let mut owner = String::new();
                let _ = file.read_to_string(&mut owner);
                let owner = match owner.trim() {
                    "" => String::new(),
                    pid => format!(" (process {pid})"),
                };
                bail!(
                    "another `study run`{owner} is writing to {}; wait for it to finish, or give this one another --out",
                    out_dir.display()
                );
            }
            Err(TryLockError::Error(e)) => {
                return Err(e).with_context(|| format!("cannot lock {}", path.display()));
            }
        }
        file.set_len(0)
            .and_then(|()| file.rewind())
            .and_then(|()| writeln!(file, "{}", std::process::id()))
            .with_context(|| format!("cannot write {}", path.display()))?;
        Ok(OutLock { _file: file })
    }
}
