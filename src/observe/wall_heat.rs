//! Heat exchanged with thermal walls: the kinetic energy each wall gives the
//! particles that hit it (negative when the gas heats the wall).

use super::{Context, Entry, Kind, Measure, Observable, Part, Setup, StateIn, StateOut};
use crate::engine::{Observer, WallHit};
use crate::model::need::Need;
use crate::model::run_output::RunOutput;

pub struct WallHeat {
    /// Energy in from [axis][low, high].
    gain: Vec<[f64; 2]>,
}

impl Observable for WallHeat {
    const ENTRY: Entry = Entry {
        name: "wall_heat",
        kind: Kind::Scalars,
        writes: "heat_in.axis<k>.<low|high>",
        label: "heat in from the <low|high> wall of axis <k>",
        unit: "kT",
        needs: &[Need::ThermalWalls],
        doc: "energy each wall gave the particles over the measured time (negative: the gas heated the wall)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(WallHeat {
            gain: vec![[0.0; 2]; D],
        }))
    }
}

impl<const D: usize> Observer<D> for WallHeat {
    fn wall_hit(&mut self, e: &WallHit<D>) {
        self.gain[e.axis][e.high as usize] += e.energy_gain;
    }
}

impl<const D: usize> Measure<D> for WallHeat {
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
    fn save(&self, out: &mut StateOut) -> bool {
        out.list(&self.gain.concat());
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        let flat = from.list()?;
        if flat.len() != 2 * self.gain.len() {
            return Err(format!(
                "wall_heat has {} walls, its state {}",
                2 * self.gain.len(),
                flat.len()
            ));
        }
        self.gain = flat.chunks(2).map(|c| [c[0], c[1]]).collect();
        Ok(())
    }
}
