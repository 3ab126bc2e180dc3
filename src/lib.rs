//! bonkers: ensemble studies of hard-particle gases on an exact event-driven engine.
//!
//! Layers, bottom to top (each imports only layers below it; a test reads the
//! `use crate::` lines): model, files and pages, engine, theory, scene, observe, stats,
//! studies, report, descriptor, runner, cli.

// Loops over axes `for k in 0..D` index several vectors at once and read like
// the formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod cli;
pub mod descriptor;
pub mod engine;
pub mod files;
pub mod model;
pub mod observe;
pub mod pages;
pub mod report;
pub mod runner;
pub mod scene;
pub mod stats;
pub mod studies;
pub mod theory;
