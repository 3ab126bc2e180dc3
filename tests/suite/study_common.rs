//! Shared by the study tests: a valid descriptor and a fast, deterministic
//! fake simulator (outputs are a pure function of the run's seed and params).
#![allow(dead_code)]

use bonkers::descriptor::errors::StudyError;
use bonkers::descriptor::load::parse;
use bonkers::model::run_output::{Histogram, RunOutput, Series};
use bonkers::model::run_spec::RunSpec;
use bonkers::runner::execute::progress::ProgressMode;
use bonkers::runner::execute::run::SimulateFn;
use bonkers::runner::pipeline::{StudyOptions, StudyOutcome, run_study};
use bonkers::runner::plan::plan;
use bonkers::runner::store::read_parquet;
use polars::prelude::DataFrame;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

pub const PISTON: &str = r#"# A small piston study.
[study]
name = "piston-test"
description = "Piston frequency against piston mass"
replicas = 3
seed = 42

[scene]
dimension = 1
box = [40.0]
boundary = ["walls"]

[[scene.species]]
name = "gas"
count = 10
mass = 1.0
region = { from = [0.0], to = [0.45] }
[scene.piston]
mass = 5.0
position = 0.5

[scene.velocities]
kind = "maxwell"
temperature = 1.0

[sweep]
mode = "product"

[sweep.parameters]
"scene.piston.mass" = [1.0, 10.0, 100.0]
"scene.species.0.count" = { from = 5, to = 15, steps = 2 }

[run]
duration = 100.0
equilibrate = 10.0
sample_every = 0.5

[observe]
scalars = ["wall_pressure"]
series = ["piston_position"]

[quick]
"study.replicas" = 1
"run.duration" = 10.0
"sweep.parameters.scene.piston.mass" = [1.0, 100.0]
"#;

pub fn write_descriptor(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("study.toml");
    std::fs::write(&path, text).unwrap();
    path
}

/// Outputs depend only on the spec: a stand-in for the real simulator.
pub fn fake(spec: &RunSpec) -> anyhow::Result<RunOutput> {
    let s = spec.seed;
    let u = (s >> 11) as f64 / (1u64 << 53) as f64;
    let mass = spec
        .descriptor
        .scene
        .piston
        .as_ref()
        .map_or(1.0, |p| p.mass);
    let mut scalars = vec![("frequency".to_string(), 1.0 / mass.sqrt() + 0.01 * u)];
    if spec.replica.is_multiple_of(2) {
        // A result only some runs report: its column must be null elsewhere.
        scalars.push(("even_only".to_string(), u));
    }
    Ok(RunOutput {
        scalars,
        series: vec![Series {
            observable: "piston_x".into(),
            t: vec![0.0, 0.5, 1.0],
            value: vec![u, 2.0 * u, 3.0 * u],
        }],
        histograms: vec![Histogram {
            observable: "v".into(),
            lo: vec![0.0, 1.0],
            hi: vec![1.0, 2.0],
            count: vec![3.0, (s % 7) as f64],
        }],
        events: s % 1000 + 10,
        collisions: s % 500 + 5,
        wall_seconds: 0.0,
        cpu_seconds: 0.0,
        prepare_seconds: 0.0,
    })
}

/// A fake that raises the stop flag once `after` runs have started, like Ctrl-C.
pub struct Interrupting {
    pub started: AtomicUsize,
    pub after: usize,
    pub stop: AtomicBool,
}

impl Interrupting {
    pub fn new(after: usize) -> Self {
        Interrupting {
            started: AtomicUsize::new(0),
            after,
            stop: AtomicBool::new(false),
        }
    }
    pub fn simulate(&self, spec: &RunSpec) -> anyhow::Result<RunOutput> {
        if self.started.fetch_add(1, Ordering::SeqCst) + 1 >= self.after {
            self.stop.store(true, Ordering::SeqCst);
        }
        fake(spec)
    }
}

/// Every table of `dir` without the timing columns, which legitimately vary.
pub fn tables(dir: &Path) -> Vec<(String, DataFrame)> {
    [
        "runs.parquet",
        "series.parquet",
        "histograms.parquet",
        "summary.parquet",
    ]
    .iter()
    .map(|name| {
        let mut df = read_parquet(&dir.join(name)).unwrap();
        for col in ["wall_seconds", "cpu_seconds", "prepare_seconds"] {
            if df.column(col).is_ok() {
                df = df.drop(col).unwrap();
            }
        }
        (name.to_string(), df)
    })
    .collect()
}

pub fn assert_same(a: &[(String, DataFrame)], b: &[(String, DataFrame)]) {
    assert_eq!(a.len(), b.len());
    for ((name, x), (_, y)) in a.iter().zip(b) {
        assert_eq!(x.get_column_names(), y.get_column_names(), "{name}");
        assert_eq!(x.height(), y.height(), "{name}");
        for (cx, cy) in x.columns().iter().zip(y.columns()) {
            assert!(
                cx.equals_missing(cy),
                "{name}: column {} differs",
                cx.name()
            );
        }
    }
}

/// Every planned run of descriptor `text`, on two threads.
pub fn ensemble(text: &str) -> Vec<(RunSpec, RunOutput)> {
    let loaded = parse("test.toml", text).expect("valid descriptor");
    let specs = plan(&loaded).expect("plan");
    let (a, b) = specs.split_at(specs.len() / 2);
    let run = |part: &[RunSpec]| -> Vec<(RunSpec, RunOutput)> {
        part.iter()
            .map(|r| {
                (
                    r.clone(),
                    bonkers::runner::execute::simulate::run(r).expect("run"),
                )
            })
            .collect()
    };
    std::thread::scope(|s| {
        let first = s.spawn(|| run(a));
        let mut out = run(b);
        let mut all = first.join().expect("thread");
        all.append(&mut out);
        all
    })
}

/// `study run` options for the tests: quiet, into `out`, on `threads` threads.
pub fn run_options(out: &Path, threads: usize) -> StudyOptions {
    StudyOptions {
        out: Some(out.to_path_buf()),
        threads: Some(threads),
        replicas: None,
        quick: false,
        fresh: false,
        prune: false,
        progress: ProgressMode::Quiet,
        yes: false,
        command_line: vec!["study".into(), "run".into()],
        checkpoint_every: None,
        force: false,
    }
}

/// `run_study` of `file` into `out` with `run_options(out, threads)`, never
/// asked to stop.
pub fn run_into(
    file: &Path,
    out: &Path,
    threads: usize,
    simulate: &SimulateFn<'_>,
) -> Result<StudyOutcome, StudyError> {
    run_study(
        file,
        &run_options(out, threads),
        simulate,
        &AtomicBool::new(false),
    )
}

/// A scalar result over an ensemble's runs, from those that measured it finite.
pub fn stats(runs: &[(RunSpec, RunOutput)], name: &str) -> bonkers::stats::summary::Stats {
    bonkers::stats::summary::scalar(runs.iter().map(|(_, o)| o), name)
}

/// `study ARGS`: its exit code, stdout and stderr.
pub fn study(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_study"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
