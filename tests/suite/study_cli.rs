//! The `study` binary: exit codes and what users see on stderr.

use crate::study_common::{PISTON, study, write_descriptor};
use std::process::Command;

#[test]
fn validate_prints_the_plan() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let (code, out, _) = study(&["validate", file.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(out.contains("points: 6, replicas: 3, runs: 18"), "{out}");
    assert!(
        out.contains("scene.piston.mass = [1.0, 10.0, 100.0]"),
        "{out}"
    );
    let (code, out, _) = study(&[
        "validate",
        file.to_str().unwrap(),
        "--quick",
        "--replicas",
        "4",
    ]);
    assert_eq!(code, 0);
    assert!(out.contains("runs: 16"), "{out}");
}

#[test]
fn bad_input_exits_2_with_a_located_error() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), &PISTON.replace("replicas = 3", "replicaz = 3"));
    let (code, _, err) = study(&["validate", file.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.starts_with(&format!(
            "error: {}:5:1: unknown key `replicaz`",
            file.display()
        )),
        "{err}"
    );
    assert!(err.contains("hint: did you mean `replicas`?"), "{err}");
    let (code, _, err) = study(&["run", file.to_str().unwrap(), "--quiet"]);
    assert_eq!(code, 2, "{err}");
    let (code, _, _) = study(&["run", "--threads", "0", file.to_str().unwrap()]);
    assert_eq!(code, 2);
    let (code, _, _) = study(&["frobnicate"]);
    assert_eq!(code, 2);
    let (code, _, err) = study(&["validate", "/no/such/file.toml"]);
    assert_eq!(code, 2);
    assert!(err.contains("cannot read the descriptor"), "{err}");
}

#[test]
fn huge_plans_need_yes() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(
        dir.path(),
        &PISTON.replace("replicas = 3", "replicas = 20000"),
    );
    let (code, _, err) = study(&["validate", file.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("--yes"), "{err}");
    let (code, out, _) = study(&["validate", file.to_str().unwrap(), "--yes"]);
    assert_eq!(code, 0);
    assert!(out.contains("runs: 120000"), "{out}");
}

#[test]
fn help_and_list_exit_0() {
    assert_eq!(study(&["--help"]).0, 0);
    let (code, out, _) = study(&["list"]);
    assert_eq!(code, 0);
    assert!(out.contains("studies") && out.contains("scenes"), "{out}");
    // One line per observable and analysis, the analysis with its options.
    for line in [
        "  scalars    wall_heat ",
        "  histograms scaled_velocity_x ",
        "  quickstart ",
    ] {
        assert!(out.contains(line), "{line:?} in\n{out}");
    }
    assert!(
        out.lines().any(|l| l.starts_with("  piston ")
            && l.contains("window_periods (a number > 0, default 4)")),
        "{out}"
    );
    // From another directory it still finds the bundled studies.
    let elsewhere = tempfile::tempdir().unwrap();
    let listed = Command::new(env!("CARGO_BIN_EXE_study"))
        .arg("list")
        .current_dir(elsewhere.path())
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&listed.stdout);
    assert!(text.contains("  quickstart "), "{text}");
}

/// A scene from a preset still gets an estimate (the particle count comes
/// from the resolved scene), with collisions and time.
#[test]
fn validate_estimates_collisions_and_time_for_preset_scenes() {
    let (code, out, _) = study(&["validate", "studies/quickstart.toml"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("points: 2 and 1 case(s) (mackay), replicas: 8, runs: 20"),
        "{out}"
    );
    assert!(out.contains("estimated collisions: ~"), "{out}");
    assert!(out.contains("estimated time: ~"), "{out}");
    assert!(out.contains("an estimate"), "{out}");
    assert!(!out.contains("unknown"), "{out}");
}

/// On the real engine: a resumed study says what it reused, reran and
/// removed, in one line; plain progress lines carry an ETA.
#[test]
fn resuming_says_what_it_reuses_reruns_and_removes() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let run = |extra: &[&str]| {
        let mut args = vec![
            "run",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend(extra);
        let (code, _, err) = study(&args);
        assert_eq!(code, 0, "{err}");
        err
    };
    let err = run(&[]);
    assert!(
        err.contains("study: 18/18 runs,") && err.contains("ETA done"),
        "{err}"
    );
    let err = run(&["--replicas", "2"]);
    assert!(
        err.contains(
            "study: resuming 12 saved runs; kept 6 records that are not in this plan (runs/run-"
        ) && err.contains(" and 3 more); --prune deletes them"),
        "{err}"
    );
    let err = run(&["--replicas", "2", "--prune"]);
    assert!(
        err.contains(
            "study: resuming 12 saved runs; removed 6 saved runs that are not in this plan"
        ),
        "{err}"
    );
    write_descriptor(
        dir.path(),
        &PISTON.replace("duration = 100.0", "duration = 50.0"),
    );
    let err = run(&["--prune"]);
    assert!(
        err.contains(
            "study: 12 saved runs were made by another descriptor or bonkers version and run again"
        ),
        "{err}"
    );
    assert!(err.contains("(18 run now, 0 resumed, 0 failed)"), "{err}");
}

/// What is not a descriptor file is refused at once with exit 2: a device
/// or a pipe would otherwise be read forever, a huge file into memory.
#[test]
fn devices_pipes_folders_and_huge_files_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("fifo.toml");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let huge = dir.path().join("huge.toml");
    let file = std::fs::File::create(&huge).unwrap();
    file.set_len(bonkers::descriptor::load::MAX_DESCRIPTOR_BYTES + 1)
        .unwrap();
    for (path, says) in [
        ("/dev/zero", "is not a regular file"),
        (fifo.to_str().unwrap(), "is not a regular file"),
        (dir.path().to_str().unwrap(), "is not a regular file"),
        (
            huge.to_str().unwrap(),
            "is 16777217 bytes; a descriptor is at most 16777216",
        ),
    ] {
        let (code, _, err) = study(&["validate", path]);
        assert_eq!(code, 2, "{path}: {err}");
        assert!(err.contains(&format!("error: {path}: {says}")), "{err}");
    }
}

#[test]
fn absurd_thread_counts_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let (code, _, err) = study(&[
        "run",
        file.to_str().unwrap(),
        "--threads",
        "100000",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("100000 is not in 1..=4096"), "{err}");
    assert!(!out.exists(), "nothing written");
}
