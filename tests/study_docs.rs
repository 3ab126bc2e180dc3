//! docs/descriptor.md tells the truth: its annotated example validates with
//! every name it uses and runs end to end (its `--quick` version), and its
//! catalogue lists every observable and analysis option bonkers knows.

use bonkers::descriptor::load::{parse, quick};
use bonkers::descriptor::sweep::count;
use bonkers::runner::pipeline::{StudyOptions, run_study};
use bonkers::runner::progress::ProgressMode;
use bonkers::runner::store::read_parquet;
use bonkers::studies::REGISTRY;
use std::sync::atomic::AtomicBool;

fn doc() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/descriptor.md")).unwrap()
}

fn example() -> String {
    doc()
        .split("```toml\n")
        .nth(1)
        .unwrap()
        .split("```")
        .next()
        .unwrap()
        .to_string()
}

#[test]
fn the_documented_example_is_valid() {
    let loaded = parse("docs/descriptor.md", &example()).unwrap();
    // 6 sweep points x 8 replicas and one case x 4.
    assert_eq!(count(&loaded), (6 + 1, 48 + 4));
    let q = quick(&loaded).unwrap();
    assert_eq!(count(&q), (4 + 1, 8 + 4));
    // Every name is one bonkers knows (parse checks them; these make sure
    // the example exercises each kind of name).
    let d = &loaded.descriptor;
    assert!(!d.observe.series.is_empty() && !d.observe.scalars.is_empty());
    assert!(!d.observe.histograms.is_empty());
    assert!(d.analysis["piston"].contains_key("window_periods"));
    assert_eq!(d.case.len(), 1);
}

/// The example's --quick version on the real engine: every run succeeds and
/// every table and the report are there, with the observed quantities.
#[test]
fn the_documented_example_runs() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("example.toml");
    std::fs::write(&file, example()).unwrap();
    let out = dir.path().join("out");
    let options = StudyOptions {
        out: Some(out.clone()),
        threads: Some(2),
        replicas: None,
        quick: true,
        fresh: false,
        progress: ProgressMode::Quiet,
        yes: false,
        command_line: vec!["study".into()],
    };
    let outcome = run_study(
        &file,
        &options,
        &bonkers::runner::simulate::run,
        &AtomicBool::new(false),
    )
    .unwrap();
    assert_eq!((outcome.planned, outcome.failed), (8 + 4, 0));
    let runs = read_parquet(&out.join("runs.parquet")).unwrap();
    for column in [
        "wall_pressure",
        "temperature",
        "frequency_ratio",
        "cpu_seconds",
    ] {
        assert!(runs.column(column).is_ok(), "runs.parquet lacks {column}");
    }
    let series = read_parquet(&out.join("series.parquet")).unwrap();
    let observables = series.column("observable").unwrap().str().unwrap();
    for name in ["kinetic_energy", "piston_position", "kinetic_energy.light"] {
        assert!(
            (0..observables.len()).any(|k| observables.get(k) == Some(name)),
            "no {name} series"
        );
    }
    assert!(
        read_parquet(&out.join("histograms.parquet"))
            .unwrap()
            .height()
            > 0
    );
    assert!(read_parquet(&out.join("summary.parquet")).unwrap().height() > 0);
    assert!(out.join("index.html").is_file() && out.join("manifest.json").is_file());
}

#[test]
fn every_observable_and_analysis_option_is_documented() {
    let doc = doc();
    for (kind, name, _) in bonkers::observe::CATALOGUE {
        let row = format!("| `{kind}` | `{name}` |");
        assert!(doc.contains(&row), "docs/descriptor.md lacks the row {row}");
    }
    for a in REGISTRY {
        for o in a.options() {
            let row = format!("| `{}` | `{}` |", a.name(), o.name);
            assert!(doc.contains(&row), "docs/descriptor.md lacks the row {row}");
        }
    }
}
