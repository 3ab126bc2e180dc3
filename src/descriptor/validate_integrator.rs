//! `[run] integrator` and `dt`: a fixed step needs its step, the exact engine
//! none, and the scene must be one a fixed step can move (balls of nonzero
//! radius: it finds collisions by overlap; no 2D/3D piston plane).

use crate::model::descriptor::Descriptor;
use crate::model::problem::{Check, bad, positive};
use crate::model::scene::SceneSpec;

/// Steps one run may take.
const MAX_STEPS: f64 = 1e9;

pub fn integrator(d: &Descriptor, scene: &SceneSpec) -> Check {
    let r = &d.run;
    let name = r.integrator.name();
    let Some(dt) = r.dt else {
        if r.integrator.is_exact() {
            return Ok(());
        }
        return bad(
            "run.integrator",
            format!("\"{name}\" needs its step length"),
            Some("add `dt = 0.01` (simulated time) to [run]"),
        );
    };
    if r.integrator.is_exact() {
        return bad(
            "run.dt",
            "is a fixed step's length, but the integrator is \"exact\" (event-driven, no step)",
            Some("remove `dt`, or set `integrator = \"fixed-step\"`"),
        );
    }
    positive("run.dt", dt)?;
    if let Some(t) = r.duration
        && (t + r.equilibrate) / dt > MAX_STEPS
    {
        return bad(
            "run.dt",
            format!(
                "{dt} takes {:.1e} steps over the run; a run takes at most {MAX_STEPS:.0e}",
                (t + r.equilibrate) / dt
            ),
            Some("use a longer step or a shorter run"),
        );
    }
    let dimension = scene.dimension().unwrap_or(1);
    if let Some(p) = &scene.piston {
        if dimension > 1 {
            return bad(
                "run.integrator",
                format!("\"{name}\" moves balls only, and a {dimension}D piston is a plane"),
                Some("use `integrator = \"exact\"` for 2D/3D pistons"),
            );
        }
        if p.radius <= 0.0 {
            return bad(
                "run.integrator",
                format!(
                    "\"{name}\" finds collisions by overlap, and the piston has radius {}",
                    p.radius
                ),
                Some("give the piston a radius, e.g. `radius = 0.5`"),
            );
        }
    }
    if let Some(s) = scene.species.iter().find(|s| s.radius.bounds()[0] <= 0.0) {
        return bad(
            "run.integrator",
            format!(
                "\"{name}\" finds collisions by overlap, and species \"{}\" can have radius 0 (point particles never overlap)",
                s.name
            ),
            Some("give every species a radius > 0, or use `integrator = \"exact\"`"),
        );
    }
    Ok(())
}
