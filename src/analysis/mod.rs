//! Analyses that turn finished runs into per-point statistics and report
//! sections. Each named analysis (`[analysis.<name>]` in a descriptor) is one
//! module: what it needs observed, what it adds per run, its theory, and its
//! part of the report.

pub mod piston;
pub mod piston_estimators;
mod piston_pictures;
mod piston_points;
mod piston_regimes;
mod piston_relaxation;
pub mod piston_state;
mod piston_wall;
pub mod summary;
pub mod summary_types;

use crate::observe::Context;
use crate::scene::Built;
use crate::study::descriptor_types::Descriptor;
use crate::study::output::RunOutput;
use crate::study::plan_types::RunSpec;
use std::path::Path;

/// A study-specific part of the report (e.g. the piston's space-time diagram).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReportSection {
    pub title: String,
    /// Markdown body; figures are referenced by file name.
    pub markdown: String,
    /// SVG files (already written into the out dir) with captions.
    pub figures: Vec<(String, String)>,
}

/// Analyses bonkers knows, for validation and `study list`.
pub const KNOWN: &[&str] = &["piston"];

/// Observables the named analyses need, added to what the descriptor asks.
#[derive(Debug, Default)]
pub struct Needs {
    pub series: Vec<&'static str>,
    pub scalars: Vec<&'static str>,
}

pub fn requirements(d: &Descriptor) -> Needs {
    let mut needs = Needs::default();
    if d.analysis.contains_key("piston") {
        needs.series.extend(piston::SERIES);
    }
    needs
}

/// Per-run scalars from the named analyses.
pub fn per_run<const D: usize>(
    d: &Descriptor,
    built: &Built<D>,
    ctx: &Context,
    out: &mut RunOutput,
) -> Result<(), String> {
    for name in d.analysis.keys() {
        match name.as_str() {
            "piston" => piston::per_run(d, built, ctx, out)?,
            other => {
                return Err(format!(
                    "unknown analysis `{other}`; known: {}",
                    KNOWN.join(", ")
                ));
            }
        }
    }
    Ok(())
}

/// Whether a named analysis gives (and its section presents) this result.
pub fn presents(d: &Descriptor, result: &str) -> bool {
    d.analysis.contains_key("piston") && piston::RESULTS.contains(&result)
}

/// Theory for a result, from whichever analysis defines it.
pub fn theory(d: &Descriptor, result: &str) -> Option<f64> {
    if d.analysis.contains_key("piston") {
        return piston::theory(d, result);
    }
    None
}

/// Sections contributed by the analyses the descriptor names under `[analysis]`.
/// Figures are written into `out_dir`.
pub fn sections(
    descriptor: &Descriptor,
    runs: &[(RunSpec, RunOutput)],
    out_dir: &Path,
) -> anyhow::Result<Vec<ReportSection>> {
    let mut out = Vec::new();
    if descriptor.analysis.contains_key("piston") {
        out.push(piston::section(descriptor, runs, out_dir)?);
    }
    Ok(out)
}
