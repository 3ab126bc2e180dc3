//! Packing fraction and number density: of a scene as built (what a run
//! measured) and of a scene as described (what theory is asked at).

use crate::engine::Particle;
use crate::model::descriptor::Descriptor;
use crate::model::scene::{Boundary, Drawn, SceneSpec};
use std::f64::consts::PI;

/// Volume of a ball of radius `r` in `d` dimensions (1: a rod's length).
pub fn ball(d: usize, r: f64) -> f64 {
    match d {
        1 => 2.0 * r,
        2 => PI * r * r,
        _ => 4.0 / 3.0 * PI * r.powi(3),
    }
}

/// (packing fraction, number density) of the movable particles in `volume`.
pub fn of_particles<const D: usize>(particles: &[Particle<D>], volume: f64) -> (f64, f64) {
    let balls = particles.iter().filter(|p| p.inv_mass > 0.0);
    let (n, filled) = balls.fold((0usize, 0.0), |(n, v), p| (n + 1, v + ball(D, p.radius)));
    (filled / volume, n as f64 / volume)
}

/// The packing fraction a scene describes (sweep values applied): None for
/// radii drawn from a range (then only a run knows it) or a missing box.
pub fn of_scene(scene: &SceneSpec) -> Option<f64> {
    let d = scene.dimension().ok()?;
    let volume: f64 = scene.box_size.as_ref()?.iter().product();
    let mut filled = 0.0;
    for s in &scene.species {
        let Drawn::Fixed(r) = s.radius else {
            return None;
        };
        filled += s.count as f64 * ball(d, r);
    }
    Some(filled / volume)
}

/// A descriptor's scene (its preset resolved) and what the analysis reads
/// of it without building it.
pub struct Described {
    pub scene: SceneSpec,
    pub dimension: usize,
    pub particles: usize,
    /// Whether any axis has walls (the default): then Z is the walls'.
    pub walls: bool,
}

pub fn described(d: &Descriptor) -> Option<Described> {
    let scene = crate::scene::resolve(&d.scene).ok()?;
    let walls = (scene.boundary.as_ref()).is_none_or(|b| b.contains(&Boundary::Walls));
    Some(Described {
        dimension: scene.dimension().ok()?,
        particles: scene.species.iter().map(|s| s.count).sum(),
        walls,
        scene,
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn unit_diameter_balls() {
        assert_eq!(super::ball(1, 0.5), 1.0);
        assert!((super::ball(2, 0.5) - std::f64::consts::PI / 4.0).abs() < 1e-15);
        assert!((super::ball(3, 0.5) - std::f64::consts::PI / 6.0).abs() < 1e-15);
    }
}
