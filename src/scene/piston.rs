//! The piston: a particle of its own mass, size and starting velocity (in
//! 1D a rod, above a wall along x). Its values are checked in `check`.

use super::slots::Piston;
use super::velocities;
use crate::model::scene::{PistonSpec, Velocities};
use rand_chacha::ChaCha8Rng;

/// Where the piston sits in a box of `length` along x.
pub fn at(ps: &PistonSpec, length: f64) -> Piston {
    Piston {
        x: ps.position * length,
        half: ps.radius,
        length,
    }
}

/// The piston's starting velocity: `energy` times the scene's kT, `velocity`,
/// or else drawn by the gas's rule like any particle (its x component).
pub fn velocity<const D: usize>(
    ps: &PistonSpec,
    rule: &Velocities,
    kt: f64,
    rng: &mut ChaCha8Rng,
) -> Result<f64, String> {
    match (ps.energy, ps.velocity) {
        (Some(e), _) => Ok((2.0 * e * kt / ps.mass).sqrt()),
        (None, Some(v)) => Ok(v),
        (None, None) => Ok(velocities::one::<D>(rule, 1.0 / ps.mass, rng)?[0]),
    }
}
