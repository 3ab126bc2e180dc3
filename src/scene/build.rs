//! Scene -> particles in a box, ready for the engine. All randomness comes
//! from the run's seeded stream, in a fixed order: masses and radii (particle
//! by particle), positions, the gas's velocities, the piston's.

use super::compress::{self, Preparation, Settings};
use super::slots::{self, Piston};
use super::space::{Slot, Space};
use super::{check, lattice, piston, placement, rods, velocities};
use crate::engine::{Axis, Particle, SimBox, Wall};
use crate::model::scene::{
    Boundary, CompressFrom, Drawn, Placement, RodOrder, SceneSpec, Side, Velocities,
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

/// Refuses, with the scene's checks (the ones `study validate` runs), any
/// scene that cannot be built; then draws it.
pub fn build<const D: usize>(spec: &SceneSpec, rng: &mut ChaCha8Rng) -> Result<Built<D>, String> {
    check::scene(spec).map_err(|p| p.to_string())?;
    let d = check::dimension(spec);
    if d != D {
        return Err(format!("the scene is {d}D but was built as {D}D"));
    }
    let sim_box = sim_box::<D>(spec)?;
    let space = Space {
        size: sim_box.size,
        periodic: std::array::from_fn(|k| sim_box.axes[k].is_periodic()),
    };
    let species = slots::species(spec);
    let names: Vec<String> = species.iter().map(|s| s.name.clone()).collect();
    let obstacle = spec
        .piston
        .as_ref()
        .map(|ps| piston::at(ps, sim_box.size[0]));

    // Masses, radii and regions, particle by particle.
    let mut inv_mass = Vec::new();
    let mut slots = Vec::new();
    for (index, s) in species.iter().enumerate() {
        let (lo, hi) = slots::region::<D>(s, &sim_box.size);
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

    let mut prepared = None;
    let positions = match spec
        .placement
        .clone()
        .unwrap_or(Placement::Random { order: None })
    {
        Placement::Random { order } if D == 1 => rods::place(
            &as_line(&slots),
            obstacle.map(|p| p.extent()),
            &names,
            order == Some(RodOrder::Alternating),
            rng,
        )?
        .into_iter()
        .map(|[x]| std::array::from_fn(|_| x))
        .collect(),
        Placement::Compress { .. } if D == 1 => rods::place(
            &as_line(&slots),
            obstacle.map(|p| p.extent()),
            &names,
            false,
            rng,
        )?
        .into_iter()
        .map(|[x]| std::array::from_fn(|_| x))
        .collect(),
        Placement::Random { .. } => {
            // Beside a piston wall each gas keeps to its own side.
            placement::random(&clear_of(&slots, obstacle, &names)?, &space, rng)?
        }
        Placement::Lattice { lattice } => lattice::place(
            &clear_of(&slots, obstacle, &names)?,
            &space,
            lattice.as_deref(),
            &names,
            rng,
        )?,
        Placement::Compress { growth_rate, from } => {
            let settings = Settings {
                growth_rate: growth_rate.unwrap_or(compress::GROWTH_RATE),
                from: from.unwrap_or(CompressFrom::Random),
            };
            let (x, cost) = compress::compress(&slots, &space, &names, &settings, rng)?;
            prepared = Some(cost);
            x
        }
        Placement::Explicit { positions } => positions
            .iter()
            .map(|p| Ok(space.fold(fixed::<D>(p, "placement.positions")?)))
            .collect::<Result<_, String>>()?,
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

/// The box a scene runs in: its lengths, and per axis walls (hard or
/// thermal) or a periodic boundary.
pub(crate) fn sim_box<const D: usize>(spec: &SceneSpec) -> Result<SimBox<D>, String> {
    let size = fixed::<D>(spec.box_size.as_deref().unwrap_or_default(), "scene.box")?;
    let boundary = spec
        .boundary
        .clone()
        .unwrap_or_else(|| vec![Boundary::Walls; D]);
    let mut axes: [Axis; D] = std::array::from_fn(|k| match boundary.get(k) {
        Some(Boundary::Periodic) => Axis::Periodic,
        _ => Axis::HARD,
    });
    for w in &spec.thermal_walls {
        if let Some(Axis::Walls { low, high }) = axes.get_mut(w.axis) {
            let wall = Wall::Thermal {
                temperature: w.temperature,
            };
            match w.side {
                Side::Low => *low = wall,
                Side::High => *high = wall,
            }
        }
    }
    Ok(SimBox { size, axes })
}

fn draw(value: Drawn, rng: &mut ChaCha8Rng) -> f64 {
    match value {
        Drawn::Fixed(x) => x,
        Drawn::Range([a, b]) => a + (b - a) * rng.random::<f64>(),
    }
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

/// Regions trimmed to keep clear of the piston, if there is one.
fn clear_of<const D: usize>(
    slots: &[Slot<D>],
    piston: Option<Piston>,
    names: &[String],
) -> Result<Vec<Slot<D>>, String> {
    match piston {
        Some(p) => slots::around(slots, p, names).map_err(|r| r.to_string()),
        None => Ok(slots.to_vec()),
    }
}

/// A list of one number per axis as an array (`check` has seen to its length).
fn fixed<const D: usize>(values: &[f64], key: &str) -> Result<[f64; D], String> {
    values
        .try_into()
        .map_err(|_| format!("{key} has {} entries for {D} axes", values.len()))
}
