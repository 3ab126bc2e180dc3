//! `study run`: descriptor -> plan -> parallel runs -> run records, then
//! `collect`: run records -> tables -> report. One folder per concern
//! (plan, execute, store, cluster); `pipeline` joins them into commands.

pub mod cluster;
pub mod execute;
pub mod pipeline;
pub mod plan;
pub mod store;
