//! Parquet round trip of the study tables, including nulls and text columns.

use bonkers::study::store::{read_parquet, write_parquet};
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
    assert!(
        !dir.path().join("t.parquet.tmp").exists(),
        "temporary file renamed away"
    );
    let back = read_parquet(&path).unwrap();
    assert_eq!(back.schema(), df.schema());
    for (a, b) in df.columns().iter().zip(back.columns()) {
        assert!(a.equals_missing(b), "{}", a.name());
    }
    assert_eq!(back.column("x").unwrap().f64().unwrap().get(1), None);
}
