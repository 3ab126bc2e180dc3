//! The `study` binary: exit codes and what users see on stderr.

mod study_common;

use std::process::Command;
use study_common::{PISTON, write_descriptor};

fn study(args: &[&str]) -> (i32, String, String) {
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
}
