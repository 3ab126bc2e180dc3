//! Semantic checks of a typed descriptor: what serde cannot see. Each problem
//! names its key path so the caller can point at it in the source.

use crate::model::descriptor::{Descriptor, Scale, SweepMode, SweepValues};
use crate::model::scene::SceneSpec;
use std::collections::HashSet;

pub use crate::model::problem::{Check, Problem, bad, compact, name_fits, non_negative, positive};

/// Top-level sections a sweep may set. `[study]` is not among them: replicas
/// and seeds shape the plan itself, so they cannot vary within it.
pub const SWEEPABLE: [&str; 4] = ["scene", "run", "observe", "analysis"];

/// The whole descriptor as one sweep point: `[study]`, the shape of
/// `[sweep]`, and everything a run of it needs (`point`).
pub fn descriptor(d: &Descriptor) -> Check {
    study(d)?;
    sweep(d)?;
    point(d)
}

/// What one sweep point needs to run: `[run]`, the scene after its preset is
/// resolved, `[observe]` and `[analysis.*]`.
pub fn point(d: &Descriptor) -> Check {
    Points::default().point(d)
}

/// `point` for the many points of one plan: a scene just found sound is not
/// checked again (the points of a sweep over `[run]` share theirs, and its
/// explicit positions may be many).
#[derive(Default)]
pub struct Points {
    sound: Option<SceneSpec>,
}

impl Points {
    pub fn point(&mut self, d: &Descriptor) -> Check {
        run(d)?;
        let scene = resolved(&d.scene)?;
        if self.sound.as_ref() != Some(&scene) {
            crate::descriptor::validate_scene::scene(&scene)?;
            self.sound = Some(scene.clone());
        }
        rest(d, &scene)
    }
}

/// What `point` checks beside `[run]` and the scene.
fn rest(d: &Descriptor, scene: &SceneSpec) -> Check {
    crate::descriptor::validate_integrator::integrator(d, scene)?;
    crate::descriptor::validate_collisions::reachable(d, scene)?;
    crate::descriptor::validate_room::room(scene)?;
    crate::descriptor::validate_observe::observe(d, scene)?;
    crate::descriptor::validate_observe::analysis(d, scene)
}

/// The scene with its preset applied; an unknown preset is a problem at `scene.preset`.
pub fn resolved(s: &SceneSpec) -> Result<SceneSpec, Problem> {
    if let Some(name) = &s.preset
        && crate::scene::presets::find(name).is_none()
    {
        let valid: Vec<String> = crate::scene::presets::names()
            .iter()
            .map(|n| n.to_string())
            .collect();
        let hint = match crate::descriptor::load::closest(name, &valid) {
            Some(best) => format!("did you mean \"{best}\"? (`study list` shows every preset)"),
            None => format!("bundled presets: {}", valid.join(", ")),
        };
        return Err(Problem {
            key: "scene.preset".into(),
            message: format!("unknown scene preset \"{name}\""),
            hint: Some(hint),
        });
    }
    crate::scene::resolve(s).map_err(|message| Problem {
        key: "scene.preset".into(),
        message,
        hint: None,
    })
}

pub fn study(d: &Descriptor) -> Check {
    let name = &d.study.name;
    let ok = !name.is_empty()
        && !name.starts_with('.')
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c));
    name_fits("study.name", name)?;
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

pub fn run(d: &Descriptor) -> Check {
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
            format!("must be a number >= 0, got {}", compact(r.equilibrate)),
            None,
        );
    }
    let times = [
        ("run.duration", r.duration),
        ("run.equilibrate", Some(r.equilibrate)),
    ];
    if let Some((key, Some(t))) = times
        .into_iter()
        .find(|(_, t)| t.is_some_and(|t| t > MAX_TIME))
    {
        return bad(
            key,
            format!(
                "{} is longer than a run's clock can count: at most {} in all",
                compact(t),
                compact(MAX_TIME)
            ),
            Some(
                "the clock is a 64-bit float: at 1e12 it resolves only 1e-4, about the time \
                 between events, and a run that long makes some 1e12 collisions per particle",
            ),
        );
    }
    if r.duration.unwrap_or(0.0) + r.equilibrate > MAX_TIME {
        return bad(
            "run.equilibrate",
            format!(
                "with `duration` the run lasts {}, longer than a run's clock can count (at most {})",
                compact(r.duration.unwrap_or(0.0) + r.equilibrate),
                compact(MAX_TIME)
            ),
            Some("shorten `duration` or `equilibrate`"),
        );
    }
    if let Some(dt) = r.sample_every {
        positive("run.sample_every", dt)?;
        // Analyses keep every sample of a run in memory.
        if let Some(t) = r.duration
            && t / dt > MAX_SAMPLES
        {
            return bad(
                "run.sample_every",
                format!(
                    "{} gives {:.1e} samples over the duration {}; a run keeps at most {MAX_SAMPLES:.0e}",
                    compact(dt),
                    t / dt,
                    compact(t)
                ),
                Some(&format!(
                    "sample less often, e.g. `sample_every = {}`",
                    compact(t / 1e5)
                )),
            );
        }
    }
    Ok(())
}

/// The longest simulated time a run may last (duration and equilibration).
pub const MAX_TIME: f64 = 1e12;

/// Samples one run may take: every one is kept in memory for the analyses.
pub const MAX_SAMPLES: f64 = 1e7;

/// The shape of `[sweep]`: values present, ranges sound, zip lengths equal.
pub fn sweep(d: &Descriptor) -> Check {
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
            SweepValues::List(v) => {
                too_many(&at, v.len())?;
                if sweep.mode == SweepMode::Product {
                    repeats(&at, v)?;
                }
                v.len()
            }
            SweepValues::Range(r) => {
                if r.steps == 0 {
                    return bad(at, "range needs `steps >= 1`", None);
                }
                if !r.from.is_finite() || !r.to.is_finite() {
                    return bad(
                        at,
                        format!(
                            "range bounds must be finite numbers, got from = {}, to = {}",
                            compact(r.from),
                            compact(r.to)
                        ),
                        None,
                    );
                }
                if r.from == r.to && r.steps > 1 {
                    return bad(
                        at,
                        format!(
                            "from = to = {} with {} steps repeats one value",
                            compact(r.from),
                            r.steps
                        ),
                        Some("use `steps = 1`, or different bounds"),
                    );
                }
                if r.scale == Scale::Log && (r.from <= 0.0 || r.to <= 0.0) {
                    return bad(
                        at,
                        format!(
                            "a log range needs positive bounds, got from = {}, to = {}",
                            compact(r.from),
                            compact(r.to)
                        ),
                        Some("use `scale = \"linear\"` or bounds > 0"),
                    );
                }
                r.steps
            }
        };
        too_many(&at, n)?;
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
    let points = crate::descriptor::sweep::size(sweep);
    if points > MAX_POINTS as f64 {
        let sizes: Vec<String> = lengths.iter().map(|(_, n)| n.to_string()).collect();
        return bad(
            "sweep.parameters",
            format!(
                "the sweep has {} points ({} values, every combination), more than the \
                 {MAX_POINTS} a study can plan",
                crate::descriptor::sweep::points_text(points),
                sizes.join(" x ")
            ),
            Some(
                "sweep fewer values, `mode = \"zip\"` to pair them up, or split the study into \
                 several descriptors",
            ),
        );
    }
    Ok(())
}

/// Sweep points a plan may have: each is a descriptor checked, estimated
/// and held while the study runs (about 2 kB and 10 µs each, so the largest
/// plan validates in about a second).
pub const MAX_POINTS: usize = 100_000;

/// One parameter's `n` values are more points than a plan may have.
fn too_many(at: &str, n: usize) -> Check {
    if n <= MAX_POINTS {
        return Ok(());
    }
    bad(
        at,
        format!("{n} values are more sweep points than a study can plan (at most {MAX_POINTS})"),
        Some(
            "sweep fewer values (a range with fewer `steps`), or split the study into several descriptors",
        ),
    )
}

/// A value listed twice, numbers compared as numbers (`10` and `10.0`).
fn repeats(at: &str, values: &[toml::Value]) -> Check {
    let mut first = std::collections::HashMap::with_capacity(values.len());
    for (i, x) in values.iter().enumerate() {
        if let Some(j) = first.insert(crate::descriptor::sweep::value_text(x), i) {
            let show = crate::descriptor::load::show;
            let (same, hint) = if values[j] == *x {
                (String::new(), "the same seeds")
            } else {
                (format!(" (as {})", show(&values[j])), "the same settings")
            };
            return bad(
                at,
                format!(
                    "value {}{same} is listed twice (items {j} and {i})",
                    show(x)
                ),
                Some(&format!(
                    "remove the repeat: both points would run with {hint}"
                )),
            );
        }
    }
    Ok(())
}

/// `[[case]]` number `i` (`named`: the names of those before it): a name
/// that can label its rows, used once, replicas
/// if given at least 1, keys that a sweep could set.
pub fn case<'d>(d: &'d Descriptor, i: usize, named: &mut HashSet<&'d str>) -> Check {
    let case = &d.case[i];
    let at = format!("case.{i}");
    let ok = !case.name.is_empty()
        && case
            .name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_".contains(c));
    if !ok {
        return bad(
            format!("{at}.name"),
            format!("{:?} cannot name a case", case.name),
            Some("use letters, digits, `-` or `_`, e.g. `name = \"mackay\"`"),
        );
    }
    name_fits(&format!("{at}.name"), &case.name)?;
    if !named.insert(&case.name) {
        return bad(
            format!("{at}.name"),
            format!("case \"{}\" is defined twice", case.name),
            Some("give each [[case]] its own name"),
        );
    }
    if case.replicas == Some(0) {
        return bad(
            format!("{at}.replicas"),
            "must be at least 1",
            Some("leave it out to run `study.replicas` replicas"),
        );
    }
    for key in case.set.keys() {
        sweep_key(key).map_err(|p| Problem {
            key: format!("{at}.set"),
            ..p
        })?;
    }
    Ok(())
}

/// A `[quick]` key: what a sweep may set, `study.replicas`, `sweep.mode`,
/// `sweep.parameters.<key>` and a case's `replicas` or `set.<key>`. The
/// rest would rename the study, reseed it or edit `[quick]` itself.
pub fn quick_key(key: &str) -> Check {
    let case = key.strip_prefix("case.").and_then(|rest| {
        let (index, field) = rest.split_once('.')?;
        index.parse::<usize>().ok()?;
        Some(field == "replicas" || field.strip_prefix("set.").is_some_and(|k| !k.is_empty()))
    });
    let ok = sweep_key(key).is_ok()
        || ["study.replicas", "sweep.mode"].contains(&key)
        || key
            .strip_prefix("sweep.parameters.")
            .is_some_and(|k| !k.is_empty())
        || case == Some(true);
    if ok {
        return Ok(());
    }
    bad(
        key,
        format!("`{key}` is not a key `[quick]` can set"),
        Some(&format!(
            "[quick] sets keys below {}, `study.replicas`, `sweep.mode`, \
             `sweep.parameters.<key>`, `case.<i>.replicas` or `case.<i>.set.<key>`",
            SWEEPABLE.map(|s| format!("`{s}.`")).join(", ")
        )),
    )
}

/// A sweep key must start at a section that describes runs.
pub fn sweep_key(key: &str) -> Check {
    let first = key.split('.').next().unwrap_or_default();
    if SWEEPABLE.contains(&first) && key.contains('.') {
        return Ok(());
    }
    let valid: Vec<String> = SWEEPABLE.iter().map(|s| s.to_string()).collect();
    let hint = match crate::descriptor::load::closest(first, &valid) {
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
