//! Studies on a cluster: shards of a plan for job arrays, and `study
//! slurm`'s batch scripts with the user text they may hold.

pub mod script_text;
pub mod shard;
pub mod slurm;
