//! Output that grows with the particle count stays bounded: a per-particle
//! family is drawn for an evenly spaced sample of its particles, and the
//! tables keep them all.

use crate::study_common::{run_options, write_descriptor};
use bonkers::runner::pipeline;
use std::sync::atomic::AtomicBool;

const MANY_RODS: &str = r#"
[study]
name = "many-rods"
replicas = 1
seed = 5

[scene]
dimension = 1
box = [400.0]
boundary = ["walls"]
placement = { kind = "lattice" }
species = [{ name = "rod", count = 300, radius = 0.0 }]

[observe]
histograms = ["velocity_x_each"]

[run]
duration = 2.0
sample_every = 1.0
"#;

#[test]
fn per_particle_figures_are_a_sample_and_the_tables_keep_all() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), MANY_RODS);
    let out = dir.path().join("out");
    let outcome = pipeline::run_study(
        &file,
        &run_options(&out, 2),
        &bonkers::runner::simulate::run,
        &AtomicBool::new(false),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(outcome.failed, 0);
    let figures = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".svg") && n.contains("velocity_x"))
        .count();
    assert!(
        (1..=bonkers::report::sampled::PER_FAMILY).contains(&figures),
        "{figures} per-particle figures for 300 rods"
    );
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(
        md.contains("of its 300 particles"),
        "no note of the cut in:\n{md}"
    );
    let html = std::fs::metadata(out.join("index.html")).unwrap().len();
    assert!(html < 5_000_000, "index.html is {html} bytes");
}
