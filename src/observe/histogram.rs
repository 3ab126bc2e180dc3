//! Velocity histogram: sqrt(m) v_x, so every species shares one Gaussian of
//! variance kT at equilibrium.

use super::{Context, Measure};
use crate::engine::{Observer, Snapshot};
use crate::model::run_output::{Histogram, RunOutput};

const BINS: usize = 60;
const HALF_WIDTH: f64 = 6.0;

pub struct ScaledVelocity {
    counts: Vec<f64>,
}

impl Default for ScaledVelocity {
    fn default() -> Self {
        ScaledVelocity {
            counts: vec![0.0; BINS],
        }
    }
}

impl<const D: usize> Observer<D> for ScaledVelocity {
    fn sample(&mut self, s: &Snapshot<D>) {
        for p in s.particles.iter().filter(|p| !p.is_immovable()) {
            let u = p.vel[0] / p.inv_mass.sqrt();
            let bin = ((u + HALF_WIDTH) / (2.0 * HALF_WIDTH) * BINS as f64).floor();
            if (0.0..BINS as f64).contains(&bin) {
                self.counts[bin as usize] += 1.0;
            }
        }
    }
}

impl<const D: usize> Measure<D> for ScaledVelocity {
    fn uses_samples(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        let w = 2.0 * HALF_WIDTH / BINS as f64;
        out.histograms.push(Histogram {
            observable: "scaled_velocity_x".into(),
            lo: (0..BINS).map(|b| -HALF_WIDTH + b as f64 * w).collect(),
            hi: (0..BINS)
                .map(|b| -HALF_WIDTH + (b + 1) as f64 * w)
                .collect(),
            count: self.counts,
        });
    }
}
