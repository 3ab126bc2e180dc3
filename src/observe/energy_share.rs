//! Each species' share of the kinetic energy at each sample: how far the
//! energy given to some particles has spread to the others.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct EnergyShare;

impl Observable for EnergyShare {
    const ENTRY: Entry = Entry {
        name: "energy_share",
        kind: Kind::Series,
        writes: "energy_share.<species>",
        label: "share of the kinetic energy held by <species>",
        unit: "1",
        needs: &[Need::Sampling],
        doc: "each species' share of the total kinetic energy (a piston is the species `piston`)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(EnergyShare))
    }
}

impl<const D: usize> Probe<D> for EnergyShare {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let groups = s
            .particles
            .iter()
            .map(|p| p.species as usize + 1)
            .max()
            .unwrap_or(0);
        let mut e = vec![0.0; groups];
        for p in s.particles {
            e[p.species as usize] += p.kinetic_energy();
        }
        let total: f64 = e.iter().sum();
        for v in e {
            row.push(v / total);
        }
    }
    fn name(&self, k: usize, ctx: &Context) -> String {
        match ctx.species.get(k) {
            Some(species) => format!("energy_share.{species}"),
            None => format!("energy_share.{k}"),
        }
    }
}
