//! The piston at equilibrium (microcanonical: total kinetic energy K fixed,
//! walls, so momentum is not conserved). Positions and velocities are
//! independent for hard particles: the mass-weighted velocities are uniform
//! on the sphere of radius sqrt(2K) in N_free dimensions, so each free
//! degree of freedom holds K/N_free on average (the piston, moving along x
//! only, has one); the piston's position makes the free lengths
//! l_L/(l_L+l_R) ~ Beta(N_L+1, N_R+1), the configurational weight l_L^N_L
//! l_R^N_R of ideal gases (in 1D, by the Tonks mapping, hard rods; in 2D
//! and 3D dilute hard disks and spheres, whose free length is the reach
//! less a constant, up to the small edge term).

use super::piston::{Gas, Law, PistonSystem};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;
use std::sync::Mutex;

/// Free kinetic degrees of freedom with a piston moving along x: d per gas
/// particle plus one (1D: 2 N_side + 1 for two equal sides).
pub fn degrees_of_freedom(dimension: usize, gas_particles: usize) -> usize {
    dimension * gas_particles + 1
}

/// Equilibrium mean of the oscillator energy (piston kinetic energy plus
/// adiabatic potential above its minimum) over K, with its Monte Carlo
/// standard error: the level the piston's excess energy relaxes to. It
/// depends only on the dimension and the particles per side (energies and
/// volumes enter as ratios). `draws` samples from a fixed seed, so the value
/// is reproducible; it is remembered, as every run of a sweep point asks.
pub fn oscillator_share(dimension: usize, left: usize, right: usize, draws: usize) -> (f64, f64) {
    static KNOWN: Mutex<BTreeMap<[usize; 4], (f64, f64)>> = Mutex::new(BTreeMap::new());
    let key = [dimension, left, right, draws];
    if let Some(known) = KNOWN.lock().ok().and_then(|k| k.get(&key).copied()) {
        return known;
    }
    let value = sample_oscillator_share(dimension, left, right, draws);
    if let Ok(mut k) = KNOWN.lock() {
        k.insert(key, value);
    }
    value
}

fn sample_oscillator_share(
    dimension: usize,
    left: usize,
    right: usize,
    draws: usize,
) -> (f64, f64) {
    let mut rng = ChaCha8Rng::seed_from_u64(0x9157_0e9a);
    let mut normal = || {
        let (u, v): (f64, f64) = (rng.random(), rng.random());
        (-2.0 * (1.0 - u).ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    };
    let mut half_chi2 = |k: usize| (0..k).map(|_| 0.5 * normal().powi(2)).sum::<f64>();
    let (mut sum, mut sum2) = (0.0, 0.0);
    for _ in 0..draws {
        let piston = half_chi2(1);
        let (kl, kr) = (half_chi2(dimension * left), half_chi2(dimension * right));
        // Beta(N_L+1, N_R+1) as a ratio of Gamma(N+1) = chi^2(2N+2)/2 variates.
        let (gl, gr) = (half_chi2(2 * left + 2), half_chi2(2 * right + 2));
        let split = gl / (gl + gr);
        let total = piston + kl + kr;
        let state = PistonSystem {
            dimension,
            mass: 1.0,
            x0: split,
            v0: (2.0 * piston / total).sqrt(),
            left: Gas::ideal(kl / total, 0.0, split),
            right: Gas::ideal(kr / total, 0.0, 1.0 - split),
        };
        let e = state.oscillator_energy(Law::Adiabatic);
        sum += e;
        sum2 += e * e;
    }
    let n = draws as f64;
    let mean = sum / n;
    (mean, ((sum2 / n - mean * mean) / (n - 1.0)).max(0.0).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_degree_of_freedom_for_the_piston() {
        assert_eq!(degrees_of_freedom(1, 10), 11);
        assert_eq!(degrees_of_freedom(2, 50), 101);
    }

    /// The oscillator energy holds the piston's kinetic share 1/N_free plus
    /// its potential share, which for a harmonic well would be about as much
    /// again; it scales as 1/N_free, and the estimate is precise to 1%.
    #[test]
    fn oscillator_share_is_about_two_degrees_of_freedom() {
        for n in [5, 20] {
            let (mean, se) = oscillator_share(1, n, n, 20_000);
            let per_dof = mean * degrees_of_freedom(1, 2 * n) as f64;
            assert!(se < 0.01 * mean, "{mean} +- {se}");
            assert!(
                per_dof > 1.5 && per_dof < 2.5,
                "N = {n}: {per_dof} K/N_free"
            );
        }
    }
}
