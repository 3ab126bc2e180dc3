//! Checks of a scene after its preset is resolved: everything the scene
//! builder would refuse at run time, found before anything runs.

use crate::descriptor::validate::{Check, bad, non_negative, positive};
use crate::model::scene::{Boundary, Mass, Placement, SceneSpec, Side, SpeciesSpec, Velocities};
use crate::scene::compress;
use crate::scene::placement::JAMMING;
use crate::scene::space::ball_volume;

/// Particles per run: at ~300 bytes each (3D), 15 GB.
const MAX_PARTICLES: usize = 50_000_000;

/// The dimension a scene runs in: as given, else 1 (what the simulator uses).
pub fn dimension(s: &SceneSpec) -> usize {
    s.dimension.unwrap_or(1)
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
            Some("give one edge length per axis, e.g. `box = [20.0]`, or start from a `preset`"),
        );
    };
    axes("scene.box", size.len(), s)?;
    for (i, &l) in size.iter().enumerate() {
        positive(&format!("scene.box.{i}"), l)?;
    }
    if let Some(b) = &s.boundary {
        axes("scene.boundary", b.len(), s)?;
    }
    species(s)?;
    particles_fit(s)?;
    placement(s)?;
    velocities(s)?;
    piston(s)?;
    thermal_walls(s)
}

/// A list with one entry per axis.
fn axes(key: &str, n: usize, s: &SceneSpec) -> Check {
    let d = dimension(s);
    if n == d {
        return Ok(());
    }
    let hint = match s.dimension {
        Some(_) => "give one entry per axis".to_string(),
        None => format!("the dimension defaults to 1; set `dimension = {n}` if you mean {n}D"),
    };
    bad(
        key,
        format!("has {n} entries but the scene has dimension {d}"),
        Some(&hint),
    )
}

/// `n` finite numbers, one per axis.
fn vector(key: &str, v: &[f64], s: &SceneSpec) -> Check {
    axes(key, v.len(), s)?;
    match v.iter().position(|x| !x.is_finite()) {
        Some(k) => bad(
            format!("{key}.{k}"),
            format!("must be a finite number, got {}", v[k]),
            None,
        ),
        None => Ok(()),
    }
}

fn species(s: &SceneSpec) -> Check {
    if s.species.is_empty() {
        return bad(
            "scene.species",
            "the scene has no particles",
            Some("add a `[[scene.species]]` table with `name` and `count`"),
        );
    }
    let n = particles(s);
    if n > MAX_PARTICLES {
        return bad(
            "scene.species",
            format!("{n} particles are more than one run can hold ({MAX_PARTICLES} at most)"),
            Some("the engine needs about 100-300 bytes per particle; use fewer particles"),
        );
    }
    let per_side = s.piston.as_ref().and_then(|p| p.per_side);
    if per_side == Some(0) {
        return bad(
            "scene.piston.per_side",
            "must be at least 1",
            Some("it sets the particle count of every species"),
        );
    }
    for (i, sp) in s.species.iter().enumerate() {
        let key = |k: &str| format!("scene.species.{i}.{k}");
        if sp.name.trim().is_empty() {
            return bad(
                key("name"),
                "must not be empty",
                Some("e.g. `name = \"gas\"`"),
            );
        }
        if sp.name == "piston" && s.piston.is_some() {
            return bad(
                key("name"),
                "\"piston\" names the piston in this scene",
                Some("give the species another name"),
            );
        }
        if s.species[..i].iter().any(|o| o.name == sp.name) {
            return bad(
                key("name"),
                format!("species {:?} is named twice", sp.name),
                Some("give each species its own name"),
            );
        }
        if per_side.is_none() && sp.count == 0 {
            return bad(
                key("count"),
                "must be at least 1",
                Some("remove the species instead"),
            );
        }
        for r in sp.radius.bounds() {
            non_negative(&key("radius"), r)?;
        }
        match sp.mass {
            Mass::Fixed(m) if m == f64::INFINITY => {}
            Mass::Fixed(m) => mass(&key("mass"), m)?,
            Mass::Range([lo, hi]) => {
                mass(&key("mass"), lo)?;
                mass(&key("mass"), hi)?;
                if lo > hi {
                    return bad(
                        key("mass"),
                        format!("range [{lo}, {hi}] is reversed"),
                        Some("write `[lo, hi]` with lo <= hi"),
                    );
                }
            }
        }
        if let Some(r) = &sp.region {
            axes(&key("region.from"), r.from.len(), s)?;
            axes(&key("region.to"), r.to.len(), s)?;
            for (a, (&lo, &hi)) in r.from.iter().zip(&r.to).enumerate() {
                if !(0.0..=1.0).contains(&lo) || !(0.0..=1.0).contains(&hi) || lo >= hi {
                    return bad(
                        key("region"),
                        format!("axis {a}: [{lo}, {hi}] is not a part of the box"),
                        Some("regions are fractions of the box: 0 <= from < to <= 1"),
                    );
                }
            }
        }
    }
    Ok(())
}

fn placement(s: &SceneSpec) -> Check {
    let d = dimension(s);
    match &s.placement {
        Some(Placement::Explicit { positions }) => {
            let n = particles(s);
            if positions.len() != n {
                return bad(
                    "scene.placement.positions",
                    format!("has {} entries for {n} particles", positions.len()),
                    Some("give one position per particle, species by species"),
                );
            }
            for (i, p) in positions.iter().enumerate() {
                vector(&format!("scene.placement.positions.{i}"), p, s)?;
            }
            Ok(())
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
                Some(&format!("use {}", names.join(" or "))),
            )
        }
        _ => Ok(()),
    }
}

fn velocities(s: &SceneSpec) -> Check {
    let energy = |e: &Option<f64>| match e {
        Some(e) => positive("scene.velocities.energy", *e),
        None => Ok(()),
    };
    match &s.velocities {
        Some(Velocities::Maxwell {
            temperature,
            energy: e,
            ..
        }) => {
            positive("scene.velocities.temperature", *temperature)?;
            energy(e)
        }
        Some(Velocities::Uniform { p, energy: e, .. }) => {
            positive("scene.velocities.p", *p)?;
            energy(e)
        }
        Some(Velocities::Equal { velocity }) => vector("scene.velocities.velocity", velocity, s),
        Some(Velocities::Explicit { velocities }) => {
            let n = particles(s);
            if velocities.len() != n {
                return bad(
                    "scene.velocities.velocities",
                    format!("has {} entries for {n} particles", velocities.len()),
                    Some("give one velocity per particle, species by species"),
                );
            }
            for (i, v) in velocities.iter().enumerate() {
                vector(&format!("scene.velocities.velocities.{i}"), v, s)?;
            }
            Ok(())
        }
        None => Ok(()),
    }
}

fn piston(s: &SceneSpec) -> Check {
    let Some(p) = &s.piston else { return Ok(()) };
    let d = dimension(s);
    let periodic_x = s
        .boundary
        .as_ref()
        .is_some_and(|b| b.first() == Some(&Boundary::Periodic));
    if d > 1 && periodic_x {
        return bad(
            "scene.boundary",
            "is periodic along x, but a piston wall slides along x between walls",
            Some("make the first entry \"walls\""),
        );
    }
    if d > 1 && matches!(s.placement, Some(Placement::Compress { .. })) {
        return bad(
            "scene.placement",
            "compression cannot grow particles around a piston wall",
            Some("place the gases with `kind = \"random\"` or `kind = \"lattice\"` on either side"),
        );
    }
    mass("scene.piston.mass", p.mass)?;
    non_negative("scene.piston.radius", p.radius)?;
    if !(p.position > 0.0 && p.position < 1.0) {
        return bad(
            "scene.piston.position",
            format!(
                "must be a fraction of the box between 0 and 1, got {}",
                p.position
            ),
            None,
        );
    }
    if let Some(v) = p.velocity
        && !v.is_finite()
    {
        return bad(
            "scene.piston.velocity",
            format!("must be a finite number, got {v}"),
            None,
        );
    }
    if let Some(e) = p.energy {
        non_negative("scene.piston.energy", e)?;
    }
    clear_of_piston(s)
}

/// In 2D and 3D each gas keeps to one side of the piston wall: a species'
/// region may end at the wall (it is trimmed to clear it) but not contain it.
/// (On a line the rods are placed around the piston whatever the regions.)
fn clear_of_piston(s: &SceneSpec) -> Check {
    let (Some(p), Some(size)) = (&s.piston, &s.box_size) else {
        return Ok(());
    };
    if dimension(s) == 1 {
        return Ok(());
    }
    let length = size[0];
    let x = p.position * length;
    for (i, sp) in s.species.iter().enumerate() {
        let (lo, hi) = region_x(sp);
        let inside = lo * length < x - p.radius && x + p.radius < hi * length;
        if !inside {
            continue;
        }
        let key = match sp.region {
            Some(_) => format!("scene.species.{i}.region"),
            None => format!("scene.species.{i}"),
        };
        return bad(
            key,
            format!(
                "species {:?} would be on both sides of the piston wall (at x = {x}, half thickness {}): its region [{}, {}] contains it",
                sp.name,
                p.radius,
                lo * length,
                hi * length
            ),
            Some(&format!(
                "give each species a region on one side of the piston, e.g. `region = {{ from = [0.0], to = [{}] }}`",
                ((x - p.radius) / length * 100.0).floor() / 100.0
            )),
        );
    }
    Ok(())
}

/// A finite mass whose inverse (what the engine stores) is finite too.
fn mass(key: &str, m: f64) -> Check {
    positive(key, m)?;
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

/// The particles sharing each region must fit in it: rods side by side in
/// 1D (the builder lays them so), disks and spheres at the packing fraction
/// the placement can reach. The smallest radius of a range counts, so only
/// what is certainly impossible is refused here; the builder checks the
/// radii it draws.
fn particles_fit(s: &SceneSpec) -> Check {
    let d = dimension(s);
    let Some(size) = &s.box_size else {
        return Ok(());
    };
    // The densest the placement reaches, what it is called, what else to use.
    let (limit, method, instead) = match (d, &s.placement) {
        (_, Some(Placement::Explicit { .. })) => return Ok(()),
        (1, _) => (1.0, "", ""),
        (_, None | Some(Placement::Random)) => (
            JAMMING[d - 2],
            "random insertion jams at",
            "use `placement = { kind = \"compress\" }` for dense fluids or `{ kind = \"lattice\" }` for crystals, or ",
        ),
        (_, Some(Placement::Compress { .. })) => (
            compress::LIMIT[d - 2],
            "compression reaches at most",
            "use `placement = { kind = \"lattice\" }` for denser crystals, or ",
        ),
        _ => return Ok(()),
    };
    // (region per axis, volume its particles fill, first species in it)
    type Filled = (Vec<(f64, f64)>, f64, usize);
    let mut regions: Vec<Filled> = Vec::new();
    for (i, sp) in s.species.iter().enumerate() {
        let region: Vec<(f64, f64)> = (0..d)
            .map(|k| {
                sp.region
                    .as_ref()
                    .map_or((0.0, 1.0), |r| (r.from[k], r.to[k]))
            })
            .collect();
        let filled = ball_volume(d, sp.radius.bounds()[0]) * count(s, i) as f64;
        match regions.iter_mut().find(|(r, _, _)| *r == region) {
            Some((_, occupied, _)) => *occupied += filled,
            None => regions.push((region, filled, i)),
        }
    }
    for (region, filled, first) in regions {
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
        let message = if d == 1 {
            format!("rods of total length {filled} do not fit in their region of length {volume}")
        } else {
            format!(
                "the particles would fill packing fraction {:.4} of their region; {method} \
                 {limit} in {d}D",
                filled / volume
            )
        };
        return bad(
            key,
            message,
            Some(&format!(
                "{instead}use fewer or smaller particles, or a larger box or region"
            )),
        );
    }
    Ok(())
}

/// A species' region along x, as fractions of the box.
fn region_x(sp: &SpeciesSpec) -> (f64, f64) {
    sp.region
        .as_ref()
        .and_then(|r| Some((*r.from.first()?, *r.to.first()?)))
        .unwrap_or((0.0, 1.0))
}

fn thermal_walls(s: &SceneSpec) -> Check {
    let d = dimension(s);
    for (i, w) in s.thermal_walls.iter().enumerate() {
        let key = |k: &str| format!("scene.thermal_walls.{i}.{k}");
        if w.axis >= d {
            return bad(
                key("axis"),
                format!("axis {} does not exist in {d} dimensions", w.axis),
                Some("axes count from 0 (x)"),
            );
        }
        let boundary = s.boundary.as_ref().and_then(|b| b.get(w.axis));
        if boundary == Some(&Boundary::Periodic) {
            return bad(
                key("axis"),
                format!("axis {} is periodic, so it has no wall to heat", w.axis),
                Some(&format!(
                    "make `scene.boundary.{}` \"walls\", or drop this thermal wall",
                    w.axis
                )),
            );
        }
        positive(&key("temperature"), w.temperature)?;
        if s.thermal_walls[..i]
            .iter()
            .any(|o| o.axis == w.axis && o.side == w.side)
        {
            let side = match w.side {
                Side::Low => "low",
                Side::High => "high",
            };
            return bad(
                key("side"),
                format!("axis {} has two thermal walls on its {side} side", w.axis),
                Some("give each wall one temperature"),
            );
        }
    }
    Ok(())
}
