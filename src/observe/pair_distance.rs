//! Pair separations, for the radial distribution function g(r): the mean
//! number of pairs per sample at separations in each bin, nearest periodic
//! image on periodic axes, up to half the smallest box side. g(r) is this
//! over the pairs an ideal gas of the same N would put there, N(N-1)/2
//! times the shell's volume over the box's (finite N: N - 1 partners).

use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{Histogram, RunOutput};

pub struct PairDistance {
    reach: f64,
    counts: Vec<f64>,
    samples: u64,
}

/// Bin width in σ: fine enough to extrapolate g to contact.
pub const WIDTH: f64 = 0.02;

impl Observable for PairDistance {
    const ENTRY: Entry = Entry {
        name: "pair_distance",
        kind: Kind::Histograms,
        writes: "pair_distance",
        label: "pair separation r",
        unit: "σ",
        needs: &[Need::Sampling],
        doc: "mean number of pairs per sample at each separation (nearest periodic image), bins of 0.02σ up to half the smallest box side: g(r) for periodic boxes",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(PairDistance {
            reach: f64::NAN,
            counts: Vec::new(),
            samples: 0,
        }))
    }
}

impl<const D: usize> Observer<D> for PairDistance {
    fn sample(&mut self, s: &Snapshot<D>) {
        let size = s.sim_box.size;
        if self.counts.is_empty() {
            self.reach = 0.5 * size.iter().copied().fold(f64::INFINITY, f64::min);
            self.counts = vec![0.0; (self.reach / WIDTH).floor() as usize];
        }
        let periodic = super::neighbours::periodic(s);
        let at = super::neighbours::points(s);
        let bins = self.counts.len();
        for (i, a) in at.iter().enumerate() {
            for b in &at[i + 1..] {
                let mut r2 = 0.0;
                for k in 0..D {
                    let mut d = (a[k] - b[k]).abs();
                    if periodic[k] && d > 0.5 * size[k] {
                        d = size[k] - d;
                    }
                    r2 += d * d;
                }
                let bin = (r2.sqrt() / WIDTH) as usize;
                if bin < bins {
                    self.counts[bin] += 1.0;
                }
            }
        }
        self.samples += 1;
    }
}

impl<const D: usize> Measure<D> for PairDistance {
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.number(self.reach);
        out.list(&self.counts);
        out.number(self.samples as f64);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.reach = from.number()?;
        self.counts = from.list()?;
        self.samples = from.number()? as u64;
        Ok(())
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        let per = 1.0 / self.samples.max(1) as f64;
        let bins = self.counts.len();
        out.histograms.push(Histogram {
            observable: "pair_distance".into(),
            lo: (0..bins).map(|b| b as f64 * WIDTH).collect(),
            hi: (0..bins).map(|b| (b + 1) as f64 * WIDTH).collect(),
            count: self.counts.iter().map(|c| c * per).collect(),
        });
    }
}
