//! Total kinetic energy at each sample.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct KineticEnergy;

impl Observable for KineticEnergy {
    const ENTRY: Entry = Entry {
        name: "kinetic_energy",
        kind: Kind::Series,
        writes: "kinetic_energy",
        label: "kinetic energy",
        unit: "kT",
        needs: &[Need::Sampling],
        doc: "total kinetic energy",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(KineticEnergy))
    }
}

impl<const D: usize> Probe<D> for KineticEnergy {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        row.push(s.kinetic_energy());
    }
    fn name(&self, _: usize, _: &Context) -> String {
        Self::ENTRY.writes.into()
    }
}
