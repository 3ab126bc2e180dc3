//! The gas's starting velocities, and whether momentum and energy can be
//! set as asked.

use super::{count, dimension, particles, vector, vectors};
use crate::model::problem::{Check, bad, compact, positive};
use crate::model::scene::{Boundary, Drawn, SceneSpec, Velocities};

/// The largest kinetic energy a scene may start with, in units of kT = 1.
/// Observers square energies (fluctuations, autocorrelations), and squares
/// of more than about 1e154 are infinite; time units make any larger
/// scale needless (kT = 1e10 is kT = 1 seen 1e5 times faster).
pub const MAX_ENERGY: f64 = 1e150;

pub fn velocities(s: &SceneSpec) -> Check {
    drawn(s)?;
    energy_fits(s)
}

fn drawn(s: &SceneSpec) -> Check {
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

/// The gas's kinetic energy at the start, as its velocities ask, must be
/// finite and at most `MAX_ENERGY`. A mass drawn from a range counts at its
/// largest; immovable particles carry none.
fn energy_fits(s: &SceneSpec) -> Check {
    let d = dimension(s) as f64;
    let n = particles(s) as f64;
    let heaviest = |i: usize| match s.species[i].mass.bounds()[1] {
        m if m.is_finite() => m,
        _ => 0.0,
    };
    let lightest = (0..s.species.len())
        .map(|i| s.species[i].mass.bounds()[0])
        .fold(f64::INFINITY, f64::min);
    let per_species = |f: &dyn Fn(usize) -> f64| -> f64 {
        (0..s.species.len())
            .map(|i| count(s, i) as f64 * f(i))
            .sum()
    };
    let (key, e) = match &s.velocities {
        Some(Velocities::Maxwell {
            energy: Some(e), ..
        })
        | Some(Velocities::Uniform {
            energy: Some(e), ..
        }) => ("scene.velocities.energy", *e),
        Some(Velocities::Maxwell { temperature, .. }) => {
            ("scene.velocities.temperature", 0.5 * d * n * temperature)
        }
        // Each component's momentum up to p: energy up to d p^2 / (2 m).
        Some(Velocities::Uniform { p, .. }) => {
            ("scene.velocities.p", 0.5 * d * n * (p * p) / lightest)
        }
        Some(Velocities::Equal { velocity }) => {
            let v2: f64 = velocity.iter().map(|v| v * v).sum();
            (
                "scene.velocities.velocity",
                0.5 * v2 * per_species(&heaviest),
            )
        }
        Some(Velocities::Explicit { velocities }) => {
            let masses =
                (0..s.species.len()).flat_map(|i| std::iter::repeat_n(heaviest(i), count(s, i)));
            let e = velocities
                .iter()
                .zip(masses)
                .map(|(v, m)| 0.5 * m * v.iter().map(|x| x * x).sum::<f64>())
                .sum();
            ("scene.velocities.velocities", e)
        }
        None => ("scene.velocities", 0.5 * d * n),
    };
    if e <= MAX_ENERGY {
        return Ok(());
    }
    bad(
        key,
        format!(
            "gives the gas a kinetic energy of {}, more than the {} a run can carry",
            compact(e),
            compact(MAX_ENERGY)
        ),
        Some(
            "work in reduced units (kT about 1, speeds about 1): a larger temperature only makes \
             time run faster",
        ),
    )
}
