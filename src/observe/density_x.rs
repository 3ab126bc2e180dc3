//! Histogram of the x of every movable particle over the samples: the
//! density profile along x (Imperial: "histogram the x position of the
//! particles"), flat in a dilute gas, layered at walls when dense.

use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{Histogram, RunOutput};

pub struct DensityX {
    length: f64,
    counts: Vec<f64>,
}

/// Bins over the box: 200 resolve the layering (about σ/4 apart at
/// contact) in boxes up to ~50σ.
const BINS: usize = 200;

impl Observable for DensityX {
    const ENTRY: Entry = Entry {
        name: "density_x",
        kind: Kind::Histograms,
        writes: "density_x",
        label: "x (all particles)",
        unit: "σ",
        needs: &[Need::Sampling],
        doc: "x of every movable particle at every sample, 200 bins over the box [0, L): the density profile along x",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(DensityX {
            length: f64::NAN,
            counts: vec![0.0; BINS],
        }))
    }
}

impl<const D: usize> Observer<D> for DensityX {
    fn sample(&mut self, s: &Snapshot<D>) {
        self.length = s.sim_box.size[0];
        for (i, p) in s.particles.iter().enumerate() {
            if p.is_immovable() || p.is_plane() {
                continue;
            }
            let b = (s.position(i)[0] / self.length * BINS as f64).floor();
            if (0.0..BINS as f64).contains(&b) {
                self.counts[b as usize] += 1.0;
            }
        }
    }
}

impl<const D: usize> Measure<D> for DensityX {
    fn uses_samples(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        let w = self.length / BINS as f64;
        out.histograms.push(Histogram {
            observable: "density_x".into(),
            lo: (0..BINS).map(|b| b as f64 * w).collect(),
            hi: (0..BINS).map(|b| (b + 1) as f64 * w).collect(),
            count: self.counts,
        });
    }
}
