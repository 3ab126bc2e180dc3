//! The Arrow schema stored in every table's Parquet file names plain UTF-8
//! text, never a view type: pyarrow reads string views but cannot sort or
//! filter them, so a view type here breaks the tables for Arrow tools.

use base64::Engine;
use bonkers::model::run_output::{Histogram, RunOutput, Series};
use bonkers::model::summary::SummaryRow;
use bonkers::runner::store::record::RunRecord;
use bonkers::runner::store::{read_parquet, write_tables};
use polars_arrow::datatypes::{ArrowDataType, ArrowSchema};
use std::path::Path;

/// The schema as written in the file's "ARROW:schema" metadata, undecoded by
/// polars' reader (which would turn every text type back into a view).
fn stored_arrow_schema(path: &Path) -> ArrowSchema {
    let mut file = std::fs::File::open(path).unwrap();
    let metadata = polars_parquet::read::read_metadata(&mut file).unwrap();
    let encoded = metadata
        .key_value_metadata()
        .iter()
        .flatten()
        .find(|kv| kv.key == "ARROW:schema")
        .and_then(|kv| kv.value.clone())
        .unwrap_or_else(|| panic!("{} has no Arrow schema", path.display()));
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(encoded)
        .unwrap();
    // Arrow's IPC framing: a 0xFFFFFFFF marker and the length, then the message.
    let message = if bytes[..4] == [255; 4] {
        &bytes[8..]
    } else {
        &bytes[..]
    };
    polars_arrow::io::ipc::read::deserialize_schema(message)
        .unwrap()
        .0
}

/// Every type inside `dtype` (list items, struct fields, ...), itself first.
fn all_types(dtype: &ArrowDataType) -> Vec<&ArrowDataType> {
    let mut out = vec![dtype];
    match dtype {
        ArrowDataType::List(f)
        | ArrowDataType::LargeList(f)
        | ArrowDataType::FixedSizeList(f, _)
        | ArrowDataType::Map(f, _) => out.extend(all_types(&f.dtype)),
        ArrowDataType::Struct(fields) => {
            for f in fields {
                out.extend(all_types(&f.dtype));
            }
        }
        ArrowDataType::Dictionary(_, values, _) => out.extend(all_types(values)),
        ArrowDataType::Extension(ext) => out.extend(all_types(&ext.inner)),
        _ => {}
    }
    out
}

/// The piston plan (it sweeps a text parameter, `scene.preset`) with
/// made-up outputs that fill all four tables, and one failed run.
fn runs() -> Vec<(bonkers::model::run_spec::RunSpec, RunRecord)> {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/studies/piston.toml"))
        .unwrap();
    let loaded = bonkers::descriptor::load::parse("piston.toml", &text).unwrap();
    let loaded = bonkers::descriptor::load::quick(&loaded).unwrap();
    let specs = bonkers::runner::plan::plan(&loaded).unwrap();
    specs
        .into_iter()
        .map(|spec| {
            let output = RunOutput {
                scalars: vec![("frequency".into(), spec.run_id as f64)],
                series: vec![Series {
                    observable: "piston_position".into(),
                    t: vec![0.0, 1.0],
                    value: vec![0.5, 0.25],
                }],
                histograms: vec![Histogram {
                    observable: "speed".into(),
                    lo: vec![0.0, 1.0],
                    hi: vec![1.0, 2.0],
                    count: vec![3.0, 4.0],
                }],
                ..Default::default()
            };
            let status = if spec.run_id == 1 {
                "failed: made up".into()
            } else {
                "ok".into()
            };
            let record = RunRecord {
                run_id: spec.run_id,
                fingerprint: String::new(),
                status,
                output,
            };
            (spec, record)
        })
        .collect()
}

#[test]
fn every_table_stores_plain_utf8_text_and_no_view_types() {
    let runs = runs();
    let summary: Vec<SummaryRow> = runs
        .iter()
        .map(|(spec, _)| SummaryRow {
            point_id: spec.point_id,
            params: Vec::new(),
            result: "frequency".into(),
            n: 1,
            mean: 1.0,
            std: 0.0,
            stderr: 0.0,
            ci_low: 1.0,
            ci_high: 1.0,
            theory: None,
            z: None,
            seconds: 0.0,
            collisions: 0,
        })
        .collect();
    let dir = tempfile::tempdir().unwrap();
    let written = write_tables(dir.path(), &runs, &summary).unwrap();
    let names: Vec<String> = written
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        names,
        [
            "runs.parquet",
            "series.parquet",
            "histograms.parquet",
            "summary.parquet"
        ]
    );
    // The text columns each table must have, stored as Arrow large_string.
    let text_columns: [&[&str]; 4] = [
        &["scene.preset", "status"],
        &["observable"],
        &["observable"],
        &["scene.preset", "result"],
    ];
    for (path, text) in written.iter().zip(text_columns) {
        let table = path.display();
        let schema = stored_arrow_schema(path);
        for field in schema.iter_values() {
            for dtype in all_types(&field.dtype) {
                assert!(
                    !dtype.is_view(),
                    "{table}: column {} is stored as {dtype:?}",
                    field.name
                );
            }
        }
        for name in text {
            let field = schema
                .get(name)
                .unwrap_or_else(|| panic!("{table} has no column {name}"));
            assert_eq!(field.dtype, ArrowDataType::LargeUtf8, "{table}: {name}");
        }
        // The same schema, column for column, as the frame polars reads back.
        let df = read_parquet(path).unwrap();
        let stored: Vec<&str> = schema.iter_names().map(|n| n.as_str()).collect();
        let read: Vec<&str> = df.get_column_names().iter().map(|n| n.as_str()).collect();
        assert_eq!(stored, read, "{table}");
    }
    let df = read_parquet(&dir.path().join("runs.parquet")).unwrap();
    let status = df.column("status").unwrap().str().unwrap();
    assert_eq!(status.get(1), Some("failed: made up"));
    assert_eq!(status.get(0), Some("ok"));
}
