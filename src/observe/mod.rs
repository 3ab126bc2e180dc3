//! Observers a study can ask for, by name. Only the named ones are built, and
//! each hook is only called on the observers that use it, so an observable
//! nobody asked for costs nothing per event.

mod heat;
mod histogram;
mod pressure;
mod sampled;
mod sides;

use crate::engine::{Observer, PairCollision, Snapshot, WallHit};
use crate::model::run_output::RunOutput;

pub use heat::WallHeat;
pub use histogram::ScaledVelocity;
pub use pressure::{VirialPressure, WallPressure};
pub use sampled::Sampled;
pub use sides::SideEnergies;

/// What a measurement needs to know about the run when it reports.
pub struct Context<'a> {
    pub species: &'a [String],
    pub piston: Option<usize>,
    /// Measurement time (after equilibration).
    pub duration: f64,
    pub volume: f64,
    /// Total area of the walls: two walls of area V / L_k per walled axis.
    pub wall_area: f64,
    pub dimension: usize,
    /// Degrees of freedom: d N with walls, d (N - 1) when momentum is conserved.
    pub degrees_of_freedom: f64,
}

/// An observer that, at the end, writes what it measured into the run output.
pub trait Measure<const D: usize>: Observer<D> + Send {
    fn uses_collisions(&self) -> bool {
        false
    }
    fn uses_walls(&self) -> bool {
        false
    }
    fn uses_samples(&self) -> bool {
        false
    }
    fn finish(self: Box<Self>, ctx: &Context, out: &mut RunOutput);
}

/// The observers of one run, split by the hooks they use.
pub struct ObserverSet<const D: usize> {
    measures: Vec<Box<dyn Measure<D>>>,
    on_collision: Vec<usize>,
    on_wall: Vec<usize>,
    on_sample: Vec<usize>,
    /// Off during equilibration.
    pub recording: bool,
}

impl<const D: usize> ObserverSet<D> {
    pub fn new(measures: Vec<Box<dyn Measure<D>>>) -> Self {
        let pick = |f: &dyn Fn(&dyn Measure<D>) -> bool| {
            (0..measures.len())
                .filter(|&i| f(measures[i].as_ref()))
                .collect()
        };
        ObserverSet {
            on_collision: pick(&|m| m.uses_collisions()),
            on_wall: pick(&|m| m.uses_walls()),
            on_sample: pick(&|m| m.uses_samples()),
            measures,
            recording: false,
        }
    }

    pub fn finish(self, ctx: &Context, out: &mut RunOutput) {
        for m in self.measures {
            m.finish(ctx, out);
        }
    }
}

impl<const D: usize> Observer<D> for ObserverSet<D> {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        if self.recording {
            for &i in &self.on_collision {
                self.measures[i].pair_collision(e);
            }
        }
    }
    fn wall_hit(&mut self, e: &WallHit<D>) {
        if self.recording {
            for &i in &self.on_wall {
                self.measures[i].wall_hit(e);
            }
        }
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        if self.recording {
            for &i in &self.on_sample {
                self.measures[i].sample(s);
            }
        }
    }
}

/// Every observable name a descriptor may use, with what it gives.
pub const CATALOGUE: &[(&str, &str, &str)] = &[
    ("series", "kinetic_energy", "total kinetic energy"),
    (
        "series",
        "kinetic_energy_by_species",
        "kinetic energy of each species (kinetic_energy.<name>)",
    ),
    (
        "series",
        "temperature",
        "kT from kinetic energy over the free degrees of freedom",
    ),
    ("series", "piston_position", "position of the piston"),
    (
        "series",
        "gas_energy_by_side",
        "kinetic energy of the gas left and right of the piston (gas_energy.<side>)",
    ),
    (
        "series",
        "positions",
        "x coordinate of every particle (x.<index>), for space-time diagrams",
    ),
    (
        "series",
        "left_fraction",
        "fraction of particles in the left half of the box",
    ),
    (
        "scalars",
        "wall_pressure",
        "time-averaged force per unit wall area (with walls)",
    ),
    (
        "scalars",
        "virial_pressure",
        "pressure from the collision virial (any boundary)",
    ),
    (
        "scalars",
        "temperature",
        "time-averaged kT (needs sampling)",
    ),
    (
        "scalars",
        "wall_heat",
        "energy each wall gave the particles over the run (heat_in.axis<k>.<low|high>; needs thermal walls)",
    ),
    (
        "histograms",
        "scaled_velocity_x",
        "sqrt(m) v_x of every particle at every sample, in units of sqrt(kT)",
    ),
];

/// Build the observers for the named observables.
pub fn build<const D: usize>(
    series: &[String],
    scalars: &[String],
    histograms: &[String],
    piston: Option<usize>,
) -> Result<ObserverSet<D>, String> {
    let check = |kind: &str, name: &String| {
        if CATALOGUE.iter().any(|(k, n, _)| *k == kind && n == name) {
            Ok(())
        } else {
            let known: Vec<&str> = CATALOGUE
                .iter()
                .filter(|(k, _, _)| *k == kind)
                .map(|(_, n, _)| *n)
                .collect();
            Err(format!(
                "unknown {kind} observable `{name}`; known: {}",
                known.join(", ")
            ))
        }
    };
    let mut measures: Vec<Box<dyn Measure<D>>> = Vec::new();
    let mut sampled: Vec<String> = Vec::new();
    for name in series {
        check("series", name)?;
        match name.as_str() {
            "gas_energy_by_side" => measures.push(Box::new(SideEnergies::new(piston))),
            _ => sampled.push(name.clone()),
        }
    }
    for name in scalars {
        check("scalars", name)?;
        match name.as_str() {
            "wall_pressure" => measures.push(Box::new(WallPressure::default())),
            "virial_pressure" => measures.push(Box::new(VirialPressure::<D>::default())),
            "wall_heat" => measures.push(Box::new(WallHeat::<D>::default())),
            _ => sampled.push(format!("mean:{name}")),
        }
    }
    for name in histograms {
        check("histograms", name)?;
        measures.push(Box::new(ScaledVelocity::default()));
    }
    if !sampled.is_empty() {
        measures.push(Box::new(Sampled::new(sampled, piston)));
    }
    Ok(ObserverSet::new(measures))
}
