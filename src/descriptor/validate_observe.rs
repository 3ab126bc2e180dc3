//! Checks of `[observe]` and `[analysis.*]`: every name known, every option
//! known and in range, and what each needs present in the (resolved) scene
//! and run.

use crate::descriptor::load::closest;
use crate::descriptor::validate::{Check, bad, compact};
use crate::model::descriptor::Descriptor;
use crate::model::movie::MovieSpec;
use crate::model::need::Need;
use crate::model::scene::{Boundary, SceneSpec};
use crate::model::trajectory::{MAX_PARTICLE_FRAMES, TrajectorySpec};
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
        }
    }
    series_fit(d, scene)?;
    histograms_fit(d, scene)?;
    if let Some(movie) = &o.movie {
        movie_fits(movie, scene)?;
        movie_within_run(movie, d)?;
    }
    if let Some(trajectory) = &o.trajectory {
        trajectory_fits(trajectory, d, scene)?;
    }
    Ok(())
}

/// A trajectory's frames: some time apart, from the exact engine (what a
/// fixed step would film is not the run), and at most
/// `MAX_PARTICLE_FRAMES` particle-frames over a run of known length (a run
/// stopped by collisions is checked against its estimated length with the
/// plan, `runner::plan::confirm`). Its `runs` are checked with the plan.
fn trajectory_fits(t: &TrajectorySpec, d: &Descriptor, scene: &SceneSpec) -> Check {
    if !(t.every.is_finite() && t.every > 0.0) {
        return bad(
            "observe.trajectory.every",
            format!(
                "{} is not a simulated time between frames",
                compact(t.every)
            ),
            Some("a number > 0, e.g. every = 0.5"),
        );
    }
    if t.runs.is_empty() {
        return bad(
            "observe.trajectory.runs",
            "[] names no run to write",
            Some("the `run_id`s to write, e.g. runs = [0] (the default)"),
        );
    }
    if d.run.integrator != crate::model::descriptor::Integrator::Exact {
        return bad(
            "observe.trajectory",
            format!(
                "a trajectory films the exact engine's run, not a `{}` one",
                d.run.integrator.name()
            ),
            Some("leave `run.integrator` at \"exact\" or drop the trajectory"),
        );
    }
    let Some(duration) = d.run.duration else {
        return Ok(());
    };
    let length = d.run.equilibrate + duration;
    let particles = crate::descriptor::validate_scene::particles(scene) as f64;
    let held = t.frames(length) * particles;
    if held > MAX_PARTICLE_FRAMES {
        let every = length * particles / MAX_PARTICLE_FRAMES;
        return bad(
            "observe.trajectory.every",
            format!(
                "{}: {} frames of {} particles over the run (`equilibrate` + `duration` = {}) \
                 are {held:.1e} particle-frames; a trajectory holds at most {MAX_PARTICLE_FRAMES:.0e} \
                 (about 3 GB of GSD)",
                compact(t.every),
                compact(t.frames(length)),
                compact(particles),
                compact(length)
            ),
            Some(&format!(
                "fewer frames: `every = {}` or more",
                compact_up(every)
            )),
        );
    }
    Ok(())
}

/// A number rounded up to two significant digits, for a hint.
fn compact_up(x: f64) -> String {
    if !(x.is_finite() && x > 0.0) {
        return compact(x);
    }
    let scale = 10f64.powf(x.log10().floor() - 1.0);
    compact((x / scale).ceil() * scale)
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

/// Values a run's series may hold in all (8 bytes each, in memory: every
/// sample is kept for the analyses, and each series written with its times).
pub const MAX_SERIES_VALUES: f64 = 1e8;

/// The series listed, each a column per sample for every particle
/// (`positions`, `velocities`: `<index>` in what it writes) or species it
/// writes, hold at most `MAX_SERIES_VALUES` values per run; refused at the
/// series that passes it, with what would be held.
fn series_fit(d: &Descriptor, scene: &SceneSpec) -> Check {
    let (Some(t), Some(dt)) = (d.run.duration, d.run.sample_every) else {
        return Ok(());
    };
    let samples = (t / dt).floor() + 1.0;
    let particles = crate::descriptor::validate_scene::particles(scene) as f64;
    let species = scene.species.len() as f64 + f64::from(u8::from(scene.piston.is_some()));
    let mut columns_each = 0.0;
    let mut named = Vec::new();
    for (i, name) in d.observe.series.iter().enumerate() {
        let Some(entry) = catalogue::find(Kind::Series, name) else {
            continue;
        };
        let columns = columns(entry.writes, particles, species);
        columns_each += columns;
        if columns > 1.0 {
            named.push(format!("`{name}`: {columns} columns"));
        }
        let total = columns_each * samples;
        if total > MAX_SERIES_VALUES {
            return bad(
                format!("observe.series.{i}"),
                format!(
                    "the series would hold {total:.1e} values per run ({columns_each} columns \
                     in all{}, at {samples:.1e} samples); a run keeps at most \
                     {MAX_SERIES_VALUES:.0e} values of series",
                    if named.is_empty() {
                        String::new()
                    } else {
                        format!(", of them {}", named.join(", "))
                    }
                ),
                Some(&format!(
                    "sample less often (`sample_every = {}` or more), run shorter, use fewer \
                     particles, or list fewer series",
                    round_up(t * columns_each / MAX_SERIES_VALUES)
                )),
            );
        }
    }
    Ok(())
}

/// Bins a run's per-particle histograms may have in all (each kept in up to
/// 17 blocks while the run goes, and written with its edges).
pub const MAX_HISTOGRAM_BINS: f64 = 5e6;

/// Bins of a per-particle histogram at most (`velocity_x_each`: 60).
const PARTICLE_BINS: f64 = 60.0;

/// Per-particle histograms (`<index>` in what they write) have at most
/// `MAX_HISTOGRAM_BINS` bins per run in all: refused at the one that passes it.
fn histograms_fit(d: &Descriptor, scene: &SceneSpec) -> Check {
    let particles = crate::descriptor::validate_scene::particles(scene) as f64;
    let mut bins = 0.0;
    for (i, name) in d.observe.histograms.iter().enumerate() {
        let Some(entry) = catalogue::find(Kind::Histograms, name) else {
            continue;
        };
        if !entry.writes.contains("<index>") {
            continue;
        }
        bins += columns(entry.writes, particles, 1.0) * PARTICLE_BINS;
        if bins > MAX_HISTOGRAM_BINS {
            return bad(
                format!("observe.histograms.{i}"),
                format!(
                    "the per-particle histograms would have {bins:.1e} bins per run (up to \
                     {PARTICLE_BINS} for each of {particles} particles, per histogram); a run \
                     keeps at most {MAX_HISTOGRAM_BINS:.0e}"
                ),
                Some(
                    "use fewer particles, or list fewer per-particle histograms (`scaled_velocity_x` \
                     and `scaled_speed` pool every particle into one)",
                ),
            );
        }
    }
    Ok(())
}

/// `x` > 0 rounded up to two significant digits, as text.
fn round_up(x: f64) -> String {
    let digits = 1 - x.log10().floor() as i32;
    let unit = 10f64.powi(-digits);
    format!("{:.*}", digits.max(0) as usize, (x / unit).ceil() * unit)
}

/// Columns of a series that writes `pattern`: one per particle for
/// `<index>`, per species for `<species>`, per word for `<a|b>`.
fn columns(pattern: &str, particles: f64, species: f64) -> f64 {
    pattern
        .split('<')
        .skip(1)
        .filter_map(|part| part.split_once('>').map(|(hole, _)| hole))
        .map(|hole| match hole {
            "index" => particles,
            "species" => species,
            words => words.split('|').count() as f64,
        })
        .product()
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
        Need::Dimension(want) => {
            return if dimension == want {
                Ok(())
            } else {
                bad(
                    key,
                    format!("{who} is defined in {want}D scenes; this scene is {dimension}D"),
                    Some(&format!(
                        "list it only for {want}D scenes (a `scene.box` of {want} lengths), or \
                         drop it here{}",
                        match want {
                            2 => "; spheres have `q6`",
                            3 => "; disks have `psi6`",
                            _ => "",
                        }
                    )),
                )
            };
        }
        Need::Neighbours(k) => {
            let n = crate::descriptor::validate_scene::particles(scene);
            return if n > k {
                Ok(())
            } else {
                bad(
                    key,
                    format!(
                        "{who} takes the {k} nearest neighbours of each particle; the scene has {n}"
                    ),
                    Some(&format!("give the scene at least {} particles", k + 1)),
                )
            };
        }
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
