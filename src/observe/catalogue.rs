//! Every observable a descriptor may name, one line each, in the order
//! `study list` and docs/descriptor.md show them. Adding an observable is
//! its file in this folder (a type implementing `Observable`) and its line
//! here.

use super::density_x::DensityX;
use super::energy_autocorrelation::EnergyAutocorrelation;
use super::energy_concentration::EnergyConcentration;
use super::energy_share::EnergyShare;
use super::energy_x::EnergyX;
use super::entry::{Entry, Kind, Observable, Part, Setup};
use super::gas_energy_by_side::GasEnergyBySide;
use super::kinetic_energy::KineticEnergy;
use super::kinetic_energy_by_species::KineticEnergyBySpecies;
use super::left_fraction::LeftFraction;
use super::mean_squared_displacement::Msd;
use super::pair_distance::PairDistance;
use super::piston_position::PistonPosition;
use super::position_x_each::PositionXEach;
use super::positions::Positions;
use super::psi6::{Psi6, Psi6Series};
use super::q6::{Q6, Q6Series};
use super::scaled_speed::ScaledSpeed;
use super::scaled_velocity_x::ScaledVelocityX;
use super::side_counts::SideCounts;
use super::speed_spread::SpeedSpread;
use super::temperature::{MeanTemperature, Temperature};
use super::temperature_x::TemperatureX;
use super::velocities::Velocities;
use super::velocity_x_each::VelocityXEach;
use super::velocity_x_halves::VelocityXHalves;
use super::virial_pressure::VirialPressure;
use super::virial_pressure_series::VirialPressureSeries;
use super::wall_heat::WallHeat;
use super::wall_pressure::WallPressure;
use super::wall_pressure_series::WallPressureSeries;
use crate::model::need::Need;

/// Builds one observable's part in dimension `D`.
type Make<const D: usize> = fn(&Setup) -> Part<D>;

/// From one list of types: `CATALOGUE` (their entries) and `make` (their
/// builders, in the same order, for any dimension).
macro_rules! catalogue {
    ($($observable:ty),* $(,)?) => {
        /// Every observable, with what it is and needs.
        pub const CATALOGUE: &[Entry] = &[$(<$observable as Observable>::ENTRY),*];

        /// The builder of `CATALOGUE[index]`.
        fn make<const D: usize>(index: usize) -> Make<D> {
            let makers: &[Make<D>] = &[$(<$observable as Observable>::part::<D>),*];
            makers[index]
        }
    };
}

catalogue![
    KineticEnergy,
    KineticEnergyBySpecies,
    Temperature,
    PistonPosition,
    GasEnergyBySide,
    Positions,
    Velocities,
    SpeedSpread,
    LeftFraction,
    WallPressureSeries,
    VirialPressureSeries,
    WallPressure,
    VirialPressure,
    MeanTemperature,
    WallHeat,
    ScaledVelocityX,
    EnergyShare,
    EnergyConcentration,
    EnergyAutocorrelation,
    SideCounts,
    Msd,
    VelocityXEach,
    VelocityXHalves,
    PositionXEach,
    ScaledSpeed,
    DensityX,
    EnergyX,
    PairDistance,
    TemperatureX,
    Psi6Series,
    Psi6,
    Q6Series,
    Q6,
];

/// The entry a descriptor means by `name` under `[observe] <kind>`.
pub fn find(kind: Kind, name: &str) -> Option<&'static Entry> {
    CATALOGUE.iter().find(|e| e.kind == kind && e.name == name)
}

/// The names a descriptor may list under `[observe] <kind>`.
pub fn names(kind: Kind) -> Vec<&'static str> {
    CATALOGUE
        .iter()
        .filter(|e| e.kind == kind)
        .map(|e| e.name)
        .collect()
}

/// How a run of dimension `D` computes the observable `name` of `kind`.
pub fn part<const D: usize>(kind: Kind, name: &str, setup: &Setup) -> Option<Part<D>> {
    let index = CATALOGUE
        .iter()
        .position(|e| e.kind == kind && e.name == name)?;
    Some(make::<D>(index)(setup))
}

/// The axis label and unit of a name an observable writes to a table
/// (`kinetic_energy.light` -> "kinetic energy of light", "kT").
pub fn label(written: &str) -> Option<(String, &'static str)> {
    CATALOGUE.iter().find_map(|e| {
        let parts = matches(e.writes, written)?;
        let mut label = e.label.to_string();
        for (hole, value) in parts {
            label = label.replace(&format!("<{hole}>"), value);
        }
        Some((label, e.unit))
    })
}

/// What a need asks of the descriptor, as `study list` and the docs say it.
pub fn need_text(need: Need) -> String {
    match need {
        Need::Sampling => "`sample_every`".into(),
        Need::Piston => "a piston".into(),
        Need::Walls => "a walled axis".into(),
        Need::ThermalWalls => "a thermal wall".into(),
        Need::Dimension(d) => format!("a {d}D scene"),
        Need::Neighbours(k) => format!("more than {k} particles"),
    }
}

/// The values of the `<...>` parts of `pattern` in `name`, in order, if
/// `name` is one of the names the pattern stands for. A part is a non-empty
/// run without dots; `<a|b>` is one of the words a, b.
pub fn matches<'a, 'p>(pattern: &'p str, name: &'a str) -> Option<Vec<(&'p str, &'a str)>> {
    let mut parts = Vec::new();
    fill(pattern, name, &mut parts).then_some(parts)
}

fn fill<'a, 'p>(pattern: &'p str, name: &'a str, parts: &mut Vec<(&'p str, &'a str)>) -> bool {
    let Some((literal, rest)) = pattern.split_once('<') else {
        return pattern == name;
    };
    let Some((hole, rest)) = rest.split_once('>') else {
        return false;
    };
    let Some(tail) = name.strip_prefix(literal) else {
        return false;
    };
    for (end, c) in tail.char_indices() {
        if c == '.' {
            break;
        }
        let end = end + c.len_utf8();
        let value = &tail[..end];
        if hole.contains('|') && !hole.split('|').any(|w| w == value) {
            continue;
        }
        parts.push((hole, value));
        if fill(rest, &tail[end..], parts) {
            return true;
        }
        parts.pop();
    }
    false
}
