//! Analyses that turn finished runs into per-point statistics and report sections.

pub mod summary;
pub mod summary_types;

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

/// Sections contributed by the analyses the descriptor names under `[analysis]`.
/// Figures are written into `out_dir`.
pub fn sections(
    _descriptor: &Descriptor,
    _runs: &[(RunSpec, RunOutput)],
    _out_dir: &Path,
) -> anyhow::Result<Vec<ReportSection>> {
    Ok(Vec::new())
}
