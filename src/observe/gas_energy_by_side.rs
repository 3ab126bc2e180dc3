//! Kinetic energy of the gas on each side of the piston (`gas_energy.left`,
//! `gas_energy.right`): what the piston analysis needs to follow each gas
//! along its adiabat, whatever species the gases are made of. It keeps its own
//! clock (an observer, not a probe of the shared pass), as it always has: the
//! tables keep their order.

use super::{Context, Entry, Kind, Measure, Observable, Part, Setup, StateIn, StateOut};
use crate::engine::{Observer, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{RunOutput, Series};

pub struct GasEnergyBySide {
    piston: Option<usize>,
    t: Vec<f64>,
    left: Vec<f64>,
    right: Vec<f64>,
}

impl Observable for GasEnergyBySide {
    const ENTRY: Entry = Entry {
        name: "gas_energy_by_side",
        kind: Kind::Series,
        writes: "gas_energy.<left|right>",
        label: "kinetic energy of the gas <left|right> of the piston",
        unit: "kT",
        needs: &[Need::Sampling, Need::Piston],
        doc: "kinetic energy of the gas left and right of the piston",
    };
    fn part<const D: usize>(setup: &Setup) -> Part<D> {
        Part::Observer(Box::new(GasEnergyBySide {
            piston: setup.piston,
            t: Vec::new(),
            left: Vec::new(),
            right: Vec::new(),
        }))
    }
}

impl<const D: usize> Observer<D> for GasEnergyBySide {
    fn sample(&mut self, s: &Snapshot<D>) {
        let Some(p) = self.piston else { return };
        let wall = s.position(p)[0];
        let (mut left, mut right) = (0.0, 0.0);
        for (i, q) in s.particles.iter().enumerate() {
            if i == p || q.is_immovable() {
                continue;
            }
            if s.position(i)[0] < wall {
                left += q.kinetic_energy();
            } else {
                right += q.kinetic_energy();
            }
        }
        self.t.push(s.time);
        self.left.push(left);
        self.right.push(right);
    }
}

impl<const D: usize> Measure<D> for GasEnergyBySide {
    fn uses_samples(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        for (side, value) in [("left", self.left), ("right", self.right)] {
            out.series.push(Series {
                observable: format!("gas_energy.{side}"),
                t: self.t.clone(),
                value,
            });
        }
    }
    fn save(&self, out: &mut StateOut) -> bool {
        [&self.t, &self.left, &self.right]
            .into_iter()
            .for_each(|v| out.list(v));
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.t = from.list()?;
        self.left = from.list()?;
        self.right = from.list()?;
        Ok(())
    }
}
