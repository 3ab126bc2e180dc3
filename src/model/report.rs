//! What a study contributes to the report: a titled markdown section and
//! the charts it refers to by file name. The report layer renders them.

use super::chart::ChartSpec;

/// A study's part of the report (e.g. the piston's space-time diagram).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReportSection {
    pub title: String,
    /// Markdown body; figures are referenced by file name.
    pub markdown: String,
    /// The charts the markdown refers to, rendered as `file` (SVG).
    pub figures: Vec<Figure>,
    /// Results this section presents, so the generic plots leave them out.
    pub presents: Vec<String>,
}

/// One chart of a section, written as `file` in the output folder.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub file: String,
    pub chart: ChartSpec,
}
