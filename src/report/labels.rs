//! Names as a reader wants to see them: axis labels with reduced units, short
//! parameter names for legends, and file-safe slugs.

use crate::observe::catalogue;

/// A label with units for a name an observable writes (from the catalogue),
/// a known parameter key path or result; the raw name otherwise (an unknown
/// name is still honest, just less friendly).
pub fn axis_label(name: &str) -> String {
    if let Some((label, unit)) = catalogue::label(name) {
        return match unit {
            "1" => label,
            _ => format!("{label} [{unit}]"),
        };
    }
    let known = match name {
        "t" | "time" => "time t [σ√(m/kT)]",
        "scene.piston.mass" => "piston mass M [m]",
        "scene.piston.position" => "piston start position [box fraction]",
        "scene.piston.energy" => "piston start energy [kT]",
        "scene.dimension" => "dimension d",
        "scene.placement.packing_fraction" | "packing_fraction" | "phi" => "packing fraction φ",
        "run.duration" => "run duration [σ√(m/kT)]",
        "run.collisions" => "collisions per run",
        "run.equilibrate" => "equilibration time [σ√(m/kT)]",
        "run.sample_every" => "sample interval [σ√(m/kT)]",
        "study.replicas" => "replicas",
        "frequency" | "piston_frequency" => "piston frequency [√(kT/m)/σ]",
        "period" | "piston_period" => "piston period [σ√(m/kT)]",
        "piston_x" => "piston position x [σ]",
        "piston_velocity" | "piston_v" => "piston velocity [√(kT/m)]",
        "kinetic_temperature" => "temperature [kT]",
        "energy" => "kinetic energy [kT]",
        "pressure" => "pressure βPσᵈ",
        "compressibility" | "Z" => "compressibility Z = βP/ρ",
        "density" | "rho" => "number density ρσᵈ",
        "velocity" | "speed" => "speed [√(kT/m)]",
        "vx" => "velocity vₓ [√(kT/m)]",
        "g_r" | "rdf" => "pair distribution g(r)",
        "r" => "distance r [σ]",
        "x" => "position x [σ]",
        "mixing" | "mixing_index" => "mixing index",
        "collisions" => "pair collisions",
        "wall_seconds" => "wall time [s]",
        "cpu_seconds" | "seconds" => "CPU time [s]",
        _ => return fallback(name),
    };
    known.to_string()
}

/// Species-indexed or otherwise unknown names: the raw name, with a known
/// `scene.species.N.field` path spelled out.
fn fallback(name: &str) -> String {
    let parts: Vec<&str> = name.split('.').collect();
    match parts.as_slice() {
        ["scene", "species", i, "count"] => format!("species {i} count N"),
        ["scene", "species", i, "mass"] => format!("species {i} mass [m]"),
        ["scene", "species", i, "radius"] => format!("species {i} radius [σ]"),
        ["scene", "box", i] => format!("box length L{i} [σ]"),
        _ => name.to_string(),
    }
}

/// The last segment of a key path, for legends ("scene.piston.mass" -> "mass").
pub fn short_name(key: &str) -> &str {
    key.rsplit('.').next().unwrap_or(key)
}

/// A name reduced to `[a-z0-9_]`, for file names built from result names.
pub fn slug(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect();
    if s.is_empty() { "unnamed".into() } else { s }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_units_and_fallbacks() {
        assert_eq!(axis_label("t"), "time t [σ√(m/kT)]");
        assert_eq!(axis_label("scene.piston.mass"), "piston mass M [m]");
        assert_eq!(axis_label("scene.species.1.mass"), "species 1 mass [m]");
        assert_eq!(axis_label("my_observable"), "my_observable");
        // Observables: label and unit from the catalogue, patterns filled in.
        assert_eq!(axis_label("kinetic_energy"), "kinetic energy [kT]");
        assert_eq!(axis_label("wall_pressure"), "wall pressure P [kT/σᵈ]");
        assert_eq!(
            axis_label("kinetic_energy.light"),
            "kinetic energy of light [kT]"
        );
        assert_eq!(
            axis_label("heat_in.axis1.high"),
            "heat in from the high wall of axis 1 [kT]"
        );
        assert_eq!(
            axis_label("left_fraction"),
            "fraction of the particles in the left half"
        );
        assert_eq!(axis_label("x.12"), "x of particle 12 [σ]");
        assert_eq!(short_name("scene.piston.mass"), "mass");
        assert_eq!(slug("g(r) A"), "g_r__a");
    }
}
