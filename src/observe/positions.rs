//! The x of every particle at each sample (`x.<index>`), for space-time
//! diagrams.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct Positions;

impl Observable for Positions {
    const ENTRY: Entry = Entry {
        name: "positions",
        kind: Kind::Series,
        writes: "x.<index>",
        label: "x of particle <index>",
        unit: "σ",
        needs: &[Need::Sampling],
        doc: "x of every particle (left to right in 1D), for space-time diagrams",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(Positions))
    }
}

impl<const D: usize> Probe<D> for Positions {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        for i in 0..s.particles.len() {
            row.push(s.position(i)[0]);
        }
    }
    fn name(&self, k: usize, _: &Context) -> String {
        format!("x.{k}")
    }
}
