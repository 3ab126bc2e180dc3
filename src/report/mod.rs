//! SVG plots, report.md and a self-contained index.html.
