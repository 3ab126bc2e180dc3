//! The temperature profile along x: at every sample, the number of movable
//! particles and their kinetic energy in each of `BINS` slabs across the
//! box, summed over the samples. Kinetic temperature per slab:
//! T = 2 energy / (d count); density: count / (samples * slab volume).
//! Coarser than `density_x` on purpose: a heat-conduction profile varies
//! over mean free paths, not over the layering of a dense gas at a wall.
//! Summed over the run for a steady profile; `temperature_x` gives the
//! temperature about each slab's flow at every sample instead.

use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{Histogram, RunOutput};

/// Slabs across the box, whatever its length.
pub const BINS: usize = 100;

pub struct EnergyX {
    length: f64,
    count: Vec<f64>,
    energy: Vec<f64>,
}

impl Observable for EnergyX {
    const ENTRY: Entry = Entry {
        name: "energy_x",
        kind: Kind::Histograms,
        writes: "energy_x.<count|energy>",
        label: "x (<count|energy> per slab)",
        unit: "σ",
        needs: &[Need::Sampling],
        doc: "number (count) and kinetic energy (energy) of the movable particles at every sample in 100 slabs across x: the temperature profile T = 2 energy / (d count)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(EnergyX {
            length: f64::NAN,
            count: vec![0.0; BINS],
            energy: vec![0.0; BINS],
        }))
    }
}

impl<const D: usize> Observer<D> for EnergyX {
    fn sample(&mut self, s: &Snapshot<D>) {
        self.length = s.sim_box.size[0];
        let bins = BINS as f64;
        for (i, p) in s.particles.iter().enumerate() {
            if p.is_immovable() || p.is_plane() {
                continue;
            }
            let b = (s.position(i)[0] / self.length * bins).floor();
            if (0.0..bins).contains(&b) {
                self.count[b as usize] += 1.0;
                self.energy[b as usize] += p.kinetic_energy();
            }
        }
    }
}

impl<const D: usize> Measure<D> for EnergyX {
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.number(self.length);
        out.list(&self.count);
        out.list(&self.energy);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.length = from.number()?;
        self.count = from.list()?;
        self.energy = from.list()?;
        if self.count.len() != BINS || self.energy.len() != BINS {
            return Err(format!("energy_x keeps {BINS} slabs"));
        }
        Ok(())
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        let w = self.length / BINS as f64;
        let lo: Vec<f64> = (0..BINS).map(|b| b as f64 * w).collect();
        let hi: Vec<f64> = (0..BINS).map(|b| (b + 1) as f64 * w).collect();
        for (name, values) in [("count", self.count), ("energy", self.energy)] {
            out.histograms.push(Histogram {
                observable: format!("energy_x.{name}"),
                lo: lo.clone(),
                hi: hi.clone(),
                count: values,
            });
        }
    }
}
