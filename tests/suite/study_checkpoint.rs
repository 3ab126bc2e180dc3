//! Checkpoints: a long run killed (SIGKILL) midway continues from its
//! checkpoint when the study is run again, and the tables are those of a
//! run never interrupted, bit for bit (timings aside); so does a run that
//! saved while still equilibrating.

use crate::study_common::{assert_same, write_descriptor};
use bonkers::descriptor::load::load;
use bonkers::runner::execute::checkpoint::{Phase, Saved, file};
use bonkers::runner::execute::run::{fingerprint, run_file, runs_dir};
use bonkers::runner::plan::plan;
use bonkers::runner::store::read_parquet;
use polars::prelude::DataFrame;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// One run of 300 disks between walls, about a second on one thread, with
/// observers of every kind (collisions, walls, samples, histogram).
const LONG: &str = r#"
[study]
name = "checkpoint-test"
description = "One long run of hard disks, to be killed and continued."
replicas = 1
seed = 7

[scene]
dimension = 2
box = [30.0, 30.0]
boundary = ["walls", "walls"]
velocities = { kind = "maxwell", temperature = 1.0 }

[[scene.species]]
name = "gas"
count = 300
radius = 0.5

[run]
equilibrate = 2000.0
duration = 3000.0
sample_every = 2.0

[observe]
scalars = ["wall_pressure", "virial_pressure", "temperature"]
series = ["kinetic_energy"]
histograms = ["scaled_velocity_x"]
"#;

fn tables(dir: &Path) -> Vec<(String, DataFrame)> {
    ["runs", "series", "histograms", "summary"]
        .iter()
        .map(|name| {
            let mut df = read_parquet(&dir.join(format!("{name}.parquet"))).unwrap();
            for col in ["wall_seconds", "cpu_seconds", "prepare_seconds"] {
                if df.column(col).is_ok() {
                    df = df.drop(col).unwrap();
                }
            }
            (name.to_string(), df)
        })
        .collect()
}

fn run(file: &Path, out: &Path, extra: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_study"));
    c.args([
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
    .args(["--threads", "1"])
    .args(extra);
    c
}

fn finished(o: &Output) -> String {
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(o.status.success(), "{err}");
    err
}

#[test]
fn a_killed_run_continues_from_its_checkpoint_bit_for_bit() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), LONG);
    let spec = plan(&load(&file).unwrap()).unwrap().remove(0);
    let whole = dir.path().join("whole");
    finished(&run(&file, &whole, &["--quiet"]).output().unwrap());

    // Run with a tiny checkpoint interval; keep a checkpoint written while
    // equilibrating, and kill the run at the first one written while measuring.
    let out = dir.path().join("killed");
    let ckpt = file_of(&out, spec.seed);
    let mut child = run(&file, &out, &["--quiet", "--checkpoint-every", "0.02"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut equilibrating = None;
    let began = Instant::now();
    loop {
        if let Ok(bytes) = std::fs::read(&ckpt)
            && let Ok(saved) = Saved::decode(&bytes, &fingerprint(&spec))
        {
            match saved.phase {
                Phase::Equilibrating => equilibrating = Some(bytes),
                Phase::Measuring { .. } => break,
            }
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before it saved a checkpoint while measuring"
        );
        assert!(began.elapsed() < Duration::from_secs(60), "no checkpoint");
        std::thread::sleep(Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(
        !run_file(&out, spec.seed).exists(),
        "killed before it ended"
    );
    assert!(ckpt.exists());

    let err = finished(&run(&file, &out, &[]).output().unwrap());
    assert!(
        err.contains("1 run(s) continued from their checkpoints"),
        "{err}"
    );
    assert!(!ckpt.exists(), "removed once the record is saved");
    assert_same(&tables(&whole), &tables(&out));

    // The checkpoint saved while equilibrating, in a fresh folder (with the
    // .study.json that marks a study's folder: a checkpoint alone is no proof).
    let bytes = equilibrating.expect("a checkpoint saved while equilibrating");
    let early = dir.path().join("early");
    std::fs::create_dir_all(runs_dir(&early)).unwrap();
    std::fs::copy(out.join(".study.json"), early.join(".study.json")).unwrap();
    std::fs::write(file_of(&early, spec.seed), bytes).unwrap();
    let err = finished(&run(&file, &early, &[]).output().unwrap());
    assert!(
        err.contains("1 run(s) continued from their checkpoints"),
        "{err}"
    );
    assert_same(&tables(&whole), &tables(&early));
}

fn file_of(out: &Path, seed: u64) -> std::path::PathBuf {
    file(&runs_dir(out), seed)
}
