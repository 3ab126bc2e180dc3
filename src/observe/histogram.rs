//! A histogram of one value per particle over every sample, on fixed bins:
//! what a histogram observable is made of (its file gives the value).

use super::{Context, Measure, StateIn, StateOut};
use crate::engine::{Observer, Particle, Snapshot};
use crate::model::run_output::{Histogram, RunOutput};

pub struct ParticleHistogram<const D: usize> {
    /// The name written to histograms.parquet.
    name: &'static str,
    lo: f64,
    hi: f64,
    counts: Vec<f64>,
    /// The particle's value, or None to leave it out.
    value: fn(&Particle<D>) -> Option<f64>,
}

impl<const D: usize> ParticleHistogram<D> {
    /// `bins` equal bins over [lo, hi); values outside are not counted.
    pub fn new(
        name: &'static str,
        (lo, hi): (f64, f64),
        bins: usize,
        value: fn(&Particle<D>) -> Option<f64>,
    ) -> Self {
        ParticleHistogram {
            name,
            lo,
            hi,
            counts: vec![0.0; bins],
            value,
        }
    }
}

impl<const D: usize> Observer<D> for ParticleHistogram<D> {
    fn sample(&mut self, s: &Snapshot<D>) {
        let bins = self.counts.len() as f64;
        for u in s.particles.iter().filter_map(|p| (self.value)(&p)) {
            let bin = ((u - self.lo) / (self.hi - self.lo) * bins).floor();
            if (0.0..bins).contains(&bin) {
                self.counts[bin as usize] += 1.0;
            }
        }
    }
}

impl<const D: usize> Measure<D> for ParticleHistogram<D> {
    fn uses_samples(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        let bins = self.counts.len();
        let w = (self.hi - self.lo) / bins as f64;
        out.histograms.push(Histogram {
            observable: self.name.into(),
            lo: (0..bins).map(|b| self.lo + b as f64 * w).collect(),
            hi: (0..bins).map(|b| self.lo + (b + 1) as f64 * w).collect(),
            count: self.counts,
        });
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.list(&self.counts);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        let counts = from.list()?;
        if counts.len() != self.counts.len() {
            return Err(format!(
                "{} has {} bins, its state {}",
                self.name,
                self.counts.len(),
                counts.len()
            ));
        }
        self.counts = counts;
        Ok(())
    }
}
