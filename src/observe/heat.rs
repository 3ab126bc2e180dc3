//! Heat exchanged with thermal walls: the kinetic energy each wall gives the
//! particles that hit it (negative when the gas heats the wall).

use super::{Context, Measure};
use crate::engine::{Observer, WallHit};
use crate::model::run_output::RunOutput;

pub struct WallHeat<const D: usize> {
    /// Energy in from [axis][low, high].
    gain: [[f64; 2]; D],
}

impl<const D: usize> Default for WallHeat<D> {
    fn default() -> Self {
        WallHeat {
            gain: [[0.0; 2]; D],
        }
    }
}

impl<const D: usize> Observer<D> for WallHeat<D> {
    fn wall_hit(&mut self, e: &WallHit<D>) {
        self.gain[e.axis][e.high as usize] += e.energy_gain;
    }
}

impl<const D: usize> Measure<D> for WallHeat<D> {
    fn uses_walls(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        for (axis, sides) in self.gain.iter().enumerate() {
            for (side, name) in [(0, "low"), (1, "high")] {
                out.scalars
                    .push((format!("heat_in.axis{axis}.{name}"), sides[side]));
            }
        }
    }
}
