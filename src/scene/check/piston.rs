//! The piston: where it may slide, its mass, size, place and start.
//! (Whether the gases keep clear of it is a matter of room: `layout`.)

use super::{dimension, mass};
use crate::model::problem::{Check, bad, non_negative};
use crate::model::scene::{Boundary, Placement, SceneSpec};

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
    let x = p.position * length;
    let inside =
        p.position > 0.0 && p.position < 1.0 && x - p.radius >= 0.0 && x + p.radius <= length;
    if !inside {
        return bad(
            "scene.piston.position",
            format!(
                "must be a fraction of the box between 0 and 1 that keeps the piston (radius {}) \
                 inside: at {} it is outside the box [0, {length}]",
                p.radius, p.position
            ),
            None,
        );
    }
    if let Some(v) = p.velocity
        && !v.is_finite()
    {
        return bad(
            "scene.piston.velocity",
            format!("must be a finite number, got {v}"),
            None,
        );
    }
    if let Some(e) = p.energy {
        non_negative("scene.piston.energy", e)?;
    }
    Ok(())
}
