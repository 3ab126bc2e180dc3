//! `study status DIR`: how far the study in DIR is, from its records alone:
//! runs done, failed and pending, CPU-hours spent (the records' CPU times)
//! and left (the plan's estimate, and the estimate scaled by the pace the
//! done runs showed), shards running now, and what to submit again.

use crate::model::run_spec::RunSpec;
use crate::runner::cluster::shard;
use crate::runner::cluster::slurm;
use crate::runner::execute::run::{Stored, fingerprint, read_record};
use crate::runner::store::collect::RunCommand;
use crate::runner::store::lock::holder;
use std::fmt::Write as _;
use std::path::Path;

/// The state of every run of a plan in its folder.
#[derive(Debug, Clone, PartialEq)]
pub struct Status {
    pub planned: usize,
    pub done: usize,
    pub failed: usize,
    /// No usable record yet (running, not started, or made by another plan).
    pub pending: Vec<u64>,
    /// CPU seconds the done and failed runs took.
    pub cpu_seconds: f64,
    /// The plan's estimate for the done runs, and for the runs left
    /// (pending and failed).
    pub estimated_done: f64,
    pub estimated_left: f64,
    /// Shards whose lock a process holds now: ("K/N", process id).
    pub running: Vec<(String, String)>,
    /// Shards of the Slurm job array written for this folder (if any) that
    /// still have pending or failed runs, with that array's shard count.
    pub unfinished_shards: Option<(u32, Vec<u32>)>,
}

/// Read the records of the plan `specs` in `out_dir`.
pub fn status(specs: &[RunSpec], out_dir: &Path) -> Status {
    let estimates = shard::estimated_seconds(specs);
    let mut s = Status {
        planned: specs.len(),
        done: 0,
        failed: 0,
        pending: Vec::new(),
        cpu_seconds: 0.0,
        estimated_done: 0.0,
        estimated_left: 0.0,
        running: running_shards(out_dir),
        unfinished_shards: None,
    };
    let mut left = vec![false; specs.len()];
    for (i, spec) in specs.iter().enumerate() {
        match read_record(out_dir, spec) {
            Stored::Found(r) if r.fingerprint == fingerprint(spec) => {
                if r.output.cpu_seconds.is_finite() {
                    s.cpu_seconds += r.output.cpu_seconds;
                }
                if r.ok() {
                    s.done += 1;
                    s.estimated_done += estimates[i];
                } else {
                    s.failed += 1;
                    s.estimated_left += estimates[i];
                    left[i] = true;
                }
            }
            _ => {
                s.pending.push(spec.run_id);
                s.estimated_left += estimates[i];
                left[i] = true;
            }
        }
    }
    if let Some(count) = slurm::array_shards(out_dir) {
        let dealt = shard::deal(&estimates, count);
        let mut shards: Vec<u32> = dealt
            .iter()
            .zip(&left)
            .filter(|&(_, &l)| l)
            .map(|(&k, _)| k)
            .collect();
        shards.sort_unstable();
        shards.dedup();
        s.unfinished_shards = Some((count, shards));
    }
    s
}

/// Shards running in `out_dir` now, by their lock files.
fn running_shards(out_dir: &Path) -> Vec<(String, String)> {
    let mut running: Vec<(String, String)> = std::fs::read_dir(out_dir)
        .map(|it| {
            it.flatten()
                .filter_map(|e| {
                    let name = e.file_name().to_string_lossy().into_owned();
                    let tag = name.strip_prefix(".shard-")?.strip_suffix(".lock")?;
                    let pid = holder(&e.path())?;
                    Some((tag.replace("-of-", "/"), pid))
                })
                .collect()
        })
        .unwrap_or_default();
    running.sort();
    running
}

/// Seconds as CPU-hours, e.g. "0.42 CPU-hours".
pub fn cpu_hours(seconds: f64) -> String {
    let h = seconds / 3600.0;
    let digits = if h >= 10.0 {
        0
    } else if h >= 0.1 {
        2
    } else {
        4
    };
    format!("{h:.digits$} CPU-hours")
}

impl Status {
    /// What `study status` prints; `rerun` makes the plan's runs.
    pub fn text(&self, study: &str, out_dir: &Path, rerun: &RunCommand) -> String {
        let mut out = format!(
            "{study} in {}: {} planned runs\n  done: {}, failed: {}, pending: {}\n",
            out_dir.display(),
            self.planned,
            self.done,
            self.failed,
            self.pending.len()
        );
        let _ = writeln!(
            out,
            "  CPU time spent: {} (the done and failed runs; the plan estimated {} for the done ones)",
            cpu_hours(self.cpu_seconds),
            cpu_hours(self.estimated_done)
        );
        let mut left = format!(
            "  left: ~{} by the plan's estimate",
            cpu_hours(self.estimated_left)
        );
        if self.done > 0 && self.estimated_done > 0.0 && self.cpu_seconds > 0.0 {
            let pace = self.cpu_seconds / self.estimated_done;
            let _ = write!(
                left,
                ", ~{} at the pace measured so far ({pace:.2} x the estimate)",
                cpu_hours(self.estimated_left * pace)
            );
        }
        out += &left;
        out += "\n";
        for (shard, pid) in &self.running {
            let pid = if pid.is_empty() {
                String::new()
            } else {
                format!(" (process {pid})")
            };
            let _ = writeln!(out, "  running now: shard {shard}{pid}");
        }
        let unfinished = self.failed + self.pending.len();
        if unfinished == 0 {
            let _ = writeln!(
                out,
                "  every run is done: `study collect {}` makes the tables",
                rerun.out
            );
            return out;
        }
        if let Some((count, shards)) = &self.unfinished_shards {
            let list: Vec<String> = shards.iter().map(u32::to_string).collect();
            let _ = writeln!(
                out,
                "  shards (of {count}) with runs left: {}; once they are not running, resubmit them with `sbatch --array={} {}`",
                list.join(", "),
                list.join(","),
                slurm::shards_script(Path::new(&rerun.out)).display()
            );
        }
        let _ = writeln!(
            out,
            "  or run what is left on this machine (it keeps the done runs, then collects): `{}`",
            rerun.whole()
        );
        out
    }
}
