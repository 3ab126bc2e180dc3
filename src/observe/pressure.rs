//! Pressure two ways: momentum given to the walls, and the collision virial.

use super::{Context, Measure};
use crate::engine::{Observer, PairCollision, Snapshot, WallHit};
use crate::model::run_output::RunOutput;

/// Force per unit area on the walls, time-averaged: the impulse the walls
/// receive divided by (time x wall area).
#[derive(Default)]
pub struct WallPressure {
    impulse: f64,
}

impl<const D: usize> Observer<D> for WallPressure {
    fn wall_hit(&mut self, e: &WallHit<D>) {
        // The particle's normal momentum reverses; the wall gets the opposite.
        self.impulse += e.impulse[e.axis].abs();
    }
}

impl<const D: usize> Measure<D> for WallPressure {
    fn uses_walls(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        out.scalars.push((
            "wall_pressure".into(),
            self.impulse / (ctx.duration * ctx.wall_area),
        ));
    }
}

/// P V = (2/d) <K> + (1/(d t)) sum over collisions of r_ij . dp_i.
pub struct VirialPressure<const D: usize> {
    virial: f64,
    kinetic_sum: f64,
    samples: u64,
}

impl<const D: usize> Default for VirialPressure<D> {
    fn default() -> Self {
        VirialPressure {
            virial: 0.0,
            kinetic_sum: 0.0,
            samples: 0,
        }
    }
}

impl<const D: usize> Observer<D> for VirialPressure<D> {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        // r_ij = r_i - r_j = -separation; dp_i points away from j.
        self.virial -= (0..D)
            .map(|k| e.separation[k] * e.impulse_i[k])
            .sum::<f64>();
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        self.kinetic_sum += s.kinetic_energy();
        self.samples += 1;
    }
}

impl<const D: usize> Measure<D> for VirialPressure<D> {
    fn uses_collisions(&self) -> bool {
        true
    }
    fn uses_samples(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        let d = D as f64;
        let kinetic = if self.samples > 0 {
            self.kinetic_sum / self.samples as f64
        } else {
            f64::NAN
        };
        let p = (2.0 * kinetic / d + self.virial / (d * ctx.duration)) / ctx.volume;
        out.scalars.push(("virial_pressure".into(), p));
    }
}
