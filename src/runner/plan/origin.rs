//! `OUT/.study.json`: the descriptor text and the flags that planned the runs
//! in OUT, written by every `study run` (whole or part) before it runs. With
//! it, `study collect DIR` and `study status DIR` rebuild the same plan from
//! the folder alone (on a cluster, the collect job may run long after the
//! descriptor file was edited), and name the command that redoes a run.

use crate::descriptor::errors::{DescriptorError, StudyError};
use crate::descriptor::load::{self, Loaded};
use crate::runner::store::outdir;
use anyhow::{Context, anyhow};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

pub const ORIGIN_FILE: &str = ".study.json";

/// How the command line plans a descriptor: `--quick`, `--replicas N`
/// and `--yes` (plans too large or costly to start by accident).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Flags {
    pub quick: bool,
    pub replicas: Option<u32>,
    pub yes: bool,
}

impl Flags {
    /// `loaded` with `--quick` and then `--replicas` applied.
    pub fn apply(&self, mut loaded: Loaded) -> Result<Loaded, DescriptorError> {
        if self.quick {
            loaded = load::quick(&loaded)?;
        }
        if let Some(n) = self.replicas {
            loaded = load::with_replicas(&loaded, n)?;
        }
        Ok(loaded)
    }

    /// The flags as the command line takes them (" --quick --replicas 2").
    pub fn text(&self) -> String {
        let mut text = String::new();
        if self.quick {
            text += " --quick";
        }
        if let Some(n) = self.replicas {
            text += &format!(" --replicas {n}");
        }
        if self.yes {
            text += " --yes";
        }
        text
    }
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Origin {
    /// The descriptor file, absolute (jobs may start in another folder).
    pub file: PathBuf,
    /// Its text when the runs were planned.
    pub text: String,
    #[serde(flatten)]
    pub flags: Flags,
}

impl Origin {
    pub fn new(file: &Path, loaded: &Loaded, flags: Flags) -> Self {
        Origin {
            file: std::path::absolute(file).unwrap_or_else(|_| file.to_path_buf()),
            text: loaded.text.clone(),
            flags,
        }
    }

    /// The descriptor as planned: the saved text with its flags applied.
    pub fn loaded(&self) -> Result<Loaded, DescriptorError> {
        let loaded = load::parse(&self.file.display().to_string(), &self.text)?;
        self.flags.apply(loaded)
    }
}

/// Save `origin` in `out_dir`, unless the same is already there (shards
/// starting together then write nothing).
pub fn save(out_dir: &Path, origin: &Origin) -> anyhow::Result<()> {
    if read(out_dir).is_ok_and(|o| o == *origin) {
        return Ok(());
    }
    let json = serde_json::to_string_pretty(origin).context("cannot encode .study.json")?;
    crate::files::write_atomic(&out_dir.join(ORIGIN_FILE), json.as_bytes())
}

fn read(out_dir: &Path) -> anyhow::Result<Origin> {
    let path = out_dir.join(ORIGIN_FILE);
    let text = outdir::read_own_text(&path, outdir::SMALL_LIMIT).map_err(|e| anyhow!("{e}"))?;
    serde_json::from_str(&text).with_context(|| format!("{} does not parse", path.display()))
}

/// The origin saved in `out_dir`; a folder without one is bad input.
pub fn load(out_dir: &Path) -> Result<Origin, StudyError> {
    let path = out_dir.join(ORIGIN_FILE);
    if std::fs::symlink_metadata(&path).is_err() {
        let what = if out_dir.is_dir() {
            "is not the output folder of a study: it has no .study.json"
        } else {
            "is not a folder"
        };
        return Err(DescriptorError::new(&out_dir.display().to_string(), what)
            .hint("give the --out folder of a `study run` (a bonkers older than .study.json: give the descriptor and --out instead)")
            .into());
    }
    read(out_dir).map_err(|e| {
        DescriptorError::new(&path.display().to_string(), format!("{e:#}"))
            .hint("the file is written by `study run`; run it again to rewrite it")
            .into()
    })
}
