//! The piston's state as the theory sees it: the fixed geometry of a scene
//! (masses, the room each gas has) and, per sample, the piston's position
//! and energy and each gas's energy.

use crate::engine::Particle;
use crate::model::run_output::{RunOutput, Series};
use crate::scene::Built;
use crate::theory::piston::{Gas, Law, PistonSystem};
use crate::theory::piston_exchange::{Relaxing, exchange_time};
use crate::theory::piston_room::Room;

/// What does not change during a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    pub dimension: usize,
    pub mass: f64,
    /// Box length along x and the piston's half thickness.
    pub length: f64,
    pub half_thickness: f64,
    /// Per side (left, right): the room its gas has (reach, face, excluded
    /// length), its total mass, its number of particles and the volume they
    /// take up (for the packing fraction).
    pub rooms: [Room; 2],
    pub gas_mass: [f64; 2],
    pub particles: [usize; 2],
    pub occupied: [f64; 2],
}

impl Geometry {
    /// The geometry of a scene with a piston (None without one). Particles
    /// never cross the piston, so each side's gas is fixed at the start.
    pub fn of<const D: usize>(built: &Built<D>) -> Option<Geometry> {
        let p = built.piston?;
        let piston = &built.particles[p];
        let mut radii: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
        let (mut gas_mass, mut occupied) = ([0.0; 2], [0.0; 2]);
        for (i, q) in built.particles.iter().enumerate() {
            if i == p || q.is_immovable() {
                continue;
            }
            let side = usize::from(q.pos[0] > piston.pos[0]);
            radii[side].push(q.radius);
            gas_mass[side] += q.mass();
            occupied[side] += volume::<D>(q);
        }
        let across = &built.sim_box.size[1..];
        Some(Geometry {
            dimension: D,
            mass: piston.mass(),
            length: built.sim_box.size[0],
            half_thickness: piston.radius,
            rooms: [Room::of(&radii[0], across), Room::of(&radii[1], across)],
            gas_mass,
            particles: [radii[0].len(), radii[1].len()],
            occupied,
        })
    }

    /// Reaches (left, right) with the piston at x: the length along x each
    /// gas's centres can reach, a radius short of the wall and of the piston.
    pub fn reaches(&self, x: f64) -> [f64; 2] {
        let h = self.half_thickness;
        [
            x - h - 2.0 * self.rooms[0].radius,
            self.length - x - h - 2.0 * self.rooms[1].radius,
        ]
    }

    /// Packing fraction of each side with the piston at x: the particles'
    /// volume over the region their centres reach.
    pub fn packing(&self, x: f64) -> [f64; 2] {
        let a = self.reaches(x);
        [0, 1].map(|s| self.occupied[s] / (a[s] * self.rooms[s].face))
    }

    /// The theory's view of one state: piston at x with kinetic energy
    /// `piston` (moving in the direction of `sign`), gases with energies
    /// `left` and `right`.
    pub fn system(&self, x: f64, piston: f64, left: f64, right: f64, sign: f64) -> PistonSystem {
        let a = self.reaches(x);
        let gas = |s: usize, energy: f64| Gas {
            energy,
            mass: self.gas_mass[s],
            reach: a[s],
            excluded: self.rooms[s].excluded,
            edge: self.rooms[s].edge,
        };
        PistonSystem {
            dimension: self.dimension,
            mass: self.mass,
            x0: x,
            v0: sign.signum() * (2.0 * piston.max(0.0) / self.mass).sqrt(),
            left: gas(0, left),
            right: gas(1, right),
        }
    }

    /// The gases of `system` (a state of this geometry) as relaxing springs:
    /// each side's adiabatic stiffness at the balance and the time its
    /// kinetic energy takes to share a compression along x with the other
    /// axes (at the balance, with the side's mean mass and temperature).
    pub fn relaxing(&self, system: &PistonSystem) -> Relaxing {
        let centre = system.balance(Law::Adiabatic);
        let (kl, kr) = system.stiffnesses(Law::Adiabatic);
        let a = self.reaches(centre);
        let phi = self.packing(centre);
        let d = self.dimension as f64;
        let gases = [system.left, system.right];
        let (ll, lr) = system.lengths(centre);
        let tau = |s: usize| {
            let n = self.particles[s] as f64;
            // At the balance, on the adiabat (K l^(2/d) fixed).
            let energy = gases[s].energy * (gases[s].length() / [ll, lr][s]).powf(2.0 / d);
            exchange_time(
                self.dimension,
                n / (a[s] * self.rooms[s].face),
                2.0 * self.rooms[s].radius,
                self.gas_mass[s] / n,
                2.0 * energy / (d * n),
                phi[s],
            )
        };
        Relaxing {
            dimension: self.dimension,
            sides: [(kl, tau(0)), (kr, tau(1))],
        }
    }
}

/// Length, area or volume of one particle.
fn volume<const D: usize>(p: &Particle<D>) -> f64 {
    let r = p.radius;
    match D {
        1 => 2.0 * r,
        2 => std::f64::consts::PI * r * r,
        _ => 4.0 / 3.0 * std::f64::consts::PI * r * r * r,
    }
}

/// The sampled series the analysis reads, aligned sample by sample.
pub struct Samples {
    pub t: Vec<f64>,
    pub x: Vec<f64>,
    pub piston: Vec<f64>,
    pub left: Vec<f64>,
    pub right: Vec<f64>,
    pub total: Vec<f64>,
}

/// The series names the piston analysis needs observed.
pub const SERIES: &[&str] = &[
    "piston_position",
    "kinetic_energy_by_species",
    "kinetic_energy",
    "gas_energy_by_side",
];

impl Samples {
    pub fn of(out: &RunOutput) -> Result<Samples, String> {
        let get = |name: &str| -> Result<&Series, String> {
            out.series(name)
                .ok_or(format!("`{name}` was not sampled: set [run] sample_every"))
        };
        let x = get("piston_position")?;
        let samples = Samples {
            t: x.t.clone(),
            x: x.value.clone(),
            piston: get("kinetic_energy.piston")?.value.clone(),
            left: get("gas_energy.left")?.value.clone(),
            right: get("gas_energy.right")?.value.clone(),
            total: get("kinetic_energy")?.value.clone(),
        };
        let (s, n) = (&samples, samples.t.len());
        if [&s.piston, &s.left, &s.right, &s.total]
            .iter()
            .any(|v| v.len() != n)
        {
            return Err("the piston series have different lengths".into());
        }
        if n < 2 {
            return Err(format!(
                "{n} sample(s): the run needs sample_every well below its duration"
            ));
        }
        Ok(samples)
    }

    pub fn len(&self) -> usize {
        self.t.len()
    }

    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// The state at sample k (direction of motion unknown from energies, so
    /// taken positive; nothing the analysis computes from it depends on it).
    pub fn system(&self, g: &Geometry, k: usize) -> PistonSystem {
        g.system(self.x[k], self.piston[k], self.left[k], self.right[k], 1.0)
    }

    /// Oscillator energy at every sample: the piston's kinetic energy plus the
    /// adiabatic potential above its minimum, each gas on the adiabat through
    /// its state at that sample (so heat already given to the gases does not
    /// count as oscillation).
    pub fn oscillator_energy(&self, g: &Geometry) -> Vec<f64> {
        (0..self.len())
            .map(|k| self.system(g, k).oscillator_energy(Law::Adiabatic))
            .collect()
    }
}
