//! `[observe] trajectory` through the `study` binary: the same bytes on any
//! thread count, rewritten exactly when missing on resume, nothing for runs
//! that ask for none, and bad requests refused before anything runs. The
//! files' contents are read back by gsd, ase and freud in
//! tests/frames_check.py (CI).

use crate::study_common::study;
use std::path::Path;

const DISKS: &str = r#"
[study]
name = "frames"
replicas = 3
seed = 5

[scene]
dimension = 2
box = [10.0, 10.0]
boundary = ["periodic", "walls"]
species = [{ name = "disk", count = 30 }]

[run]
duration = 5.0
sample_every = 0.5

[observe]
scalars = ["temperature"]
trajectory = { format = "gsd", every = 0.25, runs = [0, 2] }

[quick]
"observe.trajectory.format" = "xyz"
"#;

fn run(file: &Path, out: &Path, extra: &[&str]) {
    let mut args = vec!["run", file.to_str().unwrap(), "--quiet", "--out"];
    args.push(out.to_str().unwrap());
    args.extend(extra);
    let (code, _, err) = study(&args);
    assert_eq!(code, 0, "{err}");
}

fn trajectories(out: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains("trajectory"))
        .collect();
    names.sort();
    names
}

#[test]
fn the_same_bytes_on_any_thread_count_and_after_resume() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("frames.toml");
    std::fs::write(&file, DISKS).unwrap();
    let (one, two) = (dir.path().join("one"), dir.path().join("two"));
    run(&file, &one, &["--threads", "1"]);
    run(&file, &two, &["--threads", "2"]);
    assert_eq!(trajectories(&one), ["trajectory-0.gsd", "trajectory-2.gsd"]);
    let bytes = |out: &Path, name: &str| std::fs::read(out.join(name)).unwrap();
    for name in trajectories(&one) {
        assert_eq!(bytes(&one, &name), bytes(&two, &name), "{name}");
    }
    // 21 frames (0 to 5 every 0.25) of 30 disks.
    let gsd = bytes(&one, "trajectory-2.gsd");
    assert_eq!(&gsd[..8], &0x65DF_65DF_65DF_65DFu64.to_le_bytes());
    assert!(gsd.len() > 21 * 30 * 60, "{}", gsd.len());

    // A missing file is filmed again on resume, byte for byte; its run's
    // record is reused, and the tables are the same.
    let before = bytes(&one, "trajectory-2.gsd");
    let runs = bytes(&one, "runs.parquet").len();
    std::fs::remove_file(one.join("trajectory-2.gsd")).unwrap();
    run(&file, &one, &[]);
    assert_eq!(bytes(&one, "trajectory-2.gsd"), before);
    assert_eq!(bytes(&one, "runs.parquet").len(), runs);

    // The quick form writes XYZ of the same runs: no `.tmp` left behind.
    let xyz = dir.path().join("xyz");
    run(&file, &xyz, &["--quick"]);
    assert_eq!(trajectories(&xyz), ["trajectory-0.xyz", "trajectory-2.xyz"]);
    let text = String::from_utf8(bytes(&xyz, "trajectory-0.xyz")).unwrap();
    assert_eq!(text.lines().filter(|l| *l == "30").count(), 21);
    assert!(
        text.lines().nth(1).unwrap().contains("pbc=\"T F F\""),
        "{text:.300}"
    );

    // No trajectory asked: none written.
    let plain = dir.path().join("plain.toml");
    let without = DISKS.split("trajectory = ").next().unwrap().to_string();
    std::fs::write(&plain, without).unwrap();
    let none = dir.path().join("none");
    run(&plain, &none, &[]);
    assert!(trajectories(&none).is_empty());
}

#[test]
fn bad_trajectories_are_refused_at_their_key() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("frames.toml");
    let line = "trajectory = { format = \"gsd\", every = 0.25, runs = [0, 2] }";
    for (with, message) in [
        (
            "format = \"pdb\", every = 0.25",
            ":19:25: `observe.trajectory.format`: unknown value \"pdb\"",
        ),
        (
            "format = \"gsd\", every = 0.0",
            ":19:32: `observe.trajectory.every`: 0 is not a simulated time",
        ),
        (
            "format = \"gsd\", every = -1.0",
            "`observe.trajectory.every`: -1 is not a simulated time",
        ),
        (
            "format = \"gsd\", every = 1.0, runs = [3]",
            "`observe.trajectory.runs` names run 3, which is not planned: the plan's runs are 0 to 2",
        ),
        (
            "format = \"xyz\", every = 1e-7",
            "particle-frames; a trajectory holds at most 5e7",
        ),
    ] {
        std::fs::write(
            &file,
            DISKS.replace(line, &format!("trajectory = {{ {with} }}")),
        )
        .unwrap();
        let (code, _, err) = study(&["validate", file.to_str().unwrap()]);
        assert_eq!(code, 2, "{with}: {err}");
        assert!(err.contains(message), "{with}: {err}");
    }
    std::fs::write(&file, DISKS).unwrap();
    let (code, out, err) = study(&["validate", file.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("trajectory: trajectory-0.gsd, trajectory-2.gsd: 1260 particle-frames"),
        "{out}"
    );
}
