//! How many particles of each species are in the left and the right half of
//! the box along x at each sample: two gases started apart, mixing.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct SideCounts;

impl Observable for SideCounts {
    const ENTRY: Entry = Entry {
        name: "side_counts",
        kind: Kind::Series,
        writes: "count.<species>.<left|right>",
        label: "particles of <species> in the <left|right> half",
        unit: "1",
        needs: &[Need::Sampling],
        doc: "number of particles of each species in the left and the right half of the box along x",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(SideCounts))
    }
}

impl<const D: usize> Probe<D> for SideCounts {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let half = 0.5 * s.sim_box.size[0];
        let groups = s
            .particles
            .iter()
            .map(|p| p.species as usize + 1)
            .max()
            .unwrap_or(0);
        let mut counts = vec![[0usize; 2]; groups];
        for (i, p) in s.particles.iter().enumerate() {
            let side = usize::from(s.position(i)[0] >= half);
            counts[p.species as usize][side] += 1;
        }
        for [left, right] in counts {
            row.push(left as f64);
            row.push(right as f64);
        }
    }
    fn name(&self, k: usize, ctx: &Context) -> String {
        let side = if k.is_multiple_of(2) { "left" } else { "right" };
        match ctx.species.get(k / 2) {
            Some(species) => format!("count.{species}.{side}"),
            None => format!("count.{}.{side}", k / 2),
        }
    }
}
