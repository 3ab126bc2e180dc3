//! How concentrated the kinetic energy is among the particles at each
//! sample: Y = sum_i (K_i / K)^2, 1 when one particle holds it all, 1/N when
//! all hold the same. A symmetric function of the particles' energies, so it
//! ignores which particle holds what: rods of equal mass only swap their
//! velocities, and keep Y exactly.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct EnergyConcentration;

impl Observable for EnergyConcentration {
    const ENTRY: Entry = Entry {
        name: "energy_concentration",
        kind: Kind::Series,
        writes: "energy_concentration",
        label: "energy concentration Σ(Kᵢ/K)²",
        unit: "1",
        needs: &[Need::Sampling],
        doc: "sum over particles of the squared share of the kinetic energy each holds: 1 when one holds it all",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(EnergyConcentration))
    }
}

impl<const D: usize> Probe<D> for EnergyConcentration {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let total = s.kinetic_energy();
        let y: f64 = s
            .particles
            .iter()
            .map(|p| (p.kinetic_energy() / total).powi(2))
            .sum();
        row.push(y);
    }
    fn name(&self, _: usize, _: &Context) -> String {
        Self::ENTRY.writes.into()
    }
}
