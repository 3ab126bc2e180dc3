//! The error model of the 1D mixing time (the hot rod's energy spread to
//! 1/e of its excess over equipartition's concentration).
//!
//! A first passage of a chaotic transient: a run longer than the mixing buys
//! nothing (exponent 0), only replicas do; a run too short to mix gives no
//! time at all (the study counts it apart). One run's relative scatter is
//! of order one (the times are spread like a waiting time) and narrows
//! with the number of rods; it is taken as measured by the accuracy study's
//! `headline-mixing-n*` cases (masses uniform in [1, 1.3], hot rod of mass
//! 1, seed 15, 32 replicas each) at 10, 20 and 40 rods, read between them
//! on log-log axes and held beyond. Its dependence on the mass spread is
//! weak where measured (ε 0.1–1 at 20 and 40 rods) and not modelled.

use crate::model::descriptor::Descriptor;
use crate::model::scene::Mass;
use crate::stats::error_model::{ErrorModel, log_interpolate, within};

/// Rods (the hot one included) and one run's relative scatter, measured.
const RODS: [f64; 3] = [10.0, 20.0, 40.0];
/// (10 rods: two run lengths pooled, 64 runs; 32 at the others.)
const SCATTER: [f64; 3] = [0.65, 0.475, 0.328];
/// The largest relative ± of those (from each point's fourth moment: the
/// times have a long tail).
const UNCERTAINTY: f64 = 0.16;

pub fn error_model(d: &Descriptor) -> Option<ErrorModel> {
    let scene = crate::scene::resolve(&d.scene).ok()?;
    if scene.dimension().ok()? != 1 || scene.piston.is_none() {
        return None;
    }
    // Equal masses never mix: no time to scatter.
    let spread = scene
        .species
        .iter()
        .any(|s| matches!(s.mass, Mass::Range([lo, hi]) if hi > lo));
    if !spread {
        return None;
    }
    let n = (scene.species.iter().map(|s| s.count).sum::<usize>() + 1) as f64;
    Some(ErrorModel {
        result: "mixing_time",
        label: "mixing time",
        scatter: log_interpolate(&RODS, &SCATTER, n),
        uncertainty: UNCERTAINTY,
        length_exponent: 0.0,
        basis: format!(
            "one run's scatter measured at 10, 20 and 40 rods with masses in [1, 1.3] (accuracy study), read at \
             {n} rods{}; the mass spread is not modelled",
            if within(&RODS, n) {
                ""
            } else {
                " (outside: the nearest)"
            }
        ),
    })
}
