//! Run and collect apart, with the fake simulator: collect makes the tables
//! `study run` makes from the stored records alone, refuses (and lists)
//! missing runs, lists failed ones, and a plan run in parts adds up to one
//! whole run.

use crate::study_common::{
    PISTON, assert_same, fake, run_into, run_options, tables, write_descriptor,
};
use bonkers::descriptor::errors::StudyError;
use bonkers::descriptor::load::parse;
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::runner::execute::run::{Subset, run_file};
use bonkers::runner::pipeline::{CollectOptions, collect_study, run_part, run_study};
use bonkers::runner::plan::plan;
use bonkers::runner::store::collect::{MissingRuns, Unfinished};
use std::path::Path;
use std::process::Command;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

fn collect_options(out: &Path) -> CollectOptions {
    CollectOptions {
        out: Some(out.to_path_buf()),
        replicas: None,
        quick: false,
        yes: false,
        command_line: vec!["study".into(), "collect".into()],
    }
}

fn specs() -> Vec<RunSpec> {
    plan(&parse("s.toml", PISTON).unwrap()).unwrap()
}

/// The runs a collect refused, from its error.
fn missing(err: &StudyError) -> &MissingRuns {
    match err {
        StudyError::Other(e) => e
            .downcast_ref::<MissingRuns>()
            .unwrap_or_else(|| panic!("a MissingRuns error, not {e:#}")),
        other => panic!("expected missing runs, got {other}"),
    }
}

fn study(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_study"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn manifest(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("manifest.json")).unwrap()).unwrap()
}

#[test]
fn collect_after_run_gives_the_same_tables() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    run_into(&file, &out, 2, &fake).unwrap();
    let made_by_run = tables(&out);
    for table in [
        "runs.parquet",
        "series.parquet",
        "histograms.parquet",
        "summary.parquet",
        "report.md",
    ] {
        std::fs::remove_file(out.join(table)).unwrap();
    }

    let collected = collect_study(&file, &collect_options(&out)).unwrap();
    assert_eq!(
        (collected.planned, collected.ran, collected.resumed),
        (18, 0, 18)
    );
    assert!(collected.failed.is_empty());
    assert_same(&made_by_run, &tables(&out));
    assert!(out.join("report.md").is_file());
    let m = manifest(&out);
    assert_eq!(m["runs"]["planned"], 18);
    assert_eq!(m["runs"]["done"], 0);
    assert_eq!(m["runs"]["resumed"], 18);
    assert_eq!(m["command_line"][1], "collect");
}

/// The binary: `study collect` after a run exits 0 with the same tables; with
/// a record gone it lists the run, says how to run it, exits 1 and writes nothing.
#[test]
fn study_collect_on_the_command_line() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    run_into(&file, &out, 2, &fake).unwrap();
    let made_by_run = tables(&out);
    let (file_arg, out_arg) = (file.to_str().unwrap(), out.to_str().unwrap());
    let (code, err) = study(&["collect", file_arg, "--out", out_arg]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("collected 18 runs"), "{err}");
    assert_same(&made_by_run, &tables(&out));

    let parts = dir.path().join("parts");
    run_part(
        &file,
        &run_options(&parts, 2),
        Subset::All,
        &fake,
        &AtomicBool::new(false),
    )
    .unwrap();
    let spec = &specs()[7];
    std::fs::remove_file(run_file(&parts, spec.seed)).unwrap();
    let (code, err) = study(&["collect", file_arg, "--out", parts.to_str().unwrap()]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("1 of the 18 planned runs have no usable record"),
        "{err}"
    );
    assert!(
        err.contains(&format!(
            "run 7 (point 2: scene.piston.mass = 10.0, scene.species.0.count = 5; replica 1; seed {}): no record",
            spec.seed
        )),
        "{err}"
    );
    assert!(
        err.contains(&format!(
            "run them with `study run {file_arg} --out {}`",
            parts.display()
        )),
        "{err}"
    );
    assert!(!parts.join("runs.parquet").exists());
    assert!(!parts.join("manifest.json").exists());
}

#[test]
fn missing_runs_are_listed_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let stop = AtomicBool::new(false);
    run_part(&file, &run_options(&out, 2), Subset::All, &fake, &stop).unwrap();
    let specs = specs();
    for id in [3, 11] {
        std::fs::remove_file(run_file(&out, specs[id].seed)).unwrap();
    }
    let err = collect_study(&file, &collect_options(&out)).unwrap_err();
    assert_eq!(err.exit_code(), 1);
    let m = missing(&err);
    let listed: Vec<(u64, u64, u32, u64)> = m
        .missing
        .iter()
        .map(|u| (u.run_id, u.point_id, u.replica, u.seed))
        .collect();
    assert_eq!(
        listed,
        [3, 11].map(|i| (i as u64, specs[i].point_id, specs[i].replica, specs[i].seed))
    );
    assert_eq!(m.planned, 18);
    let written: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.'))
        .collect();
    assert_eq!(written, ["runs"], "only the records");

    // Records another descriptor made count as missing too, and a folder
    // that does not exist lists every run without being created.
    write_descriptor(
        dir.path(),
        &PISTON.replace("duration = 100.0", "duration = 50.0"),
    );
    let err = collect_study(&file, &collect_options(&out)).unwrap_err();
    let m = missing(&err);
    assert_eq!(m.missing.len(), 18);
    assert!(
        m.missing[0].why.contains("another descriptor"),
        "{}",
        m.missing[0]
    );
    let nowhere = dir.path().join("nowhere");
    let err = collect_study(&file, &collect_options(&nowhere)).unwrap_err();
    assert_eq!(missing(&err).missing.len(), 18);
    assert!(!nowhere.exists());
}

/// More than twenty missing runs: the first twenty in full, the rest by id.
#[test]
fn many_missing_runs_are_summed_up_by_id() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let mut more = collect_options(&dir.path().join("empty"));
    more.replicas = Some(5);
    let err = collect_study(&file, &more).unwrap_err();
    let text = err.to_string();
    assert!(
        text.starts_with("30 of the 30 planned runs have no usable record"),
        "{text}"
    );
    assert!(text.contains("  run 19 (point 3"), "{text}");
    assert!(!text.contains("  run 20 ("), "{text}");
    assert!(text.contains("  and 10 more: runs 20-29\n"), "{text}");
    assert!(text.contains("--replicas 5`"), "{text}");
}

#[test]
fn failed_runs_are_listed_and_kept_in_the_tables() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let flaky = |s: &RunSpec| match s.run_id {
        4 => anyhow::bail!("overlap at start"),
        _ => fake(s),
    };
    let report = run_part(
        &file,
        &run_options(&out, 2),
        Subset::All,
        &flaky,
        &AtomicBool::new(false),
    )
    .unwrap();
    assert_eq!((report.ran, report.failed), (18, 1));
    let collected = collect_study(&file, &collect_options(&out)).unwrap();
    let spec = &specs()[4];
    assert_eq!(
        collected.failed,
        [Unfinished {
            run_id: 4,
            point_id: spec.point_id,
            replica: spec.replica,
            seed: spec.seed,
            point: "scene.piston.mass = 1.0, scene.species.0.count = 15".into(),
            why: "failed: overlap at start".into(),
        }]
    );
    let runs = tables(&out).remove(0).1;
    let status = runs.column("status").unwrap().str().unwrap();
    assert_eq!(status.get(4), Some("failed: overlap at start"));
    assert_eq!(manifest(&out)["runs"]["failed"], 1);

    let (code, err) = study(&[
        "collect",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains(
            "study: 1 run(s) failed; their status is in runs.parquet:\n  run 4 (point 1: "
        ),
        "{err}"
    );
    assert!(err.contains("retries them"), "{err}");
}

/// Two invocations that split the plan, each running only its own runs and
/// keeping the other's records, then one collect: the tables of one run.
#[test]
fn a_plan_run_in_two_parts_then_collected_equals_one_run() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let stop = AtomicBool::new(false);
    let whole = dir.path().join("whole");
    run_study(&file, &run_options(&whole, 2), &fake, &stop).unwrap();

    let out = dir.path().join("parts");
    let calls = AtomicUsize::new(0);
    let counting = |s: &RunSpec| -> anyhow::Result<RunOutput> {
        calls.fetch_add(1, Ordering::SeqCst);
        fake(s)
    };
    let even = |s: &RunSpec| s.seed.is_multiple_of(2);
    let odd = |s: &RunSpec| !s.seed.is_multiple_of(2);
    let evens = specs().iter().filter(|s| even(s)).count();
    assert!((1..18).contains(&evens), "{evens} even seeds");

    let first = run_part(
        &file,
        &run_options(&out, 2),
        Subset::Matching(&even),
        &counting,
        &stop,
    )
    .unwrap();
    assert_eq!(
        (first.picked, first.ran, calls.swap(0, Ordering::SeqCst)),
        (evens, evens, evens)
    );
    let err = collect_study(&file, &collect_options(&out)).unwrap_err();
    let absent = &missing(&err).missing;
    assert_eq!(absent.len(), 18 - evens);
    assert!(absent.iter().all(|u| u.seed % 2 == 1));

    let second = run_part(
        &file,
        &run_options(&out, 2),
        Subset::Matching(&odd),
        &counting,
        &stop,
    )
    .unwrap();
    assert_eq!(
        (second.ran, second.resumed, calls.swap(0, Ordering::SeqCst)),
        (18 - evens, 0, 18 - evens)
    );
    collect_study(&file, &collect_options(&out)).unwrap();
    assert_same(&tables(&whole), &tables(&out));

    // --fresh on part of the plan redoes that part and keeps the rest.
    let mut fresh = run_options(&out, 2);
    fresh.fresh = true;
    let redone = run_part(&file, &fresh, Subset::Ids(&[0, 9]), &counting, &stop).unwrap();
    assert_eq!(
        (redone.ran, redone.resumed, calls.swap(0, Ordering::SeqCst)),
        (2, 0, 2)
    );
    let again = run_part(&file, &run_options(&out, 2), Subset::All, &counting, &stop).unwrap();
    assert_eq!((again.ran, again.resumed), (0, 18));
    collect_study(&file, &collect_options(&out)).unwrap();
    assert_same(&tables(&whole), &tables(&out));

    // An id the plan does not have is an error, not an empty run.
    let err = run_part(
        &file,
        &run_options(&out, 2),
        Subset::Ids(&[18]),
        &counting,
        &stop,
    )
    .unwrap_err();
    assert!(
        err.to_string().contains("run 18 is not in the plan"),
        "{err}"
    );
}
