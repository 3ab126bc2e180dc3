//! Plans too costly to start by accident: a run expected to take more
//! collisions than it could ever finish is refused, and a plan expected to
//! take more CPU time than `CONFIRM_CPU_SECONDS` needs `--yes`. Both from
//! the kinetic-theory estimate that `study validate` prints (`estimate.rs`).

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::{Loaded, show};
use crate::descriptor::locate;
use crate::model::problem::compact;
use crate::model::run_spec::RunSpec;
use crate::runner::estimate::{self, COLLISIONS_PER_SECOND, RunCost};
use crate::runner::progress::human_duration;

/// Pair collisions one run may be expected to take: about ten years on one
/// thread at the fastest nominal rate, and a run cannot be split.
pub const MAX_RUN_COLLISIONS: f64 = 1e15;

/// Plans expected to take more CPU time than this (1000 CPU-hours) need `--yes`.
pub const CONFIRM_CPU_SECONDS: f64 = 3.6e6;

/// Refuse a plan with a run that cannot finish; ask for `--yes` for one
/// whose runs together take longer than `CONFIRM_CPU_SECONDS`.
pub fn confirm_cost(loaded: &Loaded, specs: &[RunSpec], yes: bool) -> Result<(), DescriptorError> {
    let costs = estimate::by_point(specs);
    let endless = costs.iter().find_map(|(i, c, _)| {
        // NaN counts as endless too.
        c.filter(|c| c.collisions.is_nan() || c.collisions > MAX_RUN_COLLISIONS)
            .map(|c| (*i, c))
    });
    if let Some((i, cost)) = endless {
        return Err(endless_run(loaded, &specs[i], cost));
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
/// sets its length (or at the piston, if nearly all its collisions are the
/// piston's), where the plan takes it from.
fn endless_run(loaded: &Loaded, spec: &RunSpec, cost: RunCost) -> DescriptorError {
    let run = &spec.descriptor.run;
    let rate = cost.rate;
    let (key, value) = match (run.duration, run.collisions) {
        (Some(t), _) if run.equilibrate > t => ("run.equilibrate", run.equilibrate),
        (Some(t), _) => ("run.duration", t),
        (None, Some(c)) => ("run.collisions", c as f64),
        (None, None) => ("run.equilibrate", run.equilibrate),
    };
    let at_rate = if key == "run.collisions" {
        String::new()
    } else {
        format!(
            " at the scene's estimated {} per unit time",
            compact_approx(rate)
        )
    };
    let years = cost.collisions / COLLISIONS_PER_SECOND[0] / 3.156e7;
    let mut err = DescriptorError::new(
        &loaded.file,
        format!(
            "`{key}` = {}: one run would take ~{} pair collisions{at_rate}, more than a run can finish (at most {}: ~{} on one thread; this one ~{})",
            compact(value),
            compact_approx(cost.collisions),
            compact(MAX_RUN_COLLISIONS),
            human_duration(MAX_RUN_COLLISIONS / COLLISIONS_PER_SECOND[0]),
            human_duration(years * 3.156e7),
        ),
    )
    .at(place(loaded, spec, key))
    .key(key);
    if !spec.params.is_empty() {
        let point: Vec<String> = spec
            .params
            .iter()
            .map(|(k, v)| format!("`{k}` = {}", show(v)))
            .collect();
        err.message += &format!(" (sweep point {}: {})", spec.point_id, point.join(", "));
    }
    if let Some(case) = &spec.case {
        err.message += &format!(" (case \"{case}\")");
    }
    let piston = spec.descriptor.scene.piston.as_ref();
    let hint = match piston {
        Some(p) if cost.piston_share > 0.5 => format!(
            "nearly all are the piston's: with mass {} it moves far faster than the gas; give it a mass comparable to the gas's and a speed about sqrt(kT / mass)",
            compact(p.mass)
        ),
        _ if key == "run.collisions" => "ask for fewer collisions".to_string(),
        _ => format!(
            "shorten `{key}`, or check the scene's speeds and temperature (reduced units: kT about 1)"
        ),
    };
    err.hint(hint)
}

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
