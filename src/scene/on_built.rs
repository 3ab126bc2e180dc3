//! What a study reads from a run's start without running it: the scene
//! built again from a seed, in its own dimension.

use super::build::{Built, build};
use crate::model::dimension::{ForDimension, in_dimension};
use crate::model::scene::SceneSpec;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Work on a built scene, written once for every dimension.
pub trait OnBuilt {
    /// What the work gives back, the same in every dimension.
    type Output;
    /// The work on the scene built in dimension `D`.
    fn on<const D: usize>(self, built: &Built<D>) -> Self::Output;
}

/// `work` on the resolved `spec` built from the stream of `seed`; None if
/// the scene does not build.
pub fn on_built<W: OnBuilt>(spec: &SceneSpec, seed: u64, work: W) -> Option<W::Output> {
    let d = spec.dimension().ok()?;
    in_dimension(d, Building { spec, seed, work }).ok()?
}

struct Building<'a, W> {
    spec: &'a SceneSpec,
    seed: u64,
    work: W,
}

impl<W: OnBuilt> ForDimension for Building<'_, W> {
    type Output = Option<W::Output>;
    fn run<const D: usize>(self) -> Self::Output {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let built = build::<D>(self.spec, &mut rng).ok()?;
        Some(self.work.on(&built))
    }
}
