//! Observables read off the state at each sampling time (the seeds' clock).

use super::{Context, Measure};
use crate::engine::{Observer, Snapshot, degrees_of_freedom};
use crate::model::run_output::{RunOutput, Series};

/// Records the named sampled observables; a name "mean:<x>" keeps only the
/// time average of <x>, as a scalar.
pub struct Sampled {
    names: Vec<String>,
    t: Vec<f64>,
    /// (series name, values), filled on the first sample.
    columns: Vec<(String, Vec<f64>)>,
    dof: Option<f64>,
    piston: Option<usize>,
}

impl Sampled {
    pub fn new(names: Vec<String>, piston: Option<usize>) -> Self {
        Sampled {
            names,
            t: Vec::new(),
            columns: Vec::new(),
            dof: None,
            piston,
        }
    }

    fn push(&mut self, k: &mut usize, name: impl FnOnce() -> String, value: f64) {
        if self.columns.len() <= *k {
            self.columns.push((name(), Vec::new()));
        }
        self.columns[*k].1.push(value);
        *k += 1;
    }
}

impl<const D: usize> Observer<D> for Sampled {
    fn sample(&mut self, s: &Snapshot<D>) {
        self.t.push(s.time);
        let mut k = 0;
        let names = std::mem::take(&mut self.names);
        let kinetic = s.kinetic_energy();
        let dof = *self
            .dof
            .get_or_insert_with(|| degrees_of_freedom(s.particles, s.sim_box));
        for name in &names {
            let plain = name.strip_prefix("mean:").unwrap_or(name);
            match plain {
                "kinetic_energy" => self.push(&mut k, || name.clone(), kinetic),
                "temperature" => self.push(&mut k, || name.clone(), 2.0 * kinetic / dof),
                "kinetic_energy_by_species" => {
                    let groups = s
                        .particles
                        .iter()
                        .map(|p| p.species)
                        .max()
                        .map_or(0, |m| m as usize + 1);
                    let mut e = vec![0.0; groups];
                    for p in s.particles {
                        e[p.species as usize] += p.kinetic_energy();
                    }
                    for (g, v) in e.into_iter().enumerate() {
                        self.push(&mut k, || format!("kinetic_energy#{g}"), v);
                    }
                }
                "piston_position" => {
                    let x = self.piston.map(|i| s.position(i)[0]);
                    self.push(&mut k, || name.clone(), x.unwrap_or(f64::NAN));
                }
                "positions" => {
                    for i in 0..s.particles.len() {
                        self.push(&mut k, || format!("x.{i}"), s.position(i)[0]);
                    }
                }
                "left_fraction" => {
                    let half = 0.5 * s.sim_box.size[0];
                    let left = (0..s.particles.len())
                        .filter(|&i| s.position(i)[0] < half)
                        .count();
                    self.push(
                        &mut k,
                        || name.clone(),
                        left as f64 / s.particles.len().max(1) as f64,
                    );
                }
                _ => {}
            }
        }
        self.names = names;
    }
}

impl<const D: usize> Measure<D> for Sampled {
    fn uses_samples(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        for (name, values) in self.columns {
            if let Some(scalar) = name.strip_prefix("mean:") {
                let mean = values.iter().sum::<f64>() / values.len().max(1) as f64;
                out.scalars.push((
                    scalar.to_string(),
                    if values.is_empty() { f64::NAN } else { mean },
                ));
                continue;
            }
            // Species energies are named after the species.
            let observable = match name.strip_prefix("kinetic_energy#") {
                Some(g) => format!(
                    "kinetic_energy.{}",
                    g.parse::<usize>()
                        .ok()
                        .and_then(|g| ctx.species.get(g))
                        .map_or(g, |s| s)
                ),
                None => name,
            };
            out.series.push(Series {
                observable,
                t: self.t.clone(),
                value: values,
            });
        }
    }
}
