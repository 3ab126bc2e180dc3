//! `study run`: descriptor -> plan -> parallel runs -> tables -> report.

pub mod descriptor_types;
pub mod output;
pub mod plan_types;
