//! Observables a study can ask for, by name: one file each, listed in
//! `catalogue.rs`. Only the named ones are built, and each hook is only called
//! on the observers that use it, so an observable nobody asked for costs
//! nothing per event; the sampled ones share one sampling pass.

mod blocks;
pub mod catalogue;
mod entry;
pub mod film;
mod histogram;
mod lags;
mod neighbours;
mod per_particle;
mod sampled;
mod set;
pub mod state;
#[cfg(test)]
mod tests;
pub mod trajectory;

mod density_x;
mod energy_autocorrelation;
mod energy_concentration;
mod energy_share;
mod energy_x;
mod gas_energy_by_side;
mod kinetic_energy;
mod kinetic_energy_by_species;
mod left_fraction;
mod mean_squared_displacement;
mod pair_distance;
mod piston_position;
mod position_x_each;
mod positions;
mod psi6;
mod q6;
mod scaled_speed;
mod scaled_velocity_x;
mod side_counts;
mod speed_spread;
mod temperature;
mod temperature_x;
mod velocities;
mod velocity_x_each;
mod velocity_x_halves;
mod virial_pressure;
mod virial_pressure_series;
mod wall_heat;
mod wall_pressure;
mod wall_pressure_series;

use crate::engine::Observer;
use crate::model::run_output::RunOutput;

pub use catalogue::CATALOGUE;
pub use entry::{Entry, Kind, Observable, Part, Probe, Setup};
pub use sampled::Row;
pub use set::ObserverSet;
pub use state::{StateIn, StateOut};

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
    /// Append what it has accumulated, for a checkpoint; false if it cannot
    /// (then its runs are not checkpointed, and start over when stopped).
    fn save(&self, _out: &mut StateOut) -> bool {
        false
    }
    /// Take on a state `save` wrote, as if it had seen those events.
    fn restore(&mut self, _from: &mut StateIn) -> Result<(), String> {
        Err("this observer cannot be restored".into())
    }
}

/// Build the observers for the named observables; an unknown name is an
/// error. Results are written in a fixed order: the observers of their own
/// (series, then scalars, then histograms, each in the order named), then
/// what the shared sampling pass read.
pub fn build<const D: usize>(
    series: &[String],
    scalars: &[String],
    histograms: &[String],
    piston: Option<usize>,
) -> Result<ObserverSet<D>, String> {
    let setup = Setup { piston };
    let mut measures: Vec<Box<dyn Measure<D>>> = Vec::new();
    let mut sampled = sampled::Sampled::default();
    for (kind, names) in [
        (Kind::Series, series),
        (Kind::Scalars, scalars),
        (Kind::Histograms, histograms),
    ] {
        for name in names {
            let part = catalogue::part::<D>(kind, name, &setup).ok_or_else(|| {
                format!(
                    "unknown {} observable `{name}`; known: {}",
                    kind.key(),
                    catalogue::names(kind).join(", ")
                )
            })?;
            match part {
                Part::Observer(m) => measures.push(m),
                Part::Series(p) => sampled.add(p, false),
                Part::Mean(p) => sampled.add(p, true),
            }
        }
    }
    if !sampled.is_empty() {
        measures.push(Box::new(sampled));
    }
    Ok(ObserverSet::new(measures))
}
