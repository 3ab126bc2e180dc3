//! Per sweep point and result: the ensemble statistics written to `summary.parquet`.

/// One row of `summary.parquet`.
#[derive(Debug, Clone, PartialEq)]
pub struct SummaryRow {
    pub point_id: u64,
    /// Swept parameters of this point: (key path, value as f64 or NaN if not numeric).
    pub params: Vec<(String, f64)>,
    /// Scalar result name (a column of `runs.parquet`).
    pub result: String,
    pub n: u64,
    pub mean: f64,
    pub std: f64,
    pub stderr: f64,
    /// 95% confidence interval from Student's t with n-1 degrees of freedom.
    pub ci_low: f64,
    pub ci_high: f64,
    pub theory: Option<f64>,
    /// (mean - theory) / stderr.
    pub z: Option<f64>,
    /// Cost behind this mean: summed CPU (wall) seconds and collisions of its runs.
    pub seconds: f64,
    pub collisions: u64,
}
