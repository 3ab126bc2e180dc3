//! Pressure from the walls: the momentum the particles give them, per unit
//! time and wall area.

use super::{Context, Entry, Kind, Measure, Observable, Part, Setup, StateIn, StateOut};
use crate::engine::{Observer, WallHit};
use crate::model::need::Need;
use crate::model::run_output::RunOutput;

/// The impulse the walls receive, divided at the end by (time x wall area).
#[derive(Default)]
pub struct WallPressure {
    impulse: f64,
}

impl Observable for WallPressure {
    const ENTRY: Entry = Entry {
        name: "wall_pressure",
        kind: Kind::Scalars,
        writes: "wall_pressure",
        label: "wall pressure P",
        unit: "kT/σᵈ",
        needs: &[Need::Walls],
        doc: "time-averaged momentum given to the walls per unit time and wall area (βPσᵈ at kT = 1)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(WallPressure::default()))
    }
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
    fn save(&self, out: &mut StateOut) -> bool {
        out.number(self.impulse);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.impulse = from.number()?;
        Ok(())
    }
}
