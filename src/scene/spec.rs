//! The `[scene]` table of a study descriptor: what a run starts from.
//!
//! These types are the contract between the descriptor (which parses and
//! validates them) and the scene builder (which turns them into an engine
//! system). Every field has a default so a bundled preset can fill the rest.

use serde::{Deserialize, Serialize};

/// The physical setup of one run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    /// Start from a bundled scene (see `study list`); the keys given here override it.
    #[serde(default)]
    pub preset: Option<String>,
    /// 1 (rods), 2 (disks) or 3 (spheres).
    #[serde(default)]
    pub dimension: Option<usize>,
    /// Box edge length per axis, in diameters sigma.
    #[serde(default, rename = "box")]
    pub box_size: Option<Vec<f64>>,
    /// Boundary per axis: "walls" or "periodic".
    #[serde(default)]
    pub boundary: Option<Vec<Boundary>>,
    /// Groups of particles; each group has its own count, mass, radius, region.
    #[serde(default)]
    pub species: Vec<SpeciesSpec>,
    /// How particles are placed.
    #[serde(default)]
    pub placement: Option<Placement>,
    /// How initial velocities are drawn.
    #[serde(default)]
    pub velocities: Option<Velocities>,
    /// A movable piston of finite mass (1D: a particle; 2D/3D: a wall along x).
    #[serde(default)]
    pub piston: Option<PistonSpec>,
    /// Walls that act as heat baths.
    #[serde(default)]
    pub thermal_walls: Vec<ThermalWallSpec>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Boundary {
    Walls,
    Periodic,
}

/// One named group of particles.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpeciesSpec {
    pub name: String,
    pub count: usize,
    /// A fixed mass, or `[lo, hi]` for masses drawn uniformly from the range.
    #[serde(default = "one")]
    pub mass: Mass,
    /// Particle radius in units of sigma (default 0.5: diameter 1).
    #[serde(default = "half")]
    pub radius: f64,
    /// Placement region as fractions of the box per axis: `from = [0.0]`, `to = [0.5]`.
    #[serde(default)]
    pub region: Option<Region>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Mass {
    Fixed(f64),
    Range([f64; 2]),
}

fn one() -> Mass {
    Mass::Fixed(1.0)
}
fn half() -> f64 {
    0.5
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Region {
    pub from: Vec<f64>,
    pub to: Vec<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Placement {
    /// Random non-overlapping positions in each species' region.
    Random,
    /// Equal spacing (1D), square/hexagonal (2D), simple cubic/fcc (3D).
    Lattice {
        #[serde(default)]
        lattice: Option<String>,
    },
    /// Explicit positions, one list per particle.
    Explicit { positions: Vec<Vec<f64>> },
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Velocities {
    /// Maxwellian at temperature T (kT, reduced units).
    Maxwell {
        #[serde(default = "one_f")]
        temperature: f64,
        #[serde(default)]
        zero_momentum: bool,
        #[serde(default)]
        energy: Option<f64>,
    },
    /// Each component uniform in [-p, p] (momentum, as in the Imperial project).
    Uniform {
        p: f64,
        #[serde(default)]
        zero_momentum: bool,
        #[serde(default)]
        energy: Option<f64>,
    },
    /// Every particle with the same velocity vector (MacKay's piston start).
    Equal { velocity: Vec<f64> },
    /// Explicit velocities, one list per particle.
    Explicit { velocities: Vec<Vec<f64>> },
}

fn one_f() -> f64 {
    1.0
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PistonSpec {
    pub mass: f64,
    /// Initial position as a fraction of the box along x.
    #[serde(default = "half")]
    pub position: f64,
    /// Initial velocity along x (default: the velocity the other particles get).
    #[serde(default)]
    pub velocity: Option<f64>,
    /// Piston energy at the start, as a multiple of kT (overrides `velocity`).
    #[serde(default)]
    pub energy: Option<f64>,
    /// Half thickness of the piston (1D: its radius).
    #[serde(default = "half")]
    pub radius: f64,
    /// Particles per side: sets the count of every species (one species per
    /// side), so one sweep key changes both gases together.
    #[serde(default)]
    pub per_side: Option<usize>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalWallSpec {
    pub axis: usize,
    /// "low" (x = 0) or "high" (x = L).
    pub side: Side,
    pub temperature: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    Low,
    High,
}
