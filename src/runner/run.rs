//! Run the plan in parallel. Each finished run is saved as its own file
//! (`OUT/runs/run-<seed>.json`, written atomically) so an interrupted study
//! resumes where it stopped; a failing or panicking run is recorded and the
//! others go on.

use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::runner::cpu_time::thread_cpu_seconds;
use crate::runner::progress::{Progress, ProgressMode};
pub use crate::runner::record::RunRecord;
use crate::runner::seeds::fnv1a;
use anyhow::Context;
use rayon::prelude::*;
use std::collections::HashSet;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// The simulator as the runner sees it; tests inject a fake.
pub type SimulateFn<'a> = dyn Fn(&RunSpec) -> anyhow::Result<RunOutput> + Sync + 'a;

#[derive(Debug, Clone)]
pub struct RunnerOptions {
    /// Worker threads; None = all cores.
    pub threads: Option<usize>,
    /// Discard saved runs first instead of resuming from them.
    pub fresh: bool,
    pub progress: ProgressMode,
}

/// What the runner did.
#[derive(Debug, Clone)]
pub struct RunnerReport {
    /// One record per planned run, in plan order; None for runs not done
    /// because the study was interrupted.
    pub records: Vec<Option<RunRecord>>,
    pub ran: usize,
    pub failed: usize,
    pub resumed: usize,
    pub interrupted: bool,
    pub threads: usize,
}

/// The fingerprint of a planned run: a hash of everything that decides what
/// it computes: the bonkers version, its seed and replica, and its
/// descriptor with the sweep values applied, less what cannot change a run
/// (`[study]`: name, description and replica count; `[sweep]`, `[[case]]`
/// and `[quick]`, already applied). So raising `--replicas` or inserting a sweep value
/// reuses the runs already done.
pub fn fingerprint(spec: &RunSpec) -> String {
    let mut run = serde_json::to_value(&spec.descriptor).unwrap_or_default();
    if let Some(sections) = run.as_object_mut() {
        for section in ["study", "sweep", "case", "quick"] {
            sections.remove(section);
        }
    }
    let key = format!(
        "{}|{}|{}|{run}",
        crate::runner::manifest::version(),
        spec.seed,
        spec.replica
    );
    format!("{:016x}", fnv1a(key.as_bytes()))
}

pub fn runs_dir(out_dir: &Path) -> PathBuf {
    out_dir.join("runs")
}

/// A run's file is named by its seed (the `seed` column of runs.parquet),
/// which stays with the run when the sweep or the replica count changes.
pub fn run_file(out_dir: &Path, seed: u64) -> PathBuf {
    runs_dir(out_dir).join(format!("run-{seed}.json"))
}

/// Run every planned run not already saved. `stop` is checked before each
/// run starts (Ctrl-C sets it): in-flight runs finish and are saved.
/// The caller holds the out dir's lock.
pub fn run_all(
    specs: &[RunSpec],
    out_dir: &Path,
    simulate: &SimulateFn<'_>,
    options: &RunnerOptions,
    stop: &AtomicBool,
) -> anyhow::Result<RunnerReport> {
    let dir = runs_dir(out_dir);
    if options.fresh && dir.exists() {
        std::fs::remove_dir_all(&dir)
            .with_context(|| format!("cannot remove {}", dir.display()))?;
    }
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let tidied = tidy(specs, out_dir)?;

    let saved: Vec<Option<RunRecord>> = specs.iter().map(|s| load_saved(out_dir, s)).collect();
    let resumed = saved.iter().filter(|r| r.is_some()).count();
    let todo: Vec<usize> = (0..specs.len()).filter(|&i| saved[i].is_none()).collect();
    if options.progress != ProgressMode::Quiet
        && let Some(note) = tidied.note(resumed)
    {
        eprintln!("study: {note}");
    }

    let threads = options
        .threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("cannot start the worker threads")?;
    let progress = Progress::new(todo.len() as u64, options.progress);

    let fresh_records: Vec<anyhow::Result<Option<RunRecord>>> = pool.install(|| {
        todo.par_iter()
            .map(|&i| {
                if stop.load(Ordering::SeqCst) {
                    return Ok(None);
                }
                let record = execute(&specs[i], simulate);
                save(out_dir, &specs[i], &record)?;
                progress.finished(record.ok(), record.output.collisions);
                Ok(Some(record))
            })
            .collect()
    });
    progress.finish();

    let mut records = saved;
    let (mut ran, mut failed) = (0, 0);
    for (&i, result) in todo.iter().zip(fresh_records) {
        if let Some(record) = result? {
            ran += 1;
            failed += usize::from(!record.ok());
            records[i] = Some(record);
        }
    }
    let interrupted = records.iter().any(Option::is_none);
    Ok(RunnerReport {
        records,
        ran,
        failed,
        resumed,
        interrupted,
        threads,
    })
}

/// What `tidy` found among the saved runs.
#[derive(Debug, Default)]
struct Tidied {
    /// Saved successful runs of planned seeds that another descriptor or
    /// bonkers version made: they are run again.
    mismatched: usize,
    /// Run files of no planned run, removed.
    removed: usize,
}

impl Tidied {
    fn note(&self, resumed: usize) -> Option<String> {
        let mut parts = Vec::new();
        if resumed > 0 {
            parts.push(format!("resuming {resumed} saved runs"));
        }
        if self.mismatched > 0 {
            parts.push(format!(
                "{} saved runs were made by another descriptor or bonkers version and run again",
                self.mismatched
            ));
        }
        if self.removed > 0 {
            parts.push(format!(
                "removed {} saved runs that are not in this plan",
                self.removed
            ));
        }
        (!parts.is_empty()).then(|| parts.join("; "))
    }
}

/// Remove temporary files an interrupted writer left and run files of no
/// planned run (so the saved runs are those of this study), and count saved
/// runs that no longer match their plan entry.
fn tidy(specs: &[RunSpec], out_dir: &Path) -> anyhow::Result<Tidied> {
    let planned: HashSet<PathBuf> = specs.iter().map(|s| run_file(out_dir, s.seed)).collect();
    let mut tidied = Tidied::default();
    let dir = runs_dir(out_dir);
    let entries =
        std::fs::read_dir(&dir).with_context(|| format!("cannot list {}", dir.display()))?;
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        let temporary = crate::files::is_temporary(&name);
        if temporary || (name.starts_with("run-") && !planned.contains(&path)) {
            std::fs::remove_file(&path)
                .with_context(|| format!("cannot remove {}", path.display()))?;
            tidied.removed += usize::from(!temporary);
        }
    }
    for spec in specs {
        let text = std::fs::read_to_string(run_file(out_dir, spec.seed));
        if let Ok(record) = text.as_deref().map(RunRecord::from_json)
            && let Ok(record) = record
            && record.ok()
            && record.fingerprint != fingerprint(spec)
        {
            tidied.mismatched += 1;
        }
    }
    Ok(tidied)
}

/// Run one simulation, turning errors and panics into a failed record.
fn execute(spec: &RunSpec, simulate: &SimulateFn<'_>) -> RunRecord {
    let start = Instant::now();
    let cpu = thread_cpu_seconds();
    let result = catch_unwind(AssertUnwindSafe(|| simulate(spec)));
    let (status, mut output) = match result {
        Ok(Ok(output)) => ("ok".to_string(), output),
        Ok(Err(e)) => (format!("failed: {e:#}"), RunOutput::default()),
        Err(panic) => (
            format!("failed: panicked: {}", panic_message(&*panic)),
            RunOutput::default(),
        ),
    };
    if output.wall_seconds == 0.0 {
        output.wall_seconds = start.elapsed().as_secs_f64();
    }
    output.cpu_seconds = thread_cpu_seconds() - cpu;
    RunRecord {
        run_id: spec.run_id,
        fingerprint: fingerprint(spec),
        status,
        output,
    }
}

fn panic_message(panic: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = panic.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = panic.downcast_ref::<String>() {
        s.clone()
    } else {
        "(no message)".to_string()
    }
}

/// A saved successful run of exactly this plan entry, if any (its run id
/// is this plan's: ids shift when the sweep or replica count changes).
/// Failed runs are not reused: a rerun retries them.
fn load_saved(out_dir: &Path, spec: &RunSpec) -> Option<RunRecord> {
    let text = std::fs::read_to_string(run_file(out_dir, spec.seed)).ok()?;
    let mut record = RunRecord::from_json(&text).ok()?;
    record.run_id = spec.run_id;
    (record.ok() && record.fingerprint == fingerprint(spec)).then_some(record)
}

fn save(out_dir: &Path, spec: &RunSpec, record: &RunRecord) -> anyhow::Result<()> {
    let text = record.to_json().context("cannot encode a run record")?;
    crate::files::write_atomic(&run_file(out_dir, spec.seed), text.as_bytes())
}
