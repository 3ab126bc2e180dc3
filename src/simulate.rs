//! One run: scene -> engine -> observers -> RunOutput.

use crate::study::output::RunOutput;
use crate::study::plan_types::RunSpec;

/// Simulate one planned run. Errors are recorded in `runs.parquet` with the run.
pub fn run(_spec: &RunSpec) -> anyhow::Result<RunOutput> {
    anyhow::bail!("the simulator is not wired yet")
}
