//! The scene's checks, written once: everything the builder would refuse,
//! found from the resolved spec before anything is drawn. `study validate`
//! places a problem at its key in the file; `build` runs the same checks
//! first and fails with the same problem.
//!
//! What depends on the draws can still fail a run: random insertion that
//! jams below its limit, compression that jams, rods in overlapping regions
//! that no exact placement is found for. A radius drawn from a range counts
//! at its smallest here, so only what is certain to fail is refused.

mod fit;
mod grid;
mod layout;
mod motion;
mod order;
mod piston;
mod positions;
mod species;
mod walls;

use crate::model::problem::{Check, bad, compact, positive};
use crate::model::scene::{Placement, SceneSpec};

/// Particles per run: at ~300 bytes each (3D), 15 GB.
pub const MAX_PARTICLES: usize = 50_000_000;

/// The dimension a scene runs in: as given (or, before it is resolved, as
/// its box says), else 1 (what the simulator uses).
pub fn dimension(s: &SceneSpec) -> usize {
    s.dimension.or_else(|| s.dimension().ok()).unwrap_or(1)
}

/// Particles of species `i`, after `piston.per_side` (which sets every count).
pub fn count(s: &SceneSpec, i: usize) -> usize {
    s.piston
        .as_ref()
        .and_then(|p| p.per_side)
        .unwrap_or(s.species[i].count)
}

/// Particles the scene places (the piston is not among them).
pub fn particles(s: &SceneSpec) -> usize {
    (0..s.species.len()).map(|i| count(s, i)).sum()
}

/// Check a resolved scene (no preset left).
pub fn scene(s: &SceneSpec) -> Check {
    let d = dimension(s);
    if !(1..=3).contains(&d) {
        return bad(
            "scene.dimension",
            format!("must be 1, 2 or 3, got {d}"),
            Some("1 = rods, 2 = disks, 3 = spheres"),
        );
    }
    let Some(size) = &s.box_size else {
        return bad(
            "scene.box",
            "is missing",
            Some(
                "give one edge length per axis (their number sets the dimension), e.g. \
                 `box = [20.0]`, or start from a `preset`",
            ),
        );
    };
    axes("scene.box", size.len(), "lengths", s)?;
    for (i, &l) in size.iter().enumerate() {
        positive(&format!("scene.box.{i}"), l).map_err(|mut p| {
            p.hint = Some(format!("give axis {i} a finite length > 0"));
            p
        })?;
    }
    if let Some(b) = &s.boundary {
        axes("scene.boundary", b.len(), "entries", s)?;
    }
    species::species(s)?;
    fit::particles_fit(s)?;
    let volume: f64 = size.iter().product();
    if !(volume.is_finite() && volume >= f64::MIN_POSITIVE) {
        return bad(
            "scene.box",
            format!(
                "lengths {} give a volume of {}, beyond what a 64-bit number holds",
                size.iter()
                    .map(|&l| compact(l))
                    .collect::<Vec<_>>()
                    .join(" x "),
                if volume > 1.0 {
                    "more than 1e308"
                } else {
                    "less than 1e-308"
                }
            ),
            Some("work in reduced units: particles about 1 across, boxes from about 1 to 1e6 long"),
        );
    }
    placement(s)?;
    order::order(s)?;
    motion::velocities(s)?;
    piston::piston(s)?;
    walls::thermal_walls(s)?;
    layout::layout(s)?;
    grid::grid(s)
}

/// A list with one entry per axis.
fn axes(key: &str, n: usize, what: &str, s: &SceneSpec) -> Check {
    let d = dimension(s);
    if n == d {
        return Ok(());
    }
    let hint = match s.dimension {
        Some(_) => format!("the scene's dimension is {d}: give {d} {what}, one per axis"),
        None => format!("the dimension defaults to 1; set `dimension = {n}` if you mean {n}D"),
    };
    bad(
        key,
        format!("has {n} entries but the scene has dimension {d}"),
        Some(&hint),
    )
}

/// Finite numbers, one per axis.
fn vector(key: &str, v: &[f64], s: &SceneSpec) -> Check {
    axes(key, v.len(), "finite numbers", s)?;
    match v.iter().position(|x| !x.is_finite()) {
        Some(k) => bad(
            format!("{key}.{k}"),
            format!("must be a finite number, got {}", compact(v[k])),
            None,
        ),
        None => Ok(()),
    }
}

/// A list of vectors, each one finite number per axis (the key of each is
/// only written out for the one at fault: lists may be long).
fn vectors(key: &str, list: &[Vec<f64>], s: &SceneSpec) -> Check {
    let d = dimension(s);
    match list
        .iter()
        .position(|v| v.len() != d || v.iter().any(|x| !x.is_finite()))
    {
        Some(i) => vector(&format!("{key}.{i}"), &list[i], s),
        None => Ok(()),
    }
}

/// A finite mass whose inverse (what the engine stores) is finite too;
/// `hint` says what masses may be when this one is not positive.
fn mass(key: &str, m: f64, hint: Option<&str>) -> Check {
    positive(key, m).map_err(|mut p| {
        p.hint = hint.map(str::to_string);
        p
    })?;
    if (1.0 / m).is_finite() {
        Ok(())
    } else {
        bad(
            key,
            format!("{m:e} is too small: its inverse overflows"),
            Some("masses from 1e-300 up work (and `inf` for an immovable particle)"),
        )
    }
}

/// What the placement asks for, before any room is counted: the right
/// number of explicit positions, a lattice of this dimension, a growth rate
/// and particles that compression can move.
fn placement(s: &SceneSpec) -> Check {
    let d = dimension(s);
    match &s.placement {
        Some(Placement::Explicit { positions }) => {
            let n = particles(s);
            if positions.len() != n {
                return bad(
                    "scene.placement.positions",
                    format!("has {} entries for {n} particles", positions.len()),
                    Some(
                        "one per particle, species by species: give one position per particle \
                         of each species, in the order of `[[scene.species]]`",
                    ),
                );
            }
            vectors("scene.placement.positions", positions, s)
        }
        Some(Placement::Lattice {
            lattice: Some(kind),
        }) => {
            let valid: &[&str] = match d {
                1 => &["line"],
                2 => &["square", "hexagonal"],
                _ => &["cubic", "fcc"],
            };
            if valid.contains(&kind.as_str()) {
                return Ok(());
            }
            let names: Vec<String> = valid.iter().map(|v| format!("\"{v}\"")).collect();
            bad(
                "scene.placement.lattice",
                format!("\"{kind}\" is not a lattice in {d}D"),
                Some(&format!("instead of `{kind}`, use {}", names.join(" or "))),
            )
        }
        Some(Placement::Compress { .. }) if d == 1 => bad(
            "scene.placement.kind",
            "\"compress\" grows disks or spheres (2D/3D); rods on a line need no compression",
            Some("use `kind = \"random\"`: in 1D it places rods exactly at random at any density"),
        ),
        Some(Placement::Compress { growth_rate, .. }) => {
            if let Some(rate) = growth_rate {
                positive("scene.placement.growth_rate", *rate).map_err(|mut p| {
                    p.hint = Some(format!(
                        "a fraction of the final size gained per unit time (default {})",
                        crate::scene::compress::GROWTH_RATE
                    ));
                    p
                })?;
            }
            Ok(())
        }
        _ => Ok(()),
    }
}
