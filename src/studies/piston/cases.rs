//! The runs of a named `[[case]]`, as the piston's pictures use them: their
//! outputs, statistics of their results, and the scene the first replica
//! started from (rebuilt from its seed, as the run built it: no simulation).

use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::scene::{self, Built};
use crate::stats::summary::Stats;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

pub(super) type Run = (RunSpec, RunOutput);

/// The runs of case `name`, in replica order.
pub(super) fn runs<'a>(all: &'a [Run], name: &str) -> Vec<&'a Run> {
    all.iter()
        .filter(|(s, _)| s.case.as_deref() == Some(name))
        .collect()
}

/// A result over the runs that measured it.
pub(super) fn stat(runs: &[&Run], name: &str) -> Stats {
    crate::stats::summary::scalar(runs.iter().map(|r| &r.1), name)
}

/// Collisions and CPU seconds the runs cost.
pub(super) fn cost(runs: &[&Run]) -> (u64, f64) {
    runs.iter().fold((0, 0.0), |(c, s), (_, o)| {
        (c + o.collisions, s + o.cpu_seconds)
    })
}

/// The scene a run started from: the same stream, the same draws.
pub(super) fn start<const D: usize>(spec: &RunSpec) -> anyhow::Result<Built<D>> {
    let scene = scene::resolve(&spec.descriptor.scene).map_err(|e| anyhow::anyhow!(e))?;
    let mut rng = ChaCha8Rng::seed_from_u64(spec.seed);
    scene::build::<D>(&scene, &mut rng).map_err(|e| anyhow::anyhow!(e))
}
