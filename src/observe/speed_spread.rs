//! The standard deviation of the particles' speeds at each sample
//! (Imperial: "plot the evolution of the standard deviation of the particle
//! speeds as a function of time"): it settles when the speeds have relaxed
//! to their equilibrium law.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct SpeedSpread;

impl Observable for SpeedSpread {
    const ENTRY: Entry = Entry {
        name: "speed_std",
        kind: Kind::Series,
        writes: "speed_std",
        label: "std of the speeds",
        unit: "√(kT/m)",
        needs: &[Need::Sampling],
        doc: "standard deviation of the speeds of the movable particles at each sample",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(SpeedSpread))
    }
}

impl<const D: usize> Probe<D> for SpeedSpread {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let speeds: Vec<f64> = (s.particles.iter())
            .filter(|p| !p.is_immovable() && !p.is_plane())
            .map(|p| p.vel.iter().map(|v| v * v).sum::<f64>().sqrt())
            .collect();
        let n = speeds.len() as f64;
        let mean = speeds.iter().sum::<f64>() / n;
        let var = speeds.iter().map(|s| (s - mean).powi(2)).sum::<f64>() / n;
        row.push(var.sqrt());
    }
    fn name(&self, _: usize, _: &Context) -> String {
        "speed_std".into()
    }
}
