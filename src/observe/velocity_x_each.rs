//! Each particle's own histogram of v_x (MacKay: "histograms of velocities
//! of all the different masses"), over its whole reach.

use super::per_particle::{PerParticle, velocity_range};
use super::{Entry, Kind, Observable, Part, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct VelocityXEach;

/// Bins per particle.
pub const BINS: usize = 60;

impl Observable for VelocityXEach {
    const ENTRY: Entry = Entry {
        name: "velocity_x_each",
        kind: Kind::Histograms,
        writes: "velocity_x.<index>",
        label: "vₓ of particle <index>",
        unit: "√(kT/m)",
        needs: &[Need::Sampling],
        doc: "v_x of each movable particle at every sample, its own histogram: 60 bins over ±sqrt(2E/m) (E the energy at the first sample), capped at 6 sqrt(kT/m)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(PerParticle::new(
            "velocity_x",
            BINS,
            false,
            velocity_range::<D>,
            vx::<D>,
        )))
    }
}

pub fn vx<const D: usize>(s: &Snapshot<D>, i: usize) -> f64 {
    s.particles[i].vel[0]
}
