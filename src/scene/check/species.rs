//! The species: names, counts, masses, radii and regions.

use super::{MAX_PARTICLES, axes, count, mass, particles};
use crate::model::problem::{Check, bad, compact, name_fits, non_negative};
use crate::model::scene::{Drawn, SceneSpec};
use crate::scene::build::PISTON;

pub fn species(s: &SceneSpec) -> Check {
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
    if s.piston.as_ref().and_then(|p| p.per_side) == Some(0) {
        return bad(
            "scene.piston.per_side",
            "must be at least 1",
            Some("it sets the particle count of every species"),
        );
    }
    let mut names = std::collections::HashSet::new();
    for (i, sp) in s.species.iter().enumerate() {
        let key = |k: &str| format!("scene.species.{i}.{k}");
        let name = &sp.name;
        if name.trim().is_empty() {
            return bad(
                key("name"),
                "must not be empty",
                Some("e.g. `name = \"gas\"`"),
            );
        }
        if name == PISTON {
            return bad(
                key("name"),
                format!("`{PISTON}` is the name the piston's observables use"),
                Some("rename the species"),
            );
        }
        name_fits(&key("name"), name)?;
        if !names.insert(name.as_str()) {
            return bad(
                key("name"),
                format!("species {name:?} is named twice"),
                Some(&format!(
                    "give each species its own name (rename the second `{name}`)"
                )),
            );
        }
        let radii =
            format!("species `{name}`: radii are finite numbers >= 0 (0 for point particles)");
        for r in sp.radius.bounds() {
            non_negative(&key("radius"), r).map_err(|mut p| {
                p.hint = Some(radii.clone());
                p
            })?;
        }
        reversed(&key("radius"), sp.radius)?;
        let masses = format!("species `{name}`: masses are > 0 (`inf` for an immovable particle)");
        match sp.mass {
            Drawn::Fixed(m) if m == f64::INFINITY => {}
            Drawn::Fixed(m) => mass(&key("mass"), m, Some(&masses))?,
            Drawn::Range(bounds) if bounds.contains(&f64::INFINITY) => {
                return bad(
                    key("mass"),
                    format!(
                        "range [{}, {}]: a range draws finite masses",
                        compact(bounds[0]),
                        compact(bounds[1])
                    ),
                    Some("`inf` is a mass on its own: `mass = inf` makes the species immovable"),
                );
            }
            Drawn::Range([lo, hi]) => {
                mass(&key("mass"), lo, Some(&masses))?;
                mass(&key("mass"), hi, Some(&masses))?;
                reversed(&key("mass"), sp.mass)?;
            }
        }
        if let Some(r) = &sp.region {
            axes(&key("region.from"), r.from.len(), "entries", s)?;
            axes(&key("region.to"), r.to.len(), "entries", s)?;
            for (a, (&lo, &hi)) in r.from.iter().zip(&r.to).enumerate() {
                if !(0.0..=1.0).contains(&lo) || !(0.0..=1.0).contains(&hi) || lo >= hi {
                    return bad(
                        key("region"),
                        format!(
                            "axis {a}: [{}, {}] is not a part of the box",
                            compact(lo),
                            compact(hi)
                        ),
                        Some(&format!(
                            "species `{name}`: regions are fractions of the box: 0 <= from < to <= 1"
                        )),
                    );
                }
            }
        }
    }
    // A species of count 0 is absent, but some species must be present.
    if (0..s.species.len()).all(|i| count(s, i) == 0) {
        return bad(
            "scene.species",
            "the scene has no particles",
            Some("give a species a count of at least 1"),
        );
    }
    Ok(())
}

/// A range `[lo, hi]` with lo > hi.
fn reversed(key: &str, v: Drawn) -> Check {
    match v {
        Drawn::Range([lo, hi]) if lo > hi => bad(
            key,
            format!("range [{}, {}] is reversed", compact(lo), compact(hi)),
            Some("write `[lo, hi]` with lo <= hi"),
        ),
        _ => Ok(()),
    }
}
