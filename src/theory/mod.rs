//! Theory predictions, one file each, set beside measurements in the summary.

pub mod adiabat;
pub mod carnahan_starling;
pub mod carnahan_starling_kolafa;
pub mod disk_virial;
pub mod expansion;
pub mod expansion_rods;
pub mod hansen_goos;
pub mod heat;
pub mod heat_free;
pub mod henderson;
pub mod kolafa_rottner;
pub mod maxwell;
pub mod microcanonical;
pub mod mixing;
pub mod ordered_rods;
pub mod piston;
pub mod piston_equilibrium;
pub mod piston_exchange;
pub mod piston_room;
pub mod self_diffusion;
pub mod sphere_virial;
pub mod tonks;
pub mod virial_series;
