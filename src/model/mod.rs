//! The shared types every layer speaks: the descriptor and its scene, a
//! planned run, what a run hands back, summary rows and report sections.
//! Types only: this module imports nothing else from the crate.

pub mod chart;
pub mod descriptor;
pub mod dimension;
pub mod movie;
pub mod need;
pub mod problem;
pub mod report;
pub mod run_output;
pub mod run_spec;
pub mod scene;
pub mod shared;
pub mod summary;
pub mod text;
pub mod trajectory;
