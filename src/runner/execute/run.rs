//! Compute runs of a plan into run records, and nothing else: each finished
//! run is saved as its own file (`OUT/runs/run-<seed>.json`, written
//! atomically), so an interrupted study resumes where it stopped and a later
//! step (`collect.rs`) can make the tables from the files alone. A failing or
//! panicking run is recorded and the others go on. A call computes the whole
//! plan or a subset of it and leaves the other runs' records alone, so
//! invocations that split a plan between them add up to one whole run.
//! Records cost CPU hours: those of runs the plan does not have (fewer
//! replicas, a sweep value removed, `--quick`) are kept and said, and
//! deleted only with `--prune`.

use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::runner::execute::checkpoint::{self, Place};
use crate::runner::execute::cpu_time::thread_cpu_seconds;
use crate::runner::execute::progress::{Progress, ProgressMode};
use crate::runner::execute::trajectory;
use crate::runner::plan::seeds::fnv1a;
use crate::runner::store::outdir::{self, Unusable, remove_if_present};
pub use crate::runner::store::record::RunRecord;
use anyhow::{Context, bail};
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
    /// Discard the saved runs of the picked runs first instead of resuming
    /// from them.
    pub fresh: bool,
    /// Delete the records and checkpoints of runs the plan does not have
    /// (unless `shared`), and replace saved runs of the plan that another
    /// descriptor or bonkers version made (`pipeline` refuses those first
    /// without it).
    pub prune: bool,
    pub progress: ProgressMode,
    /// Other invocations (shards) may be writing into the same runs folder:
    /// remove nothing of theirs, neither their temporary files nor records
    /// of runs this plan does not have.
    pub shared: bool,
    /// Save each run's state this often (wall time) into
    /// `OUT/runs/run-<seed>.ckpt`, and continue from it (`checkpoint.rs`);
    /// None: no checkpoints.
    pub checkpoint_every: Option<std::time::Duration>,
}

/// Which runs of a plan one call computes.
#[derive(Clone, Copy)]
pub enum Subset<'a> {
    All,
    /// The runs with these ids (the `run_id` column).
    Ids(&'a [u64]),
    /// The runs this picks, e.g. one shard of the plan.
    Matching(&'a (dyn Fn(&RunSpec) -> bool + Sync)),
}

impl Subset<'_> {
    /// Indices into `specs` of the runs picked, in plan order; an id the
    /// plan does not have is an error rather than silently nothing.
    pub fn pick(&self, specs: &[RunSpec]) -> anyhow::Result<Vec<usize>> {
        let indices = 0..specs.len();
        Ok(match self {
            Subset::All => indices.collect(),
            Subset::Ids(ids) => {
                let wanted: HashSet<u64> = ids.iter().copied().collect();
                let planned: HashSet<u64> = specs.iter().map(|s| s.run_id).collect();
                if let Some(id) = ids.iter().find(|id| !planned.contains(id)) {
                    bail!(
                        "run {id} is not in the plan, whose runs are 0 to {}",
                        specs.len().saturating_sub(1)
                    );
                }
                indices
                    .filter(|&i| wanted.contains(&specs[i].run_id))
                    .collect()
            }
            Subset::Matching(picks) => indices.filter(|&i| picks(&specs[i])).collect(),
        })
    }
}

/// What the runner did with the runs it was given.
#[derive(Debug, Clone)]
pub struct RunnerReport {
    /// Runs picked from the plan.
    pub picked: usize,
    /// Run now, failed ones included.
    pub ran: usize,
    pub failed: usize,
    /// Picked runs whose record an earlier invocation saved.
    pub resumed: usize,
    /// Some picked runs were not started because `stop` was raised.
    pub interrupted: bool,
    /// Runs now that continued from a checkpoint an earlier invocation saved.
    pub continued: usize,
    pub threads: usize,
}

impl RunnerReport {
    /// Picked runs that now have a record.
    pub fn kept(&self) -> usize {
        self.resumed + self.ran
    }
}

/// The fingerprint of a planned run: a hash of everything that decides what
/// it computes: the bonkers version, its seed and replica, and its
/// descriptor with the sweep values applied, less what cannot change a run
/// (`[study]`: name, description and replica count; `[sweep]`, `[[case]]`
/// and `[quick]`, already applied; `[observe] trajectory`, which films the
/// run again). So raising `--replicas` or inserting a sweep value
/// reuses the runs already done.
pub fn fingerprint(spec: &RunSpec) -> String {
    let mut run = serde_json::to_value(&*spec.descriptor).unwrap_or_default();
    if let Some(sections) = run.as_object_mut() {
        for section in ["study", "sweep", "case", "quick"] {
            sections.remove(section);
        }
        // A trajectory is the run filmed again: it changes no result.
        if let Some(observe) = sections.get_mut("observe").and_then(|o| o.as_object_mut()) {
            observe.remove("trajectory");
        }
    }
    let key = format!(
        "{}|{}|{}|{run}",
        crate::runner::store::manifest::version(),
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
    run_subset(specs, Subset::All, out_dir, simulate, options, stop)
}

/// Run the runs of the plan `specs` that `subset` picks and that are not
/// already saved. Records of the plan's other runs are kept, whatever
/// `options.fresh` says; files of no planned run are kept too, unless
/// `options.prune` (and not `options.shared`).
pub fn run_subset(
    specs: &[RunSpec],
    subset: Subset<'_>,
    out_dir: &Path,
    simulate: &SimulateFn<'_>,
    options: &RunnerOptions,
    stop: &AtomicBool,
) -> anyhow::Result<RunnerReport> {
    let picked = subset.pick(specs)?;
    let dir = runs_dir(out_dir);
    // `outdir::check` refuses this first; a library caller may not have.
    if std::fs::symlink_metadata(&dir).is_ok_and(|m| m.file_type().is_symlink()) {
        bail!(
            "{} is a symbolic link, which bonkers does not follow",
            dir.display()
        );
    }
    if options.fresh {
        discard(specs, &picked, out_dir)?;
    }
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let mut tidied = if options.shared {
        Tidied::default()
    } else {
        tidy(specs, out_dir, options.prune)?
    };

    // Each saved record is read once, to learn whether it can be reused; a
    // reused run whose trajectory file is missing is filmed again (only).
    let mut todo = Vec::new();
    let mut films = Vec::new();
    for &i in &picked {
        match read_record(out_dir, &specs[i]) {
            Stored::Found(record)
                if record.ok() && record.fingerprint == fingerprint(&specs[i]) =>
            {
                if let Some(t) = trajectory::wanted(&specs[i])
                    && !trajectory::file(out_dir, t, specs[i].run_id).exists()
                {
                    films.push((i, record));
                }
            }
            Stored::Found(record) => {
                tidied.mismatched += usize::from(record.ok());
                todo.push(i);
            }
            Stored::Unreadable(why) => {
                tidied.unusable += 1;
                tidied.first_unusable.get_or_insert(why);
                todo.push(i);
            }
            Stored::Missing => todo.push(i),
        }
    }
    let resumed = picked.len() - todo.len();
    if options.progress != ProgressMode::Quiet
        && let Some(note) = tidied.note(resumed)
    {
        eprintln!("study: {note}");
    }

    let threads = options
        .threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        // An idle thread costs a stack and does nothing.
        .min(todo.len() + films.len())
        .max(1);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("cannot start the worker threads")?;
    let progress = Progress::new(todo.len() as u64, options.progress);

    // Some per run done (whether it succeeded, and whether it continued
    // from a checkpoint); None for a run `stop` kept from starting. Its
    // record is saved, not held.
    let done: Vec<anyhow::Result<Option<(bool, bool)>>> = pool.install(|| {
        todo.par_iter()
            .map(|&i| {
                if stop.load(Ordering::SeqCst) {
                    return Ok(None);
                }
                let place = options.checkpoint_every.map(|every| Place {
                    path: checkpoint::file(&dir, specs[i].seed),
                    every,
                    fingerprint: fingerprint(&specs[i]),
                    continued: false,
                });
                let (mut record, continued) =
                    checkpoint::scoped(place, || execute(&specs[i], simulate));
                film(out_dir, &specs[i], &mut record);
                save(out_dir, &specs[i], &record)?;
                remove_checkpoint(&dir, specs[i].seed)?;
                progress.finished(record.ok(), record.output.collisions);
                Ok(Some((record.ok(), continued)))
            })
            .collect()
    });
    progress.finish();
    // Reused runs without their trajectory file: filmed, and their record
    // kept unless filming fails (then the run is failed and made again next
    // time).
    let refilmed: Vec<anyhow::Result<Option<bool>>> = pool.install(|| {
        films
            .into_par_iter()
            .map(|(i, mut record)| {
                if stop.load(Ordering::SeqCst) {
                    return Ok(None);
                }
                film(out_dir, &specs[i], &mut record);
                if !record.ok() {
                    save(out_dir, &specs[i], &record)?;
                }
                Ok(Some(record.ok()))
            })
            .collect()
    });

    let (mut ran, mut failed, mut interrupted, mut resumed_runs) = (0, 0, false, 0);
    let mut failed_films = 0;
    for filmed in refilmed {
        match filmed? {
            Some(ok) => failed_films += usize::from(!ok),
            None => interrupted = true,
        }
    }
    for result in done {
        match result? {
            Some((ok, continued)) => {
                ran += 1;
                resumed_runs += usize::from(continued);
                failed += usize::from(!ok);
            }
            None => interrupted = true,
        }
    }
    Ok(RunnerReport {
        picked: picked.len(),
        ran: ran + failed_films,
        failed: failed + failed_films,
        resumed: resumed - failed_films,
        interrupted,
        continued: resumed_runs,
        threads,
    })
}

/// Write the trajectory a successful run's descriptor asks of it; a
/// trajectory that cannot be written fails the run (its record says why).
/// Filming runs the run again: twice its events are room enough.
fn film(out_dir: &Path, spec: &RunSpec, record: &mut RunRecord) {
    let Some(t) = trajectory::wanted(spec).filter(|_| record.ok()) else {
        return;
    };
    let budget = record
        .output
        .events
        .saturating_mul(2)
        .saturating_add(1_000_000);
    let filmed = catch_unwind(AssertUnwindSafe(|| {
        trajectory::write(spec, t, out_dir, budget)
    }));
    let why = match filmed {
        Ok(Ok(())) => return,
        Ok(Err(e)) => format!("{e:#}"),
        Err(panic) => format!("panicked: {}", panic_message(&*panic)),
    };
    record.status = format!("failed: trajectory: {why}");
}

/// `--fresh`: forget the saved records and checkpoints of the picked runs
/// (only theirs: records of runs this plan does not have stay, unless
/// `--prune`, and so do other parts' records in a shared folder).
fn discard(specs: &[RunSpec], picked: &[usize], out_dir: &Path) -> anyhow::Result<()> {
    let dir = runs_dir(out_dir);
    for &i in picked {
        remove_if_present(&run_file(out_dir, specs[i].seed))?;
        remove_checkpoint(&dir, specs[i].seed)?;
    }
    Ok(())
}

/// A run's checkpoint, once its record is saved (or `--fresh` forgets it).
fn remove_checkpoint(runs_dir: &Path, seed: u64) -> anyhow::Result<()> {
    remove_if_present(&checkpoint::file(runs_dir, seed))
}

/// What `tidy` found among the saved runs.
#[derive(Debug, Default)]
struct Tidied {
    /// Saved successful runs of planned seeds that another descriptor or
    /// bonkers version made: they are run again.
    mismatched: usize,
    /// Records of no planned run, removed (`--prune`) or kept (the first
    /// few names shown).
    removed: usize,
    kept: usize,
    first_kept: Vec<String>,
    /// Saved records of planned runs that cannot be trusted (changed since
    /// written, no checksum, a link, ...), run again; why, for the first.
    unusable: usize,
    first_unusable: Option<String>,
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
        if let Some(why) = &self.first_unusable {
            let others = match self.unusable {
                1 => String::new(),
                n => format!(" (and {} more)", n - 1),
            };
            parts.push(format!(
                "{} saved runs cannot be used and run again: {why}{others}",
                self.unusable
            ));
        }
        if self.removed > 0 {
            parts.push(format!(
                "removed {} saved runs that are not in this plan",
                self.removed
            ));
        }
        if self.kept > 0 {
            let more = match self.kept - self.first_kept.len() {
                0 => String::new(),
                n => format!(" and {n} more"),
            };
            parts.push(format!(
                "kept {} records that are not in this plan ({}{more}); --prune deletes them",
                self.kept,
                self.first_kept.join(", ")
            ));
        }
        (!parts.is_empty()).then(|| parts.join("; "))
    }
}

/// Names of kept records shown in the note.
const SHOWN: usize = 3;

/// Remove temporary files an interrupted writer left in the runs folder;
/// records and checkpoints of no planned run are counted and kept, or with
/// `prune` removed, so the saved runs are those of this study. Only names
/// bonkers makes (`outdir::is_run_file`) are touched; a link of such a name
/// is removed, never followed.
fn tidy(specs: &[RunSpec], out_dir: &Path, prune: bool) -> anyhow::Result<Tidied> {
    let dir = runs_dir(out_dir);
    let planned: HashSet<PathBuf> = specs
        .iter()
        .flat_map(|s| [run_file(out_dir, s.seed), checkpoint::file(&dir, s.seed)])
        .collect();
    let mut tidied = Tidied::default();
    let entries =
        std::fs::read_dir(&dir).with_context(|| format!("cannot list {}", dir.display()))?;
    let mut kept = Vec::new();
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        if !outdir::is_run_file(&name)
            || planned.contains(&path)
            || entry.file_type().is_ok_and(|t| t.is_dir())
        {
            continue;
        }
        let record = outdir::is_record(&name);
        if prune || crate::files::is_temporary(&name) {
            remove_if_present(&path)?;
            tidied.removed += usize::from(record);
        } else if record {
            kept.push(name);
        }
    }
    kept.sort();
    tidied.kept = kept.len();
    tidied.first_kept = kept
        .into_iter()
        .take(SHOWN)
        .map(|n| format!("runs/{n}"))
        .collect();
    Ok(tidied)
}

/// The picked runs whose saved record succeeded but was made by another
/// descriptor or bonkers version: running them would replace those records.
/// Their file names, in plan order.
pub fn replaced(
    specs: &[RunSpec],
    subset: Subset<'_>,
    out_dir: &Path,
) -> anyhow::Result<Vec<String>> {
    let mut names = Vec::new();
    for i in subset.pick(specs)? {
        if let Stored::Found(record) = read_record(out_dir, &specs[i])
            && record.ok()
            && record.fingerprint != fingerprint(&specs[i])
        {
            names.push(format!("runs/run-{}.json", specs[i].seed));
        }
    }
    Ok(names)
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
    // Plus what a run continued from a checkpoint had spent before.
    output.cpu_seconds += thread_cpu_seconds() - cpu;
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

/// A planned run's record file, as found.
#[derive(Debug)]
pub enum Stored {
    /// No file.
    Missing,
    /// A file that does not parse (the message says why).
    Unreadable(String),
    /// A record, ok or failed, with the plan's run id (ids shift when the
    /// sweep or replica count changes; the seed, which names the file, does
    /// not). Whether this plan would run exactly the same is up to the
    /// caller: compare its fingerprint with `fingerprint(spec)`.
    Found(RunRecord),
}

/// Read the record saved for `spec`, if any: a regular file only (a link
/// is not followed, a device or pipe not read), of at most
/// `outdir::RECORD_LIMIT` bytes, whose checksum holds.
pub fn read_record(out_dir: &Path, spec: &RunSpec) -> Stored {
    let path = run_file(out_dir, spec.seed);
    let text = match outdir::read_own_text(&path, outdir::RECORD_LIMIT) {
        Ok(text) => text,
        Err(Unusable::Missing) => return Stored::Missing,
        Err(Unusable::Refused(why)) => return Stored::Unreadable(why),
    };
    match RunRecord::from_json(&text) {
        Ok(mut record) => {
            record.run_id = spec.run_id;
            Stored::Found(record)
        }
        Err(e) => Stored::Unreadable(format!("{} {e}", path.display())),
    }
}

fn save(out_dir: &Path, spec: &RunSpec, record: &RunRecord) -> anyhow::Result<()> {
    let text = record.to_json().context("cannot encode a run record")?;
    crate::files::write_atomic(&run_file(out_dir, spec.seed), text.as_bytes())
}
