//! The `study` command line: parse arguments, dispatch, map outcomes to exit
//! codes (0 ok, 1 some runs failed, 2 bad input, 130 interrupted).

use super::descriptor::{Loaded, show};
use super::errors::StudyError;
use super::pipeline::{self, StudyOptions};
use super::plan;
use super::progress::ProgressMode;
use super::runner::SimulateFn;
use clap::{Args, Parser, Subcommand};
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
    /// Check a descriptor and print its plan without running anything.
    Validate(PlanArgs),
    /// List the bundled studies and scenes.
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

#[derive(Debug, Args)]
struct RunArgs {
    #[command(flatten)]
    plan: PlanArgs,
    /// Output directory (default: reports/<study name>/).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
    threads: Option<u64>,
    /// Discard runs saved by an earlier, interrupted invocation instead of resuming.
    #[arg(long)]
    fresh: bool,
    /// No progress output.
    #[arg(long)]
    quiet: bool,
}

/// Set by Ctrl-C: no new runs start.
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
    };
    let outcome = pipeline::run_study(&a.plan.file, &options, simulate, &STOP)?;
    if !a.quiet {
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

fn validate(a: &PlanArgs) -> Result<i32, StudyError> {
    let loaded = pipeline::prepare(&a.file, a.replicas, a.quick)?;
    pipeline::confirm_size(&loaded, a.yes)?;
    let specs = plan::plan(&loaded)?;
    print!("{}", describe_plan(&loaded, specs.len()));
    Ok(0)
}

/// The plan in words: sweep, counts and a crude cost estimate.
pub fn describe_plan(loaded: &Loaded, runs: usize) -> String {
    let d = &loaded.descriptor;
    let (points, _) = plan::count(loaded);
    let mut out = format!("{}: ok — {}\n", loaded.file, d.study.name);
    if let Some(sweep) = &d.sweep {
        out += &format!("  sweep ({:?}):\n", sweep.mode).to_lowercase();
        for (key, values) in &sweep.parameters {
            let v: Vec<String> = plan::expand_values(values).iter().map(show).collect();
            out += &format!("    {key} = [{}]\n", v.join(", "));
        }
    }
    out += &format!(
        "  points: {points}, replicas: {}, runs: {runs}\n",
        d.study.replicas
    );
    let particles: usize = d.scene.species.iter().map(|s| s.count).sum();
    let estimate = match (d.run.collisions, d.run.duration) {
        (Some(c), _) => format!("{:.3e} collisions ({} per run)", c as f64 * runs as f64, c),
        (None, Some(t)) if particles > 0 => format!(
            "~{:.1e} collisions (crude: about one collision per particle per unit time, {particles} particles x {t} time units per run)",
            particles as f64 * (t + d.run.equilibrate) * runs as f64
        ),
        _ => "unknown (the particle count comes from a preset)".to_string(),
    };
    out += &format!("  estimated cost: {estimate}\n");
    out
}

fn list() -> Result<i32, StudyError> {
    let dir = studies_dir();
    println!("studies ({}):", dir.display());
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|it| {
            it.flatten()
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    if files.is_empty() {
        println!("  (none found)");
    }
    for f in files {
        let stem = f
            .file_stem()
            .unwrap_or_default()
            .to_string_lossy()
            .into_owned();
        println!("  {stem:<20} {}", description(&f));
    }
    let scenes = scene_presets();
    println!("scenes:");
    if scenes.is_empty() {
        println!("  (no bundled scenes in this build; describe the scene in [scene])");
    }
    for (name, about) in scenes {
        println!("  {name:<20} {about}");
    }
    Ok(0)
}

/// `studies/` of the working directory, else the one shipped with the source.
fn studies_dir() -> PathBuf {
    let local = Path::new("studies");
    if local.is_dir() {
        local.to_path_buf()
    } else {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("studies")
    }
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

/// SEAM (scenes): bundled scene presets as (name, one-line description);
/// switch to `crate::scene::presets::list()` once presets exist.
fn scene_presets() -> Vec<(String, String)> {
    crate::scene::presets::list()
        .iter()
        .map(|p| (p.name.to_string(), p.about.to_string()))
        .collect()
}
