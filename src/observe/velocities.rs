//! The v_x of every particle at each sample (`v.<index>`), for MacKay's
//! scatter plots (v1 against v2, position against velocity).

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct Velocities;

impl Observable for Velocities {
    const ENTRY: Entry = Entry {
        name: "velocities",
        kind: Kind::Series,
        writes: "v.<index>",
        label: "vₓ of particle <index>",
        unit: "√(kT/m)",
        needs: &[Need::Sampling],
        doc: "v_x of every particle, for scatter plots beside `positions`",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(Velocities))
    }
}

impl<const D: usize> Probe<D> for Velocities {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        for p in s.particles {
            row.push(p.vel[0]);
        }
    }
    fn name(&self, k: usize, _: &Context) -> String {
        format!("v.{k}")
    }
}
