//! One conduction run in its steady state: the heat through each wall, the
//! temperature and density profiles across x, a straight line through the
//! temperature away from the walls, the conductivity flux / gradient at the
//! centre, and the temperature jumps at the walls.

use super::gas::Gas;
use crate::model::run_output::{Histogram, RunOutput};
use crate::stats::line::Sums;

/// A run's profile across x: per slab its centre, temperature, density and
/// the number of particle-samples in it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Profile {
    pub x: Vec<f64>,
    pub temperature: Vec<f64>,
    pub density: Vec<f64>,
    pub weight: Vec<f64>,
}

impl Profile {
    /// From the `energy_x` histograms (count, energy) of a run.
    pub fn of(gas: &Gas, count: &Histogram, energy: &Histogram) -> Profile {
        let samples = count.count.iter().sum::<f64>() / gas.particles;
        let cross = gas.wall_area(0);
        let d = gas.dimension as f64;
        let mut p = Profile::default();
        for b in 0..count.count.len() {
            let (c, e) = (count.count[b], energy.count[b]);
            let width = count.hi[b] - count.lo[b];
            p.x.push((count.lo[b] + count.hi[b]) / 2.0);
            p.temperature
                .push(if c > 0.0 { 2.0 * e / (d * c) } else { f64::NAN });
            p.density.push(c / (samples * width * cross));
            p.weight.push(c);
        }
        p
    }

    /// From a run's `energy_x` histograms; None if it has none.
    pub fn of_run(gas: &Gas, out: &RunOutput) -> Option<Profile> {
        let h = |n: &str| out.histograms.iter().find(|h| h.observable == n);
        Some(Profile::of(
            gas,
            h("energy_x.count")?,
            h("energy_x.energy")?,
        ))
    }
}

/// T = centre + slope (x - L/2), least squares over the slabs whose centres
/// lie within `width` (a fraction of L) of the middle, each weighted by its
/// particle-samples (its temperature's variance goes as their inverse).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    pub centre: f64,
    pub slope: f64,
    pub half_length: f64,
}

impl Line {
    pub fn fit(p: &Profile, length: f64, width: f64) -> Line {
        let mid = length / 2.0;
        let mut s = Sums::default();
        for i in 0..p.x.len() {
            let x = p.x[i] - mid;
            let (y, w) = (p.temperature[i], p.weight[i]);
            if x.abs() > width * length / 2.0 || !y.is_finite() || w <= 0.0 {
                continue;
            }
            s.add(x, y, w);
        }
        let slope = s.slope();
        Line {
            centre: (s.y - slope * s.x) / s.w,
            slope,
            half_length: mid,
        }
    }

    pub fn at(&self, x: f64) -> f64 {
        self.centre + self.slope * (x - self.half_length)
    }
}

/// Mean density over the slabs the fit used (the centre's, to second order).
pub fn centre_density(p: &Profile, length: f64, width: f64) -> f64 {
    let near = |x: f64| (x - length / 2.0).abs() <= width * length / 2.0;
    let slabs = p.x.iter().zip(&p.density).filter(|(x, _)| near(**x));
    let v: Vec<f64> = slabs.map(|(_, n)| *n).collect();
    v.iter().sum::<f64>() / v.len() as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_straight_profile_is_fitted_exactly() {
        let x: Vec<f64> = (0..10).map(|i| i as f64 + 0.5).collect();
        let p = Profile {
            temperature: x.iter().map(|x| 2.0 - 0.1 * x).collect(),
            density: x.iter().map(|x| 1.0 + x).collect(),
            weight: x.iter().map(|x| 1.0 + x * x).collect(),
            x,
        };
        let line = Line::fit(&p, 10.0, 0.5);
        assert!((line.slope + 0.1).abs() < 1e-12);
        assert!((line.centre - 1.5).abs() < 1e-12);
        assert!((line.at(0.0) - 2.0).abs() < 1e-12);
        // Slabs at 3.5, 4.5, 5.5, 6.5 lie within 2.5 of the middle.
        assert!((centre_density(&p, 10.0, 0.5) - 6.0).abs() < 1e-12);
    }
}
