//! Initial velocities: Maxwellian, uniform momenta, all equal, or explicit;
//! optionally with zero total momentum and rescaled to an exact energy.

use super::spec::Velocities;
use crate::engine::thermal::gaussian;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// Velocities for particles with the given inverse masses (0 = immovable, left at rest).
pub fn draw<const D: usize>(
    spec: &Velocities,
    inv_mass: &[f64],
    rng: &mut ChaCha8Rng,
) -> Result<Vec<[f64; D]>, String> {
    let n = inv_mass.len();
    let (mut v, zero_momentum, energy) = match spec {
        Velocities::Maxwell {
            temperature,
            zero_momentum,
            energy,
        } => {
            let v = inv_mass
                .iter()
                .map(|&im| std::array::from_fn(|_| (temperature * im).sqrt() * gaussian(rng)))
                .collect();
            (v, *zero_momentum, *energy)
        }
        Velocities::Uniform {
            p,
            zero_momentum,
            energy,
        } => {
            let v = inv_mass
                .iter()
                .map(|&im| std::array::from_fn(|_| im * p * (2.0 * rng.random::<f64>() - 1.0)))
                .collect();
            (v, *zero_momentum, *energy)
        }
        Velocities::Equal { velocity } => {
            let u = vector::<D>(velocity, "velocities.velocity")?;
            (vec![u; n], false, None)
        }
        Velocities::Explicit { velocities } => {
            if velocities.len() != n {
                return Err(format!(
                    "velocities.velocities has {} entries for {n} particles; give one per particle",
                    velocities.len()
                ));
            }
            let v = velocities
                .iter()
                .map(|u| vector::<D>(u, "velocities.velocities"))
                .collect::<Result<_, _>>()?;
            (v, false, None)
        }
    };
    for (vi, &im) in v.iter_mut().zip(inv_mass) {
        if im == 0.0 {
            *vi = [0.0; D];
        }
    }
    if zero_momentum {
        let total_mass: f64 = inv_mass
            .iter()
            .filter(|&&im| im > 0.0)
            .map(|im| 1.0 / im)
            .sum();
        let p: [f64; D] = std::array::from_fn(|k| {
            v.iter()
                .zip(inv_mass)
                .filter(|(_, im)| **im > 0.0)
                .map(|(u, im)| u[k] / im)
                .sum()
        });
        for (vi, &im) in v.iter_mut().zip(inv_mass) {
            if im > 0.0 {
                for k in 0..D {
                    vi[k] -= p[k] / total_mass;
                }
            }
        }
    }
    if let Some(target) = energy {
        let e: f64 = v
            .iter()
            .zip(inv_mass)
            .filter(|(_, im)| **im > 0.0)
            .map(|(u, im)| 0.5 * u.iter().map(|x| x * x).sum::<f64>() / im)
            .sum();
        if e <= 0.0 {
            return Err(
                "cannot rescale to the requested energy: the drawn velocities are all zero".into(),
            );
        }
        let s = (target / e).sqrt();
        v.iter_mut().flatten().for_each(|x| *x *= s);
    }
    Ok(v)
}

fn vector<const D: usize>(values: &[f64], key: &str) -> Result<[f64; D], String> {
    if values.len() != D || values.iter().any(|x| !x.is_finite()) {
        return Err(format!(
            "{key}: {values:?} must be {D} finite numbers (one per axis)"
        ));
    }
    Ok(std::array::from_fn(|k| values[k]))
}
