//! 1D: particles never pass each other, so each one can only hit the next on
//! either side (and, on a periodic line, the two ends hit each other).

use super::{Image, Neighbourhood, Persist};
use crate::engine::bodies::Body;
use crate::engine::boundary::SimBox;
use crate::engine::particle::Particle;
use crate::engine::prefetch::Lines;

#[derive(Debug, Clone)]
pub struct Chain {
    n: usize,
    periodic: bool,
}

impl<const D: usize> Neighbourhood<D> for Chain {
    fn build(particles: &[Particle<D>], sim_box: &SimBox<D>) -> Result<Self, String> {
        if D != 1 {
            return Err("the chain neighbourhood is for one dimension only".into());
        }
        Ok(Chain {
            n: particles.len(),
            periodic: sim_box.axes[0].is_periodic(),
        })
    }

    #[inline(always)]
    fn candidates(&self, i: usize) -> impl Iterator<Item = (usize, Image)> {
        // Images in 1D: 0 = one box to the left, 1 = none, 2 = one box to the right.
        let wraps = self.periodic && self.n > 1;
        let left = if i > 0 {
            Some((i - 1, 1))
        } else {
            wraps.then(|| (self.n - 1, 0))
        };
        let right = if i + 1 < self.n {
            Some((i + 1, 1))
        } else {
            wraps.then_some((0, 2))
        };
        left.into_iter().chain(right)
    }

    /// Only the end particles can reach a wall: the others have a neighbour
    /// in the way.
    #[inline(always)]
    fn can_reach_wall(&self, i: usize, high: bool) -> bool {
        if high { i + 1 == self.n } else { i == 0 }
    }

    fn next_renewal(&self, _i: usize, _p: &Body<D>) -> Option<f64> {
        None
    }

    fn renew(&mut self, _i: usize, _p: &mut Body<D>, _now: f64, _bodies: Option<Lines>) -> bool {
        false
    }
}

/// The chain is fixed by the particle count and the box: nothing to save.
impl<const D: usize> Persist<D> for Chain {
    const KIND: u32 = 0;

    fn state(&self) -> Vec<u32> {
        Vec::new()
    }

    fn restore(
        particles: &[Particle<D>],
        sim_box: &SimBox<D>,
        state: &[u32],
    ) -> Result<Self, String> {
        if !state.is_empty() {
            return Err(format!(
                "a chain has no saved state, found {} words",
                state.len()
            ));
        }
        <Chain as Neighbourhood<D>>::build(particles, sim_box)
    }
}
