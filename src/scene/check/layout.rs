//! Room: whether the particles can be put where they must go, asked of the
//! placements themselves (the same functions that place them), species by
//! species, at the smallest radius each may draw.

use super::{dimension, positions};
use crate::model::dimension::{ForDimension, in_dimension};
use crate::model::problem::{Check, Problem, bad, compact};
use crate::model::scene::{Boundary, Placement, SceneSpec};
use crate::scene::refusal::{Blame, Refusal};
use crate::scene::slots::{self, Group, Piston};
use crate::scene::space::{Slot, Space};
use crate::scene::{lattice, piston, placement, rods};

pub fn layout(s: &SceneSpec) -> Check {
    // Another dimension is refused before this check.
    in_dimension(dimension(s), Room(s)).unwrap_or(Ok(()))
}

/// Room for the scene's particles in its dimension.
struct Room<'a>(&'a SceneSpec);

impl ForDimension for Room<'_> {
    type Output = Check;
    fn run<const D: usize>(self) -> Check {
        at::<D>(self.0)
    }
}

fn at<const D: usize>(s: &SceneSpec) -> Check {
    let Some(size) = s
        .box_size
        .as_deref()
        .and_then(|b| <[f64; D]>::try_from(b).ok())
    else {
        return Ok(());
    };
    let periodic: [bool; D] = std::array::from_fn(|k| {
        s.boundary.as_ref().and_then(|b| b.get(k)) == Some(&Boundary::Periodic)
    });
    let space = Space { size, periodic };
    let species = slots::species(s);
    let names: Vec<String> = species.iter().map(|sp| sp.name.clone()).collect();
    let groups: Vec<Group<D>> = species
        .iter()
        .enumerate()
        .filter(|(_, sp)| sp.count > 0)
        .map(|(i, sp)| {
            let (lo, hi) = slots::region(sp, &size);
            Group {
                slot: Slot {
                    radius: sp.radius.bounds()[0],
                    lo,
                    hi,
                    species: i as u16,
                },
                count: sp.count,
            }
        })
        .collect();
    if D > 1 {
        periodic_room(&groups, &space)?;
    }
    let piston = s.piston.as_ref().map(|p| piston::at(p, size[0]));
    let room = match s
        .placement
        .as_ref()
        .unwrap_or(&Placement::Random { order: None })
    {
        Placement::Explicit { positions } => {
            return positions::positions(&species, positions, &space, piston);
        }
        Placement::Random { .. } | Placement::Compress { .. } if D == 1 => {
            rods::room(&on_line(&groups), piston.map(|p| p.extent()))
        }
        Placement::Random { .. } => {
            clear(&groups, piston, &names).and_then(|g| placement::room(&g, &space))
        }
        Placement::Compress { .. } => placement::room(&groups, &space),
        Placement::Lattice { lattice } => clear(&groups, piston, &names)
            .and_then(|g| lattice::room(&g, &space, lattice.as_deref(), &names)),
    };
    room.map_err(|r| problem(s, r))
}

/// The engine's neighbour lists need a periodic axis to be longer than
/// about three diameters of the largest particle (the rule is the engine's:
/// `NeighbourList::build` refuses the same).
fn periodic_room<const D: usize>(groups: &[Group<D>], space: &Space<D>) -> Check {
    let largest = groups.iter().map(|g| g.slot.radius).fold(0.0, f64::max);
    let sigma = 2.0 * largest;
    for k in 0..D {
        let l = space.size[k];
        if space.periodic[k] && l / 6.0 - largest < 0.01 * sigma.max(f64::MIN_POSITIVE) {
            return bad(
                format!("scene.box.{k}"),
                format!(
                    "periodic axis {k} is {} long, too short for particles of diameter {}",
                    compact(l),
                    compact(sigma)
                ),
                Some(&format!(
                    "make it at least {} long, or use walls on that axis",
                    compact(3.0 * sigma * 1.02)
                )),
            );
        }
    }
    Ok(())
}

/// Groups with their regions trimmed clear of the piston, if any.
fn clear<const D: usize>(
    groups: &[Group<D>],
    piston: Option<Piston>,
    names: &[String],
) -> Result<Vec<Group<D>>, Refusal> {
    let Some(p) = piston else {
        return Ok(groups.to_vec());
    };
    let slots: Vec<Slot<D>> = groups.iter().map(|g| g.slot).collect();
    let trimmed = slots::around(&slots, p, names)?;
    Ok(groups
        .iter()
        .zip(trimmed)
        .map(|(g, slot)| Group {
            slot,
            count: g.count,
        })
        .collect())
}

/// 1D groups as groups on a line.
fn on_line<const D: usize>(groups: &[Group<D>]) -> Vec<Group<1>> {
    groups
        .iter()
        .map(|g| Group {
            slot: Slot {
                radius: g.slot.radius,
                lo: [g.slot.lo[0]],
                hi: [g.slot.hi[0]],
                species: g.slot.species,
            },
            count: g.count,
        })
        .collect()
}

/// A refusal at the key to change: the count (or `per_side`, which sets
/// it), or the region (the species, when it has none of its own).
fn problem(s: &SceneSpec, r: Refusal) -> Problem {
    let i = r.species;
    let per_side = s.piston.as_ref().and_then(|p| p.per_side).is_some();
    let has_region = s.species.get(i).is_some_and(|sp| sp.region.is_some());
    let key = match r.blame {
        Blame::Count if per_side => "scene.piston.per_side".to_string(),
        Blame::Count => format!("scene.species.{i}.count"),
        Blame::Region if has_region => format!("scene.species.{i}.region"),
        Blame::Region => format!("scene.species.{i}"),
    };
    Problem {
        key,
        message: r.message,
        hint: Some(r.hint),
    }
}
