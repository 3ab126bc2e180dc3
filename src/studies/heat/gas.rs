//! The scene as the heat theory sees it: particles, box, thermal walls and
//! the start, read from a descriptor's scene (sweep values applied), and
//! which experiment it is: a gas relaxing to walls at one temperature, or
//! conducting heat from a hot to a cold wall across x.

use crate::engine::boundary::ball_volume;
use crate::model::descriptor::Descriptor;
use crate::model::scene::{Boundary, Placement, RodOrder, Side};
use crate::scene::velocities::maxwell_temperature;
use crate::theory::heat::{compressibility, exchange_rate, mean_free_path};
use crate::theory::heat_free::FreeRelaxation;

#[derive(Debug, Clone, PartialEq)]
pub struct Gas {
    pub dimension: usize,
    pub particles: f64,
    /// Mean diameter and mass (midpoints of drawn ranges).
    pub diameter: f64,
    pub mass: f64,
    pub size: Vec<f64>,
    pub walled: Vec<bool>,
    /// (axis, high, kT) of each thermal wall.
    pub walls: Vec<(usize, bool, f64)>,
    /// kT of a Maxwellian start (None for other velocity rules).
    pub start: Option<f64>,
    /// Rods placed with the species in turn (`placement.order = "alternating"`).
    pub alternating: bool,
}

/// What a run of the heat analysis is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Experiment {
    /// Every thermal wall at `wall`: the gas relaxes to it.
    Relax { wall: f64 },
    /// A hot and a cold wall facing each other across x, the only thermal walls.
    Conduct { hot: f64, cold: f64, hot_high: bool },
}

impl Gas {
    pub fn of(d: &Descriptor) -> Result<Gas, String> {
        let scene = crate::scene::resolve(&d.scene)?;
        let dimension = scene.dimension()?;
        let size = scene.box_size.clone().ok_or("the scene has no box")?;
        let walled = match &scene.boundary {
            None => vec![true; dimension],
            Some(b) => b.iter().map(|b| *b == Boundary::Walls).collect(),
        };
        let mut n = 0.0;
        let (mut diameter, mut mass) = (0.0, 0.0);
        for s in &scene.species {
            let c = s.count as f64;
            let [r0, r1] = s.radius.bounds();
            let [m0, m1] = s.mass.bounds();
            n += c;
            diameter += c * (r0 + r1);
            mass += c * (m0 + m1) / 2.0;
        }
        if n == 0.0 {
            return Err("the scene has no particles".into());
        }
        let walls = scene
            .thermal_walls
            .iter()
            .map(|w| (w.axis, w.side == Side::High, w.temperature))
            .collect();
        let start = maxwell_temperature(scene.velocities.as_ref());
        Ok(Gas {
            dimension,
            particles: n,
            diameter: diameter / n,
            mass: mass / n,
            size,
            walled,
            walls,
            start,
            alternating: matches!(
                scene.placement,
                Some(Placement::Random {
                    order: Some(RodOrder::Alternating)
                })
            ),
        })
    }

    pub fn experiment(&self) -> Result<Experiment, String> {
        let temps: Vec<f64> = self.walls.iter().map(|w| w.2).collect();
        let Some(&first) = temps.first() else {
            return Err("the heat analysis needs thermal walls (scene.thermal_walls)".into());
        };
        if temps.iter().all(|&t| t == first) {
            return Ok(Experiment::Relax { wall: first });
        }
        match self.walls[..] {
            [(0, a, ta), (0, b, tb)] if a != b => {
                let (hot, cold) = (ta.max(tb), ta.min(tb));
                Ok(Experiment::Conduct {
                    hot,
                    cold,
                    hot_high: if ta > tb { a } else { b },
                })
            }
            _ => Err(
                "the heat analysis needs every thermal wall at one temperature \
                 (relaxation) or exactly two on axis 0, low and high, at different \
                 temperatures (conduction)"
                    .into(),
            ),
        }
    }

    pub fn volume(&self) -> f64 {
        self.size.iter().product()
    }

    /// Volume of one particle (length, area, volume of a ball).
    pub fn particle_volume(&self) -> f64 {
        ball_volume(self.dimension, self.diameter / 2.0)
    }

    pub fn packing(&self) -> f64 {
        self.particles * self.particle_volume() / self.volume()
    }

    /// The volume particle centres move in: a diameter less per walled axis.
    pub fn free_volume(&self) -> f64 {
        self.size
            .iter()
            .zip(&self.walled)
            .map(|(l, w)| if *w { l - self.diameter } else { *l })
            .product()
    }

    /// Area of one wall across `axis`.
    pub fn wall_area(&self, axis: usize) -> f64 {
        self.volume() / self.size[axis]
    }

    /// Density at contact with a wall: N / free volume times beta P / n of
    /// the fluid at the box's packing fraction (the contact theorem).
    pub fn contact_density(&self) -> f64 {
        self.particles / self.free_volume() * compressibility(self.dimension, self.packing())
    }

    /// c of dT/dt = c sqrt(T) (T_w - T) for the well-mixed gas.
    pub fn exchange_rate(&self) -> f64 {
        let area: f64 = self.walls.iter().map(|w| self.wall_area(w.0)).sum();
        exchange_rate(
            self.dimension,
            self.particles,
            area,
            self.contact_density(),
            self.mass,
        )
    }

    /// Dilute mean free path at number density `n` over the box length along x.
    pub fn knudsen_at(&self, n: f64) -> f64 {
        let path = if self.diameter > 0.0 {
            mean_free_path(self.dimension, n, self.diameter)
        } else {
            f64::INFINITY
        };
        path / self.size[0]
    }

    /// The collisionless relaxation from `start` to walls at `wall`, on a
    /// grid of `dt` up to `until`; only for the two walls across x (None
    /// otherwise). Exact for point particles.
    pub fn free(&self, wall: f64, start: f64, until: f64) -> Option<FreeRelaxation> {
        if self.walls.len() != 2 || self.walls.iter().any(|w| w.0 != 0) {
            return None;
        }
        let length = self.size[0] - self.diameter;
        let dt = (length / (start.max(wall) / self.mass).sqrt() / 400.0).min(until / 100.0);
        let steps = (until / dt).ceil() as usize;
        Some(FreeRelaxation::new(
            self.dimension,
            length,
            self.mass,
            wall,
            start,
            dt,
            steps,
        ))
    }

    pub fn knudsen(&self) -> f64 {
        self.knudsen_at(self.particles / self.volume())
    }
}
