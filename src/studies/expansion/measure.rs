//! What one run of an expansion says: when its left fraction relaxed, where
//! it settled and how much it fluctuates there; and the collisionless
//! prediction for the scene it started from.

use crate::engine::boundary::ball_volume;
use crate::model::descriptor::Descriptor;
use crate::model::scene::{Drawn, Velocities};
use crate::scene::Built;
use crate::stats::groups::first_seen;
use crate::stats::late::late_mean;
use crate::theory::expansion::{Diffusive, FreeExpansion, Mixture, Speeds, compressibility};
use crate::theory::expansion_rods::{Collisionless, Rods};
use crate::theory::heat::mean_free_path;
use crate::theory::self_diffusion;

/// Mean of f over the last `LATE` of the run (see `stats::late`), and its
/// mean square deviation from 1/2 (the mean by symmetry: a run's own mean
/// would hide its slowest fluctuations).
pub fn late(t: &[f64], f: &[f64]) -> (f64, f64) {
    let square: Vec<f64> = f.iter().map(|x| (x - 0.5).powi(2)).collect();
    (late_mean(t, f), late_mean(t, &square))
}

/// The scene as the theory sees it: its particles' kinds (radius, mass,
/// count), the box along x and its number density.
#[derive(Debug, Clone, PartialEq)]
pub struct Gas {
    pub dimension: usize,
    pub length: f64,
    pub particles: usize,
    pub density: f64,
    /// Mean diameter.
    pub diameter: f64,
    /// Volume the particles fill over the box's.
    pub packing: f64,
    pub kinds: Vec<(f64, f64, usize)>,
}

impl Gas {
    /// The gas a run started with.
    pub fn of<const D: usize>(built: &Built<D>) -> Gas {
        let moving = (built.particles.iter()).filter(|p| !p.is_immovable() && !p.is_plane());
        Gas::new(
            D,
            &built.sim_box.size,
            moving.map(|p| (p.radius, p.mass(), 1)),
        )
    }

    /// The gas a descriptor's scene describes, read from the spec (not
    /// built): None when radii or masses are drawn from ranges, which only
    /// a run knows.
    pub fn of_descriptor(d: &Descriptor) -> Option<Gas> {
        let scene = crate::scene::resolve(&d.scene).ok()?;
        let kinds = (scene.species.iter().filter(|s| s.count > 0))
            .map(|s| match (s.radius, s.mass) {
                (Drawn::Fixed(r), Drawn::Fixed(m)) => Some((r, m, s.count)),
                _ => None,
            })
            .collect::<Option<Vec<_>>>()?;
        Some(Gas::new(
            scene.dimension().ok()?,
            scene.box_size.as_ref()?,
            kinds,
        ))
    }

    /// From (radius, mass, count) groups, those of one radius and mass
    /// merged, in a box of edges `size`.
    fn new(
        dimension: usize,
        size: &[f64],
        groups: impl IntoIterator<Item = (f64, f64, usize)>,
    ) -> Gas {
        let same = |a: &(f64, f64, usize), b: &(f64, f64, usize)| (a.0, a.1) == (b.0, b.1);
        let kinds: Vec<(f64, f64, usize)> = (first_seen(groups, same).into_iter())
            .map(|g| (g[0].0, g[0].1, g.iter().map(|k| k.2).sum()))
            .collect();
        let n: usize = kinds.iter().map(|k| k.2).sum();
        let diameter = kinds.iter().map(|k| 2.0 * k.0 * k.2 as f64).sum::<f64>() / n as f64;
        let filled: f64 = (kinds.iter())
            .map(|k| ball_volume(dimension, k.0) * k.2 as f64)
            .sum();
        let volume: f64 = size.iter().product();
        Gas {
            dimension,
            packing: filled / volume,
            length: size[0],
            particles: n,
            density: n as f64 / volume,
            diameter,
            kinds,
        }
    }

    /// Mean free path over the box length along x at the final (whole box)
    /// density, dilute kinetic theory: lambda = 1/(2 sqrt2 n d) for disks,
    /// 1/(sqrt2 pi n d^2) for spheres; infinite for points. Rods have none
    /// (they never pass each other): NaN.
    pub fn knudsen(&self) -> f64 {
        mean_free_path(self.dimension, self.density, self.diameter) / self.length
    }

    pub fn volume(&self) -> f64 {
        self.particles as f64 / self.density
    }

    /// Variance of the late split over the binomial's: S(0).
    pub fn compressibility(&self) -> f64 {
        compressibility(self.dimension, self.packing)
    }

    /// The collisionless prediction for velocities drawn by `draw`: free
    /// particles, or in 1D rods of one kind by Tonks' mapping (exact: equal
    /// rods that collide swap velocities).
    pub fn free(&self, draw: Draw) -> Collisionless {
        if let [(r, m, c)] = self.kinds[..]
            && self.dimension == 1
            && r > 0.0
            && let Some(rods) = Rods::new(self.length, c, 2.0 * r, draw.speeds(m))
        {
            return Collisionless::Rods(rods);
        }
        let free = |&(r, m, c): &(f64, f64, usize)| {
            (
                FreeExpansion::with(self.length, r, draw.speeds(m)),
                c as f64,
            )
        };
        Collisionless::Free(Mixture {
            kinds: self.kinds.iter().map(free).collect(),
        })
    }

    /// kT once the gas has shared its energy: the count-weighted mean of
    /// each kind's m <v_x^2>.
    pub fn temperature(&self, draw: Draw) -> f64 {
        let energy = |&(_, m, c): &(f64, f64, usize)| c as f64 * m * draw.speeds(m).mean_square();
        self.kinds.iter().map(energy).sum::<f64>() / self.particles as f64
    }

    /// Enskog's self-diffusion coefficient of the gas filling the whole box
    /// at its final temperature (the count-weighted mean mass and diameter
    /// of a mixture). NaN for rods and points.
    pub fn diffusion_enskog(&self, draw: Draw) -> f64 {
        let n = self.particles as f64;
        let mass = self.kinds.iter().map(|k| k.1 * k.2 as f64).sum::<f64>() / n;
        let kt = self.temperature(draw);
        let (d, rho) = (self.diameter, self.density);
        if d > 0.0 {
            self_diffusion::enskog(self.dimension, rho, d, kt, mass, self.packing)
        } else {
            f64::NAN
        }
    }

    /// The diffusive prediction with coefficient `diffusion`.
    pub fn diffusive(&self, diffusion: f64) -> Diffusive {
        Diffusive::new(self.length, 0.5 * self.diameter, diffusion)
    }
}

/// How the gas's velocities were drawn, as far as the theory follows them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Draw {
    /// Maxwellian at this kT.
    Maxwell(f64),
    /// Each momentum component uniform in [-p, p] (the Imperial start).
    Uniform(f64),
}

impl Draw {
    /// The distribution of v_x of a particle of mass `mass`.
    pub fn speeds(&self, mass: f64) -> Speeds {
        match *self {
            Draw::Maxwell(kt) => Speeds::Maxwell((kt / mass).sqrt()),
            Draw::Uniform(p) => Speeds::Uniform(p / mass),
        }
    }
}

/// Whether every species starts in the left half (its region ends at x <=
/// L/2): the expansion's relaxation and its theories need that; a case
/// that fills the box (to measure diffusion) has none.
pub fn starts_left(d: &Descriptor) -> bool {
    crate::scene::resolve(&d.scene).is_ok_and(|scene| {
        scene.species.iter().all(|s| {
            s.region
                .as_ref()
                .is_some_and(|r| r.to.first().is_some_and(|&x| x <= 0.5))
        })
    })
}

/// The start's velocity rule, when the theory holds for it: a Maxwellian
/// (the default when the scene gives none) or uniform momenta, as drawn
/// (not rescaled to an energy). Zero total momentum shifts every velocity
/// by the mean, of order p / sqrt(N): the theory ignores it. None for other
/// rules.
pub fn draw(d: &Descriptor) -> Option<Draw> {
    let scene = crate::scene::resolve(&d.scene).ok()?;
    match scene.velocities {
        None => Some(Draw::Maxwell(1.0)),
        Some(Velocities::Maxwell {
            temperature,
            energy: None,
            ..
        }) => Some(Draw::Maxwell(temperature)),
        Some(Velocities::Uniform {
            p, energy: None, ..
        }) => Some(Draw::Uniform(p)),
        Some(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn late_half_statistics() {
        let t = [0.0, 1.0, 2.0, 3.0, 4.0];
        let f = [1.0, 0.9, 0.4, 0.6, 0.5];
        let (m, v) = late(&t, &f);
        assert!((m - 0.5).abs() < 1e-12);
        assert!((v - 0.02 / 3.0).abs() < 1e-12);
        let (_, v) = late(&t, &[0.0, 0.0, 0.4, 0.4, 0.7]);
        assert!((v - 0.06 / 3.0).abs() < 1e-12);
    }
}
