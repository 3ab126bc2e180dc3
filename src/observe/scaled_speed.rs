//! Histogram of sqrt(m) |v| over all movable particles (Imperial:
//! "another with the speed of the particles"): scaled by sqrt(m) so that a
//! mixture shares one Maxwell-Boltzmann law.

use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, Particle, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{Histogram, RunOutput};

pub struct ScaledSpeed {
    /// Upper end of the bins, from the first sample.
    hi: Option<f64>,
    counts: Vec<f64>,
}

const BINS: usize = 60;
/// The bins reach this many sqrt(kT), kT = 2E/(d N) at the first sample.
const REACH: f64 = 6.0;

impl Observable for ScaledSpeed {
    const ENTRY: Entry = Entry {
        name: "scaled_speed",
        kind: Kind::Histograms,
        writes: "scaled_speed",
        label: "scaled speed √m |v|",
        unit: "√(kT)",
        needs: &[Need::Sampling],
        doc: "sqrt(m) times the speed of every movable particle at every sample, 60 bins over [0, 6 sqrt(kT)), kT = 2E/(d N) at the first sample",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(ScaledSpeed {
            hi: None,
            counts: vec![0.0; BINS],
        }))
    }
}

fn moving<const D: usize>(p: &Particle<D>) -> bool {
    !p.is_immovable() && !p.is_plane()
}

impl<const D: usize> Observer<D> for ScaledSpeed {
    fn sample(&mut self, s: &Snapshot<D>) {
        let hi = *self.hi.get_or_insert_with(|| {
            let n = s.particles.iter().filter(moving).count();
            REACH * (2.0 * s.kinetic_energy() / (D * n) as f64).sqrt()
        });
        for p in s.particles.iter().filter(moving) {
            let u = (2.0 * p.kinetic_energy()).sqrt();
            let b = (u / hi * BINS as f64).floor();
            if b < BINS as f64 {
                self.counts[b as usize] += 1.0;
            }
        }
    }
}

impl<const D: usize> Measure<D> for ScaledSpeed {
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.list(&self.hi.into_iter().collect::<Vec<_>>());
        out.list(&self.counts);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.hi = from.list()?.first().copied();
        self.counts = from.list()?;
        Ok(())
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        let w = self.hi.unwrap_or(REACH) / BINS as f64;
        out.histograms.push(Histogram {
            observable: "scaled_speed".into(),
            lo: (0..BINS).map(|b| b as f64 * w).collect(),
            hi: (0..BINS).map(|b| (b + 1) as f64 * w).collect(),
            count: self.counts,
        });
    }
}
