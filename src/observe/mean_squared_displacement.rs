//! Mean-squared displacement of each species along each axis against lag,
//! over every time origin, on the fixed lag grid of `lags`. Positions are
//! unwrapped through periodic boundaries by the smallest image of each step
//! between samples, which is right while no particle moves half a box
//! between two samples: a step above a quarter box makes that axis NaN
//! rather than a wrong number. The series' time axis is the lag.

use super::lags::{LAGS, Ring};
use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{RunOutput, Series};

pub struct MeanSquaredDisplacement<const D: usize> {
    species: Vec<usize>,
    folded: Vec<[f64; D]>,
    unwrapped: Vec<f64>,
    ring: Ring,
    /// Sum of squared displacements by (species, lag, axis).
    sums: Vec<f64>,
    /// Displacements summed, by (species, lag).
    counts: Vec<u64>,
    /// Sum of the lag times, by lag.
    lag_time: Vec<f64>,
    lag_count: Vec<u64>,
    /// Largest step between samples over the box length, by axis.
    largest_step: [f64; D],
}

pub const AXES: [&str; 3] = ["x", "y", "z"];

impl<const D: usize> Default for MeanSquaredDisplacement<D> {
    fn default() -> Self {
        MeanSquaredDisplacement {
            species: Vec::new(),
            folded: Vec::new(),
            unwrapped: Vec::new(),
            ring: Ring::new(0),
            sums: Vec::new(),
            counts: Vec::new(),
            lag_time: vec![0.0; LAGS.len()],
            lag_count: vec![0; LAGS.len()],
            largest_step: [0.0; D],
        }
    }
}

/// Catalogue entry (the observer is generic over the dimension).
pub struct Msd;

impl Observable for Msd {
    const ENTRY: Entry = Entry {
        name: "mean_squared_displacement",
        kind: Kind::Series,
        writes: "msd.<species>.<x|y|z>",
        label: "mean-squared displacement of <species> along <x|y|z> (t: lag)",
        unit: "σ²",
        needs: &[Need::Sampling],
        doc: "mean-squared displacement of each species along each axis against lag (the series' t), over every time origin, unwrapped through periodic boundaries",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(MeanSquaredDisplacement::<D>::default()))
    }
}

impl<const D: usize> MeanSquaredDisplacement<D> {
    fn start(&mut self, s: &Snapshot<D>) {
        let n = s.particles.len();
        self.species = s.particles.iter().map(|p| p.species as usize).collect();
        let groups = self.species.iter().max().map_or(0, |m| m + 1);
        self.folded = (0..n).map(|i| s.position(i)).collect();
        self.unwrapped = self.folded.iter().flatten().copied().collect();
        self.ring = Ring::new(n * D);
        self.sums = vec![0.0; groups * LAGS.len() * D];
        self.counts = vec![0; groups * LAGS.len()];
    }
}

impl<const D: usize> Observer<D> for MeanSquaredDisplacement<D> {
    fn sample(&mut self, s: &Snapshot<D>) {
        if self.ring.pushed == 0 {
            self.start(s);
        } else {
            for i in 0..self.folded.len() {
                let x = s.position(i);
                for k in 0..D {
                    let mut step = x[k] - self.folded[i][k];
                    let size = s.sim_box.size[k];
                    if s.sim_box.axes[k].is_periodic() {
                        step -= size * (step / size).round();
                    }
                    self.largest_step[k] = self.largest_step[k].max(step.abs() / size);
                    self.unwrapped[i * D + k] += step;
                }
                self.folded[i] = x;
            }
        }
        self.ring.push(s.time, &self.unwrapped);
        let lags = LAGS.len();
        for (l, &lag) in LAGS.iter().enumerate() {
            let Some((t0, then)) = self.ring.back(lag) else {
                break;
            };
            self.lag_time[l] += s.time - t0;
            self.lag_count[l] += 1;
            for (i, &sp) in self.species.iter().enumerate() {
                for k in 0..D {
                    let dx = self.unwrapped[i * D + k] - then[i * D + k];
                    self.sums[(sp * lags + l) * D + k] += dx * dx;
                }
                self.counts[sp * lags + l] += 1;
            }
        }
    }
}

impl<const D: usize> Measure<D> for MeanSquaredDisplacement<D> {
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        let whole = |v: &[u64]| v.iter().map(|&k| k as f64).collect::<Vec<_>>();
        out.list(&self.species.iter().map(|&k| k as f64).collect::<Vec<_>>());
        out.list(&self.folded.iter().flatten().copied().collect::<Vec<_>>());
        out.list(&self.unwrapped);
        self.ring.save(out);
        out.list(&self.sums);
        out.list(&whole(&self.counts));
        out.list(&self.lag_time);
        out.list(&whole(&self.lag_count));
        out.list(&self.largest_step);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        let whole = |v: Vec<f64>| v.iter().map(|&k| k as u64).collect::<Vec<_>>();
        self.species = from.list()?.iter().map(|&k| k as usize).collect();
        self.folded = from
            .list()?
            .chunks_exact(D)
            .map(|c| std::array::from_fn(|k| c[k]))
            .collect();
        self.unwrapped = from.list()?;
        self.ring = Ring::restore(from)?;
        self.sums = from.list()?;
        self.counts = whole(from.list()?);
        self.lag_time = from.list()?;
        self.lag_count = whole(from.list()?);
        let largest = from.list()?;
        if largest.len() != D {
            return Err("the observers' state has a step of another dimension".into());
        }
        self.largest_step = std::array::from_fn(|k| largest[k]);
        Ok(())
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        let lags = LAGS.len();
        let kept: Vec<usize> = (0..lags).filter(|&l| self.lag_count[l] > 0).collect();
        let t: Vec<f64> = kept
            .iter()
            .map(|&l| self.lag_time[l] / self.lag_count[l] as f64)
            .collect();
        for sp in 0..self.counts.len() / lags {
            let name = ctx.species.get(sp).cloned().unwrap_or(sp.to_string());
            for (k, axis) in AXES.iter().enumerate().take(D) {
                // A step this large may have crossed to another image.
                let trusted = self.largest_step[k] <= 0.25;
                let value = kept
                    .iter()
                    .map(|&l| {
                        let n = self.counts[sp * lags + l];
                        if trusted && n > 0 {
                            self.sums[(sp * lags + l) * D + k] / n as f64
                        } else {
                            f64::NAN
                        }
                    })
                    .collect();
                out.series.push(Series {
                    observable: format!("msd.{name}.{axis}"),
                    t: t.clone(),
                    value,
                });
            }
        }
    }
}
