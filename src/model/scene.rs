//! The `[scene]` table of a study descriptor: what a run starts from.
//!
//! These types are the contract between the descriptor (which parses and
//! validates them) and the scene builder (which turns them into an engine
//! system). Every field has a default so a bundled preset can fill the rest.

use crate::model::shared::Shared;
use serde::{Deserialize, Serialize};

/// The physical setup of one run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    /// Start from a bundled scene (see `study list`); the keys given here override it.
    #[serde(default)]
    pub preset: Option<String>,
    /// 1 (rods), 2 (disks) or 3 (spheres). May be left out when `box` is
    /// given: the dimension is then the number of box lengths.
    #[serde(default)]
    pub dimension: Option<usize>,
    /// Box edge length per axis, in diameters sigma.
    #[serde(default, rename = "box")]
    pub box_size: Option<Vec<f64>>,
    /// Boundary per axis: "walls" or "periodic" (default: walls on every axis).
    #[serde(default)]
    pub boundary: Option<Vec<Boundary>>,
    /// Groups of particles; each group has its own count, mass, radius, region.
    #[serde(default)]
    pub species: Vec<SpeciesSpec>,
    /// How particles are placed (default: random).
    #[serde(default)]
    pub placement: Option<Placement>,
    /// How initial velocities are drawn (default: Maxwellian at kT = 1).
    #[serde(default)]
    pub velocities: Option<Velocities>,
    /// A movable piston of finite mass (1D: a particle; 2D/3D: a wall along x).
    #[serde(default)]
    pub piston: Option<PistonSpec>,
    /// Walls that act as heat baths.
    #[serde(default)]
    pub thermal_walls: Vec<ThermalWallSpec>,
}

impl SceneSpec {
    /// Whether `axis` is periodic (axes the boundary does not name have walls).
    pub fn periodic(&self, axis: usize) -> bool {
        self.boundary.as_ref().and_then(|b| b.get(axis)) == Some(&Boundary::Periodic)
    }

    /// The scene's dimension: `dimension` if given, otherwise the number of
    /// `box` lengths (or of `boundary` entries). An error when the two
    /// disagree or when nothing says.
    pub fn dimension(&self) -> Result<usize, String> {
        let from_axes = self
            .box_size
            .as_ref()
            .map(|b| ("box", b.len()))
            .or(self.boundary.as_ref().map(|b| ("boundary", b.len())));
        let d = match (self.dimension, from_axes) {
            (Some(d), Some((key, n))) if n != d => {
                return Err(format!(
                    "scene.dimension is {d} but scene.{key} has {n} entries; give one per axis"
                ));
            }
            (Some(d), _) => d,
            (None, Some((_, n))) => n,
            (None, None) => {
                return Err(
                    "the scene does not say its dimension: give `box` (one length per axis) or `dimension`"
                        .into(),
                );
            }
        };
        if !(1..=3).contains(&d) {
            return Err(format!(
                "scene.dimension = {d}; use 1 (rods), 2 (disks) or 3 (spheres)"
            ));
        }
        Ok(d)
    }
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
    /// Names label observables (`kinetic_energy.<name>`); "piston" is reserved.
    pub name: String,
    /// How many particles; 0 is allowed (the species is then absent).
    pub count: usize,
    /// A fixed mass, or `[lo, hi]` for masses drawn uniformly from the range.
    #[serde(default = "one")]
    pub mass: Mass,
    /// Radius in units of sigma (default 0.5: diameter 1): fixed, or `[lo, hi]`
    /// for radii drawn uniformly from the range, one per particle.
    #[serde(default = "half_radius")]
    pub radius: Radius,
    /// Placement region as fractions of the box per axis: `from = [0.0]`, `to = [0.5]`.
    /// Particles lie wholly inside it, radius included (default: the whole box).
    #[serde(default)]
    pub region: Option<Region>,
}

/// A per-particle quantity: one fixed value, or `[lo, hi]` for values drawn
/// uniformly from the range, independently for each particle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Drawn {
    Fixed(f64),
    Range([f64; 2]),
}

pub type Mass = Drawn;
pub type Radius = Drawn;

impl Drawn {
    /// The smallest and largest value it can take.
    pub fn bounds(&self) -> [f64; 2] {
        match *self {
            Drawn::Fixed(x) => [x, x],
            Drawn::Range(r) => r,
        }
    }
}

fn one() -> Mass {
    Drawn::Fixed(1.0)
}
fn half_radius() -> Radius {
    Drawn::Fixed(0.5)
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

/// The order of the species along a line of rods.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RodOrder {
    /// Every order equally likely (the uniform placement).
    Random,
    /// Species take turns: 0, 1, ..., 0, 1, ... from x = 0.
    Alternating,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Placement {
    /// Uniformly random, non-overlapping positions in each species' region.
    /// 1D is exact at any density; 2D/3D use random sequential insertion,
    /// which jams near packing fraction 0.547 (2D) and 0.38 (3D) — use
    /// "compress" or "lattice" for denser scenes.
    Random {
        /// 1D only: the species' order along the line. Random (default) or
        /// "alternating": the species take turns, in `[[scene.species]]`
        /// order (the alternating-mass chain), with the gaps still uniform.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        order: Option<RodOrder>,
    },
    /// Lattice sites filling each species' region, radius included: equal
    /// spacing (1D, `lattice = "line"`), "square" or "hexagonal" (2D, default
    /// hexagonal), "cubic" or "fcc" (3D, default fcc). Species with the same
    /// region share one lattice, their particles on randomly assigned sites.
    Lattice {
        #[serde(default)]
        lattice: Option<String>,
    },
    /// Lubachevsky–Stillinger compression (2D/3D): start from small particles
    /// at a low density and grow them, in an event-driven run, to the species'
    /// radii; the target packing fraction is what the species and box imply.
    /// Reaches dense fluids, polycrystals and glasses up to packing fraction
    /// 0.88 (2D; above about 0.87 it may jam first) or 0.64 (3D), less in
    /// small walled boxes; beyond, use "lattice". 2D/3D only: in 1D "random"
    /// is exact at any density.
    Compress {
        /// How fast radii grow, as a fraction of their final size per unit time,
        /// with the particles kept at kT = 1 meanwhile (default 0.005). Slower
        /// is closer to equilibrium and takes proportionally longer.
        #[serde(default)]
        growth_rate: Option<f64>,
        /// The low-density start: "random" (default) or "lattice".
        #[serde(default)]
        from: Option<CompressFrom>,
    },
    /// Explicit positions, one list per particle (shared by the plan's points).
    Explicit { positions: Shared<Vec<Vec<f64>>> },
}

/// Where a compression starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum CompressFrom {
    Random,
    Lattice,
}

/// Initial velocities of the species' particles (the gas). `energy` and the
/// temperature describe the gas; the piston, if any, is set by `[scene.piston]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Velocities {
    /// Maxwellian at temperature T (kT, reduced units).
    Maxwell {
        #[serde(default = "one_f")]
        temperature: f64,
        /// Total momentum of all particles (piston included) is made zero by a
        /// common shift of the gas velocities.
        #[serde(default)]
        zero_momentum: bool,
        /// Rescale the gas to exactly this kinetic energy.
        #[serde(default)]
        energy: Option<f64>,
    },
    /// Each momentum component uniform in [-p, p] (as in the Imperial project).
    Uniform {
        p: f64,
        #[serde(default)]
        zero_momentum: bool,
        #[serde(default)]
        energy: Option<f64>,
    },
    /// Every particle with the same velocity vector (MacKay's piston start).
    Equal { velocity: Vec<f64> },
    /// Explicit velocities, one list per particle (piston not included;
    /// shared by the plan's points).
    Explicit { velocities: Shared<Vec<Vec<f64>>> },
}

fn one_f() -> f64 {
    1.0
}

/// The piston. It is a particle like the others: unless `velocity` or
/// `energy` says otherwise it gets its velocity the way the gas particles get
/// theirs (a Maxwellian draw at the scene's kT with its own mass, a uniform
/// momentum in [-p, p], the common velocity, or 0 for explicit velocities).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PistonSpec {
    pub mass: f64,
    /// Initial position as a fraction of the box along x.
    #[serde(default = "half")]
    pub position: f64,
    /// Initial velocity along x (default: drawn like the other particles').
    #[serde(default)]
    pub velocity: Option<f64>,
    /// Initial kinetic energy, as a multiple of the scene's kT, moving towards
    /// +x (overrides `velocity`). The scene's kT is the Maxwellian temperature
    /// of `velocities`, or, when `velocities` sets an `energy` or is not
    /// Maxwellian, the gas's kinetic temperature 2 E / f (f = d N free degrees
    /// of freedom; d (N - 1) in a fully periodic box).
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
