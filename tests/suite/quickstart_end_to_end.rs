//! The bundled quickstart, end to end through the `study` binary: it runs,
//! writes every output, and its tables read back.

use bonkers::runner::store::read_parquet;
use std::process::Command;

#[test]
fn quickstart_runs_and_its_tables_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("quickstart");
    let status = Command::new(env!("CARGO_BIN_EXE_study"))
        .args(["run", "studies/quickstart.toml", "--quiet", "--out"])
        .arg(&out)
        .status()
        .unwrap();
    assert!(status.success());
    for file in [
        "report.md",
        "index.html",
        "manifest.json",
        "mackay_spacetime_200.svg",
        "piston_frequency_ratio_1d.svg",
    ] {
        assert!(out.join(file).is_file(), "{file} missing");
    }
    let runs = read_parquet(&out.join("runs.parquet")).unwrap();
    // 2 sweep points x 8 replicas, and MacKay's case x 4.
    assert_eq!(runs.height(), 16 + 4);
    let status = runs.column("status").unwrap().str().unwrap();
    assert!((0..status.len()).all(|k| status.get(k) == Some("ok")));
    let summary = read_parquet(&out.join("summary.parquet")).unwrap();
    assert!(summary.height() >= 2 * 10);
    let series = read_parquet(&out.join("series.parquet")).unwrap();
    assert!(series.height() > 1000);
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(html.contains("<svg") && !html.contains("http://") && !html.contains("https://"));
}

/// A small 1D piston study and a 2D gas between thermal walls (the engine's
/// own random stream), each with scalars, series and histograms.
const TINY: [&str; 2] = [
    r#"
[study]
name = "tiny-1d"
replicas = 3
seed = 7

[scene]
preset = "mackay-piston"
velocities = { kind = "maxwell", temperature = 1.0 }
piston = { mass = 40.0, position = 0.5, radius = 0.0, energy = 5.0 }

[sweep.parameters]
"scene.piston.mass" = [10.0, 100.0]

[run]
duration = 300.0
sample_every = 1.0

[observe]
scalars = ["wall_pressure", "temperature"]
histograms = ["scaled_velocity_x"]

[analysis.piston]
"#,
    r#"
[study]
name = "tiny-2d"
replicas = 3
seed = 8

[scene]
dimension = 2
box = [12.0, 12.0]
boundary = ["walls", "periodic"]
species = [{ name = "disk", count = 30 }]
thermal_walls = [{ axis = 0, side = "low", temperature = 2.0 }]

[run]
duration = 10.0
sample_every = 0.5

[observe]
series = ["temperature"]
scalars = ["virial_pressure", "wall_heat"]
histograms = ["scaled_velocity_x"]
"#,
];

/// The real engine, not a stand-in: the same descriptor gives bit-identical
/// tables on 1, 2 and 4 threads: every column of every table but the
/// timings (`wall_seconds`, `cpu_seconds`, `prepare_seconds`).
#[test]
fn tables_are_bit_identical_whatever_the_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    for (k, text) in TINY.iter().enumerate() {
        let file = dir.path().join(format!("tiny{k}.toml"));
        std::fs::write(&file, text).unwrap();
        let run = |threads: &str| {
            let out = dir.path().join(format!("t{k}-{threads}"));
            let status = Command::new(env!("CARGO_BIN_EXE_study"))
                .args(["run", "--quiet", "--threads", threads, "--out"])
                .arg(&out)
                .arg(&file)
                .status()
                .unwrap();
            assert!(status.success());
            ["runs", "series", "histograms", "summary"].map(|name| {
                let mut df = read_parquet(&out.join(format!("{name}.parquet"))).unwrap();
                for timing in ["wall_seconds", "cpu_seconds", "prepare_seconds"] {
                    if df.column(timing).is_ok() {
                        df = df.drop(timing).unwrap();
                    }
                }
                (name, df)
            })
        };
        let one = run("1");
        assert_eq!(one[0].1.height(), if k == 0 { 6 } else { 3 });
        let status = one[0].1.column("status").unwrap().str().unwrap();
        assert!((0..status.len()).all(|i| status.get(i) == Some("ok")));
        for threads in ["2", "4"] {
            let other = run(threads);
            for ((name, a), (_, b)) in one.iter().zip(&other) {
                assert_eq!(a.get_column_names(), b.get_column_names(), "{name}");
                assert!(a.height() > 0, "{name} is empty");
                assert!(
                    a.equals_missing(b),
                    "tiny{k}: {name}.parquet differs on {threads} threads"
                );
            }
        }
    }
}
