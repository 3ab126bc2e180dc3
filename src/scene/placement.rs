//! Random placement in 2D and 3D: random sequential insertion (RSA), each
//! particle uniform in its region among the positions the earlier ones leave
//! free. (1D is exact at any density: see `rods.rs`.)

use super::refusal::{Blame, Refusal};
use super::slots::Group;
use super::space::{CellList, Slot, Space};
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// Tries per particle before random insertion is given up as jammed.
const TRIES: usize = 100_000;

/// Packing fractions at which random sequential insertion jams in an
/// unbounded space (2D, 3D); finite boxes with walls jam below them.
pub const JAMMING: [f64; 2] = [0.547, 0.384];

/// Refuses, rather than loops forever, when a region is too full.
pub fn random<const D: usize>(
    slots: &[Slot<D>],
    space: &Space<D>,
    rng: &mut ChaCha8Rng,
) -> Result<Vec<[f64; D]>, String> {
    let reach = 2.0 * slots.iter().map(|s| s.radius).fold(0.0, f64::max);
    let mut cells = CellList::new(*space, reach, slots.len())?;
    let mut placed: Vec<[f64; D]> = Vec::with_capacity(slots.len());
    for (i, s) in slots.iter().enumerate() {
        let ranges = ranges(s, space).map_err(|r| r.to_string())?;
        let mut found = None;
        for _ in 0..TRIES {
            let x: [f64; D] = std::array::from_fn(|k| {
                let (lo, hi) = ranges[k];
                lo + (hi - lo) * rng.random::<f64>()
            });
            let free = cells.near_point(&x).all(|j| {
                let r = space.separation(&x, &placed[j]);
                let d2: f64 = r.iter().map(|c| c * c).sum();
                d2 >= (s.radius + slots[j].radius).powi(2)
            });
            if free {
                found = Some(x);
                break;
            }
        }
        let Some(x) = found else {
            return Err(format!(
                "could not place particle {i} at random without overlap after {TRIES} tries ({} placed); \
                 random insertion jams near packing fraction {} in {D}D (and well before that in \
                 practice): use `placement = {{ kind = \"compress\" }}` for dense \
                 fluids and glasses, `{{ kind = \"lattice\" }}` for crystals, or fewer or smaller \
                 particles or a larger region",
                placed.len(),
                JAMMING[D - 2]
            ));
        };
        cells.push(&x);
        placed.push(x);
    }
    Ok(placed)
}

/// Refuses particles wider than their region: the checks ask it species by
/// species, random insertion particle by particle.
pub fn room<const D: usize>(groups: &[Group<D>], space: &Space<D>) -> Result<(), Refusal> {
    groups
        .iter()
        .try_for_each(|g| ranges(&g.slot, space).map(|_| ()))
}

/// Where a particle's centre may go along each axis: anywhere around an
/// axis its region wraps, otherwise one radius in from the region's ends.
pub fn ranges<const D: usize>(s: &Slot<D>, space: &Space<D>) -> Result<[(f64, f64); D], Refusal> {
    let mut out = [(0.0, 0.0); D];
    for k in 0..D {
        out[k] = if space.wraps(&s.lo, &s.hi, k) {
            (0.0, space.size[k])
        } else if s.hi[k] - s.lo[k] >= 2.0 * s.radius {
            (s.lo[k] + s.radius, s.hi[k] - s.radius)
        } else {
            return Err(Refusal {
                species: s.species as usize,
                blame: Blame::Region,
                message: format!(
                    "a particle of radius {} does not fit in its region along axis {k}, which is {} long",
                    s.radius,
                    s.hi[k] - s.lo[k]
                ),
                hint: "widen the region or the box, or use smaller particles".into(),
            });
        };
    }
    Ok(out)
}
