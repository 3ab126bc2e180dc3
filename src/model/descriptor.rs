//! The typed study descriptor (`studies/*.toml`). Parsing, validation and the
//! error messages live in `descriptor.rs`; these are the shapes.

use crate::model::scene::SceneSpec;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Descriptor {
    pub study: StudySection,
    pub scene: SceneSpec,
    #[serde(default)]
    pub sweep: Option<SweepSection>,
    pub run: RunSection,
    #[serde(default)]
    pub observe: ObserveSection,
    /// Named analyses, each a table of its own options (may be empty).
    #[serde(default)]
    pub analysis: BTreeMap<String, toml::Table>,
    /// Showcase cases beside the sweep, each the descriptor with some keys
    /// set, planned, run, stored and resumed like sweep points.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub case: Vec<CaseSection>,
    /// Overrides applied by `--quick`: key path -> value (e.g. "study.replicas" = 2).
    #[serde(default)]
    pub quick: BTreeMap<String, toml::Value>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StudySection {
    pub name: String,
    #[serde(default)]
    pub description: String,
    #[serde(default = "default_replicas")]
    pub replicas: u32,
    #[serde(default)]
    pub seed: u64,
}

fn default_replicas() -> u32 {
    1
}

/// `[[case]]`: one named run configuration beside the sweep (a study's
/// pictures of one system, say). Its runs start from the descriptor without
/// its sweep, with `set` applied like a sweep point's values.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseSection {
    /// Names the case in the tables (`case` column) and for its study.
    pub name: String,
    /// Replicas of this case; default: `study.replicas`.
    #[serde(default)]
    pub replicas: Option<u32>,
    /// Key path -> value, e.g. `"run.duration" = 200.0`.
    #[serde(default)]
    pub set: BTreeMap<String, toml::Value>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepSection {
    /// "product" (default) or "zip".
    #[serde(default)]
    pub mode: SweepMode,
    /// Key path (e.g. "scene.piston.mass") -> values.
    pub parameters: BTreeMap<String, SweepValues>,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SweepMode {
    #[default]
    Product,
    Zip,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum SweepValues {
    /// An explicit list of values.
    List(Vec<toml::Value>),
    /// `{ from, to, steps, scale = "linear" | "log" }`.
    Range(SweepRange),
}

/// A list, or a table read as a range: a range's own error (an unknown
/// `scale`, a missing `steps`) is said, naming its key, rather than
/// "matches neither".
impl<'de> Deserialize<'de> for SweepValues {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        match toml::Value::deserialize(d)? {
            toml::Value::Array(items) => Ok(SweepValues::List(items)),
            toml::Value::Table(range) => {
                if let Some(scale) = range.get("scale")
                    && !matches!(scale.as_str(), Some("linear" | "log"))
                {
                    return Err(D::Error::custom(format!(
                        "range key `scale` = {scale} is not a scale: write `scale = \"linear\"` or `scale = \"log\"`"
                    )));
                }
                SweepRange::deserialize(toml::Value::Table(range))
                    .map(SweepValues::Range)
                    .map_err(|e| D::Error::custom(e.message()))
            }
            _ => Err(D::Error::custom(
                "data did not match any variant of untagged enum SweepValues",
            )),
        }
    }
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepRange {
    pub from: f64,
    pub to: f64,
    pub steps: usize,
    #[serde(default)]
    pub scale: Scale,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Scale {
    #[default]
    Linear,
    Log,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunSection {
    /// Simulated time to run after equilibration (reduced units).
    #[serde(default)]
    pub duration: Option<f64>,
    /// Or: number of pair collisions to run after equilibration.
    #[serde(default)]
    pub collisions: Option<u64>,
    /// Simulated time discarded before measuring.
    #[serde(default)]
    pub equilibrate: f64,
    /// Interval between samples (the seeds' clock Tc).
    #[serde(default)]
    pub sample_every: Option<f64>,
    /// Store every sample of each series; by default `series.parquet` keeps
    /// an evenly strided subset of at most 4000 points per series and run.
    #[serde(default, skip_serializing_if = "is_false")]
    pub full_series: bool,
    /// What moves the particles: the exact event-driven engine (default) or
    /// the Imperial project's fixed step of `dt`.
    #[serde(default, skip_serializing_if = "Integrator::is_exact")]
    pub integrator: Integrator,
    /// The fixed step's length (simulated time); only with a fixed step.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
}

/// `[run] integrator`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Integrator {
    /// Event-driven: every collision at its exact time.
    #[default]
    Exact,
    /// Move by `dt`, then bounce overlapping pairs and wall overlaps that
    /// approach (the Imperial project's method with its sticking fix).
    FixedStep,
    /// The same without the approach check: the seeds' first version, whose
    /// overlapping pairs can stick together.
    FixedStepNaive,
}

impl Integrator {
    pub fn is_exact(&self) -> bool {
        *self == Integrator::Exact
    }
    /// The name a descriptor uses.
    pub fn name(&self) -> &'static str {
        match self {
            Integrator::Exact => "exact",
            Integrator::FixedStep => "fixed-step",
            Integrator::FixedStepNaive => "fixed-step-naive",
        }
    }
}

fn is_false(b: &bool) -> bool {
    !*b
}

#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObserveSection {
    /// Observable names (see `observe::catalogue`); only these are computed.
    #[serde(default)]
    pub series: Vec<String>,
    #[serde(default)]
    pub histograms: Vec<String>,
    /// Scalar observables (time averages), e.g. "wall_pressure".
    #[serde(default)]
    pub scalars: Vec<String>,
    /// A movie of the plan's first run, embedded in the report.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub movie: Option<super::movie::MovieSpec>,
    /// Frames of chosen runs written to `OUT/trajectory-<run_id>.<format>`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trajectory: Option<super::trajectory::TrajectorySpec>,
}
