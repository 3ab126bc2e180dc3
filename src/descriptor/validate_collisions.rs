//! A run stopped by `collisions` ends only when that many pair collisions
//! have happened: in a scene where no pair can ever meet it would run (and
//! sample) forever. What is certain from the scene alone is refused here;
//! the run loop stops a run whose pairs meet far more rarely than expected.

use crate::model::descriptor::Descriptor;
use crate::model::problem::{Check, bad, compact};
use crate::model::scene::{Boundary, Drawn, SceneSpec, Velocities};
use crate::scene::check::{count, dimension, particles};

pub fn reachable(d: &Descriptor, scene: &SceneSpec) -> Check {
    let (None, Some(c)) = (d.run.duration, d.run.collisions) else {
        return Ok(());
    };
    let Some(why) = never_meet(scene) else {
        return Ok(());
    };
    bad(
        "run.collisions",
        format!(
            "no pair can ever collide ({why}), so a run stopped after {} collisions would never end",
            compact(c as f64)
        ),
        Some("stop the run by `duration` instead, or give the scene particles that can meet"),
    )
}

/// Why no pair of the scene's particles can ever collide, if that is certain.
fn never_meet(s: &SceneSpec) -> Option<String> {
    let bodies = particles(s) + usize::from(s.piston.is_some());
    let present = |i: &usize| count(s, *i) > 0;
    let species = || (0..s.species.len()).filter(present);
    if bodies < 2 {
        return Some(format!(
            "the scene has {bodies} particle{}",
            if bodies == 1 { "" } else { "s" }
        ));
    }
    let immovable = |i: usize| s.species[i].mass == Drawn::Fixed(f64::INFINITY);
    let piston_moves = s.piston.as_ref().is_some_and(|p| p.mass.is_finite());
    if species().all(immovable) && !piston_moves {
        return Some("every particle is immovable (infinite mass)".into());
    }
    let d = dimension(s);
    if d > 1 && s.piston.is_none() && species().all(|i| s.species[i].radius.bounds()[1] == 0.0) {
        return Some(format!(
            "point {} (radius 0) never meet in {d}D",
            if d == 2 { "disks" } else { "spheres" }
        ));
    }
    let still = |v: &[f64]| v.iter().all(|&x| x == 0.0);
    let piston_still = s
        .piston
        .as_ref()
        .is_none_or(|p| p.energy.is_none() && p.velocity.is_none_or(|v| v == 0.0));
    match &s.velocities {
        Some(Velocities::Equal { velocity }) if still(velocity) && piston_still => {
            Some("every velocity is zero: nothing moves".into())
        }
        Some(Velocities::Explicit { velocities })
            if velocities.iter().all(|v| still(v)) && piston_still =>
        {
            Some("every velocity is zero: nothing moves".into())
        }
        Some(Velocities::Equal { .. })
            if s.piston.is_none()
                && species().all(|i| !immovable(i))
                && s.boundary
                    .as_ref()
                    .is_some_and(|b| b.iter().all(|&x| x == Boundary::Periodic)) =>
        {
            Some(
                "every particle moves with the same velocity in a periodic box, so none gains \
                 on another"
                    .into(),
            )
        }
        _ => None,
    }
}
