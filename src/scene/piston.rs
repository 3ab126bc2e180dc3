//! The 1D piston: a particle of its own mass, size and starting velocity.

use super::velocities;
use crate::model::scene::{PistonSpec, Velocities};
use rand_chacha::ChaCha8Rng;

/// Where the piston sits on a line of `length`: its extent [x - R, x + R].
pub fn extent(ps: &PistonSpec, length: f64) -> Result<[f64; 2], String> {
    if !(ps.mass.is_finite() && ps.mass > 0.0) {
        return Err(format!(
            "piston.mass must be a positive number, got {}",
            ps.mass
        ));
    }
    if !(ps.radius.is_finite() && ps.radius >= 0.0) {
        return Err(format!(
            "piston.radius must be a number >= 0, got {}",
            ps.radius
        ));
    }
    let x = ps.position * length;
    if !(ps.position.is_finite() && x - ps.radius >= 0.0 && x + ps.radius <= length) {
        return Err(format!(
            "piston.position = {} puts the piston (radius {}) outside the box [0, {length}]; give a \
             fraction of the box between 0 and 1 that leaves room for its radius",
            ps.position, ps.radius
        ));
    }
    Ok([x - ps.radius, x + ps.radius])
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
        (Some(e), _) if !(e.is_finite() && e >= 0.0) => Err(format!(
            "piston.energy must be a number >= 0 (a multiple of kT), got {e}"
        )),
        (Some(e), _) => Ok((2.0 * e * kt / ps.mass).sqrt()),
        (None, Some(v)) if !v.is_finite() => {
            Err(format!("piston.velocity must be a finite number, got {v}"))
        }
        (None, Some(v)) => Ok(v),
        (None, None) => Ok(velocities::one::<D>(rule, 1.0 / ps.mass, rng)?[0]),
    }
}
