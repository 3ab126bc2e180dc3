//! Thermal walls: on an axis that exists and has walls, one per side, and
//! no hotter than the gas may be: it heats up to the wall's temperature,
//! so the cap on the start's energy (`motion::MAX_ENERGY`) holds for it too.

use super::motion::MAX_ENERGY;
use super::{dimension, particles};
use crate::model::problem::{Check, bad, compact, positive};
use crate::model::scene::{Boundary, SceneSpec, Side};

pub fn thermal_walls(s: &SceneSpec) -> Check {
    let d = dimension(s);
    for (i, w) in s.thermal_walls.iter().enumerate() {
        let key = |k: &str| format!("scene.thermal_walls.{i}.{k}");
        if w.axis >= d {
            return bad(
                key("axis"),
                format!("axis {} does not exist in {d} dimensions", w.axis),
                Some(&format!(
                    "axes count from 0 (x), and the box has {d} {}",
                    if d == 1 { "axis" } else { "axes" }
                )),
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
        let energy = 0.5 * d as f64 * particles(s).max(1) as f64 * w.temperature;
        if energy > MAX_ENERGY {
            return bad(
                key("temperature"),
                format!(
                    "{} heats the gas to a kinetic energy of {}, more than the {} a run can carry",
                    compact(w.temperature),
                    compact(energy),
                    compact(MAX_ENERGY)
                ),
                Some(
                    "work in reduced units (kT about 1): a hotter wall only makes time run faster",
                ),
            );
        }
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
