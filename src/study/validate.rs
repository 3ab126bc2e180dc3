//! Semantic checks of a typed descriptor: what serde cannot see. Each problem
//! names its key path so the caller can point at it in the source.

use super::descriptor_types::{Descriptor, Scale, SweepMode, SweepValues};
use crate::scene::spec::{Mass, SceneSpec, Velocities};

/// One problem: the key it concerns, what is wrong, what would be right.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    pub key: String,
    pub message: String,
    pub hint: Option<String>,
}

type Check = Result<(), Problem>;

fn bad(key: impl Into<String>, message: impl Into<String>, hint: Option<&str>) -> Check {
    Err(Problem {
        key: key.into(),
        message: message.into(),
        hint: hint.map(str::to_string),
    })
}

fn positive(key: &str, v: f64) -> Check {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        bad(key, format!("must be a positive number, got {v}"), None)
    }
}

/// Radii may be 0: point particles (an ideal gas, or MacKay's point rods).
fn non_negative(key: &str, v: f64) -> Check {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        bad(key, format!("must be a number >= 0, got {v}"), None)
    }
}

/// Top-level sections a sweep may set. `[study]` is not among them: replicas
/// and seeds shape the plan itself, so they cannot vary within it.
pub const SWEEPABLE: [&str; 4] = ["scene", "run", "observe", "analysis"];

pub fn descriptor(d: &Descriptor) -> Check {
    study(d)?;
    run(d)?;
    scene(&d.scene)?;
    sweep(d)
}

fn study(d: &Descriptor) -> Check {
    let name = &d.study.name;
    let ok = !name.is_empty()
        && !name.starts_with('.')
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c));
    if !ok {
        return bad(
            "study.name",
            format!("{name:?} cannot name an output folder"),
            Some("use letters, digits, `-`, `_` or `.` (not first), e.g. `name = \"piston\"`"),
        );
    }
    if d.study.replicas == 0 {
        return bad(
            "study.replicas",
            "must be at least 1",
            Some("`replicas = 1` runs each sweep point once"),
        );
    }
    Ok(())
}

fn run(d: &Descriptor) -> Check {
    let r = &d.run;
    match (r.duration, r.collisions) {
        (None, None) => {
            return bad(
                "run",
                "says neither how long to run nor how many collisions",
                Some("add `duration = 1000.0` (simulated time) or `collisions = 1000000`"),
            );
        }
        (Some(t), _) => positive("run.duration", t)?,
        (None, Some(0)) => return bad("run.collisions", "must be at least 1", None),
        _ => {}
    }
    if !(r.equilibrate.is_finite() && r.equilibrate >= 0.0) {
        return bad(
            "run.equilibrate",
            format!("must be a number >= 0, got {}", r.equilibrate),
            None,
        );
    }
    if let Some(dt) = r.sample_every {
        positive("run.sample_every", dt)?;
    }
    Ok(())
}

fn scene(s: &SceneSpec) -> Check {
    if let Some(d) = s.dimension
        && !(1..=3).contains(&d)
    {
        return bad(
            "scene.dimension",
            format!("must be 1, 2 or 3, got {d}"),
            Some("1 = rods, 2 = disks, 3 = spheres"),
        );
    }
    let axes = |what: &str, n: usize| -> Check {
        match s.dimension {
            Some(d) if d != n => bad(
                format!("scene.{what}"),
                format!("has {n} entries but the scene has dimension {d}"),
                Some("give one entry per axis"),
            ),
            None if !(1..=3).contains(&n) => bad(
                format!("scene.{what}"),
                format!("has {n} entries; give 1, 2 or 3 (one per axis)"),
                None,
            ),
            _ => Ok(()),
        }
    };
    if let Some(b) = &s.box_size {
        axes("box", b.len())?;
        for (i, &l) in b.iter().enumerate() {
            positive(&format!("scene.box.{i}"), l)?;
        }
    }
    if let Some(b) = &s.boundary {
        axes("boundary", b.len())?;
    }
    for (i, sp) in s.species.iter().enumerate() {
        let key = |k: &str| format!("scene.species.{i}.{k}");
        if sp.name.is_empty() {
            return bad(key("name"), "must not be empty", None);
        }
        if s.species[..i].iter().any(|o| o.name == sp.name) {
            return bad(
                key("name"),
                format!("species {:?} is named twice", sp.name),
                Some("give each species its own name"),
            );
        }
        for r in sp.radius.bounds() {
            non_negative(&key("radius"), r)?;
        }
        match sp.mass {
            Mass::Fixed(m) => positive(&key("mass"), m)?,
            Mass::Range([lo, hi]) => {
                positive(&key("mass"), lo)?;
                positive(&key("mass"), hi)?;
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
            if r.from.len() != r.to.len() {
                return bad(
                    key("region"),
                    "`from` and `to` must have the same number of axes",
                    None,
                );
            }
            axes(&format!("species.{i}.region.from"), r.from.len())?;
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
    match &s.velocities {
        Some(Velocities::Maxwell {
            temperature,
            energy,
            ..
        }) => {
            positive("scene.velocities.temperature", *temperature)?;
            if let Some(e) = energy {
                positive("scene.velocities.energy", *e)?;
            }
        }
        Some(Velocities::Uniform { p, energy, .. }) => {
            positive("scene.velocities.p", *p)?;
            if let Some(e) = energy {
                positive("scene.velocities.energy", *e)?;
            }
        }
        _ => {}
    }
    if let Some(p) = &s.piston {
        positive("scene.piston.mass", p.mass)?;
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
    }
    for (i, w) in s.thermal_walls.iter().enumerate() {
        if let Some(d) = s.dimension
            && w.axis >= d
        {
            return bad(
                format!("scene.thermal_walls.{i}.axis"),
                format!("axis {} does not exist in {d} dimensions", w.axis),
                Some("axes count from 0 (x)"),
            );
        }
        positive(
            &format!("scene.thermal_walls.{i}.temperature"),
            w.temperature,
        )?;
    }
    Ok(())
}

fn sweep(d: &Descriptor) -> Check {
    let Some(sweep) = &d.sweep else { return Ok(()) };
    if sweep.parameters.is_empty() {
        return bad(
            "sweep.parameters",
            "is empty",
            Some("name at least one key path to sweep, or remove [sweep]"),
        );
    }
    let mut lengths = Vec::new();
    for (key, values) in &sweep.parameters {
        let at = format!("sweep.parameters.{key}");
        let n = match values {
            SweepValues::List(v) if v.is_empty() => {
                return bad(at, "has no values", Some("give at least one value"));
            }
            SweepValues::List(v) => v.len(),
            SweepValues::Range(r) => {
                if r.steps == 0 {
                    return bad(at, "range needs `steps >= 1`", None);
                }
                if r.steps as u64 > super::plan::HARD_LIMIT {
                    return bad(
                        at,
                        format!("{} steps is more than a study can run", r.steps),
                        Some("use fewer steps"),
                    );
                }
                if !r.from.is_finite() || !r.to.is_finite() {
                    return bad(at, "range bounds must be finite numbers", None);
                }
                if r.scale == Scale::Log && (r.from <= 0.0 || r.to <= 0.0) {
                    return bad(
                        at,
                        format!(
                            "a log range needs positive bounds, got from = {}, to = {}",
                            r.from, r.to
                        ),
                        Some("use `scale = \"linear\"` or bounds > 0"),
                    );
                }
                r.steps
            }
        };
        lengths.push((key.clone(), n));
    }
    if sweep.mode == SweepMode::Zip
        && let Some((k0, n0)) = lengths.first()
        && let Some((k, n)) = lengths.iter().find(|(_, n)| n != n0)
    {
        return bad(
            "sweep.mode",
            format!(
                "zip needs equally long parameters, but `{k0}` has {n0} values and `{k}` has {n}"
            ),
            Some("give every parameter the same number of values, or use `mode = \"product\"`"),
        );
    }
    Ok(())
}

/// A sweep key must start at a section that describes runs.
pub fn sweep_key(key: &str) -> Check {
    let first = key.split('.').next().unwrap_or_default();
    if SWEEPABLE.contains(&first) && key.contains('.') {
        return Ok(());
    }
    let valid: Vec<String> = SWEEPABLE.iter().map(|s| s.to_string()).collect();
    let hint = match super::descriptor::closest(first, &valid) {
        Some(best) if best != first => format!(
            "did you mean `{best}.…`? keys start with one of {}",
            SWEEPABLE.join(", ")
        ),
        _ => format!(
            "write a full key path such as `scene.piston.mass`; keys start with one of {}",
            SWEEPABLE.join(", ")
        ),
    };
    bad(
        key,
        format!("`{key}` is not a key path that can be swept"),
        Some(&hint),
    )
}
