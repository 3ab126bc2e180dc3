//! A finished run as saved in `OUT/runs/run-<id>.json`. Floats are saved as
//! strings in Rust's shortest round-trip form ("0.1", "NaN", "inf"): JSON has
//! no NaN or infinity, and serde_json's number parsing is not exact to the
//! last bit, while a resumed study must give bit-identical tables.
//!
//! A record starts with a checksum of the rest of its bytes:
//! `{"checksum":"xxh3-64:<16 hex digits>","run_id":...}`, XXH3 (64 bits, the
//! `xxhash-rust` crate, already built for polars) of everything after the
//! checksum's comma, as written. A record changed after bonkers wrote it
//! (a digit edited, a tool reformatting it, a torn write) fails it and its
//! run is made again; so is a record without one (written before records
//! had checksums, or not by bonkers). Not a defence against forgery, which
//! anyone can recompute: a guard against trusting a record blindly.

use crate::model::run_output::{Histogram, RunOutput, Series};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use xxhash_rust::xxh3::xxh3_64;

/// A finished run, as handed to the store.
#[derive(Debug, Clone, PartialEq)]
pub struct RunRecord {
    pub run_id: u64,
    /// Hash of what the run did (see `execute::run::fingerprint`): a saved run is
    /// reused only if this plan would run exactly the same.
    pub fingerprint: String,
    /// `"ok"` or `"failed: <message>"`.
    pub status: String,
    pub output: RunOutput,
}

impl RunRecord {
    pub fn ok(&self) -> bool {
        self.status == "ok"
    }

    /// The record's file: checksum, then fields (see the module comment).
    pub fn to_json(&self) -> serde_json::Result<String> {
        let json = serde_json::to_string(&Saved::from(self))?;
        // `{` + fields: the fields, after the checksum, are what it covers.
        let fields = json.strip_prefix('{').unwrap_or(&json);
        Ok(format!(
            "{CHECKSUM}{:016x}\",{fields}",
            xxh3_64(fields.as_bytes())
        ))
    }

    /// A record's file read back, if its checksum holds.
    pub fn from_json(text: &str) -> Result<RunRecord, RecordError> {
        let rest = text.strip_prefix(CHECKSUM).ok_or(RecordError::NoChecksum)?;
        let (hex, fields) = rest
            .split_at_checked(16)
            .and_then(|(hex, after)| Some((hex, after.strip_prefix("\",")?)))
            .ok_or(RecordError::NoChecksum)?;
        let sum = u64::from_str_radix(hex, 16).map_err(|_| RecordError::NoChecksum)?;
        if xxh3_64(fields.as_bytes()) != sum {
            return Err(RecordError::Damaged);
        }
        // The checksum is a field serde skips; the fields parse as always.
        serde_json::from_str::<Saved>(text)
            .map(RunRecord::from)
            .map_err(RecordError::Parse)
    }
}

/// How a record's file starts, up to the checksum's hex digits.
const CHECKSUM: &str = "{\"checksum\":\"xxh3-64:";

/// Why a record's file is not a record to trust.
#[derive(Debug)]
pub enum RecordError {
    NoChecksum,
    Damaged,
    Parse(serde_json::Error),
}

impl std::fmt::Display for RecordError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RecordError::NoChecksum => f.write_str(
                "has no checksum (written by an older bonkers, or not by bonkers), so it is not trusted",
            ),
            RecordError::Damaged => {
                f.write_str("fails its checksum: it was changed after bonkers wrote it")
            }
            RecordError::Parse(e) => write!(f, "does not parse: {e}"),
        }
    }
}

impl std::error::Error for RecordError {}

#[derive(Clone, Copy)]
struct F(f64);

/// A number a record did not save is unknown.
impl Default for F {
    fn default() -> F {
        F(f64::NAN)
    }
}

impl Serialize for F {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        // `{:?}` is the shortest text that parses back to the same bits.
        s.serialize_str(&format!("{:?}", self.0))
    }
}

impl<'de> Deserialize<'de> for F {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<F, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Raw {
            N(f64),
            S(String),
        }
        match Raw::deserialize(d)? {
            Raw::N(x) => Ok(F(x)),
            Raw::S(s) => s
                .parse::<f64>()
                .map(F)
                .map_err(|_| serde::de::Error::custom(format!("not a number: {s:?}"))),
        }
    }
}

fn wrap(v: &[f64]) -> Vec<F> {
    v.iter().copied().map(F).collect()
}

fn unwrap(v: Vec<F>) -> Vec<f64> {
    v.into_iter().map(|f| f.0).collect()
}

/// (observable, lo, hi, count) of one histogram.
type SavedHistogram = (String, Vec<F>, Vec<F>, Vec<F>);

#[derive(Serialize, Deserialize)]
struct Saved {
    run_id: u64,
    fingerprint: String,
    status: String,
    scalars: Vec<(String, F)>,
    series: Vec<(String, Vec<F>, Vec<F>)>,
    histograms: Vec<SavedHistogram>,
    events: u64,
    collisions: u64,
    wall_seconds: F,
    #[serde(default)]
    cpu_seconds: F,
    #[serde(default)]
    prepare_seconds: F,
}

impl From<&RunRecord> for Saved {
    fn from(r: &RunRecord) -> Saved {
        let o = &r.output;
        Saved {
            run_id: r.run_id,
            fingerprint: r.fingerprint.clone(),
            status: r.status.clone(),
            scalars: o.scalars.iter().map(|(k, v)| (k.clone(), F(*v))).collect(),
            series: o
                .series
                .iter()
                .map(|s| (s.observable.clone(), wrap(&s.t), wrap(&s.value)))
                .collect(),
            histograms: o
                .histograms
                .iter()
                .map(|h| {
                    (
                        h.observable.clone(),
                        wrap(&h.lo),
                        wrap(&h.hi),
                        wrap(&h.count),
                    )
                })
                .collect(),
            events: o.events,
            collisions: o.collisions,
            wall_seconds: F(o.wall_seconds),
            cpu_seconds: F(o.cpu_seconds),
            prepare_seconds: F(o.prepare_seconds),
        }
    }
}

impl From<Saved> for RunRecord {
    fn from(s: Saved) -> RunRecord {
        RunRecord {
            run_id: s.run_id,
            fingerprint: s.fingerprint,
            status: s.status,
            output: RunOutput {
                scalars: s.scalars.into_iter().map(|(k, v)| (k, v.0)).collect(),
                series: s
                    .series
                    .into_iter()
                    .map(|(observable, t, value)| Series {
                        observable,
                        t: unwrap(t),
                        value: unwrap(value),
                    })
                    .collect(),
                histograms: s
                    .histograms
                    .into_iter()
                    .map(|(observable, lo, hi, count)| Histogram {
                        observable,
                        lo: unwrap(lo),
                        hi: unwrap(hi),
                        count: unwrap(count),
                    })
                    .collect(),
                events: s.events,
                collisions: s.collisions,
                wall_seconds: s.wall_seconds.0,
                cpu_seconds: s.cpu_seconds.0,
                prepare_seconds: s.prepare_seconds.0,
            },
        }
    }
}
