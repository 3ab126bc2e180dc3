//! Pressure on the walls against time (the Imperial project's "plot of
//! pressure vs. time"): the momentum the walls receive over each sampling
//! interval, per unit time and wall area. Its mean over a run is the
//! `wall_pressure` scalar.

use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, Snapshot, WallHit};
use crate::model::need::Need;
use crate::model::run_output::{RunOutput, Series};

#[derive(Default)]
pub struct WallPressureSeries {
    impulse: f64,
    last: Option<f64>,
    /// (end time, length, impulse) per interval.
    rows: Vec<[f64; 3]>,
}

impl Observable for WallPressureSeries {
    const ENTRY: Entry = Entry {
        name: "wall_pressure",
        kind: Kind::Series,
        writes: "wall_pressure",
        label: "wall pressure P",
        unit: "kT/σᵈ",
        needs: &[Need::Walls, Need::Sampling],
        doc: "momentum given to the walls per unit time and wall area over each sampling interval",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(WallPressureSeries::default()))
    }
}

impl<const D: usize> Observer<D> for WallPressureSeries {
    fn wall_hit(&mut self, e: &WallHit<D>) {
        self.impulse += e.impulse[e.axis].abs();
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        if let Some(last) = self.last {
            self.rows.push([s.time, s.time - last, self.impulse]);
        }
        self.impulse = 0.0;
        self.last = Some(s.time);
    }
}

impl<const D: usize> Measure<D> for WallPressureSeries {
    fn uses_walls(&self) -> bool {
        true
    }
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.number(self.impulse);
        out.list(&self.last.into_iter().collect::<Vec<_>>());
        out.list(&self.rows.concat());
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.impulse = from.number()?;
        self.last = from.list()?.first().copied();
        self.rows = from
            .list()?
            .chunks_exact(3)
            .map(|r| std::array::from_fn(|k| r[k]))
            .collect();
        Ok(())
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        let (t, value) = self
            .rows
            .iter()
            .map(|&[t, dt, p]| (t, p / (dt * ctx.wall_area)))
            .unzip();
        out.series.push(Series {
            observable: "wall_pressure".into(),
            t,
            value,
        });
    }
}
