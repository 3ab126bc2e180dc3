//! A scene that names a preset starts from it; every key the descriptor
//! gives overrides the preset's. The result always says its dimension
//! (given, or the number of box lengths).

use super::presets;
use crate::model::scene::SceneSpec;

pub fn resolve(spec: &SceneSpec) -> Result<SceneSpec, String> {
    let mut merged = match &spec.preset {
        None => spec.clone(),
        Some(name) => {
            let Some(base) = presets::find(name) else {
                return Err(format!(
                    "unknown scene preset `{name}`; bundled presets are: {}",
                    presets::names().join(", ")
                ));
            };
            SceneSpec {
                preset: None,
                dimension: spec.dimension.or(base.dimension),
                box_size: spec.box_size.clone().or(base.box_size),
                boundary: spec.boundary.clone().or(base.boundary),
                species: if spec.species.is_empty() {
                    base.species
                } else {
                    spec.species.clone()
                },
                placement: spec.placement.clone().or(base.placement),
                velocities: spec.velocities.clone().or(base.velocities),
                piston: spec.piston.clone().or(base.piston),
                thermal_walls: if spec.thermal_walls.is_empty() {
                    base.thermal_walls
                } else {
                    spec.thermal_walls.clone()
                },
            }
        }
    };
    // Filled in where box or boundary tell; a scene that says nothing, or
    // contradicts itself, is left for `dimension()` to refuse where it is
    // needed, so a caller can point at the key at fault.
    if let Ok(d) = merged.dimension() {
        merged.dimension = Some(d);
    }
    Ok(merged)
}
