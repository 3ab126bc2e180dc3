//! The piston: where it may slide, its mass, size, place and start.
//! (Whether the gases keep clear of it is a matter of room: `layout`.)

use super::motion::MAX_ENERGY;
use super::{dimension, mass};
use crate::model::problem::{Check, bad, compact, non_negative};
use crate::model::scene::{Boundary, Placement, SceneSpec, Velocities};

pub fn piston(s: &SceneSpec) -> Check {
    let Some(p) = &s.piston else { return Ok(()) };
    let d = dimension(s);
    let periodic_x = s
        .boundary
        .as_ref()
        .is_some_and(|b| b.first() == Some(&Boundary::Periodic));
    if d > 1 && periodic_x {
        return bad(
            "scene.boundary",
            "is periodic along x, but a piston wall slides along x between walls",
            Some("make the first entry \"walls\""),
        );
    }
    if d > 1 && matches!(s.placement, Some(Placement::Compress { .. })) {
        return bad(
            "scene.placement",
            "compression cannot grow particles around a piston wall",
            Some("place the gases with `kind = \"random\"` or `kind = \"lattice\"` on either side"),
        );
    }
    mass("scene.piston.mass", p.mass, None)?;
    non_negative("scene.piston.radius", p.radius)?;
    let length = s
        .box_size
        .as_ref()
        .and_then(|b| b.first().copied())
        .unwrap_or(f64::NAN);
    // A piston wider than the box fits at no position: its radius is at fault.
    if 2.0 * p.radius > length {
        return bad(
            "scene.piston.radius",
            format!(
                "{} is more than half the box length {}: the piston fits nowhere",
                compact(p.radius),
                compact(length)
            ),
            Some("a piston is a thin wall; its radius is small beside the box, e.g. 0 or 0.5"),
        );
    }
    let x = p.position * length;
    let inside =
        p.position > 0.0 && p.position < 1.0 && x - p.radius >= 0.0 && x + p.radius <= length;
    if !inside {
        return bad(
            "scene.piston.position",
            format!(
                "must be a fraction of the box between 0 and 1 that keeps the piston (radius {}) \
                 inside: at {} it is outside the box [0, {}]",
                compact(p.radius),
                compact(p.position),
                compact(length)
            ),
            None,
        );
    }
    if let Some(v) = p.velocity
        && !v.is_finite()
    {
        return bad(
            "scene.piston.velocity",
            format!("must be a finite number, got {}", compact(v)),
            None,
        );
    }
    if let Some(e) = p.energy {
        non_negative("scene.piston.energy", e)?;
        // In units of the scene's kT (the gas's temperature where it is given).
        let kt = match &s.velocities {
            Some(Velocities::Maxwell {
                temperature,
                energy: None,
                ..
            }) => *temperature,
            _ => 1.0,
        };
        if e * kt > MAX_ENERGY {
            return bad(
                "scene.piston.energy",
                format!(
                    "{} kT is a kinetic energy of {}, more than the {} a run can carry",
                    compact(e),
                    compact(e * kt),
                    compact(MAX_ENERGY)
                ),
                Some("the piston's energy is a multiple of the scene's kT, e.g. `energy = 10.0`"),
            );
        }
    }
    if let Some(v) = p.velocity
        && 0.5 * p.mass * v * v > MAX_ENERGY
    {
        return bad(
            "scene.piston.velocity",
            format!(
                "gives the piston (mass {}) a kinetic energy of {}, more than the {} a run can carry",
                compact(p.mass),
                compact(0.5 * p.mass * v * v),
                compact(MAX_ENERGY)
            ),
            Some("work in reduced units: speeds about sqrt(kT / mass)"),
        );
    }
    Ok(())
}
