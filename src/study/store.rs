//! Tidy Parquet tables of a study (polars), each written to a temporary file
//! and renamed, so a reader never sees half a table.

use super::plan_types::RunSpec;
use super::record::RunRecord;
use crate::analysis::summary_types::SummaryRow;
use anyhow::Context;
use polars::prelude::{Column, DataFrame, ParquetReader, ParquetWriter, SerReader};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Write `bytes` to `path` via a temporary sibling and a rename.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    let tmp = temp_name(path);
    std::fs::write(&tmp, bytes).with_context(|| format!("cannot write {}", tmp.display()))?;
    std::fs::rename(&tmp, path)
        .with_context(|| format!("cannot move {} into place", path.display()))
}

fn temp_name(path: &Path) -> PathBuf {
    let mut name = path.file_name().unwrap_or_default().to_os_string();
    name.push(".tmp");
    path.with_file_name(name)
}

/// Write `df` as Parquet at `path`, atomically.
pub fn write_parquet(path: &Path, df: &mut DataFrame) -> anyhow::Result<()> {
    let tmp = temp_name(path);
    let file =
        std::fs::File::create(&tmp).with_context(|| format!("cannot create {}", tmp.display()))?;
    ParquetWriter::new(file)
        .finish(df)
        .with_context(|| format!("cannot write {}", tmp.display()))?;
    std::fs::rename(&tmp, path)
        .with_context(|| format!("cannot move {} into place", path.display()))
}

/// Read a Parquet table back (tests, `.ci/run`, later analyses).
pub fn read_parquet(path: &Path) -> anyhow::Result<DataFrame> {
    let file =
        std::fs::File::open(path).with_context(|| format!("cannot open {}", path.display()))?;
    ParquetReader::new(file)
        .finish()
        .with_context(|| format!("cannot read {}", path.display()))
}

/// Columns of `runs.parquet` that are always there; scalar results with one
/// of these names are stored as `result.<name>`.
const FIXED: [&str; 8] = [
    "run_id",
    "point_id",
    "replica",
    "seed",
    "events",
    "collisions",
    "wall_seconds",
    "status",
];

/// Write runs.parquet, series.parquet and histograms.parquet (the last two
/// only if some run produced them) and summary.parquet. Returns the files written.
pub fn write_tables(
    out_dir: &Path,
    runs: &[(RunSpec, RunRecord)],
    summary: &[SummaryRow],
) -> anyhow::Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    let mut put = |name: &str, mut df: DataFrame| -> anyhow::Result<()> {
        let path = out_dir.join(name);
        write_parquet(&path, &mut df)?;
        written.push(path);
        Ok(())
    };
    put("runs.parquet", runs_table(runs)?)?;
    if runs.iter().any(|(_, r)| !r.output.series.is_empty()) {
        put("series.parquet", series_table(runs)?)?;
    }
    if runs.iter().any(|(_, r)| !r.output.histograms.is_empty()) {
        put("histograms.parquet", histograms_table(runs)?)?;
    }
    let specs: Vec<&RunSpec> = runs.iter().map(|(s, _)| s).collect();
    put("summary.parquet", summary_table(&specs, summary)?)?;
    Ok(written)
}

/// One column per swept key path: f64 if every value is a number, else text.
fn param_columns(specs: &[&RunSpec], rows: &[&[(String, toml::Value)]]) -> Vec<Column> {
    let Some(first) = specs.first() else {
        return Vec::new();
    };
    first
        .params
        .iter()
        .enumerate()
        .map(|(i, (key, _))| {
            let values: Vec<Option<&toml::Value>> =
                rows.iter().map(|p| p.get(i).map(|(_, v)| v)).collect();
            let numeric = values.iter().flatten().all(|v| as_f64(v).is_some());
            if numeric {
                let col: Vec<Option<f64>> = values.iter().map(|v| v.and_then(as_f64)).collect();
                Column::new(key.as_str().into(), col)
            } else {
                let col: Vec<Option<String>> = values.iter().map(|v| v.map(text)).collect();
                Column::new(key.as_str().into(), col)
            }
        })
        .collect()
}

pub fn as_f64(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Integer(i) => Some(*i as f64),
        toml::Value::Float(f) => Some(*f),
        _ => None,
    }
}

fn text(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

fn runs_table(runs: &[(RunSpec, RunRecord)]) -> anyhow::Result<DataFrame> {
    let specs: Vec<&RunSpec> = runs.iter().map(|(s, _)| s).collect();
    let params: Vec<&[(String, toml::Value)]> = specs.iter().map(|s| s.params.as_slice()).collect();
    let mut columns = vec![
        Column::new(
            "run_id".into(),
            runs.iter().map(|(s, _)| s.run_id).collect::<Vec<u64>>(),
        ),
        Column::new(
            "point_id".into(),
            runs.iter().map(|(s, _)| s.point_id).collect::<Vec<u64>>(),
        ),
        Column::new(
            "replica".into(),
            runs.iter().map(|(s, _)| s.replica).collect::<Vec<u32>>(),
        ),
        Column::new(
            "seed".into(),
            runs.iter().map(|(s, _)| s.seed).collect::<Vec<u64>>(),
        ),
    ];
    columns.extend(param_columns(&specs, &params));
    // Scalar names in order of first appearance (deterministic: runs are in plan order).
    let mut names: Vec<&str> = Vec::new();
    for (_, r) in runs {
        for (name, _) in &r.output.scalars {
            if !names.contains(&name.as_str()) {
                names.push(name);
            }
        }
    }
    for name in names {
        let col: Vec<Option<f64>> = runs.iter().map(|(_, r)| r.output.scalar(name)).collect();
        let taken = FIXED.contains(&name)
            || specs
                .first()
                .is_some_and(|s| s.params.iter().any(|(k, _)| k == name));
        let column_name = if taken {
            format!("result.{name}")
        } else {
            name.to_string()
        };
        columns.push(Column::new(column_name.as_str().into(), col));
    }
    columns.push(Column::new(
        "events".into(),
        runs.iter()
            .map(|(_, r)| r.output.events)
            .collect::<Vec<u64>>(),
    ));
    columns.push(Column::new(
        "collisions".into(),
        runs.iter()
            .map(|(_, r)| r.output.collisions)
            .collect::<Vec<u64>>(),
    ));
    columns.push(Column::new(
        "wall_seconds".into(),
        runs.iter()
            .map(|(_, r)| r.output.wall_seconds)
            .collect::<Vec<f64>>(),
    ));
    columns.push(Column::new(
        "status".into(),
        runs.iter()
            .map(|(_, r)| r.status.clone())
            .collect::<Vec<String>>(),
    ));
    DataFrame::new(runs.len(), columns).context("cannot build runs.parquet")
}

fn series_table(runs: &[(RunSpec, RunRecord)]) -> anyhow::Result<DataFrame> {
    let (mut id, mut t, mut obs, mut value) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (spec, r) in runs {
        for s in &r.output.series {
            for (&ti, &vi) in s.t.iter().zip(&s.value) {
                id.push(spec.run_id);
                t.push(ti);
                obs.push(s.observable.clone());
                value.push(vi);
            }
        }
    }
    let n = id.len();
    DataFrame::new(
        n,
        vec![
            Column::new("run_id".into(), id),
            Column::new("t".into(), t),
            Column::new("observable".into(), obs),
            Column::new("value".into(), value),
        ],
    )
    .context("cannot build series.parquet")
}

fn histograms_table(runs: &[(RunSpec, RunRecord)]) -> anyhow::Result<DataFrame> {
    let (mut id, mut obs, mut lo, mut hi, mut count) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (spec, r) in runs {
        for h in &r.output.histograms {
            for ((&l, &u), &c) in h.lo.iter().zip(&h.hi).zip(&h.count) {
                id.push(spec.run_id);
                obs.push(h.observable.clone());
                lo.push(l);
                hi.push(u);
                count.push(c);
            }
        }
    }
    let n = id.len();
    DataFrame::new(
        n,
        vec![
            Column::new("run_id".into(), id),
            Column::new("observable".into(), obs),
            Column::new("lo".into(), lo),
            Column::new("hi".into(), hi),
            Column::new("count".into(), count),
        ],
    )
    .context("cannot build histograms.parquet")
}

/// summary.parquet; parameter columns come from the plan (so text values stay text).
fn summary_table(specs: &[&RunSpec], summary: &[SummaryRow]) -> anyhow::Result<DataFrame> {
    let by_point: BTreeMap<u64, &RunSpec> = specs.iter().map(|s| (s.point_id, *s)).collect();
    let point_specs: Vec<&RunSpec> = summary
        .iter()
        .filter_map(|r| by_point.get(&r.point_id).copied())
        .collect();
    let params: Vec<&[(String, toml::Value)]> = summary
        .iter()
        .map(|r| {
            by_point
                .get(&r.point_id)
                .map_or(&[][..], |s| s.params.as_slice())
        })
        .collect();
    let mut columns = vec![Column::new(
        "point_id".into(),
        summary.iter().map(|r| r.point_id).collect::<Vec<u64>>(),
    )];
    columns.extend(param_columns(&point_specs, &params));
    let f = |name: &str, get: &dyn Fn(&SummaryRow) -> f64| {
        Column::new(name.into(), summary.iter().map(get).collect::<Vec<f64>>())
    };
    columns.push(Column::new(
        "result".into(),
        summary
            .iter()
            .map(|r| r.result.clone())
            .collect::<Vec<String>>(),
    ));
    columns.push(Column::new(
        "n".into(),
        summary.iter().map(|r| r.n).collect::<Vec<u64>>(),
    ));
    columns.push(f("mean", &|r| r.mean));
    columns.push(f("std", &|r| r.std));
    columns.push(f("stderr", &|r| r.stderr));
    columns.push(f("ci_low", &|r| r.ci_low));
    columns.push(f("ci_high", &|r| r.ci_high));
    columns.push(Column::new(
        "theory".into(),
        summary
            .iter()
            .map(|r| r.theory)
            .collect::<Vec<Option<f64>>>(),
    ));
    columns.push(Column::new(
        "z".into(),
        summary.iter().map(|r| r.z).collect::<Vec<Option<f64>>>(),
    ));
    columns.push(f("seconds", &|r| r.seconds));
    columns.push(Column::new(
        "collisions".into(),
        summary.iter().map(|r| r.collisions).collect::<Vec<u64>>(),
    ));
    DataFrame::new(summary.len(), columns).context("cannot build summary.parquet")
}
