//! `manifest.json`: what made this output — descriptor as run, version,
//! command line, times, threads and run counts.

use serde::Serialize;
use std::time::{SystemTime, UNIX_EPOCH};

#[derive(Debug, Clone, Serialize)]
pub struct Manifest {
    pub bonkers_version: String,
    pub command_line: Vec<String>,
    pub started: String,
    pub finished: String,
    pub threads: usize,
    pub runs: RunCounts,
    /// Overrides applied on top of the file (`--quick`, `--replicas`).
    pub overrides: Vec<(String, String)>,
    /// The descriptor as run: TOML text and parsed.
    pub descriptor_toml: String,
    pub descriptor: serde_json::Value,
    /// The files this study published beside the manifest (and the manifest):
    /// the next study in the same directory replaces exactly these.
    pub outputs: Vec<String>,
}

#[derive(Debug, Clone, Copy, Serialize)]
pub struct RunCounts {
    pub planned: usize,
    /// Run in this invocation (including failed ones).
    pub done: usize,
    pub failed: usize,
    /// Reused from an earlier invocation.
    pub resumed: usize,
}

pub fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}

/// RFC 3339 UTC timestamp (seconds) of `t`.
pub fn rfc3339(t: SystemTime) -> String {
    let secs = t.duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, rem) = (secs / 86_400, secs % 86_400);
    let (y, m, d) = civil_from_days(days as i64);
    format!(
        "{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}Z",
        rem / 3600,
        rem % 3600 / 60,
        rem % 60
    )
}

/// Days since 1970-01-01 -> (year, month, day) in the proleptic Gregorian
/// calendar (H. Hinnant's algorithm, eras of 400 years).
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

impl Manifest {
    pub fn to_json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }
}
