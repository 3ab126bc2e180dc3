//! Autocorrelation of each particle's kinetic energy against lag,
//! C_i(lag) = cov(K_i(t), K_i(t + lag)) / var(K_i), over every time origin
//! on the fixed lag grid of `lags`, averaged over the particles of each
//! species. Sums accumulate as the run goes; the means are taken at the end
//! (for each lag over the pairs it saw), the variance over every sample. The
//! series' time axis is the lag.

use super::lags::{LAGS, Ring};
use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Setup};
use crate::engine::{Observer, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::{RunOutput, Series};

#[derive(Default)]
pub struct EnergyAutocorrelation {
    species: Vec<usize>,
    energy: Vec<f64>,
    ring: Option<Ring>,
    /// Per particle: sum of K and of K^2 over the samples.
    sum: Vec<f64>,
    sum2: Vec<f64>,
    /// Per (particle, lag): sums of K(t) K(t + lag), K(t), K(t + lag).
    cross: Vec<f64>,
    early: Vec<f64>,
    late: Vec<f64>,
    /// Per lag: pairs seen and summed lag times.
    pairs: Vec<u64>,
    lag_time: Vec<f64>,
}

impl Observable for EnergyAutocorrelation {
    const ENTRY: Entry = Entry {
        name: "energy_autocorrelation",
        kind: Kind::Series,
        writes: "energy_autocorrelation.<species>",
        label: "kinetic-energy autocorrelation of <species> (t: lag)",
        unit: "1",
        needs: &[Need::Sampling],
        doc: "each particle's kinetic-energy autocorrelation against lag (the series' t), over every time origin, averaged over each species",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(EnergyAutocorrelation::default()))
    }
}

impl<const D: usize> Observer<D> for EnergyAutocorrelation {
    fn sample(&mut self, s: &Snapshot<D>) {
        let n = s.particles.len();
        let lags = LAGS.len();
        if self.ring.is_none() {
            self.species = s.particles.iter().map(|p| p.species as usize).collect();
            self.ring = Some(Ring::new(n));
            self.sum = vec![0.0; n];
            self.sum2 = vec![0.0; n];
            self.cross = vec![0.0; n * lags];
            self.early = vec![0.0; n * lags];
            self.late = vec![0.0; n * lags];
            self.pairs = vec![0; lags];
            self.lag_time = vec![0.0; lags];
        }
        self.energy.clear();
        self.energy
            .extend(s.particles.iter().map(|p| p.kinetic_energy()));
        for (i, k) in self.energy.iter().enumerate() {
            self.sum[i] += k;
            self.sum2[i] += k * k;
        }
        let ring = self.ring.as_mut().expect("set above");
        ring.push(s.time, &self.energy);
        for (l, &lag) in LAGS.iter().enumerate() {
            let Some((t0, then)) = ring.back(lag) else {
                break;
            };
            self.pairs[l] += 1;
            self.lag_time[l] += s.time - t0;
            for i in 0..n {
                let (a, b) = (then[i], self.energy[i]);
                self.cross[i * lags + l] += a * b;
                self.early[i * lags + l] += a;
                self.late[i * lags + l] += b;
            }
        }
    }
}

impl<const D: usize> Measure<D> for EnergyAutocorrelation {
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        let Some(ring) = &self.ring else {
            out.number(0.0);
            return true;
        };
        out.number(1.0);
        ring.save(out);
        out.list(&self.species.iter().map(|&k| k as f64).collect::<Vec<_>>());
        for values in [&self.sum, &self.sum2, &self.cross, &self.early, &self.late] {
            out.list(values);
        }
        out.list(&self.pairs.iter().map(|&k| k as f64).collect::<Vec<_>>());
        out.list(&self.lag_time);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        if from.number()? == 0.0 {
            return Ok(());
        }
        self.ring = Some(Ring::restore(from)?);
        self.species = from.list()?.iter().map(|&k| k as usize).collect();
        self.sum = from.list()?;
        self.sum2 = from.list()?;
        self.cross = from.list()?;
        self.early = from.list()?;
        self.late = from.list()?;
        self.pairs = from.list()?.iter().map(|&k| k as u64).collect();
        self.lag_time = from.list()?;
        Ok(())
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        let lags = LAGS.len();
        let samples = self.ring.as_ref().map_or(0, |r| r.pushed) as f64;
        let kept: Vec<usize> = (0..self.pairs.len())
            .filter(|&l| self.pairs[l] > 0)
            .collect();
        let t: Vec<f64> = kept
            .iter()
            .map(|&l| self.lag_time[l] / self.pairs[l] as f64)
            .collect();
        let groups = self.species.iter().max().map_or(0, |m| m + 1);
        for sp in 0..groups {
            let members: Vec<usize> = (0..self.species.len())
                .filter(|&i| self.species[i] == sp)
                .collect();
            let value = kept
                .iter()
                .map(|&l| {
                    let n = self.pairs[l] as f64;
                    let (mut total, mut used) = (0.0, 0);
                    for &i in &members {
                        let mean = self.sum[i] / samples;
                        let var = self.sum2[i] / samples - mean * mean;
                        // A particle whose energy never changed has no correlation time.
                        if var > 0.0 {
                            let j = i * lags + l;
                            let cov = self.cross[j] / n - (self.early[j] / n) * (self.late[j] / n);
                            total += cov / var;
                            used += 1;
                        }
                    }
                    total / used as f64
                })
                .collect();
            let name = ctx.species.get(sp).cloned().unwrap_or(sp.to_string());
            out.series.push(Series {
                observable: format!("energy_autocorrelation.{name}"),
                t: t.clone(),
                value,
            });
        }
    }
}
