//! `study run` end to end: descriptor -> plan -> runs -> tables -> report -> manifest.
//! The calls into the analysis and report layers are the two marked seams.

use crate::descriptor::errors::{DescriptorError, StudyError};
use crate::descriptor::load::{self, Loaded};
use crate::descriptor::sweep::{self, CONFIRM_ABOVE};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::model::summary::SummaryRow;
use crate::report::ReportMeta;
use crate::runner::lock::OutLock;
use crate::runner::manifest::{Manifest, RunCounts, rfc3339, version};
use crate::runner::plan;
use crate::runner::progress::ProgressMode;
use crate::runner::publish::{self, Staging};
use crate::runner::record::RunRecord;
use crate::runner::run::{RunnerOptions, SimulateFn, run_all};
use crate::runner::store;
use anyhow::Context;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::time::{Instant, SystemTime};

/// Options of `study run` (and what `study validate` shares).
#[derive(Debug, Clone)]
pub struct StudyOptions {
    /// Output directory; default `default_out_dir`.
    pub out: Option<PathBuf>,
    pub threads: Option<usize>,
    pub replicas: Option<u32>,
    pub quick: bool,
    pub fresh: bool,
    pub progress: ProgressMode,
    /// Confirm plans of more than `CONFIRM_ABOVE` runs.
    pub yes: bool,
    /// Recorded in the manifest.
    pub command_line: Vec<String>,
}

/// What a finished study did.
#[derive(Debug, Clone)]
pub struct StudyOutcome {
    pub out_dir: PathBuf,
    pub planned: usize,
    pub ran: usize,
    pub failed: usize,
    pub resumed: usize,
}

/// Load the descriptor and apply `--quick` and `--replicas`, in that order.
pub fn prepare(path: &Path, replicas: Option<u32>, quick: bool) -> Result<Loaded, DescriptorError> {
    let mut loaded = load::load(path)?;
    if quick {
        loaded = load::quick(&loaded)?;
    }
    if let Some(n) = replicas {
        loaded = load::with_replicas(&loaded, n)?;
    }
    Ok(loaded)
}

/// Refuse plans too large to start by accident.
pub fn confirm_size(loaded: &Loaded, yes: bool) -> Result<(), DescriptorError> {
    let (points, runs) = sweep::count(loaded);
    if runs > CONFIRM_ABOVE && !yes {
        return Err(DescriptorError::new(
            &loaded.file,
            format!("the plan has {runs} runs ({points} sweep points x {} replicas), more than {CONFIRM_ABOVE}", loaded.descriptor.study.replicas),
        )
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

/// Run the study at `path`. Completed runs are kept under `OUT/runs/` so an
/// interrupted study resumes; tables, plots, report and manifest are written
/// only when every run has finished, and published together (`publish.rs`).
pub fn run_study(
    path: &Path,
    options: &StudyOptions,
    simulate: &SimulateFn<'_>,
    stop: &AtomicBool,
) -> Result<StudyOutcome, StudyError> {
    let started = SystemTime::now();
    let clock = Instant::now();
    let loaded = prepare(path, options.replicas, options.quick)?;
    confirm_size(&loaded, options.yes)?;
    let specs = plan::plan(&loaded)?;
    let out_dir = options
        .out
        .clone()
        .unwrap_or_else(|| default_out_dir(&loaded, options.quick));
    std::fs::create_dir_all(&out_dir)
        .with_context(|| format!("cannot create the output directory {}", out_dir.display()))?;
    let _lock = OutLock::acquire(&out_dir)?;
    publish::remove_leftovers(&out_dir)?;

    let runner_options = RunnerOptions {
        threads: options.threads,
        fresh: options.fresh,
        progress: options.progress,
    };
    let runs_clock = Instant::now();
    let report = run_all(&specs, &out_dir, simulate, &runner_options, stop)?;
    let runs_wall_seconds = runs_clock.elapsed().as_secs_f64();
    if report.interrupted {
        return Err(StudyError::Interrupted(
            report.records.iter().flatten().count(),
        ));
    }
    let runs: Vec<(RunSpec, RunRecord)> = specs
        .into_iter()
        .zip(report.records.into_iter().flatten())
        .collect();
    let succeeded: Vec<(RunSpec, RunOutput)> = runs
        .iter()
        .filter(|(_, r)| r.ok())
        .map(|(s, r)| (s.clone(), r.output.clone()))
        .collect();

    let staging = Staging::create(&out_dir)?;
    let summary = summarize(&succeeded);
    store::write_tables(staging.dir(), &runs, &summary)?;
    let sections = crate::studies::sections(&loaded.descriptor, &succeeded)?;
    let info = ReportMeta {
        command: options.command_line.join(" "),
        threads: report.threads,
        started: rfc3339(started),
        finished: rfc3339(SystemTime::now()),
        version: version().to_string(),
        total_wall_seconds: clock.elapsed().as_secs_f64(),
        runs_wall_seconds,
        resumed_runs: report.resumed,
        planned_runs: runs.len(),
        failed_runs: runs
            .iter()
            .filter(|(_, r)| !r.ok())
            .map(|(s, r)| (s.run_id, r.status.clone()))
            .collect(),
    };
    write_report(
        staging.dir(),
        &loaded,
        &succeeded,
        &summary,
        &sections,
        &info,
    )?;

    let counts = RunCounts {
        planned: runs.len(),
        done: report.ran,
        failed: report.failed,
        resumed: report.resumed,
    };
    let mut outputs = staging.files()?;
    outputs.push(publish::MANIFEST.to_string());
    outputs.sort();
    let manifest = Manifest {
        bonkers_version: info.version,
        command_line: options.command_line.clone(),
        started: info.started,
        finished: info.finished,
        threads: info.threads,
        runs: counts,
        overrides: loaded
            .overrides
            .iter()
            .map(|(k, v)| (k.clone(), load::show(v)))
            .collect(),
        descriptor_toml: loaded.text_as_run(),
        descriptor: serde_json::to_value(&loaded.descriptor).unwrap_or_default(),
        outputs,
    };
    let json = manifest.to_json().context("cannot encode manifest.json")?;
    crate::files::write_atomic(&staging.dir().join(publish::MANIFEST), json.as_bytes())?;
    staging.publish()?;
    Ok(StudyOutcome {
        out_dir,
        planned: counts.planned,
        ran: counts.done,
        failed: counts.failed,
        resumed: counts.resumed,
    })
}

/// Per sweep point and result: ensemble statistics beside theory.
fn summarize(runs: &[(RunSpec, RunOutput)]) -> Vec<SummaryRow> {
    crate::stats::summary::summarize(runs, &crate::studies::theory)
}

fn write_report(
    out_dir: &Path,
    loaded: &Loaded,
    runs: &[(RunSpec, RunOutput)],
    summary: &[SummaryRow],
    sections: &[crate::model::report::ReportSection],
    meta: &ReportMeta,
) -> anyhow::Result<()> {
    crate::report::write(out_dir, &loaded.descriptor, runs, summary, sections, meta)
}
