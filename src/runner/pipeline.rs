//! The study front ends, each descriptor -> plan first: `study run` (run the
//! plan, then collect), a run of part of a plan (records only), and
//! `study collect` (stored records -> tables, report, manifest).

use crate::descriptor::errors::{DescriptorError, StudyError};
use crate::descriptor::load::{self, Loaded};
use crate::descriptor::sweep::{self, CONFIRM_ABOVE};
use crate::files::write_atomic;
use crate::model::run_spec::RunSpec;
use crate::runner::cluster::shard::{self, Shard};
use crate::runner::execute::checkpoint;
use crate::runner::execute::progress::ProgressMode;
use crate::runner::execute::run::{
    self, RunnerOptions, RunnerReport, SimulateFn, Subset, run_subset,
};
use crate::runner::plan;
pub use crate::runner::plan::confirm::confirm_cost;
use crate::runner::plan::origin::{self, Flags, Origin};
use crate::runner::store::collect::{self, Collected, Invocation, RunCommand};
use crate::runner::store::lock::OutLock;
use crate::runner::store::outdir;
use anyhow::Context;
use std::ops::RangeInclusive;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant, SystemTime};

/// Options of `study run` (and what `study validate` shares).
#[derive(Debug, Clone)]
pub struct StudyOptions {
    /// Output directory; default `default_out_dir`.
    pub out: Option<PathBuf>,
    pub threads: Option<usize>,
    pub replicas: Option<u32>,
    pub quick: bool,
    pub fresh: bool,
    /// Delete records of runs the plan does not have, and let the plan
    /// replace saved runs another descriptor made (`guard`).
    pub prune: bool,
    pub progress: ProgressMode,
    /// Confirm plans of more than `CONFIRM_ABOVE` runs.
    pub yes: bool,
    /// Recorded in the manifest.
    pub command_line: Vec<String>,
    /// Wall time between checkpoints of a run (`checkpoint.rs`); None: the
    /// default, five minutes; zero: no checkpoints.
    pub checkpoint_every: Option<Duration>,
    /// Write into a non-empty folder that is not a study's output
    /// (`outdir::check`).
    pub force: bool,
}

/// Options of `study collect`: those that find the plan and its folder.
#[derive(Debug, Clone)]
pub struct CollectOptions {
    /// Output directory; default `default_out_dir`.
    pub out: Option<PathBuf>,
    pub replicas: Option<u32>,
    pub quick: bool,
    pub yes: bool,
    /// Recorded in the manifest.
    pub command_line: Vec<String>,
}

impl StudyOptions {
    pub fn flags(&self) -> Flags {
        Flags {
            quick: self.quick,
            replicas: self.replicas,
            yes: self.yes,
        }
    }
}

impl CollectOptions {
    pub fn flags(&self) -> Flags {
        Flags {
            quick: self.quick,
            replicas: self.replicas,
            yes: self.yes,
        }
    }
}

/// What a finished study did.
#[derive(Debug, Clone)]
pub struct StudyOutcome {
    pub out_dir: PathBuf,
    pub planned: usize,
    pub ran: usize,
    pub failed: usize,
    pub resumed: usize,
    /// Run now from a checkpoint an earlier invocation saved.
    pub continued: usize,
}

/// Load the descriptor and apply `--quick` and `--replicas`, in that order.
pub fn prepare(path: &Path, flags: Flags) -> Result<Loaded, DescriptorError> {
    flags.apply(load::load(path)?)
}

/// Refuse plans too large to start by accident.
pub fn confirm_size(loaded: &Loaded, yes: bool) -> Result<(), DescriptorError> {
    let (points, runs) = sweep::count(loaded);
    if runs > CONFIRM_ABOVE && !yes {
        let at = if loaded.descriptor.sweep.is_some() {
            "sweep"
        } else {
            "study.replicas"
        };
        return Err(DescriptorError::new(
            &loaded.file,
            format!("the plan has {runs} runs ({points} sweep points x {} replicas), more than {CONFIRM_ABOVE}", loaded.descriptor.study.replicas),
        )
        .at(crate::descriptor::locate::position_of(&loaded.text, at))
        .key(at)
        .hint("pass --yes if you mean it, or sweep fewer values / fewer replicas"));
    }
    Ok(())
}

/// `reports/<study name>/`, or `reports/<study name>-quick/` for `--quick`,
/// so a quick look never overwrites the full study's runs.
pub fn default_out_dir(loaded: &Loaded, quick: bool) -> PathBuf {
    let name = &loaded.descriptor.study.name;
    let folder = if quick {
        format!("{name}-quick")
    } else {
        name.clone()
    };
    Path::new("reports").join(folder)
}

/// A descriptor planned, with its output folder.
struct Planned {
    loaded: Loaded,
    specs: Vec<RunSpec>,
    out_dir: PathBuf,
    origin: Origin,
    /// The descriptor's path as given (the origin's is absolute).
    path: PathBuf,
}

/// The plan of a `study run` with `options`.
fn plan_study(path: &Path, flags: Flags, out: Option<&PathBuf>) -> Result<Planned, StudyError> {
    let loaded = prepare(path, flags)?;
    confirm_size(&loaded, flags.yes)?;
    let specs = plan::plan(&loaded)?;
    confirm_cost(&loaded, &specs, flags.yes)?;
    let out_dir = out
        .cloned()
        .unwrap_or_else(|| default_out_dir(&loaded, flags.quick));
    let origin = Origin::new(path, &loaded, flags);
    Ok(Planned {
        loaded,
        specs,
        out_dir,
        origin,
        path: path.to_path_buf(),
    })
}

/// The plan whose runs are in `out_dir`, from its `.study.json`.
fn plan_folder(out_dir: &Path) -> Result<Planned, StudyError> {
    let origin = origin::load(out_dir)?;
    let loaded = origin.loaded()?;
    let specs = plan::plan(&loaded)?;
    Ok(Planned {
        loaded,
        specs,
        out_dir: out_dir.to_path_buf(),
        path: origin.file.clone(),
        origin,
    })
}

impl Planned {
    fn rerun(&self) -> RunCommand {
        let o = &self.origin;
        rerun(&self.path, &self.out_dir, o.flags)
    }
}

/// Check, create and lock the output folder, and remove what a killed
/// invocation left.
fn claim(out_dir: &Path, force: bool) -> Result<OutLock, StudyError> {
    outdir::check(out_dir, force)?;
    let made = create_out_dir(out_dir)?;
    let lock = OutLock::acquire(out_dir).inspect_err(|_| unmake(&made))?;
    outdir::remove_leftovers(out_dir)?;
    Ok(lock)
}

/// Create `out_dir` and any folders above it that are missing; returns
/// those it created, deepest first. If it fails, what it created is
/// removed again: a study that cannot start leaves no empty `reports/`.
fn create_out_dir(out_dir: &Path) -> Result<Vec<PathBuf>, StudyError> {
    let made: Vec<PathBuf> = out_dir
        .ancestors()
        .filter(|a| !a.as_os_str().is_empty())
        .take_while(|a| std::fs::symlink_metadata(a).is_err())
        .map(Path::to_path_buf)
        .collect();
    std::fs::create_dir_all(out_dir)
        .inspect_err(|_| unmake(&made))
        .with_context(|| format!("cannot create the output directory {}", out_dir.display()))?;
    Ok(made)
}

/// Remove the folders `create_out_dir` made (deepest first) that are empty
/// (some may not have been made: `remove_dir` leaves anything else alone).
fn unmake(made: &[PathBuf]) {
    for dir in made {
        let _ = std::fs::remove_dir(dir);
    }
}

/// Create the output folder and lock it shared with other parts of the
/// plan (`shard`: and that shard's own lock). Nothing is removed: the
/// leftovers may be another part's work in flight.
fn claim_shared(out_dir: &Path, shard: Option<Shard>, force: bool) -> Result<OutLock, StudyError> {
    outdir::check(out_dir, force)?;
    let made = create_out_dir(out_dir)?;
    Ok(OutLock::shared(out_dir, shard.map(|s| s.tag()).as_deref())
        .inspect_err(|_| unmake(&made))?)
}

/// The `study run` command that runs (or resumes) the plan these flags
/// make into `out_dir`, in parts so a `--runs` can go between them.
pub fn rerun(path: &Path, out_dir: &Path, flags: Flags) -> RunCommand {
    let out = shell_word(&out_dir.to_string_lossy());
    let head = format!(
        "study run {} --out {out}",
        shell_word(&path.to_string_lossy())
    );
    RunCommand {
        head,
        tail: flags.text(),
        out,
    }
}

/// `word` as a POSIX shell reads it back: bare if it is plain, else quoted.
pub fn shell_word(word: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "-_./=:,+@%".contains(c);
    if !word.is_empty() && word.chars().all(plain) {
        word.to_string()
    } else {
        format!("'{}'", word.replace('\'', r"'\''"))
    }
}

/// How the caller holds the output folder.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Claim {
    /// Alone (exclusive lock).
    Whole,
    /// Beside other parts of the plan (shared lock): remove nothing of theirs.
    Shared,
}

/// Run the picked runs of the plan into records; Ctrl-C is an error that
/// says how many runs are kept. Returns the report and its wall time.
fn compute(
    planned: &Planned,
    subset: Subset<'_>,
    options: &StudyOptions,
    claim: Claim,
    simulate: &SimulateFn<'_>,
    stop: &AtomicBool,
) -> Result<(RunnerReport, f64), StudyError> {
    if !options.prune {
        guard(&planned.specs, subset, &planned.out_dir, &planned.origin)?;
    }
    let runner_options = RunnerOptions {
        threads: options.threads,
        fresh: options.fresh,
        prune: options.prune,
        progress: options.progress,
        shared: claim == Claim::Shared,
        checkpoint_every: match options.checkpoint_every {
            None => Some(checkpoint::DEFAULT_EVERY),
            Some(every) if every.is_zero() => None,
            every => every,
        },
    };
    origin::save(&planned.out_dir, &planned.origin)?;
    let clock = Instant::now();
    let report = run_subset(
        &planned.specs,
        subset,
        &planned.out_dir,
        simulate,
        &runner_options,
        stop,
    )?;
    if report.interrupted {
        return Err(StudyError::Interrupted(report.kept()));
    }
    Ok((report, clock.elapsed().as_secs_f64()))
}

/// Refuse to run a plan other than the one OUT's `.study.json` saved if
/// that would replace successful runs it made (another descriptor: their
/// fingerprints differ): they cost CPU hours, so only `--prune` (or
/// another --out) does that. The same plan passes at once: its saved runs
/// that do not match were made by another bonkers version, and run again.
/// (`study slurm` asks the same before it writes its scripts.)
pub fn guard(
    specs: &[RunSpec],
    subset: Subset<'_>,
    out: &Path,
    ours: &Origin,
) -> Result<(), StudyError> {
    let saved = origin::load(out).ok();
    if saved.as_ref().is_some_and(|o| same_plan(o, ours)) {
        return Ok(());
    }
    let replaced = run::replaced(specs, subset, out)?;
    let Some(first) = replaced.first() else {
        return Ok(());
    };
    let whose = match &saved {
        Some(o) => format!(
            "the plan its {} saved ({}{})",
            origin::ORIGIN_FILE,
            shell_word(&o.file.to_string_lossy()),
            Flags {
                yes: false,
                ..o.flags
            }
            .text()
        ),
        None => "another descriptor".to_string(),
    };
    let what = format!(
        "holds {} successful runs of {whose} whose settings differ from this plan's (e.g. {first}); running this plan would replace them",
        replaced.len()
    );
    Err(DescriptorError::new(&out.display().to_string(), what)
        .hint("give this plan another --out (`--quick` alone writes to reports/<name>-quick/), or pass --prune to replace them (and delete the records of runs this plan does not have)")
        .into())
}

/// Two origins plan the same runs (where the descriptor file lies aside).
fn same_plan(a: &Origin, b: &Origin) -> bool {
    let plans = |o: &Origin| (o.text.clone(), o.flags.quick, o.flags.replicas);
    plans(a) == plans(b)
}

/// Run the study at `path`: its whole plan, then collect. Completed runs
/// are kept under `OUT/runs/` so an interrupted study resumes; tables,
/// plots, report and manifest are written only when every run has
/// finished, and published together (`collect.rs`).
pub fn run_study(
    path: &Path,
    options: &StudyOptions,
    simulate: &SimulateFn<'_>,
    stop: &AtomicBool,
) -> Result<StudyOutcome, StudyError> {
    let started = SystemTime::now();
    let clock = Instant::now();
    let planned = plan_study(path, options.flags(), options.out.as_ref())?;
    let _lock = claim(&planned.out_dir, options.force)?;
    let (report, runs_wall_seconds) =
        compute(&planned, Subset::All, options, Claim::Whole, simulate, stop)?;
    let invocation = Invocation {
        command_line: options.command_line.clone(),
        started,
        clock,
        threads: report.threads,
        runs_wall_seconds,
        ran: report.ran,
        rerun: planned.rerun(),
    };
    let Planned {
        loaded,
        specs,
        out_dir,
        ..
    } = planned;
    collect::collect(&loaded, specs, &out_dir, &invocation)?;
    Ok(StudyOutcome {
        out_dir,
        planned: report.picked,
        ran: report.ran,
        failed: report.failed,
        resumed: report.resumed,
        continued: report.continued,
    })
}

/// Run only the runs `subset` picks from the plan at `path`, into records
/// under `OUT/runs/`, resuming like `run_study`; records of the plan's other
/// runs stay. No tables: `collect_study` makes them once every run is done.
pub fn run_part(
    path: &Path,
    options: &StudyOptions,
    subset: Subset<'_>,
    simulate: &SimulateFn<'_>,
    stop: &AtomicBool,
) -> Result<RunnerReport, StudyError> {
    let planned = plan_study(path, options.flags(), options.out.as_ref())?;
    let _lock = claim(&planned.out_dir, options.force)?;
    let claim = Claim::Whole;
    Ok(compute(&planned, subset, options, claim, simulate, stop)?.0)
}

/// Which part of a plan `run_slice` runs.
#[derive(Debug, Clone, PartialEq)]
pub enum Slice {
    /// `--shard K/N` (see `shard.rs`).
    Shard(Shard),
    /// `--runs 3,7-9`: these ranges of run ids (`collect::parse_ranges`).
    Runs(Vec<RangeInclusive<u64>>),
}

/// The ids `ranges` name, once every one is shown to be in the plan `specs`
/// (bad input otherwise, naming the plan's range): never more ids than
/// the plan has runs, whatever the ranges say.
pub fn ids_in_plan(
    file: &Path,
    specs: &[RunSpec],
    ranges: &[RangeInclusive<u64>],
) -> Result<Vec<u64>, DescriptorError> {
    let runs = specs.len() as u64;
    if let Some(r) = ranges.iter().find(|r| *r.end() >= runs) {
        let id = (*r.start()).max(runs);
        let whose = match runs {
            0 => "which has no runs".to_string(),
            n => format!("whose runs are 0 to {}", n - 1),
        };
        return Err(DescriptorError::new(
            &file.display().to_string(),
            format!("--runs: run {id} is not in the plan, {whose}"),
        )
        .hint(format!(
            "give ids below {runs} (the run_id column), e.g. --runs 0-{}",
            runs.saturating_sub(1)
        )));
    }
    Ok(ranges.iter().flat_map(|r| r.clone()).collect())
}

/// A part of the plan at `path` (`--shard`, `--runs`), run into records
/// beside any other parts running at the same time in the same folder (a
/// shared lock: see `lock.rs`). No tables: `study collect` makes them.
pub fn run_slice(
    path: &Path,
    options: &StudyOptions,
    slice: &Slice,
    simulate: &SimulateFn<'_>,
    stop: &AtomicBool,
) -> Result<RunnerReport, StudyError> {
    let planned = plan_study(path, options.flags(), options.out.as_ref())?;
    // The ids first: ids outside the plan are bad input, and nothing is
    // written before that is known.
    let (ids, shard) = match slice {
        Slice::Shard(s) => {
            let dealt = shard::deal(&shard::estimated_seconds(&planned.specs), s.count);
            let ids: Vec<u64> = planned
                .specs
                .iter()
                .zip(&dealt)
                .filter(|&(_, &k)| k == s.index)
                .map(|(spec, _)| spec.run_id)
                .collect();
            (ids, Some(*s))
        }
        Slice::Runs(ranges) => (ids_in_plan(path, &planned.specs, ranges)?, None),
    };
    let _lock = claim_shared(&planned.out_dir, shard, options.force)?;
    let subset = Subset::Ids(&ids);
    let report = compute(&planned, subset, options, Claim::Shared, simulate, stop)?;
    Ok(report.0)
}

/// `study collect DIR [MORE...]`: the runs of the plan that DIR's
/// `.study.json` saved, into tables, report and manifest in DIR. Records in
/// the MORE folders (shards run into folders of their own, e.g. one per
/// node) are copied into DIR first; each folder must hold the same plan, a
/// record DIR already has is kept, and every record is checked against its
/// run as any record is.
pub fn collect_folder(
    out_dir: &Path,
    more: &[PathBuf],
    command_line: Vec<String>,
) -> Result<Collected, StudyError> {
    let started = SystemTime::now();
    let clock = Instant::now();
    let planned = plan_folder(out_dir)?;
    let invocation = Invocation {
        command_line,
        started,
        clock,
        threads: 1,
        runs_wall_seconds: 0.0,
        ran: 0,
        rerun: planned.rerun(),
    };
    let _lock = claim(out_dir, false)?;
    for other in more {
        join_records(&planned, other)?;
    }
    collect::collect(&planned.loaded, planned.specs, out_dir, &invocation)
}

/// Copy into the plan's folder the records of `other` it lacks, once
/// `other` is shown to hold the same plan and no shard is writing there.
fn join_records(planned: &Planned, other: &Path) -> Result<(), StudyError> {
    let same = |a: &Path, b: &Path| {
        a.canonicalize()
            .is_ok_and(|a| b.canonicalize().is_ok_and(|b| a == b))
    };
    if same(other, &planned.out_dir) {
        return Err(DescriptorError::new(
            &other.display().to_string(),
            format!(
                "is the folder collected into ({}): it cannot be joined into itself",
                planned.out_dir.display()
            ),
        )
        .hint("give as MORE only other folders, e.g. `study collect DIR SHARD1 SHARD2`")
        .into());
    }
    let theirs = origin::load(other)?;
    if !same_plan(&theirs, &planned.origin) {
        return Err(DescriptorError::new(
            &other.display().to_string(),
            format!(
                "holds runs of another plan than {} (its .study.json differs: descriptor text, --quick or --replicas)",
                planned.out_dir.display()
            ),
        )
        .hint("collect together only folders that ran shards of the same `study run` command")
        .into());
    }
    outdir::check(other, false)?;
    let _theirs_lock = OutLock::acquire(other)?;
    std::fs::create_dir_all(run::runs_dir(&planned.out_dir)).with_context(|| {
        format!(
            "cannot create {}",
            run::runs_dir(&planned.out_dir).display()
        )
    })?;
    for spec in &planned.specs {
        let (from, to) = (
            run::run_file(other, spec.seed),
            run::run_file(&planned.out_dir, spec.seed),
        );
        // Ours stays if it is a file; theirs is read as any record (not
        // through a link, not a device), copied as it is, checked at collect.
        if std::fs::symlink_metadata(&to).is_ok_and(|m| m.file_type().is_file()) {
            continue;
        }
        match outdir::read_own(&from, outdir::RECORD_LIMIT) {
            Ok(bytes) => write_atomic(&to, &bytes)?,
            Err(outdir::Unusable::Missing) => {}
            Err(outdir::Unusable::Refused(why)) => eprintln!("study: not joined: {why}"),
        }
    }
    Ok(())
}

/// The plan of the runs in `out_dir` (from its `.study.json`): descriptor,
/// runs, and the command that makes them.
pub fn folder_plan(out_dir: &Path) -> Result<(Loaded, Vec<RunSpec>, RunCommand), StudyError> {
    let planned = plan_folder(out_dir)?;
    let rerun = planned.rerun();
    Ok((planned.loaded, planned.specs, rerun))
}

/// `study collect`: the records of the plan at `path`, stored in its output
/// folder, into tables, report and manifest, running nothing. Missing runs
/// are an error that lists them (`collect::MissingRuns`); a folder that
/// does not exist is not created.
pub fn collect_study(path: &Path, options: &CollectOptions) -> Result<Collected, StudyError> {
    let started = SystemTime::now();
    let clock = Instant::now();
    let planned = plan_study(path, options.flags(), options.out.as_ref())?;
    let invocation = Invocation {
        command_line: options.command_line.clone(),
        started,
        clock,
        threads: 1,
        runs_wall_seconds: 0.0,
        ran: 0,
        rerun: planned.rerun(),
    };
    let _lock = if planned.out_dir.is_dir() {
        Some(claim(&planned.out_dir, false)?)
    } else {
        None
    };
    collect::collect(
        &planned.loaded,
        planned.specs,
        &planned.out_dir,
        &invocation,
    )
}
