//! The ensemble one run samples, from the scene it started from: masses,
//! energy, conserved momenta and free degrees of freedom, and from them
//! each particle's exact velocity and position laws. A run's start is
//! rebuilt from its seed (the scene draws first from the run's stream), so
//! the report can set each replica beside its own laws.

use crate::engine::{Particle, degrees_of_freedom};
use crate::model::run_spec::RunSpec;
use crate::scene::{Built, OnBuilt, on_built};
use crate::theory::microcanonical::{SpeedMarginal, VelocityMarginal};
use crate::theory::ordered_rods::{self, RodPosition};

#[derive(Debug, Clone, Default, PartialEq)]
pub struct Ensemble {
    pub dimension: usize,
    /// Engine index of each movable ball, with its mass, radius and start x.
    pub balls: Vec<Ball>,
    pub energy: f64,
    pub total_mass: f64,
    /// Total momentum along each axis.
    pub momentum: Vec<f64>,
    /// Whether momentum is conserved along each axis.
    pub conserved: Vec<bool>,
    pub dof: f64,
    pub size: Vec<f64>,
    pub volume: f64,
    pub periodic: Vec<bool>,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ball {
    pub index: usize,
    pub mass: f64,
    pub radius: f64,
    pub x: f64,
}

impl Ensemble {
    pub fn of<const D: usize>(b: &Built<D>) -> Ensemble {
        let moving = |p: &Particle<D>| !p.is_immovable() && !p.is_plane();
        let balls: Vec<Ball> = (b.particles.iter().enumerate())
            .filter(|(_, p)| moving(p))
            .map(|(index, p)| Ball {
                index,
                mass: p.mass(),
                radius: p.radius,
                x: p.pos[0],
            })
            .collect();
        let anchored = b.particles.iter().any(|p| p.is_immovable() || p.is_plane());
        let all = b.particles.iter().filter(|p| !p.is_immovable());
        let periodic: Vec<bool> = (0..D).map(|k| b.sim_box.axes[k].is_periodic()).collect();
        Ensemble {
            dimension: D,
            energy: b.particles.iter().map(Particle::kinetic_energy).sum(),
            total_mass: all.clone().map(Particle::mass).sum(),
            momentum: (0..D)
                .map(|k| all.clone().map(|p| p.mass() * p.vel[k]).sum())
                .collect(),
            conserved: periodic.iter().map(|p| !anchored && *p).collect(),
            periodic,
            dof: degrees_of_freedom(&b.particles, &b.sim_box),
            size: b.sim_box.size.to_vec(),
            volume: b.sim_box.volume(),
            balls,
        }
    }

    /// The start of a planned run, rebuilt from its seed.
    pub fn of_run(spec: &RunSpec) -> Option<Ensemble> {
        Self::of_seed(&spec.descriptor.scene, spec.seed)
    }

    pub fn of_seed(scene: &crate::model::scene::SceneSpec, seed: u64) -> Option<Ensemble> {
        struct Of;
        impl OnBuilt for Of {
            type Output = Ensemble;
            fn on<const D: usize>(self, built: &Built<D>) -> Ensemble {
                Ensemble::of(built)
            }
        }
        on_built(&crate::scene::resolve(scene).ok()?, seed, Of)
    }

    /// Kinetic energy less that of the centre of mass along conserved axes.
    pub fn internal_energy(&self) -> f64 {
        let com: f64 = (self.momentum.iter().zip(&self.conserved))
            .filter(|(_, c)| **c)
            .map(|(p, _)| p * p / (2.0 * self.total_mass))
            .sum();
        self.energy - com
    }

    /// kT = 2E'/f.
    pub fn kt(&self) -> f64 {
        2.0 * self.internal_energy() / self.dof
    }

    /// The exact law of v_x of a ball of mass m.
    pub fn velocity_law(&self, mass: f64) -> VelocityMarginal {
        let (energy, dof) = (self.internal_energy(), self.dof);
        if self.conserved[0] {
            VelocityMarginal::conserved(mass, self.total_mass, self.momentum[0], energy, dof)
        } else {
            VelocityMarginal::free(mass, energy, dof)
        }
    }

    /// The exact law of sqrt(m)|v - V| of a ball of mass m.
    pub fn speed_law(&self, mass: f64) -> SpeedMarginal {
        let conserved = self.conserved.iter().any(|c| *c);
        let share = 1.0
            - if conserved {
                mass / self.total_mass
            } else {
                0.0
            };
        SpeedMarginal {
            scale: 2.0 * self.internal_energy() * share,
            dimension: self.dimension as f64,
            dof: self.dof,
        }
    }

    /// Balls from left to right at the start (rods keep this order).
    pub fn by_rank(&self) -> Vec<Ball> {
        self.sorted(|b| b.x)
    }

    /// Balls from the lightest to the heaviest (equal masses in index order).
    pub fn by_mass(&self) -> Vec<Ball> {
        self.sorted(|b| b.mass)
    }

    fn sorted(&self, key: fn(&Ball) -> f64) -> Vec<Ball> {
        let mut v = self.balls.clone();
        v.sort_by(|a, b| key(a).total_cmp(&key(b)));
        v
    }

    /// Each rod's position law, left to right (1D with walls only).
    pub fn rod_laws(&self) -> Option<Vec<(Ball, RodPosition)>> {
        if self.dimension != 1 || self.periodic[0] {
            return None;
        }
        let ranked = self.by_rank();
        let radii: Vec<f64> = ranked.iter().map(|b| b.radius).collect();
        let laws = ordered_rods::positions(self.size[0], &radii);
        Some(ranked.into_iter().zip(laws).collect())
    }

    /// The ball with engine index `index`.
    pub fn ball(&self, index: usize) -> Option<Ball> {
        self.balls.iter().copied().find(|b| b.index == index)
    }

    /// Packing fraction (every ball's volume over the box's).
    pub fn packing(&self) -> f64 {
        let ball = |r: f64| match self.dimension {
            1 => 2.0 * r,
            2 => std::f64::consts::PI * r * r,
            _ => 4.0 / 3.0 * std::f64::consts::PI * r.powi(3),
        };
        self.balls.iter().map(|b| ball(b.radius)).sum::<f64>() / self.volume
    }
}
