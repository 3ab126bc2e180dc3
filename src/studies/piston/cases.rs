//! The runs of a named `[[case]]`, as the piston's pictures use them: their
//! outputs, statistics of their results, and what the first replica started
//! from and recorded (its scene rebuilt from its seed, as the run built it:
//! no simulation).

use super::DRAWS;
use super::state::{Geometry, Samples};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::scene::{self, Built};
use crate::stats::summary::Stats;
use crate::theory::piston::PistonSystem;
use crate::theory::piston_equilibrium::oscillator_share;
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

/// A replica as the pictures draw it.
pub(super) struct First<'a, const D: usize> {
    pub built: Built<D>,
    pub out: &'a RunOutput,
    pub samples: Samples,
    pub geometry: Geometry,
    /// The theory's view of the start, moving the way the piston did.
    pub start: PistonSystem,
    /// The oscillator energy at every sample, and its equilibrium mean.
    pub energy: Vec<f64>,
    pub equilibrium: f64,
}

impl<'a, const D: usize> First<'a, D> {
    pub fn of((spec, out): &'a Run) -> anyhow::Result<Self> {
        let resolved = scene::resolve(&spec.descriptor.scene).map_err(anyhow::Error::msg)?;
        let mut rng = ChaCha8Rng::seed_from_u64(spec.seed);
        let built = scene::build::<D>(&resolved, &mut rng).map_err(anyhow::Error::msg)?;
        let geometry = Geometry::of(&built).ok_or_else(|| anyhow::anyhow!("no piston"))?;
        let samples = Samples::of(out).map_err(anyhow::Error::msg)?;
        let s = &samples;
        let v = built.particles[built.piston.unwrap_or(0)].vel[0];
        let start = geometry.system(s.x[0], s.piston[0], s.left[0], s.right[0], v);
        let [left, right] = geometry.particles;
        let equilibrium = oscillator_share(D, left, right, DRAWS).0 * s.total[0];
        let energy = samples.oscillator_energy(&geometry);
        Ok(First {
            built,
            out,
            samples,
            geometry,
            start,
            energy,
            equilibrium,
        })
    }
}
