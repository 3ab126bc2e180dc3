//! The registry's promises: every registered study is one folder with a
//! bundled descriptor of its name, and on every bundled descriptor that asks
//! for it each run writes exactly the results the study declares for that
//! run (`Study::writes`).

use crate::study_common::run_options;
use bonkers::descriptor::load::{load, quick, with_replicas};
use bonkers::runner::pipeline::{StudyOptions, run_study};
use bonkers::runner::plan::plan;
use bonkers::runner::store::read_parquet;
use bonkers::studies::{REGISTRY, named};
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The bundled descriptors, by file name.
fn bundled() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("studies"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_study_is_a_folder_with_a_descriptor_of_its_name() {
    for s in REGISTRY {
        let folder = root().join("src/studies").join(s.name());
        assert!(folder.join("mod.rs").is_file(), "no {}", folder.display());
        let descriptor = root().join("studies").join(format!("{}.toml", s.name()));
        assert!(descriptor.is_file(), "no {}", descriptor.display());
    }
}

#[test]
fn every_run_writes_exactly_what_its_studies_declare() {
    let mut exercised: Vec<&str> = Vec::new();
    for file in bundled() {
        let loaded = with_replicas(&quick(&load(&file).unwrap()).unwrap(), 1).unwrap();
        let specs = plan(&loaded).unwrap();
        let studies: Vec<&str> = named(&loaded.descriptor).map(|s| s.name()).collect();
        if studies.is_empty() {
            continue;
        }
        exercised.extend(&studies);
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        let options = StudyOptions {
            quick: true,
            replicas: Some(1),
            ..run_options(&out, 2)
        };
        let outcome = run_study(
            &file,
            &options,
            &bonkers::runner::execute::simulate::run,
            &AtomicBool::new(false),
        )
        .unwrap();
        assert_eq!(outcome.failed, 0, "{}: runs failed", file.display());
        assert_eq!(outcome.planned, specs.len(), "{}", file.display());
        // Each run's row holds a value (NaN included) for exactly the
        // results its studies declare for it: a result left out is a null.
        let runs = read_parquet(&out.join("runs.parquet")).unwrap();
        let ids = runs.column("run_id").unwrap().u64().unwrap().clone();
        for spec in &specs {
            let row = (0..ids.len()).find(|&k| ids.get(k) == Some(spec.run_id));
            let row = row.expect("every planned run has a row");
            for s in named(&spec.descriptor) {
                let declared = s.writes(&spec.descriptor);
                for result in s.results() {
                    let value = runs.column(result).ok().map(|c| c.f64().unwrap().get(row));
                    assert_eq!(
                        value.flatten().is_some(),
                        declared.contains(result),
                        "{} run {}: the {} analysis {} `{result}`",
                        file.display(),
                        spec.run_id,
                        s.name(),
                        if declared.contains(result) {
                            "declares but did not write"
                        } else {
                            "wrote without declaring"
                        }
                    );
                }
            }
        }
    }
    for s in REGISTRY {
        assert!(
            exercised.contains(&s.name()),
            "no bundled descriptor asks for the {} analysis",
            s.name()
        );
    }
}
