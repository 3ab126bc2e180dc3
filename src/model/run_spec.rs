//! One planned simulation: the contract between the planner and the simulator.

use crate::model::descriptor::Descriptor;
use std::sync::Arc;

/// A sweep point (or a case) x replica, with its own seed and the descriptor
/// as it applies to this point (sweep values or the case's keys already set).
/// The replicas of a point share its descriptor and parameters, so a plan
/// costs memory in proportion to its points, not to points times the
/// descriptor's size for each run.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSpec {
    pub run_id: u64,
    pub point_id: u64,
    pub replica: u32,
    /// Seed of this run's ChaCha stream, derived from (study seed, point, replica).
    pub seed: u64,
    /// Swept parameters of this point: (key path, value); empty for a case.
    pub params: Arc<Vec<(String, toml::Value)>>,
    /// The `[[case]]` this run belongs to; None for the sweep's runs.
    pub case: Option<String>,
    /// The point's descriptor, without `[sweep]`, `[[case]]` and `[quick]`
    /// (already applied).
    pub descriptor: Arc<Descriptor>,
}
