//! Temperature from the kinetic energy, kT = 2 K / f with f the free degrees
//! of freedom: as a series, and its time average as a scalar.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::{Snapshot, degrees_of_freedom};
use crate::model::need::Need;

/// The `temperature` series.
pub struct Temperature;

/// The `temperature` scalar: the time average of the series.
pub struct MeanTemperature;

impl Observable for Temperature {
    const ENTRY: Entry = Entry {
        name: "temperature",
        kind: Kind::Series,
        writes: "temperature",
        label: "temperature",
        unit: "kT",
        needs: &[Need::Sampling],
        doc: "kT = 2K / f, f the free degrees of freedom (d per particle, 1 for a piston wall, one less per periodic axis: momentum is conserved along it)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(Reading::default()))
    }
}

impl Observable for MeanTemperature {
    const ENTRY: Entry = Entry {
        name: "temperature",
        kind: Kind::Scalars,
        writes: "temperature",
        label: "temperature",
        unit: "kT",
        needs: &[Need::Sampling],
        doc: "time average of the `temperature` series",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Mean(Box::new(Reading::default()))
    }
}

#[derive(Default)]
struct Reading {
    /// Degrees of freedom, counted at the first sample (they do not change).
    dof: Option<f64>,
}

impl<const D: usize> Probe<D> for Reading {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let dof = *self
            .dof
            .get_or_insert_with(|| degrees_of_freedom(s.particles, s.sim_box));
        row.push(2.0 * s.kinetic_energy() / dof);
    }
    fn name(&self, _: usize, _: &Context) -> String {
        "temperature".into()
    }
}
