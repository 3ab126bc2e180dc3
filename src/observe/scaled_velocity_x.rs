//! Velocity histogram of sqrt(m) v_x, so that every species shares one
//! Gaussian of variance kT at equilibrium.

use super::histogram::ParticleHistogram;
use super::{Entry, Kind, Observable, Part, Setup};
use crate::engine::Particle;
use crate::model::need::Need;

pub struct ScaledVelocityX;

/// 60 bins over [-6, 6) in units of sqrt(kT).
const BINS: usize = 60;
const HALF_WIDTH: f64 = 6.0;

impl Observable for ScaledVelocityX {
    const ENTRY: Entry = Entry {
        name: "scaled_velocity_x",
        kind: Kind::Histograms,
        writes: "scaled_velocity_x",
        label: "scaled velocity √m vₓ",
        unit: "√(kT)",
        needs: &[Need::Sampling],
        doc: "sqrt(m) v_x of every movable particle at every sample, 60 bins over [-6, 6)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(ParticleHistogram::new(
            Self::ENTRY.writes,
            (-HALF_WIDTH, HALF_WIDTH),
            BINS,
            scaled_vx::<D>,
        )))
    }
}

fn scaled_vx<const D: usize>(p: &Particle<D>) -> Option<f64> {
    (!p.is_immovable()).then(|| p.vel[0] / p.inv_mass.sqrt())
}
