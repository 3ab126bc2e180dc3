//! Z of one run, from the pressure it measured and its own temperature.
//!
//! The temperature is kT = 2K/f with K the kinetic energy (conserved: the
//! dynamics is elastic) and f the run's free degrees of freedom.
//! - Walls (`wall_pressure`, per unit wall area): Z = P V / (N kT), f = dN.
//!   For rods the box length is the volume: the exact finite-N result is
//!   P (L - N sigma) = N kT, i.e. Tonks' Z = 1/(1 - eta) with eta = N sigma/L.
//! - Periodic (`virial_pressure`): P V = 2K/d + W/d, W the collision virial
//!   per unit time. Momentum is conserved, so f = d(N - 1): the centre of mass
//!   carries no heat and the mechanical ideal part 2K/d is (N - 1) kT. The
//!   canonical ensemble the equations of state describe has N kT there, so Z
//!   takes the ideal part as 1 and the excess from the virial at the run's
//!   temperature: Z = 1 + W / (d N kT), W / d = P V - 2K/d.

use super::packing;
use crate::engine::Particle;
use crate::model::run_output::RunOutput;
use crate::observe::Context;

/// What one run adds: Z, packing fraction and number density.
pub struct Measured {
    pub z: f64,
    pub packing_fraction: f64,
    pub density: f64,
}

pub fn measure<const D: usize>(
    particles: &[Particle<D>],
    ctx: &Context,
    out: &RunOutput,
) -> Result<Measured, String> {
    let movable: Vec<&Particle<D>> = particles.iter().filter(|p| p.inv_mass > 0.0).collect();
    let n = movable.len() as f64;
    let kinetic: f64 = movable
        .iter()
        .map(|p| 0.5 * p.vel.iter().map(|v| v * v).sum::<f64>() / p.inv_mass)
        .sum();
    let kt = 2.0 * kinetic / ctx.degrees_of_freedom;
    let volume = ctx.volume;
    let (packing_fraction, density) = packing::of_particles(particles, volume);
    let z = if let Some(p) = out.scalar("wall_pressure") {
        p * volume / (n * kt)
    } else if let Some(p) = out.scalar("virial_pressure") {
        1.0 + (p * volume - 2.0 * kinetic / D as f64) / (n * kt)
    } else {
        return Err("the pressure analysis needs `wall_pressure` (walls) or `virial_pressure` (periodic) in [observe] scalars".into());
    };
    Ok(Measured {
        z,
        packing_fraction,
        density,
    })
}
