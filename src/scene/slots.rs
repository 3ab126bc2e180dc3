//! Where each species may go, in box coordinates: shared by the builder
//! (particle by particle) and the scene's checks (species by species), so
//! both see the same regions, trimmed the same way around a piston.

use super::refusal::{Blame, Refusal};
use super::space::Slot;
use crate::model::scene::{SceneSpec, SpeciesSpec};

/// Particles sharing a radius and a region: a whole species as the checks
/// see it, or a single particle (count 1) as a placement sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Group<const D: usize> {
    pub slot: Slot<D>,
    pub count: usize,
}

/// One group per slot: particles as placements see them.
pub fn singles<const D: usize>(slots: &[Slot<D>]) -> Vec<Group<D>> {
    slots.iter().map(|&slot| Group { slot, count: 1 }).collect()
}

/// The species with `piston.per_side` applied (it sets every count).
pub fn species(spec: &SceneSpec) -> Vec<SpeciesSpec> {
    let per_side = spec.piston.as_ref().and_then(|p| p.per_side);
    spec.species
        .iter()
        .map(|s| SpeciesSpec {
            count: per_side.unwrap_or(s.count),
            ..s.clone()
        })
        .collect()
}

/// A species' region in box coordinates (the whole box without one).
pub fn region<const D: usize>(s: &SpeciesSpec, size: &[f64; D]) -> ([f64; D], [f64; D]) {
    let Some(r) = &s.region else {
        return ([0.0; D], *size);
    };
    let at = |v: &[f64], k: usize, default: f64| v.get(k).copied().unwrap_or(default);
    (
        std::array::from_fn(|k| at(&r.from, k, 0.0) * size[k]),
        std::array::from_fn(|k| at(&r.to, k, 1.0) * size[k]),
    )
}

/// The piston: its centre along x and its half thickness (1D: its radius),
/// in a box of this length along x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piston {
    pub x: f64,
    pub half: f64,
    pub length: f64,
}

impl Piston {
    /// The stretch of x it takes.
    pub fn extent(&self) -> [f64; 2] {
        [self.x - self.half, self.x + self.half]
    }
}

/// Slots trimmed to keep clear of the piston, which may cut off an end of a
/// region but not lie inside one: a gas keeps to one side of it.
pub fn around<const D: usize>(
    slots: &[Slot<D>],
    piston: Piston,
    names: &[String],
) -> Result<Vec<Slot<D>>, Refusal> {
    let [a, b] = piston.extent();
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
                    return Err(straddled(&s, piston, names, D));
                }
            }
            Ok(s)
        })
        .collect()
}

fn straddled<const D: usize>(s: &Slot<D>, p: Piston, names: &[String], d: usize) -> Refusal {
    let name = names.get(s.species as usize).map_or("?", String::as_str);
    let wall = if d == 1 { "piston" } else { "piston wall" };
    // The example region ends a little short of the piston's near side.
    let end = ((p.x - p.half) / p.length * 100.0).floor() / 100.0;
    Refusal {
        species: s.species as usize,
        blame: Blame::Region,
        message: format!(
            "species {name:?} would be on both sides of the {wall} (at x = {}, half thickness {}): \
             its region [{}, {}] contains it",
            p.x, p.half, s.lo[0], s.hi[0]
        ),
        hint: format!(
            "the piston lies inside the region of `{name}`: give each species a region on either \
             side of it, e.g. `region = {{ from = [0.0], to = [{end}] }}`"
        ),
    }
}
