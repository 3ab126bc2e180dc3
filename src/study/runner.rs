//! Run the plan in parallel. Each finished run is saved as its own file
//! (`OUT/runs/run-<id>.json`, written atomically) so an interrupted study
//! resumes where it stopped; a failing or panicking run is recorded and the
//! others go on.

use super::output::RunOutput;
use super::plan_types::RunSpec;
use super::progress::{Progress, ProgressMode};
pub use super::record::RunRecord;
use super::seeds::fnv1a;
use anyhow::Context;
use rayon::prelude::*;
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

/// The fingerprint of a planned run.
pub fn fingerprint(spec: &RunSpec) -> String {
    let descriptor = serde_json::to_string(&spec.descriptor).unwrap_or_default();
    let key = format!(
        "{}|{}|{}|{}|{descriptor}",
        spec.run_id, spec.point_id, spec.replica, spec.seed
    );
    format!("{:016x}", fnv1a(key.as_bytes()))
}

pub fn runs_dir(out_dir: &Path) -> PathBuf {
    out_dir.join("runs")
}

fn run_file(out_dir: &Path, run_id: u64) -> PathBuf {
    runs_dir(out_dir).join(format!("run-{run_id}.json"))
}

/// Run every planned run not already saved. `stop` is checked before each
/// run starts (Ctrl-C sets it): in-flight runs finish and are saved.
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

    let saved: Vec<Option<RunRecord>> = specs.iter().map(|s| load_saved(out_dir, s)).collect();
    let resumed = saved.iter().filter(|r| r.is_some()).count();
    let todo: Vec<usize> = (0..specs.len()).filter(|&i| saved[i].is_none()).collect();

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
                save(out_dir, &record)?;
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

/// Run one simulation, turning errors and panics into a failed record.
fn execute(spec: &RunSpec, simulate: &SimulateFn<'_>) -> RunRecord {
    let start = Instant::now();
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

/// A saved successful run of exactly this plan entry, if any. Failed runs
/// are not reused: a rerun retries them.
fn load_saved(out_dir: &Path, spec: &RunSpec) -> Option<RunRecord> {
    let text = std::fs::read_to_string(run_file(out_dir, spec.run_id)).ok()?;
    let record = RunRecord::from_json(&text).ok()?;
    (record.ok() && record.run_id == spec.run_id && record.fingerprint == fingerprint(spec))
        .then_some(record)
}

fn save(out_dir: &Path, record: &RunRecord) -> anyhow::Result<()> {
    let text = record.to_json().context("cannot encode a run record")?;
    super::store::write_atomic(&run_file(out_dir, record.run_id), text.as_bytes())
}
