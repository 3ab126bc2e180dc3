//! `order = "alternating"`: one chain of rods whose species take turns, so
//! 1D only, the species in equal numbers on one shared stretch of line.

use super::{count, dimension};
use crate::model::problem::{Check, bad};
use crate::model::scene::{Placement, RodOrder, SceneSpec};

const KEY: &str = "scene.placement.order";

pub fn order(s: &SceneSpec) -> Check {
    let Some(Placement::Random {
        order: Some(RodOrder::Alternating),
    }) = &s.placement
    else {
        return Ok(());
    };
    let d = dimension(s);
    if d != 1 {
        return bad(
            KEY,
            format!("\"alternating\" orders rods along a line, and this scene is {d}D"),
            Some("leave `order` out in 2D and 3D (or make the scene 1D)"),
        );
    }
    if s.piston.is_some() {
        return bad(
            KEY,
            "\"alternating\" makes one chain of rods, and the piston cuts the line in two",
            Some("leave `order` out with a piston, or drop the piston"),
        );
    }
    let name = |i: usize| s.species[i].name.as_str();
    let region = |i: usize| {
        s.species[i]
            .region
            .as_ref()
            .map_or((vec![0.0], vec![1.0]), |r| (r.from.clone(), r.to.clone()))
    };
    for i in 1..s.species.len() {
        if count(s, i) != count(s, 0) {
            return bad(
                KEY,
                format!(
                    "\"alternating\" needs the species in equal numbers, but `{}` has {} and `{}` has {}",
                    name(0),
                    count(s, 0),
                    name(i),
                    count(s, i)
                ),
                Some(
                    "give every species the same count (sweep the counts together with \
                     `mode = \"zip\"`), or leave `order` out for a random order",
                ),
            );
        }
        if region(i) != region(0) {
            return bad(
                KEY,
                format!(
                    "\"alternating\" needs the species on one stretch of line, but `{}` and `{}` have different regions",
                    name(0),
                    name(i)
                ),
                Some("give every species the same `region` (or none), or leave `order` out"),
            );
        }
    }
    Ok(())
}
