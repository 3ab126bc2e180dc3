//! Kinetic energy of each species at each sample, named after the species
//! (a piston is the species `piston`).

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

pub struct KineticEnergyBySpecies;

impl Observable for KineticEnergyBySpecies {
    const ENTRY: Entry = Entry {
        name: "kinetic_energy_by_species",
        kind: Kind::Series,
        writes: "kinetic_energy.<species>",
        label: "kinetic energy of <species>",
        unit: "kT",
        needs: &[Need::Sampling],
        doc: "kinetic energy of each species (a piston is the species `piston`)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(KineticEnergyBySpecies))
    }
}

impl<const D: usize> Probe<D> for KineticEnergyBySpecies {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let groups = s
            .particles
            .iter()
            .map(|p| p.species)
            .max()
            .map_or(0, |m| m as usize + 1);
        let mut e = vec![0.0; groups];
        for p in s.particles {
            e[p.species as usize] += p.kinetic_energy();
        }
        for v in e {
            row.push(v);
        }
    }
    fn name(&self, k: usize, ctx: &Context) -> String {
        match ctx.species.get(k) {
            Some(species) => format!("kinetic_energy.{species}"),
            None => format!("kinetic_energy.{k}"),
        }
    }
}
