//! Parquet round trip of the study tables, including nulls and text columns.

use bonkers::runner::store::{read_parquet, write_parquet};
use polars::prelude::{Column, DataFrame};

#[test]
fn parquet_round_trip_keeps_types_values_and_nulls() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("t.parquet");
    let mut df = DataFrame::new(
        3,
        vec![
            Column::new("run_id".into(), vec![0u64, 1, 2]),
            Column::new("replica".into(), vec![0u32, 1, 0]),
            Column::new("x".into(), vec![Some(0.1f64), None, Some(f64::MAX)]),
            Column::new(
                "status".into(),
                vec!["ok".to_string(), "failed: x".into(), "ok".into()],
            ),
        ],
    )
    .unwrap();
    write_parquet(&path, &mut df).unwrap();
    let names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["t.parquet"], "temporary file renamed away");
    let back = read_parquet(&path).unwrap();
    assert_eq!(back.schema(), df.schema());
    for (a, b) in df.columns().iter().zip(back.columns()) {
        assert!(a.equals_missing(b), "{}", a.name());
    }
    assert_eq!(back.column("x").unwrap().f64().unwrap().get(1), None);
}

/// A scalar result named like a column runs.parquet already has (`seed`, a
/// swept key path, or an earlier renamed one) gets a free name, the same one
/// every time, instead of failing the table after every run has finished.
#[test]
fn clashing_result_names_get_distinct_deterministic_columns() {
    use bonkers::model::run_output::RunOutput;
    use bonkers::runner::store::record::RunRecord;
    use bonkers::runner::store::write_tables;
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/studies/quickstart.toml"
    ))
    .unwrap();
    let specs =
        bonkers::runner::plan::plan(&bonkers::descriptor::load::parse("q.toml", &text).unwrap())
            .unwrap();
    let runs: Vec<_> = specs
        .into_iter()
        .map(|spec| {
            let output = RunOutput {
                scalars: vec![
                    ("seed".into(), 1.0),
                    ("result.seed".into(), 2.0),
                    ("scene.piston.mass".into(), 3.0),
                    ("status".into(), 4.0),
                ],
                ..Default::default()
            };
            let record = RunRecord {
                run_id: spec.run_id,
                fingerprint: String::new(),
                status: "ok".into(),
                output,
            };
            (spec, record)
        })
        .collect();
    let dir = tempfile::tempdir().unwrap();
    write_tables(dir.path(), &runs, &[]).unwrap();
    let df = read_parquet(&dir.path().join("runs.parquet")).unwrap();
    let names: Vec<String> = df
        .get_column_names()
        .iter()
        .map(|s| s.to_string())
        .collect();
    for (column, value) in [
        ("result.seed", 1.0),
        ("result.result.seed", 2.0),
        ("result.scene.piston.mass", 3.0),
        ("result.status", 4.0),
    ] {
        let col = df
            .column(column)
            .unwrap_or_else(|_| panic!("{column} in {names:?}"));
        assert_eq!(col.f64().unwrap().get(0), Some(value), "{column}");
    }
    // The built-in columns keep their meaning.
    assert_eq!(
        df.column("status").unwrap().str().unwrap().get(0),
        Some("ok")
    );
    assert_eq!(
        df.column("scene.piston.mass")
            .unwrap()
            .f64()
            .unwrap()
            .get(0),
        Some(30.0)
    );
}
