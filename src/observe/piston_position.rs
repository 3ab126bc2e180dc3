//! Where the piston is (its x) at each sample; NaN without a piston.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct PistonPosition {
    piston: Option<usize>,
}

impl Observable for PistonPosition {
    const ENTRY: Entry = Entry {
        name: "piston_position",
        kind: Kind::Series,
        writes: "piston_position",
        label: "piston position x",
        unit: "σ",
        needs: &[Need::Sampling, Need::Piston],
        doc: "x of the piston",
    };
    fn part<const D: usize>(setup: &Setup) -> Part<D> {
        Part::Series(Box::new(PistonPosition {
            piston: setup.piston,
        }))
    }
}

impl<const D: usize> Probe<D> for PistonPosition {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let x = self.piston.map(|i| s.position(i)[0]);
        row.push(x.unwrap_or(f64::NAN));
    }
    fn name(&self, _: usize, _: &Context) -> String {
        Self::ENTRY.writes.into()
    }
}
