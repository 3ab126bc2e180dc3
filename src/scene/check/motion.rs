//! The gas's starting velocities, and whether momentum and energy can be
//! set as asked.

use super::{count, dimension, particles, vector, vectors};
use crate::model::problem::{Check, bad, positive};
use crate::model::scene::{Boundary, Drawn, SceneSpec, Velocities};

pub fn velocities(s: &SceneSpec) -> Check {
    let energy = |e: &Option<f64>| match e {
        Some(e) => positive("scene.velocities.energy", *e),
        None => Ok(()),
    };
    match &s.velocities {
        Some(Velocities::Maxwell {
            temperature,
            energy: e,
            zero_momentum,
        }) => {
            positive("scene.velocities.temperature", *temperature)?;
            energy(e)?;
            adjustable(s, *zero_momentum, *e)
        }
        Some(Velocities::Uniform {
            p,
            energy: e,
            zero_momentum,
        }) => {
            positive("scene.velocities.p", *p)?;
            energy(e)?;
            adjustable(s, *zero_momentum, *e)
        }
        Some(Velocities::Equal { velocity }) => vector("scene.velocities.velocity", velocity, s),
        Some(Velocities::Explicit { velocities }) => {
            let n = particles(s);
            if velocities.len() != n {
                return bad(
                    "scene.velocities.velocities",
                    format!("has {} entries for {n} particles", velocities.len()),
                    Some(
                        "one per particle, species by species: give one velocity per particle \
                         of each species, in the order of `[[scene.species]]` (the piston's is \
                         set in `[scene.piston]`)",
                    ),
                );
            }
            vectors("scene.velocities.velocities", velocities, s)
        }
        None => Ok(()),
    }
}

/// Zero momentum and an exact energy need particles that move: some at all,
/// and for an energy with zero momentum more than one (a single particle
/// has no motion about the mean to rescale).
fn adjustable(s: &SceneSpec, zero_momentum: bool, energy: Option<f64>) -> Check {
    if !zero_momentum && energy.is_none() {
        return Ok(());
    }
    let movable: usize = (0..s.species.len())
        .filter(|&i| s.species[i].mass != Drawn::Fixed(f64::INFINITY))
        .map(|i| count(s, i))
        .sum();
    let key = match energy {
        Some(_) => "scene.velocities.energy",
        None => "scene.velocities.zero_momentum",
    };
    if movable == 0 {
        return bad(
            key,
            "cannot set the momentum or energy of the gas: no particle can move (every one has infinite mass)",
            Some("drop `energy` and `zero_momentum`, or give some species a finite mass"),
        );
    }
    if let (true, Some(e), 1) = (zero_momentum, energy, movable) {
        return bad(
            key,
            format!(
                "cannot rescale to energy {e}: with zero_momentum the one movable particle has no \
                 motion about the mean, so its velocities are all zero"
            ),
            Some("give more than one movable particle, or drop `zero_momentum`"),
        );
    }
    match (zero_momentum, energy) {
        (true, Some(e)) => balances_piston(s, e, movable),
        _ => Ok(()),
    }
}

/// With zero momentum the gas drifts against the piston's momentum, which
/// takes kinetic energy M U^2 / 2 of its own (M the gas's mass): the energy
/// asked for must exceed it. Known before the draws when the piston's start
/// is given (`velocity`, or `energy` in units of the kT that the gas's energy
/// sets); masses drawn from a range count at their largest, which drifts
/// least. The arithmetic is the builder's (`velocities::adjust`).
fn balances_piston(s: &SceneSpec, e: f64, movable: usize) -> Check {
    let Some(p) = &s.piston else { return Ok(()) };
    let all_periodic = s
        .boundary
        .as_ref()
        .is_some_and(|b| b.iter().all(|&x| x == Boundary::Periodic));
    let free = (movable.saturating_sub(usize::from(all_periodic)) * dimension(s)).max(1);
    let v = match (p.energy, p.velocity) {
        (Some(energy), _) => (2.0 * energy * (2.0 * e / free as f64) / p.mass).sqrt(),
        (None, Some(v)) => v,
        (None, None) => return Ok(()),
    };
    let mut mass = 0.0;
    for (i, sp) in s.species.iter().enumerate() {
        let m = sp.mass.bounds()[1];
        if m != f64::INFINITY {
            for _ in 0..count(s, i) {
                mass += 1.0 / (1.0 / m);
            }
        }
    }
    let drift = -(p.mass * v) / mass;
    let bulk = 0.5 * mass * (drift * drift);
    if e > bulk {
        return Ok(());
    }
    bad(
        "scene.velocities.energy",
        format!(
            "{e} is too small: balancing the piston's momentum alone gives the gas a kinetic \
             energy of {bulk}"
        ),
        Some("ask for more energy, or drop `zero_momentum`"),
    )
}
