//! `study run`: descriptor -> plan -> parallel runs -> run records, then
//! `collect`: run records -> tables -> report.

pub mod checkpoint;
pub mod collect;
pub mod confirm;
pub mod cpu_time;
pub mod error_bars;
pub mod estimate;
pub mod lock;
pub mod manifest;
pub mod movie;
pub mod origin;
pub mod outdir;
pub mod pipeline;
pub mod plan;
pub mod progress;
pub mod publish;
pub mod record;
pub mod run;
pub mod script_text;
pub mod seeds;
pub mod shard;
pub mod simulate;
pub mod slurm;
pub mod status;
pub mod store;
