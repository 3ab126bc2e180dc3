//! Initial velocities: Maxwellian, uniform momenta, all equal, or explicit;
//! optionally with zero total momentum and the gas rescaled to an exact
//! energy. Immovable particles (inverse mass 0) stay at rest. The rule's
//! values are checked in `check`.

use crate::engine::thermal::gaussian;
use crate::model::scene::Velocities;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// Velocities as the rule draws them, for particles with these inverse masses.
pub fn draw<const D: usize>(
    spec: &Velocities,
    inv_mass: &[f64],
    rng: &mut ChaCha8Rng,
) -> Result<Vec<[f64; D]>, String> {
    if let Velocities::Explicit { velocities } = spec {
        if velocities.len() != inv_mass.len() {
            return Err(format!(
                "velocities.velocities has {} entries for {} particles; give one per particle",
                velocities.len(),
                inv_mass.len()
            ));
        }
        let mut v = Vec::with_capacity(inv_mass.len());
        for (u, &im) in velocities.iter().zip(inv_mass) {
            let u = vector::<D>(u, "velocities.velocities")?;
            v.push(if im == 0.0 { [0.0; D] } else { u });
        }
        return Ok(v);
    }
    inv_mass.iter().map(|&im| one::<D>(spec, im, rng)).collect()
}

/// One particle's draw (an explicit list gives none: 0).
pub fn one<const D: usize>(
    spec: &Velocities,
    inv_mass: f64,
    rng: &mut ChaCha8Rng,
) -> Result<[f64; D], String> {
    if inv_mass == 0.0 {
        return Ok([0.0; D]);
    }
    Ok(match spec {
        Velocities::Maxwell { temperature, .. } => {
            std::array::from_fn(|_| (temperature * inv_mass).sqrt() * gaussian(rng))
        }
        Velocities::Uniform { p, .. } => {
            std::array::from_fn(|_| inv_mass * p * (2.0 * rng.random::<f64>() - 1.0))
        }
        Velocities::Equal { velocity } => vector::<D>(velocity, "velocities.velocity")?,
        Velocities::Explicit { .. } => [0.0; D],
    })
}

/// kT of a Maxwellian start set by its temperature (Maxwell at kT = 1 is
/// the rule when a scene gives none); None for other rules, or one that
/// sets the energy instead.
pub fn maxwell_temperature(rule: Option<&Velocities>) -> Option<f64> {
    match rule {
        None => Some(1.0),
        Some(Velocities::Maxwell {
            temperature,
            energy: None,
            ..
        }) => Some(*temperature),
        Some(_) => None,
    }
}

/// (zero_momentum, energy) of the rule.
pub fn adjustments(spec: &Velocities) -> (bool, Option<f64>) {
    match spec {
        Velocities::Maxwell {
            zero_momentum,
            energy,
            ..
        }
        | Velocities::Uniform {
            zero_momentum,
            energy,
            ..
        } => (*zero_momentum, *energy),
        _ => (false, None),
    }
}

/// The gas's kT: the Maxwellian temperature asked for, or else the kinetic
/// temperature 2 E / dof of the gas as it will start (E the requested
/// `energy`, or the energy drawn).
pub fn temperature<const D: usize>(
    spec: &Velocities,
    v: &[[f64; D]],
    inv_mass: &[f64],
    dof: f64,
) -> f64 {
    match (spec, adjustments(spec).1) {
        (Velocities::Maxwell { temperature, .. }, None) => *temperature,
        (_, Some(e)) => 2.0 * e / dof,
        (_, None) => 2.0 * kinetic_energy(v, inv_mass) / dof,
    }
}

pub fn kinetic_energy<const D: usize>(v: &[[f64; D]], inv_mass: &[f64]) -> f64 {
    v.iter()
        .zip(inv_mass)
        .filter(|(_, im)| **im > 0.0)
        .map(|(u, im)| 0.5 * u.iter().map(|x| x * x).sum::<f64>() / im)
        .sum()
}

/// Make the total momentum zero (the gas balancing `other`, the momentum of
/// particles outside it, by a common drift U) and/or rescale the gas's motion
/// about that drift so that its kinetic energy is exactly `energy`:
/// u_i = c (w_i - w_mean) + U, with E = c^2 E_internal + M U^2 / 2.
pub fn adjust<const D: usize>(
    v: &mut [[f64; D]],
    inv_mass: &[f64],
    zero_momentum: bool,
    other: [f64; D],
    energy: Option<f64>,
) -> Result<(), String> {
    let movable = || v.iter().zip(inv_mass).filter(|(_, im)| **im > 0.0);
    let mass: f64 = movable().map(|(_, im)| 1.0 / im).sum();
    if mass == 0.0 {
        return match (zero_momentum, energy) {
            (false, None) => Ok(()),
            _ => Err("cannot set the momentum or energy of the gas: no particle can move".into()),
        };
    }
    let momentum: [f64; D] =
        std::array::from_fn(|k| movable().map(|(u, im)| u[k] / im).sum::<f64>());
    let (mean, drift): ([f64; D], [f64; D]) = if zero_momentum {
        (
            std::array::from_fn(|k| momentum[k] / mass),
            std::array::from_fn(|k| -other[k] / mass),
        )
    } else {
        ([0.0; D], [0.0; D])
    };
    let scale = match energy {
        None => 1.0,
        Some(e) => {
            let internal: f64 = movable()
                .map(|(u, im)| 0.5 * (0..D).map(|k| (u[k] - mean[k]).powi(2)).sum::<f64>() / im)
                .sum();
            let bulk = 0.5 * mass * drift.iter().map(|x| x * x).sum::<f64>();
            if internal <= 0.0 {
                return Err(
                    "cannot rescale to the requested energy: the drawn velocities are all zero \
                     (relative to their mean, with zero_momentum); draw them from a distribution \
                     or give more than one movable particle"
                        .into(),
                );
            }
            if e <= bulk {
                return Err(format!(
                    "velocities.energy = {e} is too small: balancing the piston's momentum alone \
                     gives the gas a kinetic energy of {bulk}; ask for more energy, or drop zero_momentum"
                ));
            }
            ((e - bulk) / internal).sqrt()
        }
    };
    for (u, &im) in v.iter_mut().zip(inv_mass) {
        if im > 0.0 {
            *u = std::array::from_fn(|k| scale * (u[k] - mean[k]) + drift[k]);
        }
    }
    Ok(())
}

fn vector<const D: usize>(values: &[f64], key: &str) -> Result<[f64; D], String> {
    if values.len() != D || values.iter().any(|x| !x.is_finite()) {
        return Err(format!(
            "{key}: {values:?} must be {D} finite numbers (one per axis)"
        ));
    }
    Ok(std::array::from_fn(|k| values[k]))
}
