//! Sizes that grew without bound (issue 50, items 8 and 9): what a run keeps
//! in memory, how many sweep points a plan holds, how much `study validate`
//! prints, how many figures a report draws and what a forged record with
//! many names costs `study collect`. Each refusal is exit 2 at its key
//! within a time and memory bound (`bounded.rs`); what is accepted finishes
//! within one, and the report keeps what it leaves out in its tables.

use crate::bounded::{Finished, finish, limited, names};
use bonkers::runner::store::read_parquet;
use bonkers::runner::store::record::RunRecord;
use std::path::Path;
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_secs(60);

/// A 1D base with `scene`, `run` and `observe` left to each case.
fn study(count: usize, run: &str, observe: &str, sweep: &str) -> String {
    format!(
        "[study]\nname = \"caps\"\nseed = 50\n\n[scene]\nbox = [{}.0]\n\
         velocities = {{ kind = \"maxwell\", temperature = 1.0 }}\n\n\
         [[scene.species]]\nname = \"gas\"\ncount = {count}\n\n\
         [run]\n{run}\n\n[observe]\n{observe}\n\n{sweep}\n",
        4 * count + 20
    )
}

/// `study ARGS` in `dir`, bounded in time and memory; no panic.
fn run(dir: &Path, args: &[&str], limit: Duration) -> Finished {
    let mut command = limited(env!("CARGO_BIN_EXE_study"));
    command.args(args).current_dir(dir);
    let done = finish(command, &format!("study {args:?}"), limit);
    assert!(
        !done.stderr.contains("panicked"),
        "{args:?}: {}",
        done.stderr
    );
    done
}

fn ranges(n: usize, steps: usize) -> String {
    let keys = [
        "run.duration",
        "run.equilibrate",
        "scene.box.0",
        "scene.species.0.radius",
        "scene.species.0.mass",
        "run.sample_every",
        "scene.velocities.temperature",
    ];
    let mut text = "[sweep.parameters]\n".to_string();
    for (i, key) in keys.iter().take(n).enumerate() {
        let from = 1.0 + i as f64;
        text += &format!(
            "\"{key}\" = {{ from = {from:?}, to = {:?}, steps = {steps} }}\n",
            2.0 * from
        );
    }
    text
}

fn list(key: &str, n: usize) -> String {
    let values: Vec<String> = (0..n).map(|i| format!("{:?}", 10.0 + i as f64)).collect();
    format!("[sweep.parameters]\n\"{key}\" = [{}]\n", values.join(", "))
}

/// Each row is refused with exit 2 by `study validate` (with `--yes`, so no
/// confirmation stands in for the cap), naming its key, the size it would
/// have and the cap, in a short message, quickly and within 2 GB.
#[test]
fn sizes_past_the_caps_are_refused_at_their_key() {
    let sampled = "duration = 1000000.0\nsample_every = 1.0";
    let rows: Vec<(&str, String, &[&str])> = vec![
        (
            "1000 rods' velocities at 1e6 samples",
            study(
                1000,
                sampled,
                "series = [\"kinetic_energy\", \"velocities\"]",
                "",
            ),
            &[
                "`observe.series.1`",
                "1.0e9 values per run",
                "at most 1e8",
                "sample less often (`sample_every = 11` or more)",
            ],
        ),
        (
            "positions and velocities share the cap",
            study(
                1000,
                "duration = 60000.0\nsample_every = 1.0",
                "series = [\"positions\", \"velocities\"]",
                "",
            ),
            &[
                "`observe.series.1`",
                "1.2e8 values per run",
                "`positions`: 1000 columns, `velocities`: 1000 columns",
                "at most 1e8",
            ],
        ),
        (
            "a series per species of many species",
            {
                let species: Vec<String> = (0..2000)
                    .map(|i| format!("{{ name = \"s{i}\", count = 1 }}"))
                    .collect();
                format!(
                    "[study]\nname = \"caps\"\n\n[scene]\nbox = [8000.0]\nspecies = [{}]\n\n\
                     [run]\nduration = 100000.0\nsample_every = 1.0\n\n[observe]\n\
                     series = [\"kinetic_energy_by_species\"]\n",
                    species.join(", ")
                )
            },
            &["`observe.series.0`", "2.0e8 values per run", "at most 1e8"],
        ),
        (
            "per-particle histograms of 100000 rods",
            study(
                100_000,
                "duration = 1.0\nsample_every = 1.0",
                "histograms = [\"velocity_x_each\"]",
                "",
            ),
            &[
                "`observe.histograms.0`",
                "6.0e6 bins per run",
                "at most 5e6",
            ],
        ),
        (
            "two ranges of 1400 steps",
            study(5, "duration = 50.0", "", &ranges(2, 1400)),
            &[
                "`sweep.parameters`",
                "1960000 points (1400 x 1400 values",
                "more than the 100000",
            ],
        ),
        (
            "2^70 points",
            study(5, "duration = 50.0", "", &ranges(7, 1024)),
            &[
                "`sweep.parameters`",
                "about 1.2e21 points",
                "more than the 100000",
            ],
        ),
        (
            "a range of 10^12 steps",
            study(5, "duration = 50.0", "", &ranges(1, 1_000_000_000_000)),
            &[
                "`sweep.parameters.run.duration`",
                "1000000000000 values",
                "at most 100000",
            ],
        ),
        (
            "a list of 10^6 values",
            study(5, "duration = 50.0", "", &list("run.duration", 1_000_000)),
            &[
                "`sweep.parameters.run.duration`",
                "1000000 values",
                "at most 100000",
            ],
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (what, text, expect) in rows {
        std::fs::write(dir.path().join("f.toml"), &text).unwrap();
        let done = run(dir.path(), &["validate", "f.toml", "--yes"], LIMIT);
        assert_eq!(done.code, 2, "{what}: {}{}", done.stdout, done.stderr);
        for e in expect {
            assert!(
                done.stderr.contains(e),
                "{what}: no {e:?} in\n{}",
                done.stderr
            );
        }
        assert!(
            done.stderr.len() < 1000,
            "{what}: {} bytes",
            done.stderr.len()
        );
    }
}

/// The largest plan the cap admits validates within the bound, and a long
/// list prints as its ends and its count, not every value.
#[test]
fn the_largest_sweep_validates_quickly_and_prints_briefly() {
    let dir = tempfile::tempdir().unwrap();
    let text = study(5, "duration = 50.0", "", &list("run.duration", 100_000));
    std::fs::write(dir.path().join("f.toml"), text).unwrap();
    let done = run(dir.path(), &["validate", "f.toml", "--yes"], LIMIT);
    assert_eq!(done.code, 0, "{}", done.stderr);
    assert!(
        done.stdout
            .contains("run.duration = [10.0, 11.0, 12.0, 13.0, 14.0, …, 100009.0 (100000 values)]"),
        "{}",
        done.stdout
    );
    assert!(done.stdout.contains("points: 100000"), "{}", done.stdout);
    assert!(done.stdout.len() < 2000, "{} bytes", done.stdout.len());
}

/// Figures of a per-particle family are drawn for 16 evenly spaced
/// particles; every particle stays in the tables, and the report says so.
#[test]
fn per_particle_figures_are_a_sample() {
    let n = 200;
    let dir = tempfile::tempdir().unwrap();
    let text = study(
        n,
        "duration = 2.0\nsample_every = 0.5",
        "series = [\"positions\"]\nhistograms = [\"velocity_x_each\"]",
        "",
    );
    std::fs::write(dir.path().join("f.toml"), text).unwrap();
    let done = run(
        dir.path(),
        &["run", "f.toml", "--out", "out", "--quiet"],
        LIMIT,
    );
    assert_eq!(done.code, 0, "{}", done.stderr);
    let out = dir.path().join("out");
    let files = names(&out);
    let count = |prefix: &str| {
        files
            .iter()
            .filter(|f| f.starts_with(prefix) && f.ends_with(".svg"))
            .count()
    };
    assert_eq!(count("hist_velocity_x_"), 16, "{files:?}");
    assert_eq!(count("series_x_"), 16, "{files:?}");
    // Evenly spaced, first and last included.
    for i in [0, n - 1] {
        assert!(
            files.contains(&format!("hist_velocity_x_{i}.svg")),
            "{files:?}"
        );
    }
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    for family in ["`velocity_x.<index>`", "`x.<index>`"] {
        assert!(
            report.contains(&format!("{family}: figures of 16 of its {n} particles")),
            "{report}"
        );
    }
    assert!(report.contains("every particle is in `histograms.parquet`"));
    let histograms = read_parquet(&out.join("histograms.parquet")).unwrap();
    let observables = histograms.column("observable").unwrap().n_unique().unwrap();
    assert_eq!(observables, n);
}

/// A run's record forged to hold `names` scalar results, its checksum made
/// again (the checksum guards against accidents, not forgery).
fn forge(out: &Path, names: usize) {
    let runs = out.join("runs");
    for file in std::fs::read_dir(&runs).unwrap() {
        let path = file.unwrap().path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let mut record = RunRecord::from_json(&text).unwrap();
        record.output.scalars = (0..names)
            .map(|i| (format!("forged_{i}"), i as f64))
            .collect();
        std::fs::write(&path, record.to_json().unwrap()).unwrap();
    }
}

/// `study collect` of a record with 10 000 scalar names takes a bounded
/// time (it was quadratic: 1000 names 3.6 s, 10 000 over 30 s), writes every
/// name into runs.parquet and summary.parquet, and draws at most 200 of
/// them, saying so.
#[test]
fn collect_is_linear_in_a_records_names() {
    let dir = tempfile::tempdir().unwrap();
    let text = study(5, "duration = 5.0", "scalars = [\"wall_pressure\"]", "");
    std::fs::write(dir.path().join("f.toml"), text).unwrap();
    let done = run(
        dir.path(),
        &["run", "f.toml", "--out", "out", "--quiet"],
        LIMIT,
    );
    assert_eq!(done.code, 0, "{}", done.stderr);
    let out = dir.path().join("out");
    let mut seconds = Vec::new();
    for n in [1000, 10_000] {
        forge(&out, n);
        let clock = Instant::now();
        let done = run(dir.path(), &["collect", "f.toml", "--out", "out"], LIMIT);
        seconds.push(clock.elapsed().as_secs_f64());
        assert_eq!(done.code, 0, "{n} names: {}", done.stderr);
        let runs = read_parquet(&out.join("runs.parquet")).unwrap();
        assert!(
            runs.get_column_names()
                .iter()
                .any(|c| c.as_str() == format!("forged_{}", n - 1)),
            "{n} names"
        );
        let summary = read_parquet(&out.join("summary.parquet")).unwrap();
        assert_eq!(summary.height(), n);
        let scalars = names(&out)
            .iter()
            .filter(|f| f.starts_with("scalar_") && f.ends_with(".svg"))
            .count();
        assert_eq!(scalars, 200, "{n} names");
        let report = std::fs::read_to_string(out.join("report.md")).unwrap();
        assert!(
            report.contains(&format!("figures of the first 200 of {n} names")),
            "{n} names"
        );
    }
    // Quadratic work would take 100 times as long for ten times the names.
    assert!(
        seconds[1] < 30.0 * seconds[0],
        "1000 names {} s, 10 000 names {} s",
        seconds[0],
        seconds[1]
    );
}
