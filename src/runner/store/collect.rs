//! Collect: the stored run records of a plan -> tables, report and manifest,
//! published as one set (`publish.rs`). It runs nothing. A planned run
//! without a usable record is listed, with the command that runs it, and
//! nothing is written; failed runs are listed and kept in the tables, as
//! their status.
//!
//! Memory: records are read one at a time, in plan order. The long tables
//! (series, histograms) are written as they stream past, a row group at a
//! time; what is held is each run's scalars and histograms, the series of
//! the first few replicas of each point, and each point's series means
//! (`stats::ensemble`): memory grows with the plan's points, not its
//! replicas, and never holds the samples of all runs.

use crate::descriptor::errors::StudyError;
use crate::descriptor::load::{self, Loaded};
use crate::files::write_atomic;
use crate::model::movie::MovieSpec;
use crate::model::report::ReportSection;
use crate::model::run_spec::RunSpec;
use crate::model::summary::SummaryRow;
use crate::report::ReportMeta;
use crate::runner::execute::run::{Stored, fingerprint, read_record};
use crate::runner::store;
use crate::runner::store::manifest::{Manifest, RunCounts, rfc3339, version};
use crate::runner::store::publish::{self, Staging};
use crate::stats::ensemble::Runs;
use anyhow::Context;
use std::fmt;
use std::path::{Path, PathBuf};
use std::time::{Instant, SystemTime};

/// The invocation that collects, as the report and the manifest tell it.
#[derive(Debug, Clone)]
pub struct Invocation {
    pub command_line: Vec<String>,
    pub started: SystemTime,
    /// Started with the invocation: the report's total wall time.
    pub clock: Instant,
    /// Worker threads of the runs this invocation ran (1 if it ran none).
    pub threads: usize,
    /// Wall time spent running runs, and how many ran (the rest were saved
    /// by earlier invocations).
    pub runs_wall_seconds: f64,
    pub ran: usize,
    /// The command that runs what is missing, shown when something is.
    pub rerun: RunCommand,
}

/// The `study run` that makes a plan's runs into its folder, as words:
/// `head` is `study run FILE --out DIR`, `tail` the flags that set the plan
/// (`--quick`, `--replicas`, `--yes`).
#[derive(Debug, Clone, PartialEq)]
pub struct RunCommand {
    pub head: String,
    pub tail: String,
    /// The output folder as typed, for the `study collect` that follows a part.
    pub out: String,
}

impl RunCommand {
    /// Runs (or resumes) the whole plan, then collects.
    pub fn whole(&self) -> String {
        format!("{}{}", self.head, self.tail)
    }

    /// Runs exactly the runs `ids` (ascending), records only: a
    /// `study collect` of `out` follows.
    pub fn for_runs(&self, ids: &[u64]) -> String {
        let ranges = id_ranges(ids).replace(' ', "");
        format!("{} --runs {ranges}{}", self.head, self.tail)
    }
}

/// A planned run that has no usable record, or whose record says it failed.
#[derive(Debug, Clone, PartialEq)]
pub struct Unfinished {
    pub run_id: u64,
    pub point_id: u64,
    pub replica: u32,
    pub seed: u64,
    /// The point's swept values, e.g. "scene.piston.mass = 10.0".
    pub point: String,
    /// "no record", why the record cannot be used, or the failed status.
    pub why: String,
}

impl Unfinished {
    fn of(spec: &RunSpec, why: String) -> Unfinished {
        Unfinished {
            run_id: spec.run_id,
            point_id: spec.point_id,
            replica: spec.replica,
            seed: spec.seed,
            point: spec
                .params
                .iter()
                .map(|(k, v)| format!("{k} = {}", load::show(v)))
                .collect::<Vec<_>>()
                .join(", "),
            why,
        }
    }
}

impl fmt::Display for Unfinished {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let point = if self.point.is_empty() {
            String::new()
        } else {
            format!(": {}", self.point)
        };
        write!(
            f,
            "run {} (point {}{point}; replica {}; seed {}): {}",
            self.run_id, self.point_id, self.replica, self.seed, self.why
        )
    }
}

/// Collect refused: these planned runs have no usable record.
#[derive(Debug, Clone)]
pub struct MissingRuns {
    pub out_dir: PathBuf,
    pub planned: usize,
    pub missing: Vec<Unfinished>,
    /// The command that runs them (and keeps the runs already saved).
    pub rerun: String,
    /// The command that runs exactly them and nothing else (beside shards
    /// still running, say), when some runs do have records; then
    /// `study collect` of `collect` makes the tables.
    pub exact: Option<String>,
    pub collect: String,
}

impl fmt::Display for MissingRuns {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{} of the {} planned runs have no usable record in {}, so nothing was written:",
            self.missing.len(),
            self.planned,
            self.out_dir.display()
        )?;
        f.write_str(&listing(&self.missing))?;
        write!(f, "  hint: run them with `{}`", self.rerun)?;
        if let Some(exact) = &self.exact {
            write!(
                f,
                "\n  hint: or exactly them, records only (e.g. while shards still run): `{exact}`, then `study collect {}`",
                self.collect
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for MissingRuns {}

/// Lines listed in full; the rest are summed up by their ids.
const LISTED: usize = 20;

/// One indented line per run, the first `LISTED` of them, then the ids of
/// the others as ranges.
pub fn listing(runs: &[Unfinished]) -> String {
    let mut out = String::new();
    for run in runs.iter().take(LISTED) {
        out += &format!("  {run}\n");
    }
    if runs.len() > LISTED {
        let ids: Vec<u64> = runs[LISTED..].iter().map(|r| r.run_id).collect();
        out += &format!(
            "  and {} more: runs {}\n",
            runs.len() - LISTED,
            id_ranges(&ids)
        );
    }
    out
}

/// Ascending ids as "0-4, 7, 9-10".
fn id_ranges(ids: &[u64]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut i = 0;
    while i < ids.len() {
        let mut j = i;
        while j + 1 < ids.len() && ids[j + 1] == ids[j] + 1 {
            j += 1;
        }
        parts.push(if j == i {
            ids[i].to_string()
        } else {
            format!("{}-{}", ids[i], ids[j])
        });
        i = j + 1;
    }
    parts.join(", ")
}

/// "0-4,7,9-10" (as `--runs` takes them) -> ascending, disjoint ranges of
/// ids, not the ids: a range can be as long as u64 allows until it is
/// checked against the plan (`pipeline::ids_in_plan`).
pub fn parse_ranges(text: &str) -> Result<Vec<std::ops::RangeInclusive<u64>>, String> {
    let bad = |part: &str| {
        format!(
            "`{part}` is not a run id or a range of them: write e.g. `3,7-9` (the run_id column)"
        )
    };
    let mut ranges = Vec::new();
    for part in text.split(',').map(str::trim) {
        let number = |s: &str| s.trim().parse::<u64>().map_err(|_| bad(part));
        let (a, b) = match part.split_once('-') {
            Some((a, b)) => (number(a)?, number(b)?),
            None => (number(part)?, number(part)?),
        };
        if a > b {
            return Err(bad(part));
        }
        ranges.push((a, b));
    }
    ranges.sort_unstable();
    let mut merged: Vec<std::ops::RangeInclusive<u64>> = Vec::with_capacity(ranges.len());
    for (a, b) in ranges {
        match merged.last_mut() {
            Some(last) if a <= last.end().saturating_add(1) => {
                *last = *last.start()..=b.max(*last.end());
            }
            _ => merged.push(a..=b),
        }
    }
    Ok(merged)
}

/// What a collect made.
#[derive(Debug, Clone)]
pub struct Collected {
    pub out_dir: PathBuf,
    pub planned: usize,
    /// Run by this invocation, and saved by earlier ones.
    pub ran: usize,
    pub resumed: usize,
    /// Runs whose record says they failed: in runs.parquet with their
    /// status, absent from the statistics.
    pub failed: Vec<Unfinished>,
    /// The command that retries exactly the failed runs, records only ("" if
    /// none failed); `study collect` then remakes the tables.
    pub retry: String,
    /// CPU seconds the runs took, as their records say, and as the plan's
    /// estimate expected.
    pub cpu_seconds: f64,
    pub estimated_seconds: f64,
}

/// Collect the records of the plan `specs` saved in `out_dir` into the
/// tables, report and manifest there. The caller holds the out dir's lock.
pub fn collect(
    loaded: &Loaded,
    specs: Vec<RunSpec>,
    out_dir: &Path,
    invocation: &Invocation,
) -> Result<Collected, StudyError> {
    let planned = specs.len();
    let estimated_seconds: f64 = crate::runner::cluster::shard::estimated_seconds(&specs)
        .iter()
        .sum();
    let Streamed {
        staged,
        runs,
        missing,
        failed,
        cpu_seconds,
    } = stream(specs, out_dir)?;
    if !missing.is_empty() {
        return Err(StudyError::Other(anyhow::Error::new(MissingRuns {
            out_dir: out_dir.to_path_buf(),
            planned,
            rerun: invocation.rerun.whole(),
            exact: (missing.len() < planned).then(|| {
                invocation
                    .rerun
                    .for_runs(&missing.iter().map(|u| u.run_id).collect::<Vec<_>>())
            }),
            collect: invocation.rerun.out.clone(),
            missing,
        })));
    }

    let (staging, tables) = match staged {
        Some(staged) => staged,
        None => staging(out_dir)?,
    };
    let summary = summarize(&runs);
    tables.finish(&summary)?;
    let failed_runs: Vec<(u64, String)> =
        failed.iter().map(|u| (u.run_id, u.why.clone())).collect();
    let mut sections = crate::studies::sections(&loaded.descriptor, &runs)?;
    if let Some(movie) = &loaded.descriptor.observe.movie {
        sections.extend(film_run(&runs, movie, staging.dir())?);
    }
    let resumed = planned.saturating_sub(invocation.ran);
    let meta = ReportMeta {
        command: invocation.command_line.join(" "),
        threads: invocation.threads,
        started: rfc3339(invocation.started),
        finished: rfc3339(SystemTime::now()),
        version: version().to_string(),
        total_wall_seconds: invocation.clock.elapsed().as_secs_f64(),
        runs_wall_seconds: invocation.runs_wall_seconds,
        resumed_runs: resumed,
        planned_runs: planned,
        failed_runs,
    };
    crate::report::write(
        staging.dir(),
        &loaded.descriptor,
        &runs,
        &summary,
        &sections,
        &meta,
    )?;

    let counts = RunCounts {
        planned,
        done: invocation.ran,
        failed: failed.len(),
        resumed,
    };
    write_manifest(&staging, loaded, invocation, meta, counts)?;
    staging.publish()?;
    let retry = if failed.is_empty() {
        String::new()
    } else {
        let ids: Vec<u64> = failed.iter().map(|u| u.run_id).collect();
        invocation.rerun.for_runs(&ids)
    };
    Ok(Collected {
        out_dir: out_dir.to_path_buf(),
        planned,
        ran: invocation.ran,
        resumed,
        failed,
        retry,
        cpu_seconds,
        estimated_seconds,
    })
}

/// The plan's records, read one at a time in plan order.
struct Streamed {
    /// The staging folder, once a record is read, with the tables written
    /// into it so far (the long ones, and each run's row).
    staged: Option<(Staging, store::Tables)>,
    /// The successful runs, as the studies and the report take them.
    runs: Runs,
    /// Once a run is missing, nothing more is gathered: nothing will be written.
    missing: Vec<Unfinished>,
    failed: Vec<Unfinished>,
    /// CPU seconds the runs took, as their records say.
    cpu_seconds: f64,
}

/// Read the records of `specs` from `out_dir` one at a time into staged
/// tables and the runs the report takes; a record made by another
/// descriptor or bonkers version, or one that does not parse, counts as
/// missing.
fn stream(specs: Vec<RunSpec>, out_dir: &Path) -> anyhow::Result<Streamed> {
    let mut streamed = Streamed {
        staged: None,
        runs: Runs::default(),
        missing: Vec::new(),
        failed: Vec::new(),
        cpu_seconds: 0.0,
    };
    for spec in specs {
        let why = match read_record(out_dir, &spec) {
            Stored::Found(record) if record.fingerprint == fingerprint(&spec) => {
                if !record.ok() {
                    let failed = Unfinished::of(&spec, record.status.clone());
                    streamed.failed.push(failed);
                }
                if streamed.missing.is_empty() {
                    if record.output.cpu_seconds.is_finite() {
                        streamed.cpu_seconds += record.output.cpu_seconds;
                    }
                    let (_, tables) = match &mut streamed.staged {
                        Some(staged) => staged,
                        staged => staged.insert(staging(out_dir)?),
                    };
                    tables.add(&spec, &record)?;
                    if record.ok() {
                        streamed.runs.push(spec, record.output);
                    }
                }
                continue;
            }
            Stored::Found(_) => {
                "its record was made by another descriptor or bonkers version".to_string()
            }
            Stored::Unreadable(e) => format!("its record is unreadable: {e}"),
            Stored::Missing => "no record".to_string(),
        };
        if streamed.missing.is_empty() {
            streamed.staged = None;
            streamed.runs = Runs::default();
        }
        streamed.missing.push(Unfinished::of(&spec, why));
    }
    Ok(streamed)
}

/// A fresh staging folder in `out_dir`, with tables to be written there.
fn staging(out_dir: &Path) -> anyhow::Result<(Staging, store::Tables)> {
    let staging = Staging::create(out_dir)?;
    let tables = store::Tables::new(staging.dir());
    Ok((staging, tables))
}

/// Per sweep point and result: ensemble statistics of the successful runs
/// beside theory, one point at a time (the plan keeps each point's runs
/// together, in point order).
fn summarize(runs: &Runs) -> Vec<SummaryRow> {
    let mut rows = Vec::new();
    for point in runs.chunk_by(|a, b| a.0.point_id == b.0.point_id) {
        rows.extend(crate::stats::summary::summarize(
            point,
            &crate::studies::theory,
        ));
    }
    rows
}

/// The manifest lists the staged files and itself, and is staged last.
fn write_manifest(
    staging: &Staging,
    loaded: &Loaded,
    invocation: &Invocation,
    meta: ReportMeta,
    counts: RunCounts,
) -> anyhow::Result<()> {
    let mut outputs = staging.files()?;
    outputs.push(publish::MANIFEST.to_string());
    outputs.sort();
    let manifest = Manifest {
        bonkers_version: meta.version,
        command_line: invocation.command_line.clone(),
        started: meta.started,
        finished: meta.finished,
        threads: meta.threads,
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
    crate::files::write_atomic(&staging.dir().join(publish::MANIFEST), json.as_bytes())
}

/// `[observe] movie`: the run it names (or the first that succeeded),
/// filmed again from its start and written as `movie.svg`, with the section
/// that shows it.
fn film_run(runs: &Runs, movie: &MovieSpec, dir: &Path) -> anyhow::Result<Option<ReportSection>> {
    let named = runs.iter().find(|(s, _)| s.run_id == movie.run);
    let Some((spec, output)) = named.or_else(|| runs.iter().min_by_key(|(s, _)| s.run_id)) else {
        return Ok(None);
    };
    // The movie films its run again: twice the run's events is room enough.
    let budget = output.events.saturating_mul(2).saturating_add(1_000_000);
    let film = crate::runner::execute::movie::film(spec, movie, budget)
        .with_context(|| format!("filming run {} for the movie", spec.run_id))?;
    write_atomic(
        &dir.join(MOVIE_FILE),
        crate::report::movie::svg(&film).as_bytes(),
    )?;
    Ok(Some(ReportSection {
        title: "Movie".into(),
        markdown: crate::report::movie::section(&film, MOVIE_FILE),
        figures: Vec::new(),
        presents: Vec::new(),
    }))
}

const MOVIE_FILE: &str = "movie.svg";

#[cfg(test)]
mod tests {
    use super::{id_ranges, parse_ranges};

    #[test]
    fn ranges_parse_back() {
        assert_eq!(parse_ranges("0-4,7,9-10"), Ok(vec![0..=4, 7..=7, 9..=10]));
        assert_eq!(parse_ranges("5, 3,3"), Ok(vec![3..=3, 5..=5]));
        assert_eq!(parse_ranges("4-6,0-2,3,9"), Ok(vec![0..=6, 9..=9]));
        let all = u64::MAX;
        assert_eq!(parse_ranges(&format!("0-{all},{all}")), Ok(vec![0..=all]));
        for bad in ["", "4-2", "x", "1-", "-3"] {
            assert!(parse_ranges(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn ids_are_shown_as_ranges() {
        assert_eq!(id_ranges(&[0, 1, 2, 3, 4, 7, 9, 10]), "0-4, 7, 9-10");
        assert_eq!(id_ranges(&[5]), "5");
        assert_eq!(id_ranges(&[]), "");
    }
}
