//! A named `[[case]]`'s runs, as the piston's pictures use them, and what
//! the first replica started from and recorded (its scene rebuilt from its
//! seed, as the run built it: no simulation).

use super::DRAWS;
use super::state::{Geometry, Samples};
use crate::model::run_output::RunOutput;
use crate::scene::{self, Built};
use crate::stats::ensemble::Runs;
use crate::stats::point_runs::{PointRuns, by_point};
use crate::theory::piston::PistonSystem;
use crate::theory::piston_equilibrium::oscillator_share;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The runs of case `name` (in replica order), if the plan has it.
pub(super) fn case<'a>(all: &'a Runs, name: &str) -> Option<PointRuns<'a>> {
    (by_point(all).into_iter()).find(|p| p.spec.case.as_deref() == Some(name))
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
    /// The case's first replica.
    pub fn of(case: &PointRuns<'a>) -> anyhow::Result<Self> {
        let (spec, out) = (case.spec, case.outs[0]);
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
