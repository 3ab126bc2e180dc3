//! The `study` command line: parse arguments, dispatch, map outcomes to exit
//! codes (0 ok, 1 some runs failed, 2 bad input, 130 interrupted).

use crate::descriptor::errors::{DescriptorError, StudyError};
use crate::descriptor::load::{Loaded, show};
use crate::descriptor::sweep;
use crate::model::run_spec::RunSpec;
use crate::runner::cluster::shard::{self, Shard};
use crate::runner::cluster::slurm::{self, SlurmJob};
use crate::runner::execute::progress::{ProgressMode, human_duration};
use crate::runner::execute::run::{SimulateFn, Subset};
use crate::runner::pipeline::{self, CollectOptions, Slice, StudyOptions};
use crate::runner::plan;
use crate::runner::plan::estimate::{self, RunCost};
use crate::runner::plan::origin::{Flags, Origin};
use crate::runner::store::collect;
use crate::runner::store::status::{self, cpu_hours};
use clap::{Args, Parser, Subcommand};
use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

#[derive(Debug, Parser)]
#[command(
    name = "study",
    version,
    about = "Ensemble studies of hard-particle gases on an exact event-driven engine"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a study: every sweep point x replica, then tables, plots and a report.
    Run(RunArgs),
    /// Make the tables, plots and report from the saved runs, running nothing.
    ///
    /// Give it the output folder (`study collect DIR`: its .study.json says how
    /// the runs were planned; `study collect DIR MORE...` first joins the runs
    /// of shards saved in other folders), or the descriptor and flags of the
    /// `study run` that saved the runs. Planned runs with no record are listed, with the
    /// command that runs exactly them, and nothing is written.
    Collect(CollectArgs),
    /// How far the study in an output folder is: runs done, failed and
    /// pending, CPU-hours spent and left, shards running now.
    Status(StatusArgs),
    /// Write Slurm batch scripts that run the study as a job array of shards,
    /// then collect; print the sbatch commands and the estimated CPU-hours.
    Slurm(SlurmArgs),
    /// Check a descriptor and print its plan without running anything.
    Validate(PlanArgs),
    /// List the bundled studies, scenes, observables and analyses.
    List,
}

#[derive(Debug, Args)]
struct PlanArgs {
    /// The study descriptor (TOML), e.g. studies/piston.toml.
    file: PathBuf,
    /// Replicas per sweep point (overrides `study.replicas`).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    replicas: Option<u32>,
    /// Apply the descriptor's [quick] overrides (a smaller, faster study).
    #[arg(long)]
    quick: bool,
    /// Accept plans of more than 100000 runs.
    #[arg(long)]
    yes: bool,
}

impl PlanArgs {
    fn flags(&self) -> Flags {
        Flags {
            quick: self.quick,
            replicas: self.replicas,
            yes: self.yes,
        }
    }
}

#[derive(Debug, Args)]
struct RunArgs {
    #[command(flatten)]
    plan: PlanArgs,
    /// Output directory (default: reports/<study name>/).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Worker threads (default: all cores; never more than the runs to do).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=MAX_THREADS))]
    threads: Option<u64>,
    /// Discard runs saved by an earlier, interrupted invocation instead of resuming.
    #[arg(long)]
    fresh: bool,
    /// Delete saved runs this plan does not have (kept otherwise: fewer
    /// replicas, a sweep value removed), and replace saved runs that another
    /// descriptor made (refused otherwise).
    #[arg(long)]
    prune: bool,
    /// Write into --out even if it is a non-empty folder that is not a
    /// study's output (bonkers still touches only names it makes itself).
    #[arg(long)]
    force: bool,
    /// No progress output.
    #[arg(long)]
    quiet: bool,
    /// Run only shard K of N (1 <= K <= N) and store its run records, no
    /// tables: every run is in exactly one shard. Shards may share --out;
    /// `study collect OUT` makes the tables once all are done.
    #[arg(long, value_name = "K/N", conflicts_with = "runs")]
    shard: Option<Shard>,
    /// Run only these runs (the run_id column, e.g. 3,7-9) and store their
    /// records, no tables; `study collect OUT` makes them.
    #[arg(long, value_name = "IDS", value_parser = parse_runs)]
    runs: Option<RunIds>,
    /// Save each unfinished run's state this often (wall seconds; 0: never),
    /// so a killed or timed-out run continues where it was when run again.
    #[arg(long, value_name = "SECONDS", default_value_t = 300.0, value_parser = parse_seconds)]
    checkpoint_every: f64,
}

/// The longest checkpoint interval, seconds (about 31 years: longer is
/// never, which 0 says).
const MAX_CHECKPOINT_SECONDS: f64 = 1e9;

fn parse_seconds(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if (0.0..=MAX_CHECKPOINT_SECONDS).contains(&s) => Ok(s),
        _ => Err(format!(
            "`{text}` is not a number of seconds from 0 to {MAX_CHECKPOINT_SECONDS:e} (0: no checkpoints)"
        )),
    }
}

/// The ids `--runs` takes, as ranges (checked against the plan later).
#[derive(Debug, Clone)]
struct RunIds(Vec<std::ops::RangeInclusive<u64>>);

fn parse_runs(text: &str) -> Result<RunIds, String> {
    collect::parse_ranges(text).map(RunIds)
}

#[derive(Debug, Args)]
struct StatusArgs {
    /// The output folder of a study (its --out).
    dir: PathBuf,
}

#[derive(Debug, Args)]
struct SlurmArgs {
    #[command(flatten)]
    plan: PlanArgs,
    /// Output folder the shards share (default: reports/<study name>/); on a
    /// cluster, a folder on the shared file system.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Array tasks, one shard each.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    shards: u32,
    /// CPUs per task: the threads of each shard.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=MAX_THREADS as i64))]
    cpus: u32,
    /// Slurm partition (default: the cluster's).
    #[arg(long)]
    partition: Option<String>,
    /// Time limit per task, as Slurm writes it (e.g. 2:00:00 or 1-12:00:00).
    #[arg(long)]
    time: Option<String>,
    /// Memory per task, as Slurm writes it (e.g. 4G).
    #[arg(long)]
    mem: Option<String>,
    /// Save each unfinished run's state this often (wall seconds; 0: never);
    /// default: `study run`'s, 300.
    #[arg(long, value_name = "SECONDS", value_parser = parse_seconds)]
    checkpoint_every: Option<f64>,
    /// Also submit both jobs with sbatch.
    #[arg(long)]
    submit: bool,
    /// Write into --out even if it is a non-empty folder that is not a
    /// study's output (bonkers still touches only names it makes itself).
    #[arg(long)]
    force: bool,
}

#[derive(Debug, Args)]
struct CollectArgs {
    #[command(flatten)]
    plan: PlanArgs,
    /// Output directory holding the runs (default: reports/<study name>/).
    #[arg(long)]
    out: Option<PathBuf>,
    /// With an output folder as FILE: more folders whose runs (shards of the
    /// same plan) are joined into it before collecting.
    #[arg(value_name = "MORE")]
    more: Vec<PathBuf>,
}

/// Set by Ctrl-C: no new runs start.
/// More worker threads than any machine has cores: a typo, refused by clap.
const MAX_THREADS: u64 = 4096;

static STOP: AtomicBool = AtomicBool::new(false);

/// Run the command line `args` (program name first); returns the exit code.
pub fn main(args: Vec<std::ffi::OsString>, simulate: &SimulateFn<'_>) -> i32 {
    let cli = match Cli::try_parse_from(args.clone()) {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() { 2 } else { 0 };
        }
    };
    let result = match cli.command {
        Command::Run(a) => run(a, args, simulate),
        Command::Collect(a) => collect(a, args),
        Command::Status(a) => status_of(&a.dir),
        Command::Slurm(a) => slurm_job(&a),
        Command::Validate(a) => validate(&a),
        Command::List => list(),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}

fn run(
    a: RunArgs,
    args: Vec<std::ffi::OsString>,
    simulate: &SimulateFn<'_>,
) -> Result<i32, StudyError> {
    // First Ctrl-C: finish the runs in flight and keep them; second: leave now.
    // Saved runs are complete files either way, so nothing partial remains.
    let _ = ctrlc::set_handler(|| {
        if STOP.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
        eprintln!("\nstudy: stopping after the runs in flight (Ctrl-C again to abandon them)");
    });
    let options = StudyOptions {
        out: a.out,
        threads: a.threads.map(|n| n as usize),
        replicas: a.plan.replicas,
        quick: a.plan.quick,
        fresh: a.fresh,
        prune: a.prune,
        progress: if a.quiet {
            ProgressMode::Quiet
        } else {
            ProgressMode::Auto
        },
        yes: a.plan.yes,
        command_line: args
            .iter()
            .map(|s| s.to_string_lossy().into_owned())
            .collect(),
        checkpoint_every: Some(std::time::Duration::from_secs_f64(a.checkpoint_every)),
        force: a.force,
    };
    let slice = match (a.shard, a.runs) {
        (Some(shard), _) => Some(Slice::Shard(shard)),
        (None, Some(RunIds(ids))) => Some(Slice::Runs(ids)),
        (None, None) => None,
    };
    if let Some(slice) = slice {
        return run_slice(&a.plan.file, &options, &slice, simulate);
    }
    let outcome = pipeline::run_study(&a.plan.file, &options, simulate, &STOP)?;
    if !a.quiet {
        if outcome.continued > 0 {
            eprintln!(
                "study: {} run(s) continued from their checkpoints",
                outcome.continued
            );
        }
        eprintln!(
            "study: {} runs ({} run now, {} resumed, {} failed) -> {}",
            outcome.planned,
            outcome.ran,
            outcome.resumed,
            outcome.failed,
            outcome.out_dir.display()
        );
    }
    if outcome.failed > 0 {
        eprintln!(
            "study: {} run(s) failed; their status is in runs.parquet; run again to retry them",
            outcome.failed
        );
        return Ok(1);
    }
    Ok(0)
}

/// `study run --shard` or `--runs`: records only.
fn run_slice(
    file: &Path,
    options: &StudyOptions,
    slice: &Slice,
    simulate: &SimulateFn<'_>,
) -> Result<i32, StudyError> {
    let report = pipeline::run_slice(file, options, slice, simulate, &STOP)?;
    let what = match slice {
        Slice::Shard(s) => format!("shard {s}"),
        Slice::Runs(_) => "the runs asked for".to_string(),
    };
    let out = options
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("<its --out>"));
    if options.progress != ProgressMode::Quiet && report.continued > 0 {
        eprintln!(
            "study: {what}: {} run(s) continued from their checkpoints",
            report.continued
        );
    }
    if options.progress != ProgressMode::Quiet || report.failed > 0 {
        eprintln!(
            "study: {what}: {} runs ({} run now, {} resumed, {} failed) -> {}; `study collect {}` makes the tables once every part is done",
            report.picked,
            report.ran,
            report.resumed,
            report.failed,
            out.display(),
            pipeline::shell_word(&out.to_string_lossy())
        );
    }
    Ok(if report.failed > 0 { 1 } else { 0 })
}

fn collect(a: CollectArgs, args: Vec<std::ffi::OsString>) -> Result<i32, StudyError> {
    let command_line: Vec<String> = args
        .iter()
        .map(|s| s.to_string_lossy().into_owned())
        .collect();
    if a.plan.file.is_dir() {
        let dir = a.plan.file.display().to_string();
        if a.out.is_some() || a.plan.quick || a.plan.replicas.is_some() {
            return Err(DescriptorError::new(
                &dir,
                "is an output folder: --out, --quick and --replicas go with a descriptor",
            )
            .hint(format!(
                "`study collect {dir}` alone collects the plan its .study.json saved"
            ))
            .into());
        }
        let outcome = pipeline::collect_folder(&a.plan.file, &a.more, command_line)?;
        return Ok(collected(&outcome));
    }
    if let Some(more) = a.more.first() {
        return Err(DescriptorError::new(
            &more.display().to_string(),
            "more folders go with an output folder, not with a descriptor",
        )
        .hint("`study collect DIR MORE...` joins the runs of MORE into DIR and collects them")
        .into());
    }
    let options = CollectOptions {
        out: a.out,
        replicas: a.plan.replicas,
        quick: a.plan.quick,
        yes: a.plan.yes,
        command_line: args
            .iter()
            .map(|s| s.to_string_lossy().into_owned())
            .collect(),
    };
    let outcome = pipeline::collect_study(&a.plan.file, &options)?;
    Ok(collected(&outcome))
}

/// Say what a collect made; the exit code.
fn collected(outcome: &collect::Collected) -> i32 {
    eprintln!(
        "study: collected {} runs -> {}",
        outcome.planned,
        outcome.out_dir.display()
    );
    eprintln!(
        "study: the runs took {} (the plan estimated {})",
        cpu_hours(outcome.cpu_seconds),
        cpu_hours(outcome.estimated_seconds)
    );
    if !outcome.failed.is_empty() {
        eprint!(
            "study: {} run(s) failed; their status is in runs.parquet:\n{}",
            outcome.failed.len(),
            collect::listing(&outcome.failed)
        );
        eprintln!(
            "study: `{}` retries them; then `study collect {}`",
            outcome.retry,
            pipeline::shell_word(&outcome.out_dir.to_string_lossy())
        );
        return 1;
    }
    0
}

/// `study status DIR`.
fn status_of(dir: &Path) -> Result<i32, StudyError> {
    let (loaded, specs, rerun) = pipeline::folder_plan(dir)?;
    let status = status::status(&specs, dir);
    emit(&status.text(&loaded.descriptor.study.name, dir, &rerun));
    Ok(0)
}

/// `study slurm`.
fn slurm_job(a: &SlurmArgs) -> Result<i32, StudyError> {
    let absolute = |p: &Path| std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf());
    // What goes into the scripts is checked first (`script_text`).
    slurm::check_flags(a.partition.as_deref(), a.mem.as_deref(), a.time.as_deref())?;
    crate::runner::cluster::script_text::path_text("FILE", &absolute(&a.plan.file))?;
    let loaded = pipeline::prepare(&a.plan.file, a.plan.flags())?;
    pipeline::confirm_size(&loaded, a.plan.yes)?;
    let specs = plan::plan(&loaded)?;
    pipeline::confirm_cost(&loaded, &specs, a.plan.yes)?;
    if a.shards as usize > specs.len() {
        return Err(DescriptorError::new(
            "--shards",
            format!(
                "{} is more shards than the plan has runs ({})",
                a.shards,
                specs.len()
            ),
        )
        .hint(format!(
            "a shard holds at least one run: give --shards 1 to {}",
            specs.len()
        ))
        .into());
    }
    let out = a
        .out
        .clone()
        .unwrap_or_else(|| pipeline::default_out_dir(&loaded, a.plan.quick));
    crate::runner::cluster::script_text::directive_path("--out", &absolute(&out))?;
    crate::runner::store::outdir::check(&out, a.force)?;
    // So `study status OUT` knows the plan before any task has started.
    let origin = Origin::new(&a.plan.file, &loaded, a.plan.flags());
    pipeline::guard(&specs, Subset::All, &out, &origin)?;
    let study = std::env::current_exe()
        .map_err(|e| StudyError::Other(anyhow::anyhow!("cannot find the study executable: {e}")))?;
    let job = SlurmJob {
        study,
        file: absolute(&a.plan.file),
        out: absolute(&out),
        flags: a.plan.flags(),
        name: loaded.descriptor.study.name.clone(),
        shards: a.shards,
        cpus: a.cpus,
        partition: a.partition.clone(),
        time: a.time.clone(),
        mem: a.mem.clone(),
        checkpoint_every: a.checkpoint_every,
    };
    let (shards_path, collect_path) = job.write()?;
    crate::runner::plan::origin::save(&job.out, &origin)?;
    let seconds = shard::estimated_seconds(&specs);
    let loads = shard::loads(&seconds, &shard::deal(&seconds, a.shards), a.shards);
    emit(&slurm_summary(
        &job,
        &loads,
        specs.len(),
        &shards_path,
        &collect_path,
    ));
    if a.submit {
        let (array, after) = slurm::submit(&shards_path, &collect_path)?;
        emit(&format!(
            "submitted: array job {array} ({} tasks), collect job {after} after it\n  watch it with `squeue -j {array},{after}` and `study status {}`\n",
            a.shards,
            pipeline::shell_word(&job.out.to_string_lossy())
        ));
    }
    Ok(0)
}

/// What `study slurm` prints: the scripts, the cost, the commands.
fn slurm_summary(
    job: &SlurmJob,
    loads: &[f64],
    runs: usize,
    shards_path: &Path,
    collect_path: &Path,
) -> String {
    let total: f64 = loads.iter().sum();
    let mut out = format!(
        "wrote {} (an array of {} shards of the {runs} runs, {} CPU(s) each) and {}\n",
        shards_path.display(),
        job.shards,
        job.cpus,
        collect_path.display()
    );
    let _ = writeln!(
        out,
        "estimated cost: ~{} in total (the plan's estimate: see `study validate`)",
        cpu_hours(total)
    );
    let wall = |s: f64| human_duration(s / f64::from(job.cpus));
    if loads.len() <= 16 {
        for (k, l) in loads.iter().enumerate() {
            let _ = writeln!(
                out,
                "  shard {}: ~{} (~{} of wall time on {} CPU(s))",
                k + 1,
                cpu_hours(*l),
                wall(*l),
                job.cpus
            );
        }
    } else {
        let max = loads.iter().copied().fold(0.0, f64::max);
        let min = loads.iter().copied().fold(f64::INFINITY, f64::min);
        let _ = writeln!(
            out,
            "  per shard: ~{} to ~{} (the longest ~{} of wall time on {} CPU(s))",
            cpu_hours(min),
            cpu_hours(max),
            wall(max),
            job.cpus
        );
    }
    let longest = loads.iter().copied().fold(0.0, f64::max) / f64::from(job.cpus);
    if let Some(limit) = job.time.as_deref().and_then(slurm::time_limit_seconds)
        && longest > limit
    {
        let _ = writeln!(
            out,
            "  note: the longest shard is estimated at ~{}, more than --time {}: its runs checkpoint, so submitting it again continues them, but more --shards or a longer --time avoids that",
            human_duration(longest),
            job.time.as_deref().unwrap_or("")
        );
    }
    let [submit, after] = slurm::submit_commands(shards_path, collect_path);
    let _ = writeln!(out, "submit with:\n  {submit}\n  {after}");
    out
}

fn validate(a: &PlanArgs) -> Result<i32, StudyError> {
    let loaded = pipeline::prepare(&a.file, a.flags())?;
    pipeline::confirm_size(&loaded, a.yes)?;
    let specs = plan::plan(&loaded)?;
    pipeline::confirm_cost(&loaded, &specs, a.yes)?;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    emit(&describe_plan(&loaded, &specs, threads));
    Ok(0)
}

/// The plan in words: sweep, counts, and the estimated collisions and time
/// on `threads` threads.
pub fn describe_plan(loaded: &Loaded, specs: &[RunSpec], threads: usize) -> String {
    let d = &loaded.descriptor;
    let (points, _) = sweep::count(loaded);
    // One estimate per point (replicas differ only in their seeds), times its runs.
    let costs = estimate::by_point(specs);
    let known: Vec<(RunCost, f64)> = costs
        .iter()
        .filter_map(|(_, c, n)| Some(((*c)?, *n)))
        .collect();
    // "ok" promises a plan that can be run as estimated; without an estimate
    // it is only valid.
    let unknown = known.is_empty() || known.len() < costs.len();
    let verdict = if unknown { "valid, cost unknown" } else { "ok" };
    let mut out = format!("{}: {verdict} — {}\n", loaded.file, d.study.name);
    if let Some(sweep) = &d.sweep {
        out += &format!("  sweep ({:?}):\n", sweep.mode).to_lowercase();
        for (key, values) in &sweep.parameters {
            out += &format!("    {key} = [{}]\n", sweep::values_text(values, show));
        }
    }
    let cases = d.case.len() as u64;
    let cases_text = if cases > 0 {
        let names: Vec<&str> = d.case.iter().map(|c| c.name.as_str()).collect();
        format!(" and {cases} case(s) ({})", names.join(", "))
    } else {
        String::new()
    };
    out += &format!(
        "  points: {}{cases_text}, replicas: {}, runs: {}\n",
        points - cases,
        d.study.replicas,
        specs.len()
    );
    out += &crate::runner::plan::error_bars::describe(specs);
    out += &crate::runner::plan::trajectory::describe(specs);
    if unknown {
        out += &format!(
            "  estimated cost: unknown for {} of {} points (their scenes give no collision \
             rate to estimate from); the descriptor is valid, but how long its runs take is \
             not known\n",
            costs.len() - known.len(),
            costs.len()
        );
        return out;
    }
    let collisions: f64 = known.iter().map(|(c, n)| c.collisions * n).sum();
    let events: f64 = known.iter().map(|(c, n)| c.events * n).sum();
    let seconds: f64 = known.iter().map(|(c, n)| c.seconds() * n).sum();
    let busy = threads.min(specs.len()).max(1);
    let dims: BTreeSet<usize> = known.iter().map(|(c, _)| c.dimension).collect();
    let rates: Vec<String> = dims
        .iter()
        .map(|&dim| {
            format!(
                "{} collisions/s per thread in {dim}D",
                approx(estimate::COLLISIONS_PER_SECOND[dim - 1])
            )
        })
        .collect();
    out += &format!(
        "  estimated collisions: ~{} pair collisions ({} per run on average; kinetic theory of the initial state), ~{} events with the wall hits and neighbourhood renewals\n",
        approx(collisions),
        approx(collisions / specs.len().max(1) as f64),
        approx(events)
    );
    out += &format!(
        "  estimated time: ~{} on {busy} {}, at a nominal {} (docs/performance.md; any event counted as a collision); an estimate: sampling, analyses and dense or uneven scenes change it\n",
        human_duration(seconds / busy as f64),
        if busy == 1 { "thread" } else { "threads" },
        rates.join(", ")
    );
    out
}

/// 1234 -> "1234", 1.5e7 -> "1.5e7".
fn approx(x: f64) -> String {
    if x < 1e4 {
        format!("{x:.0}")
    } else {
        format!("{x:.1e}")
    }
}

fn list() -> Result<i32, StudyError> {
    emit(&listing());
    Ok(0)
}

/// What `study list` prints.
pub fn listing() -> String {
    let mut out = String::new();
    let candidates = studies_dirs();
    match candidates.iter().find(|d| d.is_dir()) {
        Some(dir) => {
            let _ = writeln!(out, "studies ({}):", dir.display());
            let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
                .map(|it| {
                    it.flatten()
                        .map(|e| e.path())
                        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                        .collect()
                })
                .unwrap_or_default();
            files.sort();
            if files.is_empty() {
                let _ = writeln!(out, "  (none found)");
            }
            for f in files {
                let stem = f
                    .file_stem()
                    .unwrap_or_default()
                    .to_string_lossy()
                    .into_owned();
                let _ = writeln!(out, "  {stem:<24} {}", description(&f));
            }
        }
        None => {
            let looked: Vec<String> = candidates.iter().map(|d| d.display().to_string()).collect();
            let _ = writeln!(out, "studies: none found (looked in {})", looked.join(", "));
        }
    }
    let _ = writeln!(out, "scenes ([scene] preset = \"<name>\"):");
    for p in crate::scene::presets::list() {
        let _ = writeln!(out, "  {:<24} {}", p.name, p.about);
    }
    let _ = writeln!(
        out,
        "observables ([observe] series / scalars / histograms = [\"<name>\"]):"
    );
    for e in crate::observe::CATALOGUE {
        let needs: Vec<String> = e
            .needs
            .iter()
            .map(|n| crate::observe::catalogue::need_text(*n))
            .collect();
        let mut line = format!(
            "  {:<10} {:<26} {} [{}]",
            e.kind.key(),
            e.name,
            e.doc,
            e.unit
        );
        if e.writes != e.name {
            let _ = write!(line, "; writes {}", e.writes);
        }
        if !needs.is_empty() {
            let _ = write!(line, "; needs {}", needs.join(", "));
        }
        let _ = writeln!(out, "{line}");
    }
    let _ = writeln!(out, "analyses ([analysis.<name>]):");
    for a in crate::studies::REGISTRY {
        let options: Vec<String> = a
            .options()
            .iter()
            .map(|o| format!("{} ({}, default {})", o.name, o.range_text(), o.default))
            .collect();
        let options = if options.is_empty() {
            "no options".to_string()
        } else {
            format!("options: {}", options.join(", "))
        };
        let _ = writeln!(out, "  {:<24} {}; {options}", a.name(), a.about());
    }
    out
}

/// Where bundled studies may be, in order: `studies/` of the working
/// directory; beside the executable or up to three folders above it
/// (`target/release/study` in a checkout); the source tree it was built from.
fn studies_dirs() -> Vec<PathBuf> {
    let mut dirs = vec![PathBuf::from("studies")];
    if let Ok(exe) = std::env::current_exe() {
        dirs.extend(exe.ancestors().skip(1).take(4).map(|a| a.join("studies")));
    }
    dirs.push(Path::new(env!("CARGO_MANIFEST_DIR")).join("studies"));
    dirs
}

fn description(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    match text.parse::<toml::Table>() {
        Ok(t) => t
            .get("study")
            .and_then(|s| s.get("description"))
            .and_then(toml::Value::as_str)
            .unwrap_or("")
            .lines()
            .next()
            .unwrap_or("")
            .to_string(),
        Err(_) => "(does not parse; see `study validate`)".to_string(),
    }
}

/// Print to stdout; a closed pipe (`study list | head`) is not an error.
fn emit(text: &str) {
    use std::io::Write;
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
}
