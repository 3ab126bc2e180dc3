//! A hard particle. Its position is stored at its own last-event time `t`
//! (lazy update): only the particles an event touches are moved.

use super::vector::Vector;

/// What a particle is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Shape {
    /// A rod, disk or sphere of its radius.
    #[default]
    Ball,
    /// A plane perpendicular to axis 0 spanning the box (the piston of 2D and
    /// 3D scenes): `radius` thick on either side, moving along axis 0 only.
    Plane,
}

/// A particle whole, as scenes build it and observers read it (the event
/// engine keeps it in two parts: see `bodies.rs`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Particle<const D: usize> {
    /// Position at time `t`.
    pub pos: Vector<D>,
    pub vel: Vector<D>,
    /// The time at which `pos` holds.
    pub t: f64,
    pub radius: f64,
    /// 1/m; 0 means immovable (infinitely massive, like the seeds' walls).
    pub inv_mass: f64,
    pub species: u16,
    pub shape: Shape,
}

impl<const D: usize> Particle<D> {
    pub fn new(pos: Vector<D>, vel: Vector<D>, mass: f64, radius: f64) -> Self {
        let inv_mass = if mass.is_infinite() { 0.0 } else { 1.0 / mass };
        Particle {
            pos,
            vel,
            t: 0.0,
            inv_mass,
            radius,
            species: 0,
            shape: Shape::Ball,
        }
    }

    /// A plane at x = `x` moving along axis 0 at `vx` (its other coordinates
    /// mean nothing and are 0), `half_thickness` thick on either side.
    pub fn plane(x: f64, vx: f64, mass: f64, half_thickness: f64) -> Self {
        let axis0 = |a| std::array::from_fn(|k| if k == 0 { a } else { 0.0 });
        Particle {
            shape: Shape::Plane,
            ..Particle::new(axis0(x), axis0(vx), mass, half_thickness)
        }
    }

    pub fn is_plane(&self) -> bool {
        self.shape == Shape::Plane
    }

    pub fn with_species(mut self, species: u16) -> Self {
        self.species = species;
        self
    }

    pub fn mass(&self) -> f64 {
        1.0 / self.inv_mass
    }

    pub fn is_immovable(&self) -> bool {
        self.inv_mass == 0.0
    }

    /// Kinetic energy; an immovable particle at rest has none.
    pub fn kinetic_energy(&self) -> f64 {
        if self.is_immovable() {
            0.0
        } else {
            0.5 * super::vector::norm2(&self.vel) / self.inv_mass
        }
    }
}
