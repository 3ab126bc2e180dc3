//! The equations of state each dimension is compared with: the first is the
//! run's theory in the summary (its z-score), the others are shown beside it.
//! Where each holds is checked in docs/pressure.md.

use crate::theory::{
    carnahan_starling, carnahan_starling_kolafa, disk_virial, hansen_goos, henderson,
    kolafa_rottner, sphere_virial, tonks,
};

/// One equation of state, Z(eta).
pub struct Equation {
    pub name: &'static str,
    pub z: fn(f64) -> f64,
    /// Packing fraction up to which it is expected to be within ~1e-3 of
    /// the equilibrium fluid's Z; the report flags points beyond it.
    pub holds_below: f64,
    /// Packing fraction beyond which the formula means nothing at all (a
    /// fit's range); charts never draw it further.
    pub defined_below: f64,
}

const fn eq(name: &'static str, z: fn(f64) -> f64, holds_below: f64) -> Equation {
    Equation {
        name,
        z,
        holds_below,
        defined_below: f64::INFINITY,
    }
}

const RODS: &[Equation] = &[eq("Tonks (exact)", tonks::z, 1.0)];

const DISKS: &[Equation] = &[
    // Fitted to the fluid's simulations up to 0.707 (rho sigma^2 = 0.90;
    // beyond, its x^57 term explodes), the last 0.008 of which may keep
    // finite-size effects; the fluid ends at 0.700. Checked here to 0.68:
    // at 0.69 1024 disks sit 0.1 % above it.
    Equation {
        defined_below: 0.707,
        ..eq("Kolafa-Rottner 2006", kolafa_rottner::z, 0.681)
    },
    // The estimated tail is 5e-5 of Z at 0.3, 7e-4 at 0.4, 0.6 % at 0.5.
    eq("virial series to B10 + tail", disk_virial::resummed, 0.4),
    // 2.5e-4 above the resummed series at 0.3, 1.4e-3 at 0.4.
    eq("Henderson 1975", henderson::z, 0.35),
];

const SPHERES: &[Equation] = &[
    // Built on B2-B10 and fitted to the fluid's simulations; the stable
    // fluid ends at freezing.
    eq("Hansen-Goos 2016", hansen_goos::z, 0.494),
    // Within 1e-4 of Hansen-Goos up to 0.4, 6e-4 below it at 0.49.
    eq(
        "Carnahan-Starling-Kolafa",
        carnahan_starling_kolafa::z,
        0.494,
    ),
    // The estimated tail is 3e-4 of Z at 0.3, 1.2e-3 at 0.35.
    eq("virial series to B10 + tail", sphere_virial::resummed, 0.35),
    // 1.3e-3 below Hansen-Goos at 0.2, 2.5e-3 at 0.3.
    eq("Carnahan-Starling", carnahan_starling::z, 0.2),
];

/// The equations for dimension `d` (1, 2 or 3), the summary's first.
pub fn of(d: usize) -> &'static [Equation] {
    match d {
        1 => RODS,
        2 => DISKS,
        _ => SPHERES,
    }
}
