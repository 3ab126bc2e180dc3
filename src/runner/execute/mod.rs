//! Running a plan: each run from scene to output (`simulate`), the runs in
//! parallel into records (`run`), checkpoints of long runs, progress, the
//! CPU time a run cost and the movie of the first run.

pub mod checkpoint;
pub mod cpu_time;
pub mod movie;
pub mod progress;
pub mod run;
pub mod simulate;
pub mod trajectory;
