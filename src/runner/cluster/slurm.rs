//! `study slurm`: a study as a Slurm job array. Writes two batch scripts into
//! `OUT/slurm/`: `shards.sbatch`, an array of N tasks each running one shard
//! (`study run --shard $SLURM_ARRAY_TASK_ID/N`, threads from the task's
//! CPUs, `--requeue` so a failed node or a preemption puts it back in the
//! queue), and `collect.sbatch`, which joins the records into the tables
//! once the array has ended (submitted with `--dependency=afterany:`).
//! Slurm does not requeue a task that hit its time limit; its finished runs
//! and the checkpoints of its unfinished ones stay, so submitting the same
//! script again (or only those tasks, `sbatch --array=3,7`) continues them.

use crate::descriptor::errors::{DescriptorError, StudyError};
use crate::runner::cluster::script_text;
use crate::runner::pipeline::shell_word;
use crate::runner::plan::origin::Flags;
use anyhow::{Context, bail};
use std::path::{Path, PathBuf};
use std::process::Command;

/// What the scripts run and ask Slurm for.
#[derive(Debug, Clone, PartialEq)]
pub struct SlurmJob {
    /// The `study` executable the tasks run, absolute.
    pub study: PathBuf,
    /// Descriptor and output folder, absolute.
    pub file: PathBuf,
    pub out: PathBuf,
    /// The flags that set the plan.
    pub flags: Flags,
    /// Job name (the study's name).
    pub name: String,
    pub shards: u32,
    pub cpus: u32,
    pub partition: Option<String>,
    pub time: Option<String>,
    pub mem: Option<String>,
    /// Seconds of wall time between checkpoints of a run (None: the default).
    pub checkpoint_every: Option<f64>,
}

pub fn slurm_dir(out: &Path) -> PathBuf {
    out.join("slurm")
}

pub fn shards_script(out: &Path) -> PathBuf {
    slurm_dir(out).join("shards.sbatch")
}

pub fn collect_script(out: &Path) -> PathBuf {
    slurm_dir(out).join("collect.sbatch")
}

/// The number of shards of the array script written for `out`, if any.
pub fn array_shards(out: &Path) -> Option<u32> {
    let limit = crate::runner::store::outdir::SMALL_LIMIT;
    let text = crate::runner::store::outdir::read_own_text(&shards_script(out), limit).ok()?;
    text.lines()
        .find_map(|l| l.strip_prefix("#SBATCH --array=1-"))
        .and_then(|n| n.trim().parse().ok())
}

/// The job's text as the scripts write it, every part checked
/// (`script_text`): paths as shell words, `#SBATCH` values as sbatch reads
/// them literally.
struct Text {
    study: String,
    file: String,
    out: String,
    /// The output folder at the start of `#SBATCH --output=` (`%` doubled).
    output: String,
    name: String,
    /// `#SBATCH` lines every job of the study shares.
    common: String,
}

/// Check `--partition`, `--mem` and `--time` for the scripts: bad input
/// (exit 2) names the flag and what would be right.
pub fn check_flags(
    partition: Option<&str>,
    mem: Option<&str>,
    time: Option<&str>,
) -> Result<(), DescriptorError> {
    if let Some(p) = partition {
        script_text::directive_value("--partition", p, "_-.,", "debug")?;
    }
    if let Some(m) = mem {
        script_text::directive_value("--mem", m, "", "4G")?;
    }
    if let Some(t) = time {
        script_text::directive_value("--time", t, ":-", "2:00:00")?;
        if time_limit_seconds(t).is_none() {
            return Err(
                DescriptorError::new("--time", format!("{t:?} is not a Slurm time limit"))
                    .hint("write minutes, H:MM:SS or D-HH:MM:SS, e.g. --time 2:00:00"),
            );
        }
    }
    Ok(())
}

impl SlurmJob {
    /// Every user string of the job, checked, as the scripts write it.
    fn text(&self) -> Result<Text, DescriptorError> {
        check_flags(
            self.partition.as_deref(),
            self.mem.as_deref(),
            self.time.as_deref(),
        )?;
        let word = |flag: &str, p: &Path| script_text::path_text(flag, p).map(shell_word);
        let mut common = String::new();
        if let Some(p) = &self.partition {
            common += &format!("#SBATCH --partition={p}\n");
        }
        if let Some(m) = &self.mem {
            common += &format!("#SBATCH --mem={m}\n");
        }
        Ok(Text {
            study: word("the study executable", &self.study)?,
            file: word("FILE", &self.file)?,
            out: word("--out", &self.out)?,
            output: script_text::directive_path("--out", &self.out)?,
            name: script_text::job_name(&self.name),
            common,
        })
    }

    /// The job array script.
    pub fn shards_text(&self) -> Result<String, DescriptorError> {
        let t = self.text()?;
        let runs = shell_word(&format!(
            "{}/runs/",
            script_text::path_text("--out", &self.out)?
        ));
        let mut s = format!(
            "#!/bin/bash\n\
             # Written by `study slurm` (bonkers {}): one shard of the study\n\
             # {} per array task, into {runs}.\n\
             # A task resumes what an earlier one left: finished runs are kept,\n\
             # unfinished ones continue from their checkpoints.\n\
             #SBATCH --job-name={}\n\
             #SBATCH --array=1-{}\n\
             #SBATCH --cpus-per-task={}\n",
            crate::runner::store::manifest::version(),
            t.file,
            t.name,
            self.shards,
            self.cpus
        );
        if let Some(time) = &self.time {
            s += &format!("#SBATCH --time={time}\n");
        }
        s += &t.common;
        s += &format!(
            "#SBATCH --requeue\n\
             #SBATCH --open-mode=append\n\
             #SBATCH --output={}/slurm/shard-%a.log\n",
            t.output
        );
        let checkpoint = self
            .checkpoint_every
            .map_or(String::new(), |c| format!(" --checkpoint-every {c}"));
        s += &format!(
            "set -eu\n\
             echo \"shard ${{SLURM_ARRAY_TASK_ID}}/{n}: job ${{SLURM_JOB_ID}} on $(hostname), restart ${{SLURM_RESTART_COUNT:-0}}\"\n\
             exec {study} run {file} --out {out} --shard \"${{SLURM_ARRAY_TASK_ID}}/{n}\" \
             --threads \"${{SLURM_CPUS_PER_TASK:-1}}\"{flags}{checkpoint}\n",
            n = self.shards,
            study = t.study,
            file = t.file,
            out = t.out,
            flags = self.flags.text(),
        );
        Ok(s)
    }

    /// The collect script, to run after the array (afterany).
    pub fn collect_text(&self) -> Result<String, DescriptorError> {
        let t = self.text()?;
        let mut s = format!(
            "#!/bin/bash\n\
             # Written by `study slurm`: joins the records of every shard into the\n\
             # tables and report of {}. If runs are missing it lists them and\n\
             # the status says which array tasks to submit again.\n\
             #SBATCH --job-name={}-collect\n\
             #SBATCH --cpus-per-task=1\n",
            t.out, t.name
        );
        s += &t.common;
        s += &format!(
            "#SBATCH --open-mode=append\n#SBATCH --output={}/slurm/collect.log\n",
            t.output
        );
        let (study, out) = (&t.study, &t.out);
        s += &format!(
            "set -u\n\
             {study} collect {out} && exit 0\n\
             code=$?\n\
             {study} status {out}\n\
             exit $code\n"
        );
        Ok(s)
    }

    /// Write both scripts; returns their paths (array, collect). Nothing
    /// is written if any part of the job cannot go into a script.
    pub fn write(&self) -> Result<(PathBuf, PathBuf), StudyError> {
        let (shards_text, collect_text) = (self.shards_text()?, self.collect_text()?);
        let dir = slurm_dir(&self.out);
        std::fs::create_dir_all(&dir)
            .with_context(|| format!("cannot create {}", dir.display()))?;
        let (shards, collect) = (shards_script(&self.out), collect_script(&self.out));
        crate::files::write_atomic(&shards, shards_text.as_bytes())?;
        crate::files::write_atomic(&collect, collect_text.as_bytes())?;
        Ok((shards, collect))
    }
}

/// The shell commands that submit the array, then the collect after it.
pub fn submit_commands(shards: &Path, collect: &Path) -> [String; 2] {
    [
        format!(
            "jobid=$(sbatch --parsable {})",
            shell_word(&shards.to_string_lossy())
        ),
        format!(
            "sbatch --dependency=afterany:${{jobid%%;*}} {}",
            shell_word(&collect.to_string_lossy())
        ),
    ]
}

/// Submit the array, then the collect after it; returns both job ids.
pub fn submit(shards: &Path, collect: &Path) -> anyhow::Result<(String, String)> {
    let array = sbatch(&["--parsable".as_ref(), shards.as_os_str()])?;
    let dependency = format!("--dependency=afterany:{array}");
    let after = sbatch(&[
        "--parsable".as_ref(),
        dependency.as_ref(),
        collect.as_os_str(),
    ])?;
    Ok((array, after))
}

/// Run `sbatch args`; its job id ("123", or "123;cluster" -> "123").
fn sbatch(args: &[&std::ffi::OsStr]) -> anyhow::Result<String> {
    let out = Command::new("sbatch")
        .args(args)
        .output()
        .context("cannot run `sbatch`: is Slurm installed here and on the PATH?")?;
    if !out.status.success() {
        bail!(
            "`sbatch` failed ({}): {}",
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        );
    }
    let text = String::from_utf8_lossy(&out.stdout);
    let id = text.trim().split(';').next().unwrap_or("").to_string();
    if id.is_empty() || !id.chars().all(|c| c.is_ascii_digit()) {
        bail!("`sbatch --parsable` printed {text:?}, not a job id");
    }
    Ok(id)
}

/// A Slurm time limit in seconds: "M", "M:S", "H:M:S", "D-H", "D-H:M",
/// "D-H:M:S", each part decimal digits. None if it is none of these.
pub fn time_limit_seconds(t: &str) -> Option<f64> {
    let number = |p: &str| {
        let digits = !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit());
        digits.then(|| p.parse::<f64>().ok()).flatten()
    };
    let (days, rest) = match t.split_once('-') {
        Some((d, rest)) => (number(d)?, rest),
        None => (0.0, t),
    };
    let parts: Vec<f64> = rest.split(':').map(number).collect::<Option<_>>()?;
    let with_days = t.contains('-');
    let seconds = match (with_days, parts.as_slice()) {
        (false, [m]) => m * 60.0,
        (false, [m, s]) => m * 60.0 + s,
        (_, [h, m, s]) => h * 3600.0 + m * 60.0 + s,
        (true, [h]) => h * 3600.0,
        (true, [h, m]) => h * 3600.0 + m * 60.0,
        _ => return None,
    };
    Some(days * 86_400.0 + seconds)
}

#[cfg(test)]
mod tests {
    use super::time_limit_seconds;

    #[test]
    fn slurm_time_limits_parse() {
        assert_eq!(time_limit_seconds("30"), Some(1800.0));
        assert_eq!(time_limit_seconds("30:15"), Some(1815.0));
        assert_eq!(time_limit_seconds("2:00:00"), Some(7200.0));
        assert_eq!(time_limit_seconds("1-0"), Some(86_400.0));
        assert_eq!(time_limit_seconds("1-2:30"), Some(86_400.0 + 9000.0));
        assert_eq!(time_limit_seconds("1-00:00:10"), Some(86_410.0));
        for bad in [
            "soon", "inf", "1e3", "+5", "1.5", "-1", "1-", "1:-2", "", "1::2",
        ] {
            assert_eq!(time_limit_seconds(bad), None, "{bad}");
        }
    }
}
