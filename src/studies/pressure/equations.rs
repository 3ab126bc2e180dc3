//! The equations of state each dimension is compared with: the first is the
//! run's theory in the summary (its z-score), the others are shown beside it.

use crate::theory::{carnahan_starling, disk_virial, henderson, kolafa_labik_malijevsky, tonks};

/// One equation of state, Z(eta).
pub struct Equation {
    pub name: &'static str,
    pub z: fn(f64) -> f64,
    /// Packing fraction up to which it is expected to be within ~1e-3 of
    /// the equilibrium fluid's Z (and the fluid to be the stable phase);
    /// the report flags points beyond it.
    pub holds_below: f64,
}

fn disk_series(eta: f64) -> f64 {
    disk_virial::z(eta, 10)
}

const RODS: &[Equation] = &[Equation {
    name: "Tonks (exact)",
    z: tonks::z,
    holds_below: 1.0,
}];

const DISKS: &[Equation] = &[
    Equation {
        name: "Henderson 1975",
        z: henderson::z,
        holds_below: 0.4,
    },
    Equation {
        name: "virial series to B10",
        // The terms left out are ~1e-4 of Z at 0.3, 2e-3 at 0.4.
        z: disk_series,
        holds_below: 0.35,
    },
];

const SPHERES: &[Equation] = &[
    Equation {
        name: "Kolafa-Labík-Malijevský 2004",
        // Freezing: above it the stable phase is the crystal.
        z: kolafa_labik_malijevsky::z,
        holds_below: 0.494,
    },
    Equation {
        name: "Carnahan-Starling",
        // 1.3e-3 below Kolafa-Labik-Malijevsky at 0.2, 2.6e-3 at 0.3.
        z: carnahan_starling::z,
        holds_below: 0.2,
    },
];

/// The equations for dimension `d` (1, 2 or 3), the summary's first.
pub fn of(d: usize) -> &'static [Equation] {
    match d {
        1 => RODS,
        2 => DISKS,
        _ => SPHERES,
    }
}
