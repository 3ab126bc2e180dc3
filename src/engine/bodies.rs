//! How the event engine keeps its particles: in two parts, so that what a
//! prediction reads of a partner is one cache line.
//!
//! - A [`Body`] per particle: position, velocity, its time and when its
//!   next event is due, all that a prediction reads of a partner; 64 bytes
//!   in 3D, side by side from the start of a cache line, so that each is
//!   one line (a 3D [`Particle`] is 80 bytes and straddled two lines three
//!   times in four). In 2D a body is 48 bytes and in 1D 32.
//! - Its radius, which a prediction adds to its own, its inverse mass, which
//!   only a collision or a wall asks, and its species and shape, which only
//!   observers do: arrays beside the bodies, each kept once when every
//!   particle shares it (a one-species gas: 64 bytes a sphere, and no second
//!   line to read in a prediction or a collision).
//!
//! `bodies[i]` is particle i's body; [`Bodies::get`] and [`Bodies::iter`]
//! put whole [`Particle`]s together for whoever needs the rest.

use super::particle::{Particle, Shape};
use super::vector::{Vector, add_scaled};

/// What a prediction reads of a particle: 2 D + 2 numbers, no padding.
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(C)]
pub struct Body<const D: usize> {
    /// Position at time `t`.
    pub pos: Vector<D>,
    pub vel: Vector<D>,
    pub t: f64,
    /// When its next event is due (a copy of the queue's time, which a
    /// prediction reads of every partner: in this line, not another).
    pub due: f64,
}

impl<const D: usize> Body<D> {
    /// Where the particle is at time `t` (free flight since its last event).
    #[inline(always)]
    pub fn position_at(&self, t: f64) -> Vector<D> {
        add_scaled(&self.pos, t - self.t, &self.vel)
    }

    /// Move the stored position forward to time `t`.
    #[inline(always)]
    pub fn advance_to(&mut self, t: f64) {
        self.pos = self.position_at(t);
        self.t = t;
    }
}

/// A cache line.
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(C, align(64))]
struct Line([f64; 8]);

/// Bodies side by side from the start of a cache line. (A `Vec<Body>`
/// starts where the allocator puts it, 16 bytes past a line for a large
/// one, and every 64-byte body would straddle two lines.)
#[derive(Debug, Clone, Default, PartialEq)]
struct Lined<const D: usize> {
    lines: Vec<Line>,
    len: usize,
}

impl<const D: usize> Lined<D> {
    /// `len` bodies at rest at the origin.
    fn zeros(&mut self, len: usize) {
        let bytes = len * std::mem::size_of::<Body<D>>();
        self.lines.clear();
        self.lines.resize(bytes.div_ceil(64), Line([0.0; 8]));
        self.lines.shrink_to_fit();
        self.len = len;
    }

    #[inline(always)]
    fn as_slice(&self) -> &[Body<D>] {
        // SAFETY: a Body is 2 D + 2 f64s (repr(C): no padding, alignment
        // 8), and every bit pattern of them is a Body. The lines hold at
        // least `len` bodies' bytes, start on a 64-byte boundary (so on an
        // 8-byte one), and stay borrowed for as long as the slice lives.
        unsafe { std::slice::from_raw_parts(self.lines.as_ptr().cast::<Body<D>>(), self.len) }
    }

    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [Body<D>] {
        // SAFETY: as in `as_slice`, borrowed mutably.
        unsafe {
            std::slice::from_raw_parts_mut(self.lines.as_mut_ptr().cast::<Body<D>>(), self.len)
        }
    }
}

/// What an observer may ask besides motion, size and mass.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Kind {
    species: u16,
    shape: Shape,
}

/// A value per particle, kept once when every particle has the same.
#[derive(Debug, Clone, PartialEq)]
struct Shared<T> {
    values: Vec<T>,
    /// `usize::MAX` with a value per particle, 0 with one for all.
    mask: usize,
}

impl<T> Default for Shared<T> {
    fn default() -> Self {
        Shared {
            values: Vec::new(),
            mask: usize::MAX,
        }
    }
}

impl<T: Copy + PartialEq> Shared<T> {
    fn refresh(&mut self, values: impl Iterator<Item = T> + Clone) {
        self.values.clear();
        let first = values.clone().next();
        if values.clone().all(|v| Some(v) == first) {
            self.values.extend(first);
            self.mask = 0;
        } else {
            self.values.extend(values);
            self.mask = usize::MAX;
        }
    }

    #[inline(always)]
    fn get(&self, i: usize) -> T {
        self.values[i & self.mask]
    }
}

/// Every particle of a system: bodies, inverse masses and kinds by index.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Bodies<const D: usize> {
    body: Lined<D>,
    radius: Shared<f64>,
    inv_mass: Shared<f64>,
    kind: Shared<Kind>,
}

impl<const D: usize> Bodies<D> {
    pub fn new(particles: &[Particle<D>]) -> Self {
        let mut bodies = Bodies::default();
        bodies.refresh(particles);
        bodies
    }

    /// Take on `particles`, reusing the room already taken.
    pub fn refresh(&mut self, particles: &[Particle<D>]) {
        self.body.zeros(particles.len());
        self.radius.refresh(particles.iter().map(|p| p.radius));
        self.inv_mass.refresh(particles.iter().map(|p| p.inv_mass));
        self.kind.refresh(particles.iter().map(|p| Kind {
            species: p.species,
            shape: p.shape,
        }));
        for (b, p) in self.body.as_mut_slice().iter_mut().zip(particles) {
            *b = Body {
                pos: p.pos,
                vel: p.vel,
                t: p.t,
                due: f64::INFINITY,
            };
        }
    }

    pub fn len(&self) -> usize {
        self.body.len
    }

    pub fn is_empty(&self) -> bool {
        self.body.len == 0
    }

    /// The bodies, to read and move.
    #[inline(always)]
    pub fn bodies(&self) -> &[Body<D>] {
        self.body.as_slice()
    }

    #[inline(always)]
    pub fn bodies_mut(&mut self) -> &mut [Body<D>] {
        self.body.as_mut_slice()
    }

    #[inline(always)]
    pub fn radius(&self, i: usize) -> f64 {
        self.radius.get(i)
    }

    /// 1/m; 0 for an immovable particle.
    #[inline(always)]
    pub fn inv_mass(&self, i: usize) -> f64 {
        self.inv_mass.get(i)
    }

    pub fn is_plane(&self, i: usize) -> bool {
        self.kind.get(i).shape == Shape::Plane
    }

    /// Particle i, whole.
    pub fn get(&self, i: usize) -> Particle<D> {
        let (b, k) = (&self.bodies()[i], self.kind.get(i));
        Particle {
            pos: b.pos,
            vel: b.vel,
            t: b.t,
            radius: self.radius.get(i),
            inv_mass: self.inv_mass.get(i),
            species: k.species,
            shape: k.shape,
        }
    }

    /// Every particle, whole, by index.
    pub fn iter(&self) -> Iter<'_, D> {
        Iter {
            bodies: self,
            at: 0..self.len(),
        }
    }

    pub fn to_vec(&self) -> Vec<Particle<D>> {
        self.iter().collect()
    }
}

/// Every particle, whole, by index (see [`Bodies::iter`]).
#[derive(Clone)]
pub struct Iter<'a, const D: usize> {
    bodies: &'a Bodies<D>,
    at: std::ops::Range<usize>,
}

impl<const D: usize> Iterator for Iter<'_, D> {
    type Item = Particle<D>;

    fn next(&mut self) -> Option<Particle<D>> {
        self.at.next().map(|i| self.bodies.get(i))
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        self.at.size_hint()
    }
}

impl<const D: usize> ExactSizeIterator for Iter<'_, D> {}

/// Particle i's body: `bodies[i].pos`.
impl<const D: usize> std::ops::Index<usize> for Bodies<D> {
    type Output = Body<D>;

    #[inline(always)]
    fn index(&self, i: usize) -> &Body<D> {
        &self.bodies()[i]
    }
}

impl<const D: usize> std::ops::IndexMut<usize> for Bodies<D> {
    #[inline(always)]
    fn index_mut(&mut self, i: usize) -> &mut Body<D> {
        &mut self.bodies_mut()[i]
    }
}

impl<'a, const D: usize> IntoIterator for &'a Bodies<D> {
    type Item = Particle<D>;
    type IntoIter = Iter<'a, D>;

    fn into_iter(self) -> Iter<'a, D> {
        self.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Particles come back whole and in order, and 3D bodies fill cache
    /// lines from the start of one.
    #[test]
    fn particles_come_back_whole_and_bodies_fill_one_line() {
        assert_eq!(std::mem::size_of::<Body<3>>(), 64);
        let ball = |x: f64, m: f64| Particle::new([x, 1.0, 2.0], [0.5, -1.0, x], m, 0.5);
        let particles = vec![
            ball(1.0, 1.0),
            ball(2.0, 4.0).with_species(1),
            ball(3.0, 1.0),
            Particle::plane(5.0, 0.1, f64::INFINITY, 0.2),
        ];
        let bodies = Bodies::new(&particles);
        assert_eq!(bodies.to_vec(), particles);
        assert_eq!(std::mem::size_of::<Kind>(), 4);
        assert!(bodies.is_plane(3) && !bodies.is_plane(0));
        assert_eq!(bodies.inv_mass(1), 0.25);
        assert_eq!((&bodies).into_iter().count(), 4);
        assert_eq!(bodies.bodies().as_ptr() as usize % 64, 0);
        // One mass and one kind for all: each kept once.
        let gas = Bodies::new(&[ball(1.0, 2.0), ball(2.0, 2.0), ball(3.0, 2.0)]);
        let kept = (gas.radius.values.len(), gas.inv_mass.values.len());
        assert_eq!((kept, gas.kind.values.len()), ((1, 1), 1));
        assert_eq!(gas.to_vec()[2], ball(3.0, 2.0));
        assert_eq!(bodies.inv_mass.values.len(), 4);
        assert_eq!(bodies.radius(3), 0.2);
    }
}
