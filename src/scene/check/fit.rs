//! The particles sharing each region must fit in it: rods side by side in
//! 1D (the builder lays them so), disks and spheres at the packing fraction
//! the placement can reach. Lattices count their sites instead (`layout`).

use super::{count, dimension};
use crate::model::problem::{Check, bad};
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
        let key = match s.piston.as_ref().and_then(|p| p.per_side) {
            Some(_) => "scene.piston.per_side".to_string(),
            None => format!("scene.species.{first}.count"),
        };
        let (message, hint) = if d == 1 {
            (
                format!(
                    "rods of total length {filled} do not fit in their region of length {volume}"
                ),
                format!(
                    "{n} rods need a length of {filled}: use fewer or shorter rods, or a longer box or region"
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
