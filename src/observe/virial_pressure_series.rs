//! Pressure against time from the collision virial: one value per sampling
//! interval, P = (2K/d + W/(d dt)) / V with W the virial of the interval's
//! collisions and K the kinetic energy at its end (constant in an elastic
//! run). Its mean over a run is the `virial_pressure` scalar; its
//! fluctuations give block-average error bars and show the equilibration.

use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, PairCollision, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{RunOutput, Series};

#[derive(Default)]
pub struct VirialPressureSeries {
    virial: f64,
    last: Option<f64>,
    /// (end time, length, kinetic energy, virial) per interval.
    rows: Vec<[f64; 4]>,
}

impl Observable for VirialPressureSeries {
    const ENTRY: Entry = Entry {
        name: "virial_pressure",
        kind: Kind::Series,
        writes: "virial_pressure",
        label: "virial pressure P",
        unit: "kT/σᵈ",
        needs: &[Need::Sampling],
        doc: "pressure from the collision virial over each sampling interval, any boundary",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(VirialPressureSeries::default()))
    }
}

impl<const D: usize> Observer<D> for VirialPressureSeries {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        // r_ij = r_i - r_j = -separation; dp_i points away from j.
        self.virial -= (0..D)
            .map(|k| e.separation[k] * e.impulse_i[k])
            .sum::<f64>();
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        if let Some(last) = self.last {
            self.rows
                .push([s.time, s.time - last, s.kinetic_energy(), self.virial]);
        }
        self.virial = 0.0;
        self.last = Some(s.time);
    }
}

impl<const D: usize> Measure<D> for VirialPressureSeries {
    fn uses_collisions(&self) -> bool {
        true
    }
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.number(self.virial);
        out.list(&self.last.into_iter().collect::<Vec<_>>());
        out.list(&self.rows.concat());
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.virial = from.number()?;
        self.last = from.list()?.first().copied();
        self.rows = from
            .list()?
            .chunks_exact(4)
            .map(|r| std::array::from_fn(|k| r[k]))
            .collect();
        Ok(())
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        let d = D as f64;
        let (t, value) = self
            .rows
            .iter()
            .map(|&[t, dt, k, w]| (t, (2.0 * k / d + w / (d * dt)) / ctx.volume))
            .unzip();
        out.series.push(Series {
            observable: "virial_pressure".into(),
            t,
            value,
        });
    }
}
