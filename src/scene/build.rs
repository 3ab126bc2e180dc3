//! Scene -> particles in a box, ready for the engine. All randomness comes
//! from the run's seeded stream, in a fixed order: masses and radii (particle
//! by particle), positions, the gas's velocities, the piston's.

use super::compress::{self, Preparation, Settings};
use super::space::{Slot, Space};
use super::{lattice, piston, placement, rods, velocities};
use crate::engine::{Axis, Particle, SimBox, Wall};
use crate::model::scene::{
    Boundary, CompressFrom, Drawn, Placement, SceneSpec, Side, SpeciesSpec, Velocities,
};
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// A scene made concrete.
#[derive(Debug, Clone)]
pub struct Built<const D: usize> {
    pub particles: Vec<Particle<D>>,
    pub sim_box: SimBox<D>,
    /// Species names by species index; the piston, if any, is the last.
    pub species: Vec<String>,
    /// Index of the piston: a particle in 1D, a plane (a wall along x) above.
    pub piston: Option<usize>,
    /// What it cost to prepare the positions, when that took a simulation
    /// of its own (compression); None for direct placements.
    pub prepared: Option<Preparation>,
}

/// The species name the piston's observables use.
pub const PISTON: &str = "piston";

pub fn build<const D: usize>(spec: &SceneSpec, rng: &mut ChaCha8Rng) -> Result<Built<D>, String> {
    let d = spec.dimension()?;
    if d != D {
        return Err(format!("the scene is {d}D but was built as {D}D"));
    }
    let sim_box = sim_box::<D>(spec)?;
    let space = Space {
        size: sim_box.size,
        periodic: std::array::from_fn(|k| sim_box.axes[k].is_periodic()),
    };
    let species = species_list(spec)?;
    let names: Vec<String> = species.iter().map(|s| s.name.clone()).collect();
    let obstacle = match &spec.piston {
        Some(_) if D > 1 && sim_box.axes[0].is_periodic() => {
            return Err(
                "a piston slides along x between walls, but axis 0 is periodic; make it \"walls\""
                    .into(),
            );
        }
        Some(ps) => Some(piston::extent(ps, sim_box.size[0])?),
        None => None,
    };

    // Masses, radii and regions, particle by particle.
    let mut inv_mass = Vec::new();
    let mut slots = Vec::new();
    for (index, s) in species.iter().enumerate() {
        let (lo, hi) = region::<D>(s, &sim_box.size)?;
        for _ in 0..s.count {
            let m = draw(s.mass, rng);
            let radius = draw(s.radius, rng);
            inv_mass.push(1.0 / m);
            slots.push(Slot {
                radius,
                lo,
                hi,
                species: index as u16,
            });
        }
    }
    if slots.is_empty() && obstacle.is_none() {
        return Err(
            "the scene has no particles: give a [[scene.species]] a count of at least 1".into(),
        );
    }

    let mut prepared = None;
    let positions = match spec.placement.clone().unwrap_or(Placement::Random) {
        Placement::Random | Placement::Compress { .. } if D == 1 => {
            rods::place(&as_line(&slots), obstacle, &names, rng)?
                .into_iter()
                .map(|[x]| std::array::from_fn(|_| x))
                .collect()
        }
        Placement::Random => match obstacle {
            // Beside a piston wall each gas keeps to its own side.
            Some(extent) => placement::random(&around(&slots, extent, &names)?, &space, rng)?,
            None => placement::random(&slots, &space, rng)?,
        },
        Placement::Compress { .. } if obstacle.is_some() => {
            return Err(
                "compression cannot grow particles around a piston wall; place the gases at random or \
                 on a lattice on either side of it"
                    .into(),
            );
        }
        Placement::Lattice { lattice } => {
            let clear = match obstacle {
                Some(extent) => around(&slots, extent, &names)?,
                None => slots.clone(),
            };
            lattice::place(&clear, &space, lattice.as_deref(), &names, rng)?
        }
        Placement::Compress { growth_rate, from } => {
            let settings = Settings {
                growth_rate: growth_rate.unwrap_or(compress::GROWTH_RATE),
                from: from.unwrap_or(CompressFrom::Random),
            };
            let (x, cost) = compress::compress(&slots, &inv_mass, &space, &names, &settings, rng)?;
            prepared = Some(cost);
            x
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

    // Velocities: the gas's, then the piston's, then momentum and energy.
    let rule = spec.velocities.clone().unwrap_or(Velocities::Maxwell {
        temperature: 1.0,
        zero_momentum: false,
        energy: None,
    });
    let mut gas = velocities::draw::<D>(&rule, &inv_mass, rng)?;
    let movable = inv_mass.iter().filter(|&&im| im > 0.0).count();
    let free = (movable.saturating_sub(usize::from(sim_box.all_periodic())) * D).max(1);
    let kt = velocities::temperature(&rule, &gas, &inv_mass, free as f64);
    let piston_v = match &spec.piston {
        Some(ps) => Some(piston::velocity::<D>(ps, &rule, kt, rng)?),
        None => None,
    };
    let (zero_momentum, energy) = velocities::adjustments(&rule);
    let mut other = [0.0; D];
    if let (Some(ps), Some(v)) = (&spec.piston, piston_v) {
        other[0] = ps.mass * v;
    }
    velocities::adjust(&mut gas, &inv_mass, zero_momentum, other, energy)?;

    let mut particles: Vec<Particle<D>> = (0..slots.len())
        .map(|i| {
            let mut p = Particle::new(positions[i], gas[i], 1.0, slots[i].radius)
                .with_species(slots[i].species);
            p.inv_mass = inv_mass[i];
            p
        })
        .collect();
    let mut names = names;
    if let (Some(ps), Some(v)) = (&spec.piston, piston_v) {
        let x = ps.position * sim_box.size[0];
        names.push(PISTON.into());
        let species = (names.len() - 1) as u16;
        // On a line the piston is a rod; above, a wall spanning the box.
        particles.push(if D == 1 {
            Particle::new([x; D], [v; D], ps.mass, ps.radius).with_species(species)
        } else {
            Particle::plane(x, v, ps.mass, ps.radius).with_species(species)
        });
    }
    if D == 1 {
        // The engine's chain needs left-to-right order.
        particles.sort_by(|a, b| a.pos[0].total_cmp(&b.pos[0]));
    }
    let piston = spec.piston.as_ref().and_then(|_| {
        particles
            .iter()
            .position(|p| p.species as usize == names.len() - 1)
    });
    Ok(Built {
        particles,
        sim_box,
        species: names,
        piston,
        prepared,
    })
}

fn sim_box<const D: usize>(spec: &SceneSpec) -> Result<SimBox<D>, String> {
    let size = fixed::<D>(
        spec.box_size
            .as_deref()
            .ok_or("scene.box is missing: give one length per axis")?,
        "scene.box",
    )?;
    if let Some(k) = (0..D).find(|&k| size[k] <= 0.0) {
        return Err(format!(
            "scene.box has length {} on axis {k}; box lengths must be positive",
            size[k]
        ));
    }
    let boundary = spec
        .boundary
        .clone()
        .unwrap_or_else(|| vec![Boundary::Walls; D]);
    if boundary.len() != D {
        return Err(format!(
            "scene.boundary has {} entries for {D} axes; give one per axis",
            boundary.len()
        ));
    }
    let mut axes: [Axis; D] = std::array::from_fn(|k| match boundary[k] {
        Boundary::Walls => Axis::HARD,
        Boundary::Periodic => Axis::Periodic,
    });
    for w in &spec.thermal_walls {
        let axis = axes.get_mut(w.axis).ok_or(format!(
            "thermal wall on axis {} but the box has {D} axes (axes count from 0)",
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
    Ok(SimBox { size, axes })
}

/// The species with `per_side` applied, their names and values checked.
fn species_list(spec: &SceneSpec) -> Result<Vec<SpeciesSpec>, String> {
    if spec.species.is_empty() {
        return Err("the scene has no particles: add at least one [[scene.species]]".into());
    }
    let per_side = spec.piston.as_ref().and_then(|p| p.per_side);
    let mut out: Vec<SpeciesSpec> = Vec::new();
    for s in &spec.species {
        if s.name == PISTON {
            return Err(format!(
                "a species is named `{PISTON}`, the name the piston's observables use; rename the species"
            ));
        }
        if out.iter().any(|o| o.name == s.name) {
            return Err(format!(
                "species `{}` is named twice; give each species its own name",
                s.name
            ));
        }
        let [m0, m1] = s.mass.bounds();
        if !(m0 > 0.0 && m0 <= m1) || m1.is_nan() {
            return Err(format!(
                "species `{}` has mass {:?}; masses must be > 0 (inf for immovable), a range as [lo, hi] with lo <= hi",
                s.name, s.mass
            ));
        }
        let [r0, r1] = s.radius.bounds();
        if !(r0 >= 0.0 && r0 <= r1 && r1.is_finite()) {
            return Err(format!(
                "species `{}` has radius {:?}; radii must be finite and >= 0, a range as [lo, hi] with lo <= hi",
                s.name, s.radius
            ));
        }
        let mut s = s.clone();
        if let Some(n) = per_side {
            s.count = n;
        }
        out.push(s);
    }
    Ok(out)
}

fn draw(value: Drawn, rng: &mut ChaCha8Rng) -> f64 {
    match value {
        Drawn::Fixed(x) => x,
        Drawn::Range([a, b]) => a + (b - a) * rng.random::<f64>(),
    }
}

/// A species' region in box coordinates.
fn region<const D: usize>(
    s: &SpeciesSpec,
    size: &[f64; D],
) -> Result<([f64; D], [f64; D]), String> {
    let Some(r) = &s.region else {
        return Ok(([0.0; D], *size));
    };
    let from = fixed::<D>(&r.from, "region.from")?;
    let to = fixed::<D>(&r.to, "region.to")?;
    if let Some(k) = (0..D).find(|&k| !(0.0 <= from[k] && from[k] < to[k] && to[k] <= 1.0)) {
        return Err(format!(
            "species `{}`: region on axis {k} is [{}, {}], not a part of the box; regions are \
             fractions of the box with 0 <= from < to <= 1",
            s.name, from[k], to[k]
        ));
    }
    Ok((
        std::array::from_fn(|k| from[k] * size[k]),
        std::array::from_fn(|k| to[k] * size[k]),
    ))
}

/// 1D slots as slots on a line.
fn as_line<const D: usize>(slots: &[Slot<D>]) -> Vec<Slot<1>> {
    slots
        .iter()
        .map(|s| Slot {
            radius: s.radius,
            lo: [s.lo[0]],
            hi: [s.hi[0]],
            species: s.species,
        })
        .collect()
}

/// Regions trimmed to keep clear of the piston, which may cut off an end of
/// a region but not split one.
fn around<const D: usize>(
    slots: &[Slot<D>],
    [a, b]: [f64; 2],
    names: &[String],
) -> Result<Vec<Slot<D>>, String> {
    slots
        .iter()
        .map(|s| {
            let mut s = *s;
            if a < s.hi[0] && b > s.lo[0] {
                if a <= s.lo[0] {
                    s.lo[0] = b;
                } else if b >= s.hi[0] {
                    s.hi[0] = a;
                } else {
                    let name = names.get(s.species as usize).map_or("?", String::as_str);
                    return Err(format!(
                        "the piston at [{a}, {b}] lies inside the region of `{name}` ([{}, {}]); a \
                         lattice cannot straddle it: give the species regions on either side of the \
                         piston, or use random placement",
                        s.lo[0], s.hi[0]
                    ));
                }
            }
            Ok(s)
        })
        .collect()
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
