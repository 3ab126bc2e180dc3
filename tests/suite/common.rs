//! Small builders shared by the engine tests (independent of the scene layer,
//! so the engine is tested on its own).
#![allow(dead_code)]

use bonkers::engine::{Particle, SimBox};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

pub fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

pub fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
    let u: f64 = 1.0 - rng.random::<f64>();
    let v: f64 = rng.random::<f64>();
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// Unit-diameter particles on a simple lattice of `per_axis` sites per axis
/// with spacing `a`, Maxwellian velocities at kT = 1, unit masses.
pub fn lattice<const D: usize>(
    per_axis: usize,
    a: f64,
    seed: u64,
) -> (Vec<Particle<D>>, SimBox<D>) {
    let mut r = rng(seed);
    let n = per_axis.pow(D as u32);
    let particles = (0..n)
        .map(|mut idx| {
            let mut pos = [0.0; D];
            for x in pos.iter_mut() {
                *x = (idx % per_axis) as f64 * a + 0.5 * a;
                idx /= per_axis;
            }
            let vel = std::array::from_fn(|_| gaussian(&mut r));
            Particle::new(pos, vel, 1.0, 0.5)
        })
        .collect();
    (particles, SimBox::periodic([per_axis as f64 * a; D]))
}

/// FCC lattice of unit spheres at packing fraction `phi`, `cells`^3 unit cells.
pub fn fcc(cells: usize, phi: f64, seed: u64) -> (Vec<Particle<3>>, SimBox<3>) {
    let mut r = rng(seed);
    let n = 4 * cells.pow(3);
    let volume = n as f64 * std::f64::consts::PI / 6.0 / phi;
    let a = volume.cbrt() / cells as f64;
    let basis = [
        [0.0, 0.0, 0.0],
        [0.5, 0.5, 0.0],
        [0.5, 0.0, 0.5],
        [0.0, 0.5, 0.5],
    ];
    let mut particles = Vec::with_capacity(n);
    for x in 0..cells {
        for y in 0..cells {
            for z in 0..cells {
                for b in &basis {
                    let pos = [
                        (x as f64 + b[0] + 0.25) * a,
                        (y as f64 + b[1] + 0.25) * a,
                        (z as f64 + b[2] + 0.25) * a,
                    ];
                    let vel = std::array::from_fn(|_| gaussian(&mut r));
                    particles.push(Particle::new(pos, vel, 1.0, 0.5));
                }
            }
        }
    }
    (particles, SimBox::periodic([cells as f64 * a; 3]))
}

/// Hexagonal lattice of unit disks at packing fraction `phi`: `cols` x `rows` (rows even).
pub fn hexagonal(cols: usize, rows: usize, phi: f64, seed: u64) -> (Vec<Particle<2>>, SimBox<2>) {
    let mut r = rng(seed);
    // Area per disk in a hexagonal lattice of spacing a: sqrt(3)/2 a^2.
    let a = ((std::f64::consts::PI / 4.0) / phi / (3f64.sqrt() / 2.0)).sqrt();
    let h = a * 3f64.sqrt() / 2.0;
    let mut particles = Vec::with_capacity(cols * rows);
    for row in 0..rows {
        for col in 0..cols {
            let shift = if row % 2 == 1 { 0.5 * a } else { 0.0 };
            let pos = [col as f64 * a + shift + 0.25 * a, row as f64 * h + 0.25 * h];
            let vel = [gaussian(&mut r), gaussian(&mut r)];
            particles.push(Particle::new(pos, vel, 1.0, 0.5));
        }
    }
    (
        particles,
        SimBox::periodic([cols as f64 * a, rows as f64 * h]),
    )
}

pub fn kinetic_energy<const D: usize>(ps: &[Particle<D>]) -> f64 {
    ps.iter().map(|p| p.kinetic_energy()).sum()
}
