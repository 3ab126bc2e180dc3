//! Observer hooks. The engine is generic over its observer, so a hook nobody
//! implements compiles to nothing: an observable a run does not ask for costs
//! no work per event.

use super::bodies::Bodies;
use super::boundary::SimBox;
use super::vector::Vector;

/// A pair collision, as the virial pressure needs it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairCollision<const D: usize> {
    /// Absolute simulation time.
    pub time: f64,
    pub i: usize,
    pub j: usize,
    /// Impulse given to i (j receives the opposite).
    pub impulse_i: Vector<D>,
    /// Centre-to-centre vector r_j - r_i at contact (periodic image applied).
    pub separation: Vector<D>,
}

/// A particle hitting a wall, as wall pressure and heat flow need it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WallHit<const D: usize> {
    pub time: f64,
    pub i: usize,
    pub axis: usize,
    /// True for the wall at x = L, false for x = 0.
    pub high: bool,
    /// Impulse given to the particle (the wall receives the opposite).
    pub impulse: Vector<D>,
    /// Kinetic energy the particle gained from the wall (nonzero only for thermal walls).
    pub energy_gain: f64,
}

/// The state at a sampling time (the seeds' clock events), read-only.
#[derive(Debug, Clone, Copy)]
pub struct Snapshot<'a, const D: usize> {
    /// Absolute simulation time.
    pub time: f64,
    /// Engine-internal time (positions are stored relative to it).
    pub(crate) now: f64,
    pub particles: &'a Bodies<D>,
    pub sim_box: &'a SimBox<D>,
}

impl<const D: usize> Snapshot<'_, D> {
    /// Position of particle i now, folded into the box on periodic axes.
    pub fn position(&self, i: usize) -> Vector<D> {
        let mut x = self.particles[i].position_at(self.now);
        for (k, axis) in self.sim_box.axes.iter().enumerate() {
            if axis.is_periodic() {
                x[k] = x[k].rem_euclid(self.sim_box.size[k]);
            }
        }
        x
    }

    pub fn kinetic_energy(&self) -> f64 {
        self.particles.iter().map(|p| p.kinetic_energy()).sum()
    }
}

pub trait Observer<const D: usize> {
    fn pair_collision(&mut self, _event: &PairCollision<D>) {}
    fn wall_hit(&mut self, _event: &WallHit<D>) {}
    fn sample(&mut self, _snapshot: &Snapshot<D>) {}
}

/// No observer at all.
impl<const D: usize> Observer<D> for () {}

impl<const D: usize, A: Observer<D>, B: Observer<D>> Observer<D> for (A, B) {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        self.0.pair_collision(e);
        self.1.pair_collision(e);
    }
    fn wall_hit(&mut self, e: &WallHit<D>) {
        self.0.wall_hit(e);
        self.1.wall_hit(e);
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        self.0.sample(s);
        self.1.sample(s);
    }
}

impl<const D: usize, O: Observer<D> + ?Sized> Observer<D> for Box<O> {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        (**self).pair_collision(e);
    }
    fn wall_hit(&mut self, e: &WallHit<D>) {
        (**self).wall_hit(e);
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        (**self).sample(s);
    }
}
