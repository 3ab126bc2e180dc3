//! The error model of Z from the collision virial (periodic boxes).
//!
//! Z − 1 = W / (d N kT), W the pair collisions' virial per unit time. Were
//! collisions independent (Poisson, rate R, virials b = σ|Δp|), a mean over
//! a time T would scatter by (Z − 1) √((1 + cv²) / (R T)), cv the relative
//! spread of b. The normal relative speed of a colliding pair is Rayleigh
//! distributed, so 1 + cv² = ⟨v²⟩/⟨v⟩² = 4/π in any dimension, and
//! Z − 1 = Γ σ √(π m / kT) / (2d), Γ = 2R/N, gives R. In units of σ, m, kT:
//!
//! ```text
//! σ_Z = c √(4 (Z − 1) / (√π d N T))
//! ```
//!
//! with c = 1 for uncorrelated collisions; `CORRELATION` is c as measured.
//! Pilot runs of 256 spheres gave c = 0.96-1.10 (± 0.18) at η = 0.1-0.45
//! but 2.1 at freezing (0.494): the model stops at the densities measured,
//! and walls, whose impulses it does not describe, get none.

use super::{equations, packing};
use crate::model::descriptor::Descriptor;
use crate::model::scene::{Drawn, Mass};
use crate::scene::velocities::maxwell_temperature;
use crate::stats::error_model::ErrorModel;
use std::f64::consts::PI;

/// c measured by studies/accuracy.toml's `headline-pressure-*` cases (seed
/// 15, 32 replicas each): 1.01, 1.05 and 1.18 (± 0.13 each) for 256 disks
/// at η = 0.3 over 50, 200 and 800 time units, 0.95 ± 0.14 for 64 disks at
/// η = 0.6, 1.05 ± 0.15 for 256 spheres at η = 0.3 (200 time units); their
/// mean, and its relative uncertainty.
pub const CORRELATION: f64 = 1.05;
const UNCERTAINTY: f64 = 0.065;
/// Packing fractions up to which c was measured (2D, 3D; none in 1D).
const MEASURED_UP_TO: [f64; 3] = [0.0, 0.6, 0.45];

pub fn error_model(d: &Descriptor) -> Option<ErrorModel> {
    let s = packing::described(d)?;
    let dim = s.dimension;
    if dim < 2 || s.scene.piston.is_some() || s.walls {
        return None;
    }
    let eta = packing::of_scene(&s.scene)?;
    // Beyond the densities measured the correlation times grow.
    if eta > MEASURED_UP_TO[dim.min(3) - 1] + 1e-6 {
        return None;
    }
    let n = s.particles;
    let (Some(species), true) = (s.scene.species.first(), n > 0) else {
        return None;
    };
    let (Drawn::Fixed(r), Mass::Fixed(m)) = (species.radius, species.mass) else {
        return None;
    };
    let kt = maxwell_temperature(s.scene.velocities.as_ref()).unwrap_or(1.0);
    let time = d.run.duration? * (kt / m).sqrt() / (2.0 * r);
    let reference = &equations::of(dim)[0];
    let z = (reference.z)(eta);
    let sigma = CORRELATION * (4.0 * (z - 1.0) / (PI.sqrt() * dim as f64 * n as f64 * time)).sqrt();
    let scatter = sigma / z;
    (scatter.is_finite() && scatter > 0.0).then(|| ErrorModel {
        result: "Z",
        label: "Z",
        scatter,
        uncertainty: UNCERTAINTY,
        length_exponent: -0.5,
        basis: format!(
            "virial of uncorrelated collisions, σ_Z = c √(4(Z−1)/(√π d N T)), Z from {} at η = {eta:.3}, \
             correlation factor c = {CORRELATION} measured for disks at η = 0.3 and 0.6 (accuracy study) \
             and spheres at 0.1-0.45; no model at higher density",
            reference.name
        ),
    })
}
