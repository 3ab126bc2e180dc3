//! The scenes of the texts bonkers grew from (MacKay's, the Imperial
//! project's), bundled and runnable by name (`preset = "..."` in `[scene]`,
//! see `study list`). Each is plain descriptor TOML, so a preset is
//! exactly what a user could have written.

use crate::model::scene::SceneSpec;

pub struct Preset {
    pub name: &'static str,
    pub about: &'static str,
    pub toml: &'static str,
}

const PRESETS: &[Preset] = &[
    Preset {
        name: "mackay-ten",
        about: "MacKay: ten rods, masses ~1 on the left and ~4 on the right, between walls",
        toml: r#"
dimension = 1
box = [11.0]
boundary = ["walls"]
species = [
  { name = "light", count = 5, mass = [0.9, 1.1], radius = 0.0, region = { from = [0.0], to = [0.5] } },
  { name = "heavy", count = 5, mass = [3.6, 4.4], radius = 0.0, region = { from = [0.5], to = [1.0] } },
]
placement = { kind = "lattice" }
velocities = { kind = "maxwell", temperature = 1.0 }
"#,
    },
    Preset {
        name: "mackay-piston",
        about: "MacKay: five light and five heavier rods either side of a piston of mass 40, all with equal \
                velocities. MacKay's text names no masses for this run (the heavier gas is \"green\", and the \
                piston starts with \"roughly 75%\" of the energy): with equal velocities the piston's \
                share is 20 / (20 + sum(m) / 2), so light masses ~1 and heavy masses 1.5-1.7 give 74-77%; \
                the ten-rod run's ~4 would give 62%",
        toml: r#"
dimension = 1
box = [12.0]
boundary = ["walls"]
species = [
  { name = "light", count = 5, mass = [0.9, 1.1], radius = 0.0, region = { from = [0.0], to = [0.5] } },
  { name = "heavy", count = 5, mass = [1.5, 1.7], radius = 0.0, region = { from = [0.5], to = [1.0] } },
]
placement = { kind = "lattice" }
velocities = { kind = "equal", velocity = [1.0] }
piston = { mass = 40.0, position = 0.5, radius = 0.0 }
"#,
    },
    Preset {
        name: "disk-piston",
        about: "MacKay's piston in 2D: five light disks (masses 0.9-1.1) left and five heavier (1.5-1.7) \
                right of a wall of mass 40 that slides along x in a 40 x 40 box with hard walls, the \
                wall starting with 10 kT. Disks of diameter 1 leave each gas dilute (packing fraction \
                0.5% with five a side, 2% with twenty) yet colliding, so it can share a compression \
                between x and y",
        toml: r#"
dimension = 2
box = [40.0, 40.0]
boundary = ["walls", "walls"]
species = [
  { name = "light", count = 5, mass = [0.9, 1.1], radius = 0.5, region = { from = [0.0, 0.0], to = [0.5, 1.0] } },
  { name = "heavy", count = 5, mass = [1.5, 1.7], radius = 0.5, region = { from = [0.5, 0.0], to = [1.0, 1.0] } },
]
placement = { kind = "random" }
velocities = { kind = "maxwell", temperature = 1.0 }
piston = { mass = 40.0, position = 0.5, radius = 0.0, energy = 10.0 }
"#,
    },
    Preset {
        name: "mackay-cradle",
        about: "MacKay (cradle2.m): walls at 0 and 35, eight point rods at 14, 15, ..., 21 with masses \
                4.123, 9.0123 and six 1s; all the energy in the left two, moving left at speed 2",
        toml: r#"
dimension = 1
box = [35.0]
boundary = ["walls"]
species = [
  { name = "m4", count = 1, mass = 4.123, radius = 0.0 },
  { name = "m9", count = 1, mass = 9.0123, radius = 0.0 },
  { name = "ones", count = 6, mass = 1.0, radius = 0.0 },
]
placement = { kind = "explicit", positions = [[14.0], [15.0], [16.0], [17.0], [18.0], [19.0], [20.0], [21.0]] }
velocities = { kind = "explicit", velocities = [[-2.0], [-2.0], [0.0], [0.0], [0.0], [0.0], [0.0], [0.0]] }
"#,
    },
    Preset {
        name: "imperial-box",
        about: "Imperial: four disks heading for the four walls",
        toml: r#"
dimension = 2
box = [100.0, 100.0]
boundary = ["walls", "walls"]
species = [{ name = "disk", count = 4, mass = 1.0, radius = 1.0 }]
placement = { kind = "explicit", positions = [[10.0, 50.0], [50.0, 90.0], [50.0, 10.0], [90.0, 50.0]] }
velocities = { kind = "explicit", velocities = [[-1.0, 0.0], [0.0, 1.0], [0.0, -1.0], [1.0, 0.0]] }
"#,
    },
    Preset {
        name: "imperial-collision-1d",
        about: "Imperial: one disk hits another at rest along the x axis",
        toml: r#"
dimension = 2
box = [100.0, 100.0]
boundary = ["walls", "walls"]
species = [{ name = "disk", count = 2, mass = 1.0, radius = 1.0 }]
placement = { kind = "explicit", positions = [[10.0, 10.0], [20.0, 10.0]] }
velocities = { kind = "explicit", velocities = [[1.0, 0.0], [0.0, 0.0]] }
"#,
    },
    Preset {
        name: "imperial-collision-2d",
        about: "Imperial: one disk hits another at rest on a diagonal",
        toml: r#"
dimension = 2
box = [100.0, 100.0]
boundary = ["walls", "walls"]
species = [{ name = "disk", count = 2, mass = 1.0, radius = 1.0 }]
placement = { kind = "explicit", positions = [[10.0, 10.0], [20.0, 15.0]] }
velocities = { kind = "explicit", velocities = [[1.0, 0.5], [0.0, 0.0]] }
"#,
    },
    Preset {
        name: "imperial-sticking",
        about: "Imperial: the five-disk case that traps disks together in a time-stepping code (equal masses)",
        toml: r#"
dimension = 2
box = [100.0, 100.0]
boundary = ["walls", "walls"]
species = [{ name = "disk", count = 5, mass = 1.0, radius = 3.0 }]
placement = { kind = "explicit", positions = [[45.0, 50.0], [55.0, 60.0], [35.0, 39.75], [65.0, 70.25], [54.0, 30.0]] }
velocities = { kind = "explicit", velocities = [[1.0, 1.0], [0.0, 0.0], [2.0, 2.0], [-1.0, -1.0], [0.5, 2.5]] }
"#,
    },
    Preset {
        name: "imperial-sticking-masses",
        about: "Imperial: the five-disk sticking case with masses 3, 2, 1, 4, 5 (momenta as in the Imperial project's handout)",
        toml: r#"
dimension = 2
box = [100.0, 100.0]
boundary = ["walls", "walls"]
species = [
  { name = "m3", count = 1, mass = 3.0, radius = 3.0 },
  { name = "m2", count = 1, mass = 2.0, radius = 3.0 },
  { name = "m1", count = 1, mass = 1.0, radius = 3.0 },
  { name = "m4", count = 1, mass = 4.0, radius = 3.0 },
  { name = "m5", count = 1, mass = 5.0, radius = 3.0 },
]
placement = { kind = "explicit", positions = [[45.0, 50.0], [55.0, 60.0], [35.0, 39.75], [65.0, 70.25], [54.0, 30.0]] }
velocities = { kind = "explicit", velocities = [[0.3333333333333333, 0.3333333333333333], [0.0, 0.0], [2.0, 2.0], [-0.25, -0.25], [0.1, 0.5]] }
"#,
    },
    Preset {
        name: "imperial-200",
        about: "Imperial: 200 disks of radius 1 in a box of 100, momenta (0.5, 0.5)",
        toml: r#"
dimension = 2
box = [100.0, 100.0]
boundary = ["walls", "walls"]
species = [{ name = "disk", count = 200, mass = 1.0, radius = 1.0 }]
placement = { kind = "random" }
velocities = { kind = "equal", velocity = [0.5, 0.5] }
"#,
    },
    Preset {
        name: "disks-dilute",
        about: "A dilute gas: 100 disks of diameter 1 in a 40 x 40 box with hard walls (packing fraction \
                0.05), Maxwellian at kT = 1; the accuracy study's easy case for a fixed step",
        toml: r#"
dimension = 2
box = [40.0, 40.0]
boundary = ["walls", "walls"]
species = [{ name = "disk", count = 100, mass = 1.0, radius = 0.5 }]
placement = { kind = "random" }
velocities = { kind = "maxwell", temperature = 1.0 }
"#,
    },
    Preset {
        name: "disks-dense",
        about: "A dense gas: 64 disks of diameter 1 in an 11.2 x 11.2 box with hard walls (packing \
                fraction 0.4), Maxwellian at kT = 1; a collision every ~0.07 per disk, the accuracy \
                study's hard case for a fixed step",
        toml: r#"
dimension = 2
box = [11.209982432795858, 11.209982432795858]
boundary = ["walls", "walls"]
species = [{ name = "disk", count = 64, mass = 1.0, radius = 0.5 }]
placement = { kind = "random" }
velocities = { kind = "maxwell", temperature = 1.0 }
"#,
    },
    Preset {
        name: "rod-piston",
        about: "A piston of mass 10 and diameter 1 between two gases of ten rods of diameter 1 (masses 1 \
                left, 2 right) in a box of 40 with hard walls, Maxwellian at kT = 1, the piston starting \
                with 10 kT: MacKay's piston with rods a fixed step can see (point rods never overlap)",
        toml: r#"
dimension = 1
box = [40.0]
boundary = ["walls"]
species = [
  { name = "light", count = 10, mass = 1.0, radius = 0.5, region = { from = [0.0], to = [0.5] } },
  { name = "heavy", count = 10, mass = 2.0, radius = 0.5, region = { from = [0.5], to = [1.0] } },
]
placement = { kind = "random" }
velocities = { kind = "maxwell", temperature = 1.0 }
piston = { mass = 10.0, position = 0.5, radius = 0.5, energy = 10.0 }
"#,
    },
];

pub fn list() -> &'static [Preset] {
    PRESETS
}

/// The preset's scene, or None for an unknown name.
pub fn find(name: &str) -> Option<SceneSpec> {
    // Parsed once: a plan resolves its scene for every sweep point.
    static PARSED: std::sync::OnceLock<Vec<Option<SceneSpec>>> = std::sync::OnceLock::new();
    let parsed = PARSED.get_or_init(|| {
        // Bundled presets are tested to parse (see the tests below).
        PRESETS
            .iter()
            .map(|p| toml::from_str(p.toml).ok())
            .collect()
    });
    let i = PRESETS.iter().position(|p| p.name == name)?;
    parsed[i].clone()
}

/// Names, for "did you mean" and error messages.
pub fn names() -> Vec<&'static str> {
    PRESETS.iter().map(|p| p.name).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_parses() {
        for p in list() {
            let parsed: Result<SceneSpec, _> = toml::from_str(p.toml);
            assert!(parsed.is_ok(), "{}: {:?}", p.name, parsed.err());
        }
    }
}
