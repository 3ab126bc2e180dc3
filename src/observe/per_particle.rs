//! One histogram per particle of a value read at every sample, each on its
//! own bins, chosen at the first sample (a particle's velocity range
//! depends on its mass and on the energy). Counts accumulate in blocks, so
//! the run's first and second halves can be written instead.

use super::blocks::Blocks;
use super::state::{StateIn, StateOut};
use super::{Context, Measure};
use crate::engine::{Observer, Snapshot};
use crate::model::run_output::{Histogram, RunOutput};

/// A particle's bins, from the first sample: Some((lo, hi)), or None to
/// leave the particle out.
pub type Range<const D: usize> = fn(&Snapshot<D>, usize) -> Option<(f64, f64)>;
/// A particle's value at a sample.
pub type Value<const D: usize> = fn(&Snapshot<D>, usize) -> f64;

pub struct PerParticle<const D: usize> {
    /// Written as `<prefix>.<index>`, or with `halves` as
    /// `<prefix>_early.<index>` and `<prefix>_late.<index>` only.
    prefix: &'static str,
    bins: usize,
    halves: bool,
    range: Range<D>,
    value: Value<D>,
    ranges: Vec<Option<(f64, f64)>>,
    counts: Option<Blocks>,
}

impl<const D: usize> PerParticle<D> {
    pub fn new(
        prefix: &'static str,
        bins: usize,
        halves: bool,
        range: Range<D>,
        value: Value<D>,
    ) -> Self {
        PerParticle {
            prefix,
            bins,
            halves,
            range,
            value,
            ranges: Vec::new(),
            counts: None,
        }
    }
}

impl<const D: usize> Observer<D> for PerParticle<D> {
    fn sample(&mut self, s: &Snapshot<D>) {
        let n = s.particles.len();
        if self.counts.is_none() {
            self.ranges = (0..n).map(|i| (self.range)(s, i)).collect();
        }
        let bins = self.bins;
        let counts = self
            .counts
            .get_or_insert_with(|| Blocks::new(n * bins))
            .counts();
        for (i, range) in self.ranges.iter().enumerate() {
            let Some((lo, hi)) = *range else { continue };
            let b = (((self.value)(s, i) - lo) / (hi - lo) * bins as f64).floor();
            if (0.0..bins as f64).contains(&b) {
                counts[i * bins + b as usize] += 1.0;
            }
        }
        if let Some(c) = self.counts.as_mut() {
            c.end_sample();
        }
    }
}

impl<const D: usize> Measure<D> for PerParticle<D> {
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        // Each range as (present, lo, hi).
        let ranges: Vec<f64> = self
            .ranges
            .iter()
            .flat_map(|r| match r {
                Some((lo, hi)) => [1.0, *lo, *hi],
                None => [0.0, 0.0, 0.0],
            })
            .collect();
        out.list(&ranges);
        match &self.counts {
            Some(blocks) => {
                out.number(1.0);
                blocks.save(out);
            }
            None => out.number(0.0),
        }
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.ranges = from
            .list()?
            .chunks_exact(3)
            .map(|r| (r[0] != 0.0).then_some((r[1], r[2])))
            .collect();
        self.counts = if from.number()? != 0.0 {
            Some(Blocks::restore(from)?)
        } else {
            None
        };
        Ok(())
    }
    fn finish(self: Box<Self>, _ctx: &Context, out: &mut RunOutput) {
        let Some(blocks) = &self.counts else { return };
        let parts = if self.halves {
            let (early, late, _) = blocks.halves();
            vec![("_early", early), ("_late", late)]
        } else {
            vec![("", blocks.total())]
        };
        let bins = self.bins;
        for (suffix, counts) in parts {
            for (i, range) in self.ranges.iter().enumerate() {
                let Some((lo, hi)) = *range else { continue };
                let w = (hi - lo) / bins as f64;
                let count = match counts.get(i * bins..(i + 1) * bins) {
                    Some(c) => c.to_vec(),
                    None => vec![0.0; bins],
                };
                out.histograms.push(Histogram {
                    observable: format!("{}{suffix}.{i}", self.prefix),
                    lo: (0..bins).map(|b| lo + b as f64 * w).collect(),
                    hi: (0..bins).map(|b| lo + (b + 1) as f64 * w).collect(),
                    count,
                });
            }
        }
    }
}

/// The range of a velocity component of particle `i`: its whole reach,
/// |v| <= sqrt(2E/m) with E the energy of the first sample, capped at six
/// thermal widths sqrt(kT/m), kT = 2E/(d N), for large N (where the reach
/// is mostly empty). Immovable particles and planes are left out.
pub fn velocity_range<const D: usize>(s: &Snapshot<D>, i: usize) -> Option<(f64, f64)> {
    let p = s.particles.get(i);
    if p.is_immovable() || p.is_plane() {
        return None;
    }
    let moving = s
        .particles
        .iter()
        .filter(|p| !p.is_immovable() && !p.is_plane())
        .count();
    let energy = s.kinetic_energy();
    let kt = 2.0 * energy / (D * moving) as f64;
    let reach = (2.0 * energy * p.inv_mass).sqrt();
    let w = reach.min(6.0 * (kt * p.inv_mass).sqrt());
    (w > 0.0).then_some((-w, w))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::{Particle, SimBox};

    /// Two rods of masses 1 and 4 with energy 1/2 + 2 = 5/2: their reaches
    /// are sqrt(5) and sqrt(5/4); each sample lands in its own particle's bin.
    #[test]
    fn each_particle_has_its_own_reach_and_counts() {
        let particles = vec![
            Particle::<1>::new([1.0], [1.0], 1.0, 0.0),
            Particle::<1>::new([3.0], [-1.0], 4.0, 0.0),
        ];
        let sim_box = SimBox::hard([4.0]);
        let bodies = crate::engine::Bodies::new(&particles);
        let s = Snapshot {
            time: 0.0,
            now: 0.0,
            particles: &bodies,
            sim_box: &sim_box,
        };
        let mut h = Box::new(PerParticle::new(
            "velocity_x",
            10,
            false,
            velocity_range::<1>,
            |s, i| s.particles[i].vel[0],
        ));
        h.sample(&s);
        h.sample(&s);
        let species = ["a".to_string()];
        let ctx = Context {
            species: &species,
            piston: None,
            duration: 1.0,
            volume: 4.0,
            wall_area: 2.0,
            dimension: 1,
            degrees_of_freedom: 2.0,
        };
        let mut out = RunOutput::default();
        h.finish(&ctx, &mut out);
        let names: Vec<&str> = out
            .histograms
            .iter()
            .map(|h| h.observable.as_str())
            .collect();
        assert_eq!(names, ["velocity_x.0", "velocity_x.1"]);
        let (a, b) = (&out.histograms[0], &out.histograms[1]);
        assert!((a.lo[0] + 5f64.sqrt()).abs() < 1e-12 && (a.hi[9] - 5f64.sqrt()).abs() < 1e-12);
        assert!((b.hi[9] - 1.25f64.sqrt()).abs() < 1e-12);
        // v = 1 of reach sqrt(5): bin floor((1 + 2.236)/4.472 * 10) = 7.
        assert_eq!(a.count[7], 2.0);
        assert_eq!(a.count.iter().sum::<f64>(), 2.0);
        // v = -1 of reach sqrt(1.25): bin floor((-1 + 1.118)/2.236 * 10) = 0.
        assert_eq!(b.count[0], 2.0);
    }
}
