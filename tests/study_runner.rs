//! Running studies with a fake simulator: determinism across thread counts,
//! resume after interruption, --fresh, failures, and the Parquet tables.

mod study_common;

use bonkers::study::errors::StudyError;
use bonkers::study::pipeline::{StudyOptions, run_study};
use bonkers::study::progress::ProgressMode;
use bonkers::study::store::read_parquet;
use polars::prelude::DataFrame;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use study_common::{Interrupting, PISTON, fake, write_descriptor};

fn options(out: &Path, threads: usize) -> StudyOptions {
    StudyOptions {
        out: Some(out.to_path_buf()),
        threads: Some(threads),
        replicas: None,
        quick: false,
        fresh: false,
        progress: ProgressMode::Quiet,
        yes: false,
        command_line: vec!["study".into(), "run".into()],
    }
}

/// Every table of `dir` without the wall-clock columns, which legitimately vary.
fn tables(dir: &Path) -> Vec<(String, DataFrame)> {
    [
        "runs.parquet",
        "series.parquet",
        "histograms.parquet",
        "summary.parquet",
    ]
    .iter()
    .map(|name| {
        let mut df = read_parquet(&dir.join(name)).unwrap();
        for col in ["wall_seconds", "seconds"] {
            if df.column(col).is_ok() {
                df = df.drop(col).unwrap();
            }
        }
        (name.to_string(), df)
    })
    .collect()
}

fn assert_same(a: &[(String, DataFrame)], b: &[(String, DataFrame)]) {
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

#[test]
fn tables_are_identical_on_1_2_and_4_threads() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let stop = AtomicBool::new(false);
    let mut all = Vec::new();
    for threads in [1, 2, 4] {
        let out = dir.path().join(format!("out{threads}"));
        let outcome = run_study(&file, &options(&out, threads), &fake, &stop).unwrap();
        assert_eq!(
            (
                outcome.planned,
                outcome.ran,
                outcome.failed,
                outcome.resumed
            ),
            (18, 18, 0, 0)
        );
        all.push(tables(&out));
    }
    assert_same(&all[0], &all[1]);
    assert_same(&all[0], &all[2]);
}

#[test]
fn runs_table_has_the_promised_columns() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    run_study(&file, &options(&out, 2), &fake, &AtomicBool::new(false)).unwrap();
    let runs = read_parquet(&out.join("runs.parquet")).unwrap();
    let names: Vec<String> = runs
        .get_column_names()
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(
        names,
        [
            "run_id",
            "point_id",
            "replica",
            "seed",
            "scene.piston.mass",
            "scene.species.0.count",
            "frequency",
            "even_only",
            "events",
            "collisions",
            "wall_seconds",
            "status"
        ]
    );
    assert_eq!(runs.height(), 18);
    let run_id: Vec<u64> = runs
        .column("run_id")
        .unwrap()
        .u64()
        .unwrap()
        .into_no_null_iter()
        .collect();
    assert_eq!(run_id, (0..18).collect::<Vec<u64>>());
    // A result reported by some runs only is null elsewhere.
    assert_eq!(runs.column("even_only").unwrap().null_count(), 6);
    let mass = runs.column("scene.piston.mass").unwrap().f64().unwrap();
    assert_eq!(mass.get(17), Some(100.0));
    let series = read_parquet(&out.join("series.parquet")).unwrap();
    assert_eq!(series.height(), 18 * 3);
    let summary = read_parquet(&out.join("summary.parquet")).unwrap();
    assert_eq!(summary.height(), 6 * 2);
    assert!(summary.column("theory").unwrap().null_count() == summary.height());
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("manifest.json")).unwrap()).unwrap();
    assert_eq!(manifest["runs"]["done"], 18);
    assert!(manifest["started"].as_str().unwrap().ends_with('Z'));
    assert!(
        manifest["descriptor_toml"]
            .as_str()
            .unwrap()
            .contains("piston-test")
    );
}

#[test]
fn an_interrupted_study_resumes_with_only_the_missing_runs() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let reference = dir.path().join("reference");
    run_study(
        &file,
        &options(&reference, 1),
        &fake,
        &AtomicBool::new(false),
    )
    .unwrap();

    let out = dir.path().join("out");
    let interrupting = Interrupting::new(5);
    let simulate = |s: &_| interrupting.simulate(s);
    let err = run_study(&file, &options(&out, 2), &simulate, &interrupting.stop).unwrap_err();
    assert!(matches!(err, StudyError::Interrupted(_)), "{err}");
    assert_eq!(err.exit_code(), 130);
    assert!(
        !out.join("runs.parquet").exists(),
        "nothing partial is written"
    );
    let saved = std::fs::read_dir(out.join("runs")).unwrap().count();
    assert!((5..18).contains(&saved), "{saved} runs saved");

    let calls = AtomicUsize::new(0);
    let counting = |s: &_| {
        calls.fetch_add(1, Ordering::SeqCst);
        fake(s)
    };
    let outcome = run_study(&file, &options(&out, 4), &counting, &AtomicBool::new(false)).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 18 - saved);
    assert_eq!((outcome.ran, outcome.resumed), (18 - saved, saved));
    assert_same(&tables(&reference), &tables(&out));

    // Deleted run files are redone, and nothing else.
    for id in [0, 7] {
        std::fs::remove_file(out.join("runs").join(format!("run-{id}.json"))).unwrap();
    }
    calls.store(0, Ordering::SeqCst);
    run_study(&file, &options(&out, 2), &counting, &AtomicBool::new(false)).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 2);
    assert_same(&tables(&reference), &tables(&out));
}

#[test]
fn a_changed_descriptor_or_fresh_reruns_everything() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let stop = AtomicBool::new(false);
    run_study(&file, &options(&out, 2), &fake, &stop).unwrap();
    let calls = AtomicUsize::new(0);
    let counting = |s: &_| {
        calls.fetch_add(1, Ordering::SeqCst);
        fake(s)
    };
    run_study(&file, &options(&out, 2), &counting, &stop).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 0, "everything resumed");

    let mut fresh = options(&out, 2);
    fresh.fresh = true;
    run_study(&file, &fresh, &counting, &stop).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 18);

    // Another duration means other runs: the saved ones must not be reused.
    write_descriptor(
        dir.path(),
        &PISTON.replace("duration = 100.0", "duration = 50.0"),
    );
    calls.store(0, Ordering::SeqCst);
    run_study(&file, &options(&out, 2), &counting, &stop).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 18);
}

#[test]
fn failing_and_panicking_runs_are_recorded_and_the_rest_go_on() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let flaky = |s: &bonkers::study::plan_types::RunSpec| match s.run_id {
        3 => anyhow::bail!("overlap at start"),
        5 => panic!("engine bug"),
        _ => fake(s),
    };
    let outcome = run_study(&file, &options(&out, 2), &flaky, &AtomicBool::new(false)).unwrap();
    assert_eq!((outcome.ran, outcome.failed), (18, 2));
    let runs = read_parquet(&out.join("runs.parquet")).unwrap();
    let status = runs.column("status").unwrap().str().unwrap();
    assert_eq!(status.get(3), Some("failed: overlap at start"));
    assert_eq!(status.get(5), Some("failed: panicked: engine bug"));
    assert_eq!(status.get(4), Some("ok"));
    assert_eq!(runs.column("frequency").unwrap().null_count(), 2);
    // A rerun retries only the failed runs.
    let calls = AtomicUsize::new(0);
    let counting = |s: &_| {
        calls.fetch_add(1, Ordering::SeqCst);
        fake(s)
    };
    let outcome = run_study(&file, &options(&out, 2), &counting, &AtomicBool::new(false)).unwrap();
    assert_eq!((calls.load(Ordering::SeqCst), outcome.failed), (2, 0));
}

#[test]
fn nan_and_infinite_results_survive_the_run_files() {
    use bonkers::study::output::RunOutput;
    use bonkers::study::record::RunRecord;
    let record = RunRecord {
        run_id: 1,
        fingerprint: "x".into(),
        status: "ok".into(),
        output: RunOutput {
            scalars: vec![
                ("a".into(), f64::NAN),
                ("b".into(), f64::INFINITY),
                ("c".into(), 0.1 + 0.2),
            ],
            ..Default::default()
        },
    };
    let back = RunRecord::from_json(&record.to_json().unwrap()).unwrap();
    assert!(back.output.scalars[0].1.is_nan());
    assert_eq!(back.output.scalars[1].1, f64::INFINITY);
    assert_eq!(back.output.scalars[2].1.to_bits(), (0.1f64 + 0.2).to_bits());
}
