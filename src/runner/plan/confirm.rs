//! Plans too costly to start by accident: a run expected to take more
//! events than it could ever finish is refused, and so are a run stopped by
//! a collision count whose samples would outgrow memory and a movie that
//! films more than its run; a plan expected to take more CPU time than
//! `CONFIRM_CPU_SECONDS` needs `--yes`. All from the kinetic-theory
//! estimate that `study validate` prints (`estimate.rs`).

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::{Loaded, show};
use crate::descriptor::locate;
use crate::descriptor::validate::MAX_SAMPLES;
use crate::model::problem::compact;
use crate::model::run_spec::RunSpec;
use crate::runner::execute::progress::human_duration;
use crate::runner::plan::estimate::{self, COLLISIONS_PER_SECOND, RunCost};

/// Events (pair collisions, wall hits, renewals) one run may be expected to
/// take: about ten years on one thread at the fastest nominal rate, and a
/// run cannot be split.
pub const MAX_RUN_EVENTS: f64 = 1e15;

/// Plans expected to take more CPU time than this (1000 CPU-hours) need `--yes`.
pub const CONFIRM_CPU_SECONDS: f64 = 3.6e6;

/// Refuse a plan with a run that cannot finish; ask for `--yes` for one
/// whose runs together take longer than `CONFIRM_CPU_SECONDS`.
pub fn confirm_cost(loaded: &Loaded, specs: &[RunSpec], yes: bool) -> Result<(), DescriptorError> {
    crate::runner::plan::trajectory::check(loaded, specs)?;
    let costs = estimate::by_point(specs);
    for (i, cost, _) in &costs {
        let Some(cost) = cost else { continue };
        // NaN counts as endless too.
        if cost.events.is_nan() || cost.events > MAX_RUN_EVENTS {
            return Err(endless_run(loaded, &specs[*i], *cost));
        }
        if let Some(err) = outgrown(loaded, &specs[*i], cost) {
            return Err(err);
        }
    }
    let seconds: f64 = costs
        .iter()
        .filter_map(|(_, c, n)| c.map(|c| c.seconds() * n))
        .sum();
    if seconds > CONFIRM_CPU_SECONDS && !yes {
        let at = if loaded.descriptor.sweep.is_some() {
            "sweep"
        } else {
            "run"
        };
        return Err(DescriptorError::new(
            &loaded.file,
            format!(
                "the plan's {} runs are estimated at ~{} of CPU time ({} CPU-hours), more than the {} CPU-hours a plan may take without --yes",
                specs.len(),
                human_duration(seconds),
                compact((seconds / 3600.0).round()),
                CONFIRM_CPU_SECONDS / 3600.0
            ),
        )
        .at(locate::position_of(&loaded.text, at))
        .key(at)
        .hint("pass --yes if you mean it, or run shorter or fewer runs (`study validate` shows the estimate)"));
    }
    Ok(())
}

/// A run of `spec`'s point expected to take `cost`: placed at the key that
/// sets its length, at the thermal wall whose heat makes it endless, or at
/// the piston if nearly all its events are the piston's, where the plan
/// takes it from.
fn endless_run(loaded: &Loaded, spec: &RunSpec, cost: RunCost) -> DescriptorError {
    let run = &spec.descriptor.run;
    let rate = cost.event_rate;
    let (mut key, value) = match (run.duration, run.collisions) {
        (Some(t), _) if run.equilibrate > t => ("run.equilibrate".to_string(), run.equilibrate),
        (Some(t), _) => ("run.duration".to_string(), t),
        (None, Some(c)) => ("run.collisions".to_string(), c as f64),
        (None, None) => ("run.equilibrate".to_string(), run.equilibrate),
    };
    let mut value = compact(value);
    // A wall whose heat alone takes the run past the limit is the key.
    let wall = cost
        .hot_wall
        .filter(|_| cost.events / cost.heating.max(1.0) <= MAX_RUN_EVENTS);
    if let Some(w) = wall {
        key = format!("scene.thermal_walls.{w}.temperature");
        value = compact(spec.descriptor.scene.thermal_walls[w].temperature);
    }
    let at_rate = if rate.is_finite() {
        format!(
            " at the scene's estimated {} per unit time",
            compact_approx(rate)
        )
    } else {
        String::new()
    };
    let mut err = DescriptorError::new(
        &loaded.file,
        format!(
            "`{key}` = {value}: one run would take ~{} events (pair collisions, wall hits and \
             neighbourhood renewals){at_rate}, more than a run can finish (at most {}: ~{} on \
             one thread; this one ~{})",
            compact_approx(cost.events),
            compact(MAX_RUN_EVENTS),
            human_duration(MAX_RUN_EVENTS / COLLISIONS_PER_SECOND[0]),
            human_duration(cost.events / COLLISIONS_PER_SECOND[0]),
        ),
    )
    .at(place(loaded, spec, &key))
    .key(&key);
    err.message += &point_of(spec);
    let piston = spec.descriptor.scene.piston.as_ref();
    let hint = match piston {
        Some(p) if cost.piston_share > 0.5 => format!(
            "nearly all are the piston's: with mass {} it moves far faster than the gas; give it a mass comparable to the gas's and a speed about sqrt(kT / mass)",
            compact(p.mass)
        ),
        _ if wall.is_some() => "the gas heats up to the wall's temperature, and its speeds \
             (about sqrt(kT / m)) with it; work in reduced units (kT about 1): a hotter wall \
             only makes time run faster"
            .to_string(),
        _ if key == "run.collisions" => "ask for fewer collisions".to_string(),
        _ => format!(
            "shorten `{key}`, or check the scene's speeds, temperature and sizes (reduced units: kT about 1, particles about 1 across)"
        ),
    };
    err.hint(hint)
}

/// The sweep point and case `spec` belongs to, for a message.
fn point_of(spec: &RunSpec) -> String {
    let mut out = String::new();
    if !spec.params.is_empty() {
        let point: Vec<String> = spec
            .params
            .iter()
            .map(|(k, v)| format!("`{k}` = {}", show(v)))
            .collect();
        out += &format!(" (sweep point {}: {})", spec.point_id, point.join(", "));
    }
    if let Some(case) = &spec.case {
        out += &format!(" (case \"{case}\")");
    }
    out
}

/// What a run of `spec`'s point would hold beyond its means: samples of a
/// run stopped by a collision count (its length known only from the
/// estimate) past what a run keeps, or a movie that films more events than
/// the run it films.
fn outgrown(loaded: &Loaded, spec: &RunSpec, cost: &RunCost) -> Option<DescriptorError> {
    let d = &spec.descriptor;
    let (key, message, hint) = if let (None, Some(c), Some(dt)) =
        (d.run.duration, d.run.collisions, d.run.sample_every)
        && cost.time / dt > MAX_SAMPLES
    {
        (
            "run.sample_every",
            format!(
                "{}: a run of {} collisions lasts about {} at the scene's estimated {} \
                 collisions per unit time, which is {} samples; a run keeps at most {}",
                compact(dt),
                compact(c as f64),
                compact_approx(cost.time),
                compact_approx(cost.rate),
                compact_approx(cost.time / dt),
                compact(MAX_SAMPLES)
            ),
            format!(
                "sample less often, e.g. `sample_every = {}`, or stop the run by `duration`",
                compact_approx(cost.time / 1e5)
            ),
        )
    } else if let Some(movie) = &d.observe.movie
        && movie.duration * cost.event_rate > (2.0 * cost.events).max(MIN_MOVIE_EVENTS)
    {
        (
            "observe.movie.duration",
            format!(
                "{}: filming it would take ~{} events, more than the ~{} of the run it films \
                 (a run lasts about {})",
                compact(movie.duration),
                compact_approx(movie.duration * cost.event_rate),
                compact_approx(cost.events),
                compact_approx(cost.time)
            ),
            "film the run's first moments: a `duration` at most the run's".to_string(),
        )
    } else {
        return None;
    };
    let err = DescriptorError::new(
        &loaded.file,
        format!("`{key}` = {message}{}", point_of(spec)),
    )
    .at(place(loaded, spec, key))
    .key(key);
    Some(err.hint(hint))
}

/// Events a movie may always take (a second or so), whatever its run's.
const MIN_MOVIE_EVENTS: f64 = 1e6;

/// Where `key` of `spec`'s point is set: its sweep parameter, its case's
/// `set`, or the key itself (or the nearest table above it) in the file.
fn place(loaded: &Loaded, spec: &RunSpec, key: &str) -> Option<(usize, usize)> {
    let text = &loaded.text;
    if spec.params.iter().any(|(k, _)| k == key) {
        return locate::position_of_keys(text, &["sweep", "parameters", key]);
    }
    if let Some(name) = &spec.case
        && let Some(i) = loaded.descriptor.case.iter().position(|c| &c.name == name)
        && loaded.descriptor.case[i].set.contains_key(key)
    {
        return locate::position_of_keys(text, &["case", &i.to_string(), "set", key]);
    }
    locate::position_of(text, key)
}

/// 1.234e152 -> "1.2e152"; everyday sizes as whole numbers.
fn compact_approx(x: f64) -> String {
    if x.is_finite() && x < 1e6 {
        format!("{x:.0}")
    } else {
        format!("{x:.1e}")
    }
}
