//! A study on disk: the output folder and its lock, run records, the
//! manifest, collecting and publishing a report, and (here) the tidy Parquet
//! tables (polars), each written to a temporary file and renamed, so a
//! reader never sees half a table.

pub mod collect;
pub mod lock;
pub mod manifest;
pub mod outdir;
pub mod publish;
pub mod record;
pub mod status;

use crate::files::write_via_temp;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::model::summary::SummaryRow;
use crate::runner::store::record::RunRecord;
use anyhow::Context;
use polars::prelude::{
    BatchedWriter, Column, CompatLevel, DataFrame, KeyValueMetadata, ParquetReader, ParquetWriter,
    SchemaExt, SerReader,
};
use polars_parquet::write::schema_to_metadata_key;
use std::collections::{BTreeMap, HashMap, HashSet};
use std::fs::File;
use std::path::{Path, PathBuf};

/// Write `df` as Parquet at `path`, atomically.
///
/// Text is stored as Parquet UTF-8 either way; the Arrow schema kept in the
/// file's metadata tells readers which Arrow type to give it. Polars writes
/// its own string-view type there, which pyarrow reads but cannot sort or
/// filter, so we store the schema of the oldest Arrow compatibility level
/// instead (`large_string`), which every Arrow tool can query.
pub fn write_parquet(path: &Path, df: &mut DataFrame) -> anyhow::Result<()> {
    let metadata = oldest_schema(df);
    write_via_temp(path, |file| {
        ParquetWriter::new(file)
            .with_key_value_metadata(Some(metadata))
            .finish(df)?;
        Ok(())
    })
}

/// The Arrow schema of `df` at the oldest compatibility level, as the
/// Parquet metadata that tells readers the Arrow types.
fn oldest_schema(df: &DataFrame) -> KeyValueMetadata {
    KeyValueMetadata::Static(vec![schema_to_metadata_key(
        &df.schema().to_arrow(CompatLevel::oldest()),
    )])
}

/// Read a Parquet table back (tests, `.ci/run`, later analyses).
pub fn read_parquet(path: &Path) -> anyhow::Result<DataFrame> {
    let file =
        std::fs::File::open(path).with_context(|| format!("cannot open {}", path.display()))?;
    ParquetReader::new(file)
        .finish()
        .with_context(|| format!("cannot read {}", path.display()))
}

/// Columns of `runs.parquet` that are always there; a scalar result whose
/// name is taken (by these or a swept key path) is stored as `result.<name>`.
const FIXED: [&str; 10] = [
    "run_id",
    "point_id",
    "replica",
    "seed",
    "events",
    "collisions",
    "wall_seconds",
    "cpu_seconds",
    "prepare_seconds",
    "status",
];

/// The tables of a study, written as its runs stream past in plan order:
/// series and histogram rows go to their Parquet files a row group at a
/// time, so memory holds one group, not the study; each run's own row (its
/// scalars, cost and status, without series or histograms) is kept for
/// runs.parquet and summary.parquet, written by `finish`.
pub struct Tables {
    dir: PathBuf,
    runs: Vec<(RunSpec, RunRecord)>,
    series: Streamed,
    histograms: Streamed,
    series_rows: SeriesRows,
    histogram_rows: HistogramRows,
}

/// Rows per row group of the long tables (polars' default for whole tables).
const ROW_GROUP: usize = 512 * 512;

impl Tables {
    /// Tables to be written into `dir` (a staging folder: files are written
    /// in place, and published together).
    pub fn new(dir: &Path) -> Tables {
        Tables {
            dir: dir.to_path_buf(),
            runs: Vec::new(),
            series: Streamed::new(dir.join("series.parquet")),
            histograms: Streamed::new(dir.join("histograms.parquet")),
            series_rows: SeriesRows::default(),
            histogram_rows: HistogramRows::default(),
        }
    }

    /// The next run of the plan.
    pub fn add(&mut self, spec: &RunSpec, record: &RunRecord) -> anyhow::Result<()> {
        let id = spec.run_id;
        for s in &record.output.series {
            let rows = &mut self.series_rows;
            for (&t, &v) in s.t.iter().zip(&s.value) {
                rows.id.push(id);
                rows.t.push(t);
                rows.observable.push(s.observable.clone());
                rows.value.push(v);
            }
        }
        for h in &record.output.histograms {
            let rows = &mut self.histogram_rows;
            for ((&lo, &hi), &c) in h.lo.iter().zip(&h.hi).zip(&h.count) {
                rows.id.push(id);
                rows.observable.push(h.observable.clone());
                rows.lo.push(lo);
                rows.hi.push(hi);
                rows.count.push(c);
            }
        }
        if self.series_rows.id.len() >= ROW_GROUP {
            self.series
                .write(std::mem::take(&mut self.series_rows).frame()?)?;
        }
        if self.histogram_rows.id.len() >= ROW_GROUP {
            self.histograms
                .write(std::mem::take(&mut self.histogram_rows).frame()?)?;
        }
        // The run's row: everything but its samples.
        let output = RunOutput {
            scalars: record.output.scalars.clone(),
            series: Vec::new(),
            histograms: Vec::new(),
            ..record.output
        };
        let row = RunRecord {
            fingerprint: String::new(),
            status: record.status.clone(),
            output,
            ..*record
        };
        self.runs.push((spec.clone(), row));
        Ok(())
    }

    /// Write what is left of the long tables (each only if some run produced
    /// rows), runs.parquet and summary.parquet. Returns the files written.
    pub fn finish(mut self, summary: &[SummaryRow]) -> anyhow::Result<Vec<PathBuf>> {
        if !self.series_rows.id.is_empty() {
            self.series.write(self.series_rows.frame()?)?;
        }
        if !self.histogram_rows.id.is_empty() {
            self.histograms.write(self.histogram_rows.frame()?)?;
        }
        let runs = self.dir.join("runs.parquet");
        write_parquet(&runs, &mut runs_table(&self.runs)?)?;
        let mut written = vec![runs];
        written.extend(self.series.finish()?);
        written.extend(self.histograms.finish()?);
        let summary_path = self.dir.join("summary.parquet");
        write_parquet(&summary_path, &mut summary_table(&self.runs, summary)?)?;
        written.push(summary_path);
        Ok(written)
    }
}

/// Every table at once from runs held in memory, in plan order.
pub fn write_tables(
    out_dir: &Path,
    runs: &[(RunSpec, RunRecord)],
    summary: &[SummaryRow],
) -> anyhow::Result<Vec<PathBuf>> {
    let mut tables = Tables::new(out_dir);
    for (spec, record) in runs {
        tables.add(spec, record)?;
    }
    tables.finish(summary)
}

/// A Parquet file written a row group at a time; created with its first group.
struct Streamed {
    path: PathBuf,
    writer: Option<BatchedWriter<File>>,
}

impl Streamed {
    fn new(path: PathBuf) -> Streamed {
        Streamed { path, writer: None }
    }

    fn write(&mut self, df: DataFrame) -> anyhow::Result<()> {
        let context = || format!("cannot write {}", self.path.display());
        if self.writer.is_none() {
            let file = File::create(&self.path).with_context(context)?;
            let writer = ParquetWriter::new(file)
                .with_key_value_metadata(Some(oldest_schema(&df)))
                .batched(df.schema())
                .with_context(context)?;
            self.writer = Some(writer);
        }
        if let Some(writer) = &mut self.writer {
            writer.write_batch(&df).with_context(context)?;
        }
        Ok(())
    }

    fn finish(self) -> anyhow::Result<Option<PathBuf>> {
        let Some(writer) = self.writer else {
            return Ok(None);
        };
        writer
            .finish()
            .with_context(|| format!("cannot write {}", self.path.display()))?;
        Ok(Some(self.path))
    }
}

/// series.parquet rows, long form.
#[derive(Default)]
struct SeriesRows {
    id: Vec<u64>,
    t: Vec<f64>,
    observable: Vec<String>,
    value: Vec<f64>,
}

impl SeriesRows {
    fn frame(self) -> anyhow::Result<DataFrame> {
        DataFrame::new(
            self.id.len(),
            vec![
                Column::new("run_id".into(), self.id),
                Column::new("t".into(), self.t),
                Column::new("observable".into(), self.observable),
                Column::new("value".into(), self.value),
            ],
        )
        .context("cannot build series.parquet")
    }
}

/// histograms.parquet rows, long form; bins are [lo, hi).
#[derive(Default)]
struct HistogramRows {
    id: Vec<u64>,
    observable: Vec<String>,
    lo: Vec<f64>,
    hi: Vec<f64>,
    count: Vec<f64>,
}

impl HistogramRows {
    fn frame(self) -> anyhow::Result<DataFrame> {
        DataFrame::new(
            self.id.len(),
            vec![
                Column::new("run_id".into(), self.id),
                Column::new("observable".into(), self.observable),
                Column::new("lo".into(), self.lo),
                Column::new("hi".into(), self.hi),
                Column::new("count".into(), self.count),
            ],
        )
        .context("cannot build histograms.parquet")
    }
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

/// The `case` column (None for the sweep's runs), if the plan has cases.
fn case_column(specs: &[&RunSpec]) -> Option<Column> {
    specs.iter().any(|s| s.case.is_some()).then(|| {
        let names: Vec<Option<&str>> = specs.iter().map(|s| s.case.as_deref()).collect();
        Column::new("case".into(), names)
    })
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
    columns.extend(case_column(&specs));
    // Scalar names in order of first appearance (deterministic: runs are in
    // plan order), each with its column, filled in one pass over each run's
    // scalars: linear in the values, whatever the number of names.
    let mut index: HashMap<&str, usize> = HashMap::new();
    let mut names: Vec<&str> = Vec::new();
    let mut values: Vec<Vec<Option<f64>>> = Vec::new();
    for (row, (_, r)) in runs.iter().enumerate() {
        for (name, value) in &r.output.scalars {
            let column = *index.entry(name.as_str()).or_insert_with(|| {
                names.push(name);
                values.push(vec![None; runs.len()]);
                names.len() - 1
            });
            // A name twice in one run: the first counts, as `RunOutput::scalar` reads it.
            values[column][row].get_or_insert(*value);
        }
    }
    let mut taken: HashSet<String> = FIXED.iter().map(|s| s.to_string()).collect();
    if let Some(first) = specs.first() {
        taken.extend(first.params.iter().map(|(k, _)| k.clone()));
    }
    for (name, col) in names.into_iter().zip(values) {
        let column_name = free_name(name, &mut taken);
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
    type Timing = fn(&RunOutput) -> f64;
    let timings: [(&str, Timing); 3] = [
        ("wall_seconds", |o| o.wall_seconds),
        ("cpu_seconds", |o| o.cpu_seconds),
        ("prepare_seconds", |o| o.prepare_seconds),
    ];
    for (name, timing) in timings {
        let values: Vec<f64> = runs.iter().map(|(_, r)| timing(&r.output)).collect();
        columns.push(Column::new(name.into(), values));
    }
    columns.push(Column::new(
        "status".into(),
        runs.iter()
            .map(|(_, r)| r.status.clone())
            .collect::<Vec<String>>(),
    ));
    DataFrame::new(runs.len(), columns).context("cannot build runs.parquet")
}

/// `name`, or if that column is taken `result.<name>` (then `result.<name>.2`,
/// `.3`, ...): the same names in the same order always get the same columns.
fn free_name(name: &str, taken: &mut HashSet<String>) -> String {
    let mut candidate = name.to_string();
    let mut k = 1;
    while taken.contains(&candidate) {
        k += 1;
        candidate = match k {
            2 => format!("result.{name}"),
            _ => format!("result.{name}.{}", k - 1),
        };
    }
    taken.insert(candidate.clone());
    candidate
}

/// summary.parquet; parameter columns come from the plan (so text values
/// stay text), the cost from the successful runs behind each point.
fn summary_table(
    runs: &[(RunSpec, RunRecord)],
    summary: &[SummaryRow],
) -> anyhow::Result<DataFrame> {
    let mut cost: BTreeMap<u64, (f64, f64)> = BTreeMap::new();
    for (spec, record) in runs.iter().filter(|(_, r)| r.ok()) {
        let c = cost.entry(spec.point_id).or_default();
        c.0 += record.output.cpu_seconds;
        c.1 += record.output.wall_seconds;
    }
    let by_point: BTreeMap<u64, &RunSpec> = runs.iter().map(|(s, _)| (s.point_id, s)).collect();
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
    columns.extend(case_column(&point_specs));
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
    let point_cost = |r: &SummaryRow| cost.get(&r.point_id).copied().unwrap_or_default();
    columns.push(f("cpu_seconds", &|r| point_cost(r).0));
    columns.push(f("wall_seconds", &|r| point_cost(r).1));
    columns.push(Column::new(
        "collisions".into(),
        summary.iter().map(|r| r.collisions).collect::<Vec<u64>>(),
    ));
    DataFrame::new(summary.len(), columns).context("cannot build summary.parquet")
}
