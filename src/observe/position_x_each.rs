//! Each particle's own histogram of x (MacKay: "histograms of positions"):
//! in 1D rods keep their order, so each has its own distribution.

use super::per_particle::PerParticle;
use super::{Entry, Kind, Observable, Part, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct PositionXEach;

const BINS: usize = 50;

impl Observable for PositionXEach {
    const ENTRY: Entry = Entry {
        name: "position_x_each",
        kind: Kind::Histograms,
        writes: "position_x.<index>",
        label: "x of particle <index>",
        unit: "σ",
        needs: &[Need::Sampling],
        doc: "x of each movable particle at every sample, its own histogram: 50 bins over the box [0, L)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(PerParticle::new(
            "position_x",
            BINS,
            false,
            range::<D>,
            x::<D>,
        )))
    }
}

fn range<const D: usize>(s: &Snapshot<D>, i: usize) -> Option<(f64, f64)> {
    let p = s.particles.get(i);
    (!p.is_immovable() && !p.is_plane()).then_some((0.0, s.sim_box.size[0]))
}

fn x<const D: usize>(s: &Snapshot<D>, i: usize) -> f64 {
    s.position(i)[0]
}
