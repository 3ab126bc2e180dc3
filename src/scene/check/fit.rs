//! The particles sharing each region must fit in it: rods side by side in
//! 1D (the builder lays them so), disks and spheres at the packing fraction
//! the placement can reach. Lattices count their sites instead (`layout`).

use super::{count, dimension};
use crate::model::problem::{Check, Problem, bad, compact};
use crate::model::scene::{Placement, SceneSpec};
use crate::scene::compress;
use crate::scene::placement::JAMMING;
use crate::scene::space::ball_volume;

pub fn particles_fit(s: &SceneSpec) -> Check {
    let d = dimension(s);
    let Some(size) = &s.box_size else {
        return Ok(());
    };
    // The densest the placement reaches, what it is called, what else to use.
    let (limit, method, instead) = match (d, &s.placement) {
        (_, Some(Placement::Explicit { .. } | Placement::Lattice { .. })) => return Ok(()),
        (1, _) => (1.0, "", ""),
        (_, None | Some(Placement::Random { .. })) => (
            JAMMING[d - 2],
            "random insertion jams at",
            "use `placement = { kind = \"compress\" }` for dense fluids or `{ kind = \"lattice\" }` for crystals, or ",
        ),
        (_, Some(Placement::Compress { .. })) => (
            compress::LIMIT[d - 2],
            "compression reaches at most",
            "use `placement = { kind = \"lattice\" }` for denser crystals, or ",
        ),
    };
    // (region per axis, volume its particles fill, their number, first species in it)
    type Filled = (Vec<(f64, f64)>, f64, usize, usize);
    let mut regions: Vec<Filled> = Vec::new();
    for (i, sp) in s.species.iter().enumerate() {
        let region: Vec<(f64, f64)> = (0..d)
            .map(|k| {
                sp.region
                    .as_ref()
                    .map_or((0.0, 1.0), |r| (r.from[k], r.to[k]))
            })
            .collect();
        let n = count(s, i);
        let filled = ball_volume(d, sp.radius.bounds()[0]) * n as f64;
        match regions.iter_mut().find(|(r, ..)| *r == region) {
            Some((_, occupied, number, _)) => {
                *occupied += filled;
                *number += n;
            }
            None => regions.push((region, filled, n, i)),
        }
    }
    for (region, filled, n, first) in regions {
        let volume: f64 = region
            .iter()
            .zip(size)
            .map(|((lo, hi), l)| (hi - lo) * l)
            .product();
        if filled <= limit * volume {
            continue;
        }
        if let Some(p) = too_narrow(s, &region, size) {
            return Err(p);
        }
        let key = match s.piston.as_ref().and_then(|p| p.per_side) {
            Some(_) => "scene.piston.per_side".to_string(),
            None => format!("scene.species.{first}.count"),
        };
        let (message, hint) = if d == 1 {
            (
                format!(
                    "rods of total length {} do not fit in their region of length {}",
                    compact(filled),
                    compact(volume)
                ),
                format!(
                    "{n} rods need a length of {}: use fewer or shorter rods, or a longer box or region",
                    compact(filled)
                ),
            )
        } else {
            (
                format!(
                    "the particles would fill packing fraction {:.4} of their region; {method} \
                     {limit} in {d}D",
                    filled / volume
                ),
                format!("{instead}use fewer or smaller particles, or a larger box or region"),
            )
        };
        return bad(key, message, Some(&hint));
    }
    Ok(())
}

/// A region too full because one of its particles is wider than it along
/// an axis: the box (or the region) is at fault there, not the count.
fn too_narrow(s: &SceneSpec, region: &[(f64, f64)], size: &[f64]) -> Option<Problem> {
    let d = region.len();
    let length = |k: usize| (region[k].1 - region[k].0) * size[k];
    let (i, sp, k) = s.species.iter().enumerate().find_map(|(i, sp)| {
        let same = (0..d).all(|k| {
            sp.region
                .as_ref()
                .map_or((0.0, 1.0), |r| (r.from[k], r.to[k]))
                == region[k]
        });
        let diameter = 2.0 * sp.radius.bounds()[0];
        let k = (0..d).find(|&k| diameter > length(k))?;
        (same && count(s, i) > 0).then_some((i, sp, k))
    })?;
    let diameter = 2.0 * sp.radius.bounds()[0];
    let whole = region[k] == (0.0, 1.0);
    let (key, what) = if whole {
        (format!("scene.box.{k}"), "the box")
    } else {
        (format!("scene.species.{i}.region"), "its region")
    };
    Some(Problem {
        key,
        message: format!(
            "axis {k} of {what} is {} long, shorter than one particle of species `{}` \
             (diameter {})",
            compact(length(k)),
            sp.name,
            compact(diameter)
        ),
        hint: Some(format!(
            "make axis {k} at least {} long, or the particles smaller",
            compact(diameter)
        )),
    })
}
