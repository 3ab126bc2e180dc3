//! Each particle's v_x histogram over the first and over the second half of
//! the run, apart: a distribution that still drifts (slow mixing) shows as
//! a difference between them.

use super::per_particle::{PerParticle, velocity_range};
use super::velocity_x_each::{BINS, vx};
use super::{Entry, Kind, Observable, Part, Setup};
use crate::model::need::Need;

pub struct VelocityXHalves;

impl Observable for VelocityXHalves {
    const ENTRY: Entry = Entry {
        name: "velocity_x_halves",
        kind: Kind::Histograms,
        writes: "velocity_x_<early|late>.<index>",
        label: "vₓ of particle <index>, <early|late> half",
        unit: "√(kT/m)",
        needs: &[Need::Sampling],
        doc: "as velocity_x_each, over the run's first and second halves apart (two equal stretches covering at least 4/5 of the run)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(PerParticle::new(
            "velocity_x",
            BINS,
            true,
            velocity_range::<D>,
            vx::<D>,
        )))
    }
}
