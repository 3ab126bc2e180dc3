//! Scene -> particles in a box, ready for the engine. All randomness comes
//! from the run's seeded stream, in a fixed order.

use super::placement::{self, Slot};
use super::spec::{Boundary, Mass, Placement, SceneSpec, Side, Velocities};
use super::velocities;
use crate::engine::{Axis, Particle, SimBox, Wall};
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// A scene made concrete.
#[derive(Debug, Clone)]
pub struct Built<const D: usize> {
    pub particles: Vec<Particle<D>>,
    pub sim_box: SimBox<D>,
    /// Species names by species index; the piston, if any, is the last.
    pub species: Vec<String>,
    /// Index of the piston particle (1D).
    pub piston: Option<usize>,
}

pub fn build<const D: usize>(spec: &SceneSpec, rng: &mut ChaCha8Rng) -> Result<Built<D>, String> {
    let size = fixed::<D>(
        spec.box_size
            .as_deref()
            .ok_or("scene.box is missing: give one length per axis")?,
        "scene.box",
    )?;
    let boundary = spec
        .boundary
        .clone()
        .unwrap_or_else(|| vec![Boundary::Walls; D]);
    if boundary.len() != D {
        return Err(format!(
            "scene.boundary has {} entries for {D} axes",
            boundary.len()
        ));
    }
    let mut axes: [Axis; D] = std::array::from_fn(|k| match boundary[k] {
        Boundary::Walls => Axis::HARD,
        Boundary::Periodic => Axis::Periodic,
    });
    for w in &spec.thermal_walls {
        let axis = axes.get_mut(w.axis).ok_or(format!(
            "thermal wall on axis {} but the box has {D} axes",
            w.axis
        ))?;
        let Axis::Walls { low, high } = axis else {
            return Err(format!(
                "thermal wall on axis {}, which is periodic; make that axis \"walls\"",
                w.axis
            ));
        };
        if !(w.temperature.is_finite() && w.temperature > 0.0) {
            return Err(format!(
                "thermal wall temperature {} must be positive",
                w.temperature
            ));
        }
        let wall = Wall::Thermal {
            temperature: w.temperature,
        };
        match w.side {
            Side::Low => *low = wall,
            Side::High => *high = wall,
        }
    }
    if spec.species.is_empty() {
        return Err("the scene has no particles: add at least one [[scene.species]]".into());
    }

    // Masses, radii and regions, species by species.
    let mut inv_mass = Vec::new();
    let mut slots = Vec::new();
    let mut species_of = Vec::new();
    let species_specs: Vec<_> = spec
        .species
        .iter()
        .map(|s| {
            let mut s = s.clone();
            if let Some(n) = spec.piston.as_ref().and_then(|p| p.per_side) {
                s.count = n;
            }
            s
        })
        .collect();
    for (s_idx, s) in species_specs.iter().enumerate() {
        let (lo, hi) = match &s.region {
            Some(r) => (
                fixed::<D>(&r.from, "region.from")?,
                fixed::<D>(&r.to, "region.to")?,
            ),
            None => ([0.0; D], [1.0; D]),
        };
        for _ in 0..s.count {
            let m = match s.mass {
                Mass::Fixed(m) => m,
                Mass::Range([a, b]) => a + (b - a) * rng.random::<f64>(),
            };
            if m.is_nan() || m <= 0.0 {
                return Err(format!(
                    "species `{}` has mass {m}; masses must be > 0 (or inf for immovable)",
                    s.name
                ));
            }
            inv_mass.push(1.0 / m);
            slots.push(Slot {
                radius: s.radius,
                lo: std::array::from_fn(|k| lo[k] * size[k]),
                hi: std::array::from_fn(|k| hi[k] * size[k]),
            });
            species_of.push(s_idx as u16);
        }
    }
    let placement = spec.placement.clone().unwrap_or(Placement::Random);
    let positions = match &placement {
        Placement::Random => placement::random(&slots, size, rng)?,
        Placement::Lattice { lattice } => {
            // Each species fills its own region.
            let mut out = Vec::with_capacity(slots.len());
            let mut start = 0;
            for s in &species_specs {
                let first = slots.get(start).ok_or("empty species")?;
                out.extend(placement::lattice::<D>(
                    s.count,
                    first.lo,
                    first.hi,
                    lattice.as_deref(),
                )?);
                start += s.count;
            }
            out
        }
        Placement::Explicit { positions } => {
            if positions.len() != slots.len() {
                return Err(format!(
                    "placement.positions has {} entries for {} particles; give one per particle",
                    positions.len(),
                    slots.len()
                ));
            }
            positions
                .iter()
                .map(|p| fixed::<D>(p, "placement.positions"))
                .collect::<Result<_, _>>()?
        }
    };
    let vel_spec = spec.velocities.clone().unwrap_or(Velocities::Maxwell {
        temperature: 1.0,
        zero_momentum: false,
        energy: None,
    });
    let velocities = velocities::draw::<D>(&vel_spec, &inv_mass, rng)?;
    let mut particles: Vec<Particle<D>> = (0..slots.len())
        .map(|i| {
            let mut p = Particle::new(positions[i], velocities[i], 1.0, slots[i].radius)
                .with_species(species_of[i]);
            p.inv_mass = inv_mass[i];
            p
        })
        .collect();
    let mut species: Vec<String> = spec.species.iter().map(|s| s.name.clone()).collect();

    let mut piston = None;
    if let Some(ps) = &spec.piston {
        if D != 1 {
            return Err("a piston is available in 1D scenes only in this version (a movable wall in 2D/3D is planned)".into());
        }
        if ps.mass.is_nan() || ps.mass <= 0.0 || !(0.0..=1.0).contains(&ps.position) {
            return Err(format!(
                "piston: mass must be > 0 and position a fraction of the box in [0, 1] (got mass {}, position {})",
                ps.mass, ps.position
            ));
        }
        let v = match (ps.energy, ps.velocity, &vel_spec) {
            (Some(e), _, _) => (2.0 * e / ps.mass).sqrt(),
            (None, Some(v), _) => v,
            (None, None, Velocities::Equal { velocity }) => velocity[0],
            _ => 0.0,
        };
        let mut vel = [0.0; D];
        vel[0] = v;
        let mut pos = [0.0; D];
        pos[0] = ps.position * size[0];
        species.push("piston".into());
        particles.push(
            Particle::new(pos, vel, ps.mass, ps.radius).with_species((species.len() - 1) as u16),
        );
    }
    if D == 1 {
        // The engine's chain needs left-to-right order.
        particles.sort_by(|a, b| a.pos[0].total_cmp(&b.pos[0]));
        piston = particles
            .iter()
            .position(|p| spec.piston.is_some() && p.species as usize == species.len() - 1);
    }
    Ok(Built {
        particles,
        sim_box: SimBox { size, axes },
        species,
        piston,
    })
}

fn fixed<const D: usize>(values: &[f64], key: &str) -> Result<[f64; D], String> {
    if values.len() != D {
        return Err(format!(
            "{key} has {} entries; a {D}D scene needs {D} (one per axis)",
            values.len()
        ));
    }
    if values.iter().any(|x| !x.is_finite()) {
        return Err(format!("{key} must be finite numbers, got {values:?}"));
    }
    Ok(std::array::from_fn(|k| values[k]))
}
