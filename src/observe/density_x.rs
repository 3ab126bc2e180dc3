//! Histogram of the x of every movable particle over the samples: the
//! density profile along x (Imperial: "histogram the x position of the
//! particles"), flat in a dilute gas, layered at walls when dense.

use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{Histogram, RunOutput};

pub struct DensityX {
    length: f64,
    counts: Vec<f64>,
}

/// Bin width in σ, about: fine enough to resolve the layers at a wall
/// and to extrapolate the density to contact.
const WIDTH: f64 = 0.02;

impl Observable for DensityX {
    const ENTRY: Entry = Entry {
        name: "density_x",
        kind: Kind::Histograms,
        writes: "density_x",
        label: "x (all particles)",
        unit: "σ",
        needs: &[Need::Sampling],
        doc: "x of every movable particle at every sample, in bins of about 0.02σ over the box [0, L): the density profile along x",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(DensityX {
            length: f64::NAN,
            counts: Vec::new(),
        }))
    }
}

impl<const D: usize> Observer<D> for DensityX {
    fn sample(&mut self, s: &Snapshot<D>) {
        if self.counts.is_empty() {
            self.length = s.sim_box.size[0];
            self.counts = vec![0.0; (self.length / WIDTH).round().max(1.0) as usize];
        }
        let bins = self.counts.len() as f64;
        for (i, p) in s.particles.iter().enumerate() {
            if p.is_immovable() || p.is_plane() {
                continue;
            }
            let b = (s.position(i)[0] / self.length * bins).floor();
            if (0.0..bins).contains(&b) {
                self.counts[b as usize] += 1.0;
            }
        }
    }
}

impl<const D: usize> Measure<D> for DensityX {
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.number(self.length);
        out.list(&self.counts);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.length = from.number()?;
        self.counts = from.list()?;
        Ok(())
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        let bins = self.counts.len();
        let w = self.length / bins as f64;
        out.histograms.push(Histogram {
            observable: "density_x".into(),
            lo: (0..bins).map(|b| b as f64 * w).collect(),
            hi: (0..bins).map(|b| (b + 1) as f64 * w).collect(),
            count: self.counts,
        });
    }
}
