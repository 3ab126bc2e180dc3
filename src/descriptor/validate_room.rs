//! Rods need room to move: on a line filled end to end, or in a stretch
//! shut in by immovable rods (or walls) that its rods fill exactly, a
//! moving rod meets its neighbour at once, and again, and every event comes
//! at one instant: the clock would never move on. Such a scene can be
//! built (placement fills a line exactly), but not run: refused for what
//! the spec makes certain (radii drawn from a range count at their
//! smallest, so only a certain fill is refused).

use crate::model::problem::{Check, bad, compact};
use crate::model::scene::{Boundary, Drawn, Placement, SceneSpec};
use crate::scene::check::{count, dimension};

/// A stretch with less free length than this share of the box counts as
/// shut (round-off in the positions given, or a gap so thin that its
/// events would come faster than the clock resolves).
const TIGHT: f64 = 1e-12;

pub fn room(s: &SceneSpec) -> Check {
    if dimension(s) != 1 {
        return Ok(());
    }
    let Some(&[length]) = s.box_size.as_deref() else {
        return Ok(());
    };
    let movable = |i: usize| s.species[i].mass != Drawn::Fixed(f64::INFINITY);
    let species = || (0..s.species.len()).filter(|&i| count(s, i) > 0);
    if !species().any(movable) && s.piston.is_none() {
        return Ok(());
    }
    let filled: f64 = species()
        .map(|i| 2.0 * s.species[i].radius.bounds()[0] * count(s, i) as f64)
        .sum::<f64>()
        + s.piston.as_ref().map_or(0.0, |p| 2.0 * p.radius);
    if length - filled <= TIGHT * length {
        return bad(
            "scene.box.0",
            format!(
                "{} is the rods' diameters end to end ({}): filled, the line leaves none of them room to move, and every event would come at one instant",
                compact(length),
                compact(filled)
            ),
            Some("make the box longer, or the rods fewer or thinner"),
        );
    }
    caged(s, length)
}

/// Explicit positions with immovable rods: each stretch between two of
/// them (or a wall) must leave its movable rods some room.
fn caged(s: &SceneSpec, length: f64) -> Check {
    let Some(Placement::Explicit { positions }) = &s.placement else {
        return Ok(());
    };
    let immovable = |i: usize| s.species[i].mass == Drawn::Fixed(f64::INFINITY);
    if s.piston.is_some() || !(0..s.species.len()).any(|i| immovable(i) && count(s, i) > 0) {
        return Ok(());
    }
    // (centre, radius, immovable, index in the positions list)
    let mut rods: Vec<(f64, f64, bool, usize)> = Vec::new();
    for (i, sp) in s.species.iter().enumerate() {
        let Drawn::Fixed(r) = sp.radius else {
            return Ok(());
        };
        let immovable = sp.mass == Drawn::Fixed(f64::INFINITY);
        for _ in 0..count(s, i) {
            let k = rods.len();
            let Some(&[x]) = positions.get(k).map(Vec::as_slice) else {
                return Ok(());
            };
            rods.push((x, r, immovable, k));
        }
    }
    let periodic = s
        .boundary
        .as_ref()
        .is_some_and(|b| b.first() == Some(&Boundary::Periodic));
    rods.sort_by(|a, b| a.0.total_cmp(&b.0));
    // On a ring, the stretch past the last immovable rod wraps round to
    // the first; between walls the walls close the ends.
    let first = rods.iter().position(|r| r.2).unwrap_or(0);
    let order: Vec<(f64, f64, bool, usize)> = if periodic {
        let mut o = rods[first..].to_vec();
        o.extend(
            rods[..first]
                .iter()
                .map(|&(x, r, m, k)| (x + length, r, m, k)),
        );
        o.push((rods[first].0 + length, rods[first].1, true, rods[first].3));
        o
    } else {
        let mut o = vec![(0.0, 0.0, true, usize::MAX)];
        o.extend(rods.iter().copied());
        o.push((length, 0.0, true, usize::MAX));
        o
    };
    let mut start = 0;
    for end in 1..order.len() {
        if !order[end].2 {
            continue;
        }
        let inside = &order[start + 1..end];
        if let Some(&(_, _, _, k)) = inside.first() {
            let free = (order[end].0 - order[end].1)
                - (order[start].0 + order[start].1)
                - inside.iter().map(|r| 2.0 * r.1).sum::<f64>();
            if free <= TIGHT * length {
                return bad(
                    format!("scene.placement.positions.{k}"),
                    format!(
                        "the rod at {} is shut in with no room to move: the immovable rods or walls on either side leave its stretch a free length of {}, and every event would come at one instant",
                        compact(order[start + 1].0 % length),
                        compact(free.max(0.0))
                    ),
                    Some("leave a gap between the immovable rods and the rods they hold in"),
                );
            }
        }
        start = end;
    }
    Ok(())
}
