//! Pressure from the collision virial, any boundary:
//! `P V = (2/d) <K> + (1/(d t)) sum over collisions of r_ij . dp_i`.

use super::{Context, Entry, Kind, Measure, Observable, Part, Setup, StateIn, StateOut};
use crate::engine::{Observer, PairCollision, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::RunOutput;

#[derive(Default)]
pub struct VirialPressure {
    virial: f64,
    kinetic_sum: f64,
    samples: u64,
}

impl Observable for VirialPressure {
    const ENTRY: Entry = Entry {
        name: "virial_pressure",
        kind: Kind::Scalars,
        writes: "virial_pressure",
        label: "virial pressure P",
        unit: "kT/σᵈ",
        // The kinetic part is averaged over the samples.
        needs: &[Need::Sampling],
        doc: "pressure from the collision virial, any boundary",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(VirialPressure::default()))
    }
}

impl<const D: usize> Observer<D> for VirialPressure {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        // r_ij = r_i - r_j = -separation; dp_i points away from j.
        self.virial -= (0..D)
            .map(|k| e.separation[k] * e.impulse_i[k])
            .sum::<f64>();
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        self.kinetic_sum += s.kinetic_energy();
        self.samples += 1;
    }
}

impl<const D: usize> Measure<D> for VirialPressure {
    fn uses_collisions(&self) -> bool {
        true
    }
    fn uses_samples(&self) -> bool {
        true
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput) {
        let d = D as f64;
        let kinetic = if self.samples > 0 {
            self.kinetic_sum / self.samples as f64
        } else {
            f64::NAN
        };
        let p = (2.0 * kinetic / d + self.virial / (d * ctx.duration)) / ctx.volume;
        out.scalars.push(("virial_pressure".into(), p));
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.number(self.virial);
        out.number(self.kinetic_sum);
        out.number(self.samples as f64);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        self.virial = from.number()?;
        self.kinetic_sum = from.number()?;
        self.samples = from.number()? as u64;
        Ok(())
    }
}
