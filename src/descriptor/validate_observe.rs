//! Checks of `[observe]` and `[analysis.*]`: every name known, every option
//! known and in range, and what each needs present in the (resolved) scene
//! and run.

use crate::descriptor::load::closest;
use crate::descriptor::validate::{Check, bad, compact};
use crate::model::descriptor::Descriptor;
use crate::model::movie::MovieSpec;
use crate::model::need::Need;
use crate::model::scene::{Boundary, SceneSpec};
use crate::observe::{CATALOGUE, Kind, catalogue};
use crate::studies;

/// `[observe]` of a descriptor whose scene is `scene` (resolved).
pub fn observe(d: &Descriptor, scene: &SceneSpec) -> Check {
    let o = &d.observe;
    for (kind, names) in [
        (Kind::Series, &o.series),
        (Kind::Scalars, &o.scalars),
        (Kind::Histograms, &o.histograms),
    ] {
        for (i, name) in names.iter().enumerate() {
            let key = format!("observe.{}.{i}", kind.key());
            let Some(entry) = catalogue::find(kind, name) else {
                return unknown(kind, name, &key);
            };
            if names[..i].contains(name) {
                return bad(key, format!("`{name}` is listed twice"), None);
            }
            for need in entry.needs {
                met(*need, d, scene, &key, &format!("`{name}`"))?;
            }
            if (kind, name.as_str()) == (Kind::Series, "positions") {
                positions_fit(d, scene, &key)?;
            }
        }
    }
    if let Some(movie) = &o.movie {
        movie_fits(movie, scene)?;
        movie_within_run(movie, d)?;
    }
    Ok(())
}

/// Most frames a movie has, and most particle positions in all its frames
/// (each is a number in the SVG, a few bytes; this keeps the file under
/// about 10 MB).
const MAX_FRAMES: usize = 2000;
const MAX_MOVIE_POSITIONS: f64 = 1e6;

fn movie_fits(movie: &MovieSpec, scene: &SceneSpec) -> Check {
    if !(movie.duration.is_finite() && movie.duration > 0.0) {
        return bad(
            "observe.movie.duration",
            format!("{} is not a simulated time to film", movie.duration),
            Some("a number > 0, e.g. duration = 20.0"),
        );
    }
    if !(2..=MAX_FRAMES).contains(&movie.frames) {
        return bad(
            "observe.movie.frames",
            format!("{} frames", movie.frames),
            Some(&format!(
                "a whole number from 2 to {MAX_FRAMES}, e.g. frames = 200"
            )),
        );
    }
    let positions =
        movie.frames as f64 * crate::descriptor::validate_scene::particles(scene) as f64;
    if positions > MAX_MOVIE_POSITIONS {
        return bad(
            "observe.movie.frames",
            format!(
                "the movie would hold {positions:.1e} particle positions (every particle in every \
                 frame); at most {MAX_MOVIE_POSITIONS:.0e} keep its file small enough to open"
            ),
            Some("fewer frames, or film a scene with fewer particles"),
        );
    }
    Ok(())
}

/// A movie films its run from the start, so it is no longer than the run
/// (equilibration included). A run stopped by a collision count has no
/// length to compare with before it runs: the cost check weighs its
/// movie's events against the run's, and filming stops where the run did.
fn movie_within_run(movie: &MovieSpec, d: &Descriptor) -> Check {
    let Some(t) = d.run.duration else {
        return Ok(());
    };
    let length = t + d.run.equilibrate;
    if movie.duration <= length {
        return Ok(());
    }
    bad(
        "observe.movie.duration",
        format!(
            "{} is longer than the run it films, which lasts {} (`equilibrate` + `duration`)",
            compact(movie.duration),
            compact(length)
        ),
        Some(&format!(
            "film the run's first moments: `duration = {}` at most",
            compact(length)
        )),
    )
}

/// Values a run's `positions` series may hold (8 bytes each, in memory).
const MAX_POSITION_VALUES: f64 = 1e8;

/// The `positions` series keeps one value per particle per sample.
fn positions_fit(d: &Descriptor, scene: &SceneSpec, key: &str) -> Check {
    let (Some(t), Some(dt)) = (d.run.duration, d.run.sample_every) else {
        return Ok(());
    };
    let values = t / dt * crate::descriptor::validate_scene::particles(scene) as f64;
    if values <= MAX_POSITION_VALUES {
        return Ok(());
    }
    bad(
        key,
        format!(
            "`positions` would hold {values:.1e} values per run (every particle at every sample); \
             a run keeps at most {MAX_POSITION_VALUES:.0e}"
        ),
        Some("sample less often, run shorter, or use fewer particles"),
    )
}

/// An unknown name: said so, with the list it belongs in, the closest known
/// name, or the known names.
fn unknown(kind: Kind, name: &str, key: &str) -> Check {
    let valid: Vec<String> = catalogue::names(kind)
        .into_iter()
        .map(String::from)
        .collect();
    let elsewhere = CATALOGUE.iter().find(|e| e.name == name);
    let kind = kind.key();
    let hint = match (elsewhere, closest(name, &valid)) {
        (Some(other), _) => {
            let other = other.kind.key();
            format!("`{name}` is a {other} observable: list it under `{other}`")
        }
        (None, Some(best)) => format!("did you mean `{best}`?"),
        (None, None) => format!("{kind} observables: {}", backticked(&valid)),
    };
    bad(
        key,
        format!("unknown {kind} observable `{name}`"),
        Some(&hint),
    )
}

/// `[analysis.*]`: known names, known options of the right type and range.
pub fn analysis(d: &Descriptor, scene: &SceneSpec) -> Check {
    for (name, options) in &d.analysis {
        let key = format!("analysis.{name}");
        let Some(info) = studies::find(name) else {
            let valid = studies::names();
            let hint = match closest(name, &valid) {
                Some(best) => format!("did you mean `{best}`?"),
                None => format!("analyses: {}", backticked(&valid)),
            };
            return bad(key, format!("unknown analysis `{name}`"), Some(&hint));
        };
        for (option, value) in options {
            let key = format!("{key}.{option}");
            let Some(spec) = info.options().iter().find(|o| o.name == option) else {
                let valid: Vec<String> =
                    info.options().iter().map(|o| o.name.to_string()).collect();
                let hint = match closest(option, &valid) {
                    Some(best) => format!("did you mean `{best}`?"),
                    None if valid.is_empty() => format!("the {name} analysis takes no options"),
                    None => format!("options of `{name}`: {}", backticked(&valid)),
                };
                return bad(
                    key,
                    format!("unknown option `{option}` of the {name} analysis"),
                    Some(&hint),
                );
            };
            let x = value
                .as_float()
                .or_else(|| value.as_integer().map(|i| i as f64));
            match x {
                Some(x) if spec.admits(x) => {}
                Some(x) => {
                    return bad(
                        key,
                        format!("must be {}, got {}", spec.range_text(), compact(x)),
                        Some(spec.about),
                    );
                }
                None => {
                    return bad(
                        key,
                        format!("must be {}, got a {}", spec.range_text(), value.type_str()),
                        Some(&format!("e.g. `{option} = {}`", spec.default)),
                    );
                }
            }
        }
        for need in info.needs() {
            met(*need, d, scene, &key, &format!("the {name} analysis"))?;
        }
        info.check(d, scene, &key)?;
    }
    Ok(())
}

/// `need` holds for `who` (named at `key`), or the problem says what to add.
fn met(need: Need, d: &Descriptor, scene: &SceneSpec, key: &str, who: &str) -> Check {
    let walled =
        |k: usize| scene.boundary.as_ref().and_then(|b| b.get(k)) != Some(&Boundary::Periodic);
    let dimension = crate::descriptor::validate_scene::dimension(scene);
    let (ok, what, hint) = match need {
        Need::Piston => (
            scene.piston.is_some(),
            "a piston in the scene",
            "add `[scene.piston]` with a `mass` (1D scenes)",
        ),
        Need::Sampling => (
            d.run.sample_every.is_some(),
            "samples",
            "set `sample_every` in [run], e.g. `sample_every = 1.0`",
        ),
        Need::Walls => (
            (0..dimension).any(walled),
            "walls",
            "make at least one axis of `scene.boundary` \"walls\"",
        ),
        Need::ThermalWalls => (
            !scene.thermal_walls.is_empty(),
            "thermal walls",
            "add a `[[scene.thermal_walls]]` table with `axis`, `side` and `temperature`",
        ),
    };
    if ok {
        Ok(())
    } else {
        bad(key, format!("{who} needs {what}"), Some(hint))
    }
}

fn backticked(names: &[String]) -> String {
    names
        .iter()
        .map(|n| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ")
}
