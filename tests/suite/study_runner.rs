//! Running studies with a fake simulator: determinism across thread counts,
//! resume after interruption, --fresh, failures, and the Parquet tables.

use crate::study_common::{
    Interrupting, PISTON, assert_same, fake, run_into, run_options, tables, write_descriptor,
};
use bonkers::descriptor::errors::StudyError;
use bonkers::descriptor::load::parse;
use bonkers::runner::execute::run::run_file;
use bonkers::runner::pipeline::run_study;
use bonkers::runner::plan::plan;
use bonkers::runner::store::read_parquet;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// A simulator that counts its calls.
struct Counting(AtomicUsize);

impl Counting {
    fn new() -> Self {
        Counting(AtomicUsize::new(0))
    }
    fn simulate(
        &self,
        spec: &bonkers::model::run_spec::RunSpec,
    ) -> anyhow::Result<bonkers::model::run_output::RunOutput> {
        self.0.fetch_add(1, Ordering::SeqCst);
        fake(spec)
    }
    /// Calls since the last `take`.
    fn take(&self) -> usize {
        self.0.swap(0, Ordering::SeqCst)
    }
}

fn run_files(out: &Path) -> usize {
    std::fs::read_dir(out.join("runs")).unwrap().count()
}

#[test]
fn tables_are_identical_on_1_2_and_4_threads() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let stop = AtomicBool::new(false);
    let mut all = Vec::new();
    for threads in [1, 2, 4] {
        let out = dir.path().join(format!("out{threads}"));
        let outcome = run_study(&file, &run_options(&out, threads), &fake, &stop).unwrap();
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
    run_into(&file, &out, 2, &fake).unwrap();
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
            "cpu_seconds",
            "prepare_seconds",
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
    run_into(&file, &reference, 1, &fake).unwrap();

    let out = dir.path().join("out");
    let interrupting = Interrupting::new(5);
    let simulate = |s: &_| interrupting.simulate(s);
    let err = run_study(&file, &run_options(&out, 2), &simulate, &interrupting.stop).unwrap_err();
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
    let outcome = run_into(&file, &out, 4, &counting).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 18 - saved);
    assert_eq!((outcome.ran, outcome.resumed), (18 - saved, saved));
    assert_same(&tables(&reference), &tables(&out));

    // Deleted run files are redone, and nothing else.
    let specs = plan(&parse("s.toml", PISTON).unwrap()).unwrap();
    for id in [0, 7] {
        std::fs::remove_file(run_file(&out, specs[id].seed)).unwrap();
    }
    calls.store(0, Ordering::SeqCst);
    run_into(&file, &out, 2, &counting).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 2);
    assert_same(&tables(&reference), &tables(&out));
}

#[test]
fn a_changed_descriptor_or_fresh_reruns_everything() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let stop = AtomicBool::new(false);
    run_study(&file, &run_options(&out, 2), &fake, &stop).unwrap();
    let calls = AtomicUsize::new(0);
    let counting = |s: &_| {
        calls.fetch_add(1, Ordering::SeqCst);
        fake(s)
    };
    run_study(&file, &run_options(&out, 2), &counting, &stop).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 0, "everything resumed");

    let mut fresh = run_options(&out, 2);
    fresh.fresh = true;
    run_study(&file, &fresh, &counting, &stop).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 18);

    // Another duration means other runs: the saved ones must not be reused,
    // nor replaced unless --prune says so.
    write_descriptor(
        dir.path(),
        &PISTON.replace("duration = 100.0", "duration = 50.0"),
    );
    calls.store(0, Ordering::SeqCst);
    let err = run_study(&file, &run_options(&out, 2), &counting, &stop).unwrap_err();
    assert_eq!(err.exit_code(), 2, "{err}");
    assert_eq!(calls.load(Ordering::SeqCst), 0);
    let mut prune = run_options(&out, 2);
    prune.prune = true;
    run_study(&file, &prune, &counting, &stop).unwrap();
    assert_eq!(calls.load(Ordering::SeqCst), 18);
}

#[test]
fn failing_and_panicking_runs_are_recorded_and_the_rest_go_on() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let flaky = |s: &bonkers::model::run_spec::RunSpec| match s.run_id {
        3 => anyhow::bail!("overlap at start"),
        5 => panic!("engine bug"),
        _ => fake(s),
    };
    let outcome = run_into(&file, &out, 2, &flaky).unwrap();
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
    let outcome = run_into(&file, &out, 2, &counting).unwrap();
    assert_eq!((calls.load(Ordering::SeqCst), outcome.failed), (2, 0));
}

#[test]
fn nan_and_infinite_results_survive_the_run_files() {
    use bonkers::model::run_output::RunOutput;
    use bonkers::runner::store::record::RunRecord;
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

/// Saved runs are found by their seed, which depends on the point's values
/// and the replica only: more replicas, an inserted sweep value or a new
/// description reuse every run already done; runs no longer planned are
/// kept (`--prune` removes them).
#[test]
fn replicas_sweep_values_and_descriptions_reuse_saved_runs() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let stop = AtomicBool::new(false);
    let counting = Counting::new();
    let simulate = |s: &_| counting.simulate(s);
    run_study(&file, &run_options(&out, 2), &simulate, &stop).unwrap();
    assert_eq!(counting.take(), 18);
    let reference = tables(&out);

    let mut more = run_options(&out, 2);
    more.replicas = Some(5);
    let outcome = run_study(&file, &more, &simulate, &stop).unwrap();
    assert_eq!((counting.take(), outcome.resumed), (6 * 2, 18));
    assert_eq!(run_files(&out), 30);

    // Back to 3 replicas: nothing runs, the two extra replicas' files stay
    // (until --prune), and the tables are those of the first study.
    run_study(&file, &run_options(&out, 2), &simulate, &stop).unwrap();
    assert_eq!(counting.take(), 0);
    assert_eq!(run_files(&out), 30);
    assert_same(&reference, &tables(&out));
    let mut prune = run_options(&out, 2);
    prune.prune = true;
    run_study(&file, &prune, &simulate, &stop).unwrap();
    assert_eq!((counting.take(), run_files(&out)), (0, 18));
    assert_same(&reference, &tables(&out));

    // A new mass between the others: only its points run.
    write_descriptor(
        dir.path(),
        &PISTON
            .replace("[1.0, 10.0, 100.0]", "[1.0, 3.0, 10.0, 100.0]")
            .replace(
                "Piston frequency against piston mass",
                "Another description",
            ),
    );
    let outcome = run_study(&file, &run_options(&out, 2), &simulate, &stop).unwrap();
    assert_eq!((counting.take(), outcome.resumed), (2 * 3, 18));
}

/// A finished study's out dir holds its outputs and nothing older: a rerun
/// that no longer makes series or histograms removes theirs; the manifest
/// lists exactly the files beside it.
#[test]
fn outputs_of_an_earlier_study_do_not_survive_a_new_one() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let stop = AtomicBool::new(false);
    run_study(&file, &run_options(&out, 2), &fake, &stop).unwrap();
    for f in [
        "series.parquet",
        "histograms.parquet",
        "series_piston_x.svg",
        "hist_v.svg",
    ] {
        assert!(out.join(f).is_file(), "{f}");
    }
    let scalars_only = |s: &bonkers::model::run_spec::RunSpec| {
        let mut o = fake(s)?;
        o.series.clear();
        o.histograms.clear();
        Ok(o)
    };
    let mut fresh = run_options(&out, 2);
    fresh.fresh = true;
    run_study(&file, &fresh, &scalars_only, &stop).unwrap();
    for f in [
        "series.parquet",
        "histograms.parquet",
        "series_piston_x.svg",
        "hist_v.svg",
    ] {
        assert!(!out.join(f).exists(), "{f} is stale");
    }
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("manifest.json")).unwrap()).unwrap();
    let listed: Vec<String> = serde_json::from_value(manifest["outputs"].clone()).unwrap();
    let mut present: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .filter(|e| e.path().is_file())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.'))
        .collect();
    present.sort();
    assert_eq!(listed, present);
    assert!(listed.contains(&"runs.parquet".to_string()));
}

#[test]
fn a_second_study_on_the_same_out_dir_fails_clearly() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    std::fs::create_dir_all(&out).unwrap();
    let held = bonkers::runner::store::lock::OutLock::acquire(&out).unwrap();
    let err = run_into(&file, &out, 2, &fake).unwrap_err();
    assert_eq!(err.exit_code(), 1);
    let msg = err.to_string();
    assert!(msg.contains("another `study run`"), "{msg}");
    assert!(
        msg.contains(&format!("process {}", std::process::id())),
        "{msg}"
    );
    assert!(!out.join("runs.parquet").exists());
    drop(held);
    run_into(&file, &out, 2, &fake).unwrap();
}

/// What a killed run leaves (a staging folder with its marker, temporary
/// files) is removed by the next. (Files of other names stay:
/// `output_folder.rs`, `hostile_outdir.rs`.)
#[test]
fn leftovers_of_a_killed_run_are_cleaned() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    run_into(&file, &out, 2, &fake).unwrap();
    std::fs::create_dir_all(out.join(".staging-4000000")).unwrap();
    let leftovers = [
        out.join(".staging-4000000").join(".bonkers"),
        out.join(".staging-4000000").join("runs.parquet"),
        out.join(".summary.parquet.4000000-3.tmp"),
        out.join(".report.md.4000000-1.tmp"),
        out.join("runs").join(".run-17.json.4000000-0.tmp"),
        out.join("runs").join(".run-5.ckpt.4000000-2.tmp"),
    ];
    for f in &leftovers {
        std::fs::write(f, "partial").unwrap();
    }
    run_into(&file, &out, 2, &fake).unwrap();
    for f in &leftovers {
        assert!(!f.exists(), "{} left", f.display());
    }
    assert!(!out.join(".staging-4000000").exists());
    assert_eq!(run_files(&out), 18);
}

#[test]
fn quick_studies_default_to_their_own_out_dir() {
    use bonkers::runner::pipeline::default_out_dir;
    let loaded = parse("s.toml", PISTON).unwrap();
    assert_eq!(
        default_out_dir(&loaded, false),
        Path::new("reports/piston-test")
    );
    assert_eq!(
        default_out_dir(&loaded, true),
        Path::new("reports/piston-test-quick")
    );
}
