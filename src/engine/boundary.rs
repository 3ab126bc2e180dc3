//! The box: per axis either two walls or a periodic boundary.

use super::vector::Vector;

/// Volume of a d-ball of radius r (a rod's length in 1D).
pub fn ball_volume(d: usize, r: f64) -> f64 {
    match d {
        1 => 2.0 * r,
        2 => std::f64::consts::PI * r * r,
        _ => 4.0 / 3.0 * std::f64::consts::PI * r * r * r,
    }
}

/// What happens at one wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Wall {
    /// Specular reflection: the normal velocity reverses.
    Hard,
    /// A heat bath at temperature kT: the particle leaves with a velocity drawn
    /// from the flux-weighted Maxwellian of the wall.
    Thermal { temperature: f64 },
}

/// One axis of the box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Axis {
    Walls { low: Wall, high: Wall },
    Periodic,
}

impl Axis {
    pub const HARD: Axis = Axis::Walls {
        low: Wall::Hard,
        high: Wall::Hard,
    };

    pub fn is_periodic(&self) -> bool {
        matches!(self, Axis::Periodic)
    }

    pub fn wall(&self, high: bool) -> Option<Wall> {
        match *self {
            Axis::Walls { low, high: h } => Some(if high { h } else { low }),
            Axis::Periodic => None,
        }
    }
}

/// A box [0, L_0] x ... x [0, L_{D-1}].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimBox<const D: usize> {
    pub size: Vector<D>,
    pub axes: [Axis; D],
}

impl<const D: usize> SimBox<D> {
    pub fn hard(size: Vector<D>) -> Self {
        SimBox {
            size,
            axes: [Axis::HARD; D],
        }
    }

    pub fn periodic(size: Vector<D>) -> Self {
        SimBox {
            size,
            axes: [Axis::Periodic; D],
        }
    }

    pub fn volume(&self) -> f64 {
        self.size.iter().product()
    }

    pub fn all_periodic(&self) -> bool {
        self.axes.iter().all(Axis::is_periodic)
    }

    pub fn has_thermal_walls(&self) -> bool {
        self.axes.iter().any(|a| {
            [false, true]
                .iter()
                .any(|&h| matches!(a.wall(h), Some(Wall::Thermal { .. })))
        })
    }
}

/// Time from a particle's stored time until it touches a wall of `axis`, and
/// which wall (`true` = high). None on periodic axes or when at rest.
#[inline(always)]
pub fn wall_time(pos: f64, vel: f64, radius: f64, length: f64, axis: &Axis) -> Option<(f64, bool)> {
    if axis.is_periodic() {
        return None;
    }
    if vel > 0.0 {
        Some((((length - radius) - pos).max(0.0) / vel, true))
    } else if vel < 0.0 {
        Some(((pos - radius).max(0.0) / -vel, false))
    } else {
        None
    }
}
