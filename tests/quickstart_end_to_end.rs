//! The bundled quickstart, end to end through the `study` binary: it runs,
//! writes every output, and its tables read back.

use bonkers::study::store::read_parquet;
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
        "scalar_frequency_ratio.svg",
    ] {
        assert!(out.join(file).is_file(), "{file} missing");
    }
    let runs = read_parquet(&out.join("runs.parquet")).unwrap();
    assert_eq!(runs.height(), 16);
    let status = runs.column("status").unwrap().str().unwrap();
    assert!((0..status.len()).all(|k| status.get(k) == Some("ok")));
    let summary = read_parquet(&out.join("summary.parquet")).unwrap();
    assert!(summary.height() >= 2 * 10);
    let series = read_parquet(&out.join("series.parquet")).unwrap();
    assert!(series.height() > 1000);
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(html.contains("<svg") && !html.contains("http://") && !html.contains("https://"));
}

/// The real engine, not a stand-in: the same descriptor gives bit-identical
/// tables on 1 and 2 threads (every column but the timings).
#[test]
fn tables_are_bit_identical_whatever_the_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let run = |threads: &str| {
        let out = dir.path().join(format!("t{threads}"));
        let status = Command::new(env!("CARGO_BIN_EXE_study"))
            .args([
                "run",
                "studies/piston.toml",
                "--quick",
                "--quiet",
                "--threads",
                threads,
                "--out",
            ])
            .arg(&out)
            .status()
            .unwrap();
        assert!(status.success());
        let runs = read_parquet(&out.join("runs.parquet"))
            .unwrap()
            .drop("wall_seconds")
            .unwrap();
        let series = read_parquet(&out.join("series.parquet")).unwrap();
        let summary = read_parquet(&out.join("summary.parquet"))
            .unwrap()
            .drop("seconds")
            .unwrap();
        (runs, series, summary)
    };
    let (a, b) = (run("1"), run("2"));
    assert_eq!(a.0.height(), 28 * 3);
    assert!(a.0.equals_missing(&b.0), "runs.parquet differs");
    assert!(a.1.equals_missing(&b.1), "series.parquet differs");
    assert!(a.2.equals_missing(&b.2), "summary.parquet differs");
}
