//! The one sampling pass the sampled observables of a run share: at each
//! sample every probe reads its values; at the end they become series (on one
//! time axis) or time averages.

use super::entry::Probe;
use super::{Context, Measure, StateIn, StateOut};
use crate::engine::{Observer, Snapshot};
use crate::model::run_output::{RunOutput, Series};

/// The probes of one run, in the order their results are written.
pub struct Sampled<const D: usize> {
    t: Vec<f64>,
    readings: Vec<Reading<D>>,
}

struct Reading<const D: usize> {
    probe: Box<dyn Probe<D>>,
    /// Keep only the time average of each value, as a scalar.
    mean: bool,
    /// One column per value, filled from the first sample.
    columns: Vec<Vec<f64>>,
}

/// Where a probe puts one sample's values.
pub struct Row<'a> {
    columns: &'a mut Vec<Vec<f64>>,
    next: usize,
}

impl Row<'_> {
    pub fn push(&mut self, value: f64) {
        if self.columns.len() <= self.next {
            self.columns.push(Vec::new());
        }
        self.columns[self.next].push(value);
        self.next += 1;
    }
}

impl<const D: usize> Default for Sampled<D> {
    fn default() -> Self {
        Sampled {
            t: Vec::new(),
            readings: Vec::new(),
        }
    }
}

impl<const D: usize> Sampled<D> {
    pub fn add(&mut self, probe: Box<dyn Probe<D>>, mean: bool) {
        self.readings.push(Reading {
            probe,
            mean,
            columns: Vec::new(),
        });
    }

    pub fn is_empty(&self) -> bool {
        self.readings.is_empty()
    }
}

impl<const D: usize> Observer<D> for Sampled<D> {
    fn sample(&mut self, s: &Snapshot<D>) {
        self.t.push(s.time);
        for r in &mut self.readings {
            let mut row = Row {
                columns: &mut r.columns,
                next: 0,
            };
            r.probe.read(s, &mut row);
        }
    }
}

impl<const D: usize> Measure<D> for Sampled<D> {
    fn uses_samples(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        for r in self.readings {
            for (k, values) in r.columns.into_iter().enumerate() {
                let name = r.probe.name(k, ctx);
                if r.mean {
                    let mean = values.iter().sum::<f64>() / values.len() as f64;
                    out.scalars.push((name, mean));
                } else {
                    out.series.push(Series {
                        observable: name,
                        t: self.t.clone(),
                        value: values,
                    });
                }
            }
        }
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.list(&self.t);
        for r in &self.readings {
            out.number(r.columns.len() as f64);
            r.columns.iter().for_each(|c| out.list(c));
        }
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.t = from.list()?;
        for r in &mut self.readings {
            let n = from.number()? as usize;
            r.columns = (0..n).map(|_| from.list()).collect::<Result<_, _>>()?;
        }
        Ok(())
    }
}
