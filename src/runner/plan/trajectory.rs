//! `[observe] trajectory` against the plan: the runs it names are planned,
//! a run stopped by a collision count keeps within `MAX_PARTICLE_FRAMES` by
//! its estimated length (one stopped by `duration` is checked with the
//! descriptor), and `study validate` says how large the files will be and
//! what filming costs (each written run is run again).

use crate::descriptor::errors::DescriptorError;
use crate::descriptor::load::Loaded;
use crate::descriptor::locate;
use crate::descriptor::validate::resolved;
use crate::descriptor::validate_scene::particles;
use crate::model::problem::compact;
use crate::model::run_spec::RunSpec;
use crate::model::trajectory::{MAX_PARTICLE_FRAMES, TrajectorySpec};
use crate::runner::plan::estimate::{RunCost, run_cost};

/// What one run's trajectory will hold.
struct Size {
    frames: f64,
    particles: f64,
    bytes: f64,
}

/// The frames, particles and bytes of `spec`'s trajectory `t` (a run stopped
/// by collisions by its estimated length); None without an estimate.
fn size(spec: &RunSpec, t: &TrajectorySpec, cost: Option<&RunCost>) -> Option<Size> {
    let scene = resolved(&spec.descriptor.scene).ok()?;
    let species = scene.species.len() + usize::from(scene.piston.is_some());
    let n = (particles(&scene) + usize::from(scene.piston.is_some())) as f64;
    let run = &spec.descriptor.run;
    let length = match run.duration {
        Some(duration) => run.equilibrate + duration,
        None => cost?.time,
    };
    let frames = t
        .frames(length)
        .min((MAX_PARTICLE_FRAMES / n.max(1.0)).floor());
    let f = t.format;
    let bytes = 256.0 + frames * (f.frame_bytes(species) + n * f.particle_bytes()) + 20.0 * n;
    Some(Size {
        frames,
        particles: n,
        bytes,
    })
}

/// Refuse `runs` naming a run the plan does not have, and a run stopped by
/// collisions whose estimated frames pass the cap.
pub fn check(loaded: &Loaded, specs: &[RunSpec]) -> Result<(), DescriptorError> {
    let key = "observe.trajectory.runs";
    let at = || locate::position_of(&loaded.text, key);
    for spec in specs {
        let Some(t) = &spec.descriptor.observe.trajectory else {
            continue;
        };
        if let Some(id) = t.runs.iter().find(|&&id| id >= specs.len() as u64) {
            let planned = match specs.len() {
                1 => "the plan has one run, 0".to_string(),
                n => format!("the plan's runs are 0 to {}", n - 1),
            };
            return Err(DescriptorError::new(
                &loaded.file,
                format!("`{key}` names run {id}, which is not planned: {planned}"),
            )
            .at(at())
            .key(key)
            .hint(
                "`run_id`s of the plan (`study validate` counts its runs; `--quick` plans fewer)",
            ));
        }
        if spec.descriptor.run.duration.is_some() || !t.writes(spec.run_id) {
            continue;
        }
        let cost = run_cost(&spec.descriptor);
        if let Some(s) = size(spec, t, cost.as_ref())
            && cost.is_some_and(|c| (c.time / t.every + 1.0) * s.particles > MAX_PARTICLE_FRAMES)
        {
            let key = "observe.trajectory.every";
            let time = cost.map_or(0.0, |c| c.time);
            return Err(DescriptorError::new(
                &loaded.file,
                format!(
                    "`{key}` = {}: run {} stops by collisions and lasts about {}, which is {:.1e} \
                     particle-frames of {} particles; a trajectory holds at most {MAX_PARTICLE_FRAMES:.0e}",
                    compact(t.every),
                    spec.run_id,
                    approx(time),
                    (time / t.every + 1.0) * s.particles,
                    compact(s.particles)
                ),
            )
            .at(locate::position_of(&loaded.text, key))
            .key(key)
            .hint(format!(
                "`every = {}` or more, or stop the run by `duration`",
                approx((time * s.particles / MAX_PARTICLE_FRAMES).ceil())
            )));
        }
    }
    Ok(())
}

/// `study validate`'s line on the trajectories: which runs, frames,
/// particles and bytes, and the events filming adds. Empty without one.
pub fn describe(specs: &[RunSpec]) -> String {
    let mut files = Vec::new();
    let (mut bytes, mut events, mut frames) = (0.0, 0.0, 0.0);
    for spec in specs {
        let Some(t) = spec.descriptor.observe.trajectory.as_ref() else {
            continue;
        };
        if !t.writes(spec.run_id) {
            continue;
        }
        let cost = run_cost(&spec.descriptor);
        files.push(t.file_name(spec.run_id));
        if let Some(s) = size(spec, t, cost.as_ref()) {
            bytes += s.bytes;
            frames += s.frames * s.particles;
        }
        events += cost.map_or(0.0, |c| c.events);
    }
    if files.is_empty() {
        return String::new();
    }
    let shown = match files.len() {
        n if n > 4 => format!("{}, … ({n} files)", files[..3].join(", ")),
        _ => files.join(", "),
    };
    format!(
        "  trajectory: {}: {} particle-frames, ~{} in all; filming runs each run again, ~{} \
         events more\n",
        shown,
        approx(frames),
        human_bytes(bytes),
        approx(events)
    )
}

fn approx(x: f64) -> String {
    if x < 1e4 {
        format!("{x:.0}")
    } else {
        format!("{x:.1e}")
    }
}

/// 1234567 -> "1.2 MB".
fn human_bytes(b: f64) -> String {
    let units = ["B", "kB", "MB", "GB", "TB"];
    let mut x = b;
    let mut unit = 0;
    while x >= 1000.0 && unit < units.len() - 1 {
        x /= 1000.0;
        unit += 1;
    }
    if unit == 0 {
        format!("{x:.0} B")
    } else {
        format!("{x:.1} {}", units[unit])
    }
}
