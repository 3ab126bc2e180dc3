//! Atomic file writes: a reader (or a crash) never sees half a report.

use anyhow::Context;
use std::path::Path;

/// Write `bytes` to `path` via `path.tmp` and a rename.
pub fn write(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    std::fs::write(&tmp, bytes).with_context(|| format!("writing {}", path.display()))?;
    std::fs::rename(&tmp, path).with_context(|| format!("renaming into {}", path.display()))
}
