//! `study run`: descriptor -> plan -> parallel runs -> tables -> report.

pub mod analyses;
pub mod check;
pub mod cli;
pub mod cpu_time;
pub mod descriptor;
pub mod descriptor_types;
pub mod errors;
pub mod estimate;
pub mod explain;
pub mod locate;
pub mod lock;
pub mod manifest;
pub mod output;
pub mod overrides;
pub mod pipeline;
pub mod plan;
pub mod plan_types;
pub mod progress;
pub mod publish;
pub mod record;
pub mod runner;
pub mod seeds;
pub mod store;
pub mod validate;
pub mod validate_observe;
pub mod validate_scene;
