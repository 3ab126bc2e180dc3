//! The fraction of the particles in the left half of the box at each sample:
//! how far two gases started apart have mixed.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct LeftFraction;

impl Observable for LeftFraction {
    const ENTRY: Entry = Entry {
        name: "left_fraction",
        kind: Kind::Series,
        writes: "left_fraction",
        label: "fraction of the particles in the left half",
        unit: "1",
        needs: &[Need::Sampling],
        doc: "fraction of the particles in the left half of the box",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(LeftFraction))
    }
}

impl<const D: usize> Probe<D> for LeftFraction {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let half = 0.5 * s.sim_box.size[0];
        let left = (0..s.particles.len())
            .filter(|&i| s.position(i)[0] < half)
            .count();
        row.push(left as f64 / s.particles.len().max(1) as f64);
    }
    fn name(&self, _: usize, _: &Context) -> String {
        Self::ENTRY.writes.into()
    }
}
