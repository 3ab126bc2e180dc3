//! Every request a scene cannot honour is a clear error saying what was
//! wrong and what would be right — never a panic, never a silent fix.

use bonkers::model::scene::SceneSpec;
use bonkers::scene::{build, resolve};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The error building `text` in `d` dimensions.
fn error(d: usize, text: &str) -> String {
    let spec: SceneSpec = toml::from_str(text).expect("scene TOML");
    let run = |spec: &SceneSpec| -> Result<(), String> {
        let spec = resolve(spec)?;
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        match d {
            1 => build::<1>(&spec, &mut rng).map(|_| ()),
            2 => build::<2>(&spec, &mut rng).map(|_| ()),
            _ => build::<3>(&spec, &mut rng).map(|_| ()),
        }
    };
    run(&spec).expect_err("this scene must be refused")
}

fn assert_says(d: usize, text: &str, words: &[&str]) {
    let err = error(d, text);
    for w in words {
        assert!(
            err.contains(w),
            "error for\n{text}\nshould mention `{w}`: {err}"
        );
    }
}

#[test]
fn bad_radii_and_masses() {
    let one = |species: &str| format!("box = [10.0, 10.0]\nspecies = [{species}]\n");
    assert_says(
        2,
        &one("{ name = \"a\", count = 2, radius = -0.5 }"),
        &["`a`", "radius", ">= 0"],
    );
    assert_says(
        2,
        &one("{ name = \"a\", count = 2, radius = nan }"),
        &["radius", "finite"],
    );
    assert_says(
        2,
        &one("{ name = \"a\", count = 2, radius = [0.6, 0.2] }"),
        &["radius", "lo <= hi"],
    );
    assert_says(
        2,
        &one("{ name = \"a\", count = 2, mass = 0.0 }"),
        &["mass", "> 0"],
    );
    assert_says(
        2,
        &one("{ name = \"a\", count = 2, mass = nan }"),
        &["mass", "> 0"],
    );
    assert_says(
        2,
        &one("{ name = \"a\", count = 2, mass = [3.0, 1.0] }"),
        &["mass", "lo <= hi"],
    );
}

#[test]
fn bad_boxes_and_dimensions() {
    let s = "species = [{ name = \"a\", count = 2 }]\n";
    assert_says(
        2,
        &format!("box = [10.0, 0.0]\n{s}"),
        &["axis 1", "positive"],
    );
    assert_says(
        2,
        &format!("box = [10.0, -3.0]\n{s}"),
        &["axis 1", "positive"],
    );
    assert_says(
        2,
        &format!("box = [10.0, inf]\n{s}"),
        &["scene.box", "finite"],
    );
    assert_says(
        2,
        &format!("dimension = 2\nbox = [10.0]\n{s}"),
        &["dimension is 2", "one per axis"],
    );
    assert_says(
        2,
        &format!("dimension = 2\n{s}"),
        &["`scene.box`: is missing"],
    );
    assert_says(2, s, &["dimension", "box"]);
    assert_says(2, &format!("box = [10.0, 10.0, 10.0]\n{s}"), &["3D", "2D"]);
    assert_says(
        2,
        &format!("box = [10.0, 10.0]\nboundary = [\"walls\"]\n{s}"),
        &["boundary", "one per axis"],
    );
}

#[test]
fn bad_thermal_walls() {
    let s = "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\n";
    assert_says(
        2,
        &format!(
            "{s}boundary = [\"periodic\", \"walls\"]\nthermal_walls = [{{ axis = 0, side = \"low\", temperature = 1.0 }}]\n"
        ),
        &["axis 0", "periodic", "\"walls\""],
    );
    assert_says(
        2,
        &format!("{s}thermal_walls = [{{ axis = 1, side = \"high\", temperature = 0.0 }}]\n"),
        &["temperature", "positive"],
    );
    assert_says(
        2,
        &format!("{s}thermal_walls = [{{ axis = 1, side = \"high\", temperature = -2.0 }}]\n"),
        &["temperature", "positive"],
    );
    assert_says(
        2,
        &format!("{s}thermal_walls = [{{ axis = 2, side = \"high\", temperature = 1.0 }}]\n"),
        &["axis 2", "2 axes"],
    );
}

#[test]
fn bad_species() {
    let b = "box = [10.0, 10.0]\n";
    assert_says(2, b, &["no particles", "scene.species"]);
    assert_says(
        2,
        &format!("{b}species = [{{ name = \"a\", count = 0 }}]\n"),
        &["no particles", "count"],
    );
    assert_says(
        2,
        &format!("{b}species = [{{ name = \"piston\", count = 3 }}]\n"),
        &["`piston`", "rename"],
    );
    assert_says(
        2,
        &format!("{b}species = [{{ name = \"a\", count = 3 }}, {{ name = \"a\", count = 1 }}]\n"),
        &["`a`", "twice"],
    );
}

#[test]
fn bad_regions() {
    let sp = |region: &str| {
        format!(
            "box = [10.0, 10.0]\nspecies = [{{ name = \"a\", count = 2, region = {region} }}]\n"
        )
    };
    assert_says(
        2,
        &sp("{ from = [0.5, 0.0], to = [0.5, 1.0] }"),
        &["`a`", "axis 0", "from < to"],
    );
    assert_says(
        2,
        &sp("{ from = [0.0, 0.0], to = [1.5, 1.0] }"),
        &["`a`", "axis 0", "to <= 1"],
    );
    assert_says(
        2,
        &sp("{ from = [-0.1, 0.0], to = [0.5, 1.0] }"),
        &["0 <= from"],
    );
    assert_says(
        2,
        &sp("{ from = [0.0], to = [0.5] }"),
        &["region.from", "one per axis"],
    );
    // A region narrower than a particle.
    assert_says(
        2,
        &sp("{ from = [0.0, 0.0], to = [0.05, 1.0] }"),
        &["radius 0.5", "does not fit", "axis 0"],
    );
}

#[test]
fn bad_placements() {
    let s = "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }]\n";
    assert_says(
        2,
        &format!("{s}placement = {{ kind = \"lattice\", lattice = \"fcc\" }}\n"),
        &["`fcc`", "2D", "\"hexagonal\""],
    );
    assert_says(
        2,
        &format!("{s}placement = {{ kind = \"explicit\", positions = [[1.0, 1.0]] }}\n"),
        &["1 entries for 3 particles", "one per particle"],
    );
    assert_says(
        2,
        &format!("{s}placement = {{ kind = \"explicit\", positions = [[1.0], [2.0], [3.0]] }}\n"),
        &["placement.positions", "one per axis"],
    );
    // Too dense for random insertion: the jamming limits and what to use instead.
    assert_says(
        2,
        "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 90 }]\n",
        &["0.547 in 2D", "compress", "lattice"],
    );
    // Species in overlapping but different regions cannot share a lattice.
    assert_says(
        2,
        "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }, { name = \"b\", count = 3, region = { from = [0.0, 0.0], to = [0.5, 0.5] } }]\nplacement = { kind = \"lattice\" }\n",
        &["`a`", "`b`", "same region"],
    );
}

#[test]
fn rods_that_cannot_be_placed() {
    assert_says(
        1,
        "box = [10.0]\nspecies = [{ name = \"a\", count = 11 }]\n",
        &["11 rods", "total length 11", "do not fit"],
    );
    assert_says(
        1,
        "box = [10.0]\nspecies = [{ name = \"a\", count = 11 }]\nplacement = { kind = \"lattice\" }\n",
        &["11 particles", "at most 10 fit"],
    );
    // Dense species in overlapping, different regions: no exact placement in sight.
    // (20 valid species orders of C(30, 15) = 1.6e8, so about 1e-7 of proposals fit.)
    assert_says(
        1,
        "box = [30.0]\nspecies = [\n  { name = \"a\", count = 15, region = { from = [0.0], to = [0.6] } },\n  { name = \"b\", count = 15, region = { from = [0.4], to = [1.0] } },\n]\n",
        &["`a` in [0, 18]", "`b` in [12, 30]", "same region"],
    );
    // Rods filling the box leave no room for a piston.
    assert_says(
        1,
        "box = [10.0]\nspecies = [{ name = \"a\", count = 10 }]\npiston = { mass = 5.0 }\n",
        &["piston", "10 rods"],
    );
}

#[test]
fn bad_pistons() {
    let s = "box = [10.0]\nspecies = [{ name = \"a\", count = 2, radius = 0.0, region = { from = [0.0], to = [0.4] } }]\n";
    assert_says(
        1,
        &format!("{s}piston = {{ mass = 5.0, position = 1.0 }}\n"),
        &["piston.position", "outside the box"],
    );
    assert_says(
        1,
        &format!("{s}piston = {{ mass = 0.0 }}\n"),
        &["piston.mass", "positive"],
    );
    assert_says(
        1,
        &format!("{s}piston = {{ mass = 5.0, energy = -1.0 }}\n"),
        &["piston.energy", ">= 0"],
    );
    // In 2D the piston is a wall: each gas keeps to one side of it, and it
    // slides between walls, not across a periodic boundary.
    assert_says(
        2,
        "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\npiston = { mass = 5.0 }\n",
        &["piston", "region of `a`", "either side"],
    );
    assert_says(
        2,
        "box = [10.0, 10.0]\nboundary = [\"periodic\", \"walls\"]\nspecies = [{ name = \"a\", count = 2, region = { from = [0.0, 0.0], to = [0.4, 1.0] } }]\npiston = { mass = 5.0 }\n",
        &["piston", "periodic", "walls"],
    );
    assert_says(
        2,
        "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2, region = { from = [0.0, 0.0], to = [0.4, 1.0] } }]\nplacement = { kind = \"compress\" }\npiston = { mass = 5.0 }\n",
        &["compress", "piston"],
    );
    // A lattice cannot straddle the piston.
    assert_says(
        1,
        "box = [10.0]\nspecies = [{ name = \"a\", count = 4, radius = 0.0 }]\nplacement = { kind = \"lattice\" }\npiston = { mass = 5.0, radius = 0.0 }\n",
        &["piston", "region of `a`", "either side"],
    );
}

#[test]
fn bad_velocities() {
    let s = "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }]\n";
    assert_says(
        2,
        &format!("{s}velocities = {{ kind = \"maxwell\", temperature = 0.0 }}\n"),
        &["velocities.temperature", "positive"],
    );
    assert_says(
        2,
        &format!("{s}velocities = {{ kind = \"maxwell\", energy = -1.0 }}\n"),
        &["velocities.energy", "positive"],
    );
    assert_says(
        2,
        &format!("{s}velocities = {{ kind = \"uniform\", p = 0.0 }}\n"),
        &["velocities.p", "positive"],
    );
    assert_says(
        2,
        &format!("{s}velocities = {{ kind = \"equal\", velocity = [1.0] }}\n"),
        &["velocities.velocity", "2 finite numbers"],
    );
    assert_says(
        2,
        &format!("{s}velocities = {{ kind = \"explicit\", velocities = [[1.0, 0.0]] }}\n"),
        &["1 entries for 3 particles", "one per particle"],
    );
    // Rescaling needs motion to rescale: one particle with zero momentum has none.
    assert_says(
        2,
        "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 1 }]\nvelocities = { kind = \"maxwell\", zero_momentum = true, energy = 2.0 }\n",
        &["cannot rescale", "all zero"],
    );
    // Immovable particles have nothing to rescale either.
    assert_says(
        2,
        "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3, mass = inf }]\nvelocities = { kind = \"maxwell\", energy = 2.0 }\n",
        &["no particle can move"],
    );
}

#[test]
fn unknown_presets_list_the_known_ones() {
    assert_says(
        1,
        "preset = \"mackay-pistn\"",
        &["`mackay-pistn`", "mackay-piston"],
    );
}

/// A scene refused the same way by the builder and by `study validate`: the
/// key at fault, and a message that says what is wrong.
struct Refused {
    scene: &'static str,
    key: &'static str,
    says: &'static str,
}

fn refused(scene: &'static str, key: &'static str, says: &'static str) -> Refused {
    Refused { scene, key, says }
}

/// A study descriptor around a scene (written as the keys of `[scene]`).
fn descriptor(scene: &str) -> String {
    format!("[study]\nname = \"t\"\n\n[scene]\n{scene}\n[run]\nduration = 1.0\n")
}

/// Build a resolved scene in its own dimension.
fn build_any(spec: &SceneSpec) -> Result<(), String> {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    match bonkers::scene::check::dimension(spec) {
        1 => build::<1>(spec, &mut rng).map(|_| ()),
        2 => build::<2>(spec, &mut rng).map(|_| ()),
        _ => build::<3>(spec, &mut rng).map(|_| ()),
    }
}

/// The scene's checks, the builder and the descriptor's validation refuse
/// each scene with the same key, message and hint; the descriptor adds only
/// where in the file the key is.
fn assert_refused_alike(cases: &[Refused]) {
    for c in cases {
        let spec = resolve(&toml::from_str(c.scene).expect("scene TOML")).expect("resolves");
        let problem = bonkers::scene::check::scene(&spec)
            .expect_err(&format!("the checks must refuse\n{}", c.scene));
        assert_eq!(problem.key, c.key, "{}\n{problem}", c.scene);
        assert!(
            problem.message.contains(c.says),
            "{}\nshould say `{}`: {problem}",
            c.scene,
            c.says
        );
        let built = build_any(&spec).expect_err(&format!("the builder must refuse\n{}", c.scene));
        assert_eq!(built, problem.to_string(), "{}", c.scene);
        let err = bonkers::descriptor::load::parse("s.toml", &descriptor(c.scene))
            .expect_err(&format!("validation must refuse\n{}", c.scene));
        assert_eq!(err.key.as_deref(), Some(c.key), "{}\n{err}", c.scene);
        assert_eq!(err.message, format!("`{}`: {}", c.key, problem.message));
        assert_eq!(err.hints, problem.hint.into_iter().collect::<Vec<_>>());
        assert!(err.position.is_some(), "{err}");
    }
}

/// Explicit positions outside the box, or overlapping each other or the
/// piston: found before anything runs, not when every run starts.
#[test]
fn explicit_positions_outside_or_overlapping_are_refused_alike() {
    assert_refused_alike(&[
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[2.0, 2.0], [10.2, 5.0]] }\n",
            "scene.placement.positions.1",
            "particle 1 at [10.2, 5.0] (radius 0.5) is outside the box on axis 0, which spans [0, 10]",
        ),
        // Within the box, but closer to a wall than its radius.
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[2.0, 0.3], [5.0, 5.0]] }\n",
            "scene.placement.positions.0",
            "particle 0 at [2.0, 0.3] (radius 0.5) is outside the box on axis 1, which spans [0, 10]",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 2, radius = 0.0 }]\nplacement = { kind = \"explicit\", positions = [[-1.0], [5.0]] }\n",
            "scene.placement.positions.0",
            "particle 0 at [-1.0] (radius 0) is outside the box on axis 0, which spans [0, 10]",
        ),
        refused(
            "box = [10.0, 10.0, 10.0]\nboundary = [\"periodic\", \"periodic\", \"walls\"]\nspecies = [{ name = \"a\", count = 1 }]\nplacement = { kind = \"explicit\", positions = [[20.0, -3.0, 9.9]] }\n",
            "scene.placement.positions.0",
            "is outside the box on axis 2, which spans [0, 10]",
        ),
        // Overlaps with walls...
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }]\nplacement = { kind = \"explicit\", positions = [[2.0, 2.0], [5.0, 5.0], [2.5, 2.0]] }\n",
            "scene.placement.positions.2",
            "particles 0 and 2 overlap: their centres are 0.500000 apart but their radii add to 1",
        ),
        refused(
            "box = [10.0, 10.0, 10.0]\nspecies = [{ name = \"a\", count = 1, radius = 1.0 }, { name = \"b\", count = 1, radius = 0.25 }]\nplacement = { kind = \"explicit\", positions = [[5.0, 5.0, 5.0], [5.5, 5.5, 5.5]] }\n",
            "scene.placement.positions.1",
            "particles 0 and 1 overlap: their centres are 0.866025 apart but their radii add to 1.25",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 3 }]\nplacement = { kind = \"explicit\", positions = [[8.0], [1.0], [7.2]] }\n",
            "scene.placement.positions.2",
            "particles 0 and 2 overlap: their centres are 0.800000 apart but their radii add to 1",
        ),
        // ...and across periodic boundaries (the nearest image counts).
        refused(
            "box = [10.0, 10.0]\nboundary = [\"periodic\", \"periodic\"]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[0.2, 5.0], [9.9, 5.2]] }\n",
            "scene.placement.positions.1",
            "particles 0 and 1 overlap: their centres are 0.360555 apart but their radii add to 1",
        ),
        refused(
            "box = [10.0, 10.0]\nboundary = [\"periodic\", \"walls\"]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[-0.2, 5.0], [10.5, 5.0]] }\n",
            "scene.placement.positions.1",
            "particles 0 and 1 overlap: their centres are 0.700000 apart but their radii add to 1",
        ),
        refused(
            "box = [10.0]\nboundary = [\"periodic\"]\nspecies = [{ name = \"a\", count = 3 }]\nplacement = { kind = \"explicit\", positions = [[0.3], [5.0], [9.5]] }\n",
            "scene.placement.positions.2",
            "particles 0 and 2 overlap: their centres are 0.800000 apart but their radii add to 1",
        ),
        // Radii drawn from a range count at their smallest.
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2, radius = [0.3, 0.6] }]\nplacement = { kind = \"explicit\", positions = [[2.0, 2.0], [2.5, 2.0]] }\n",
            "scene.placement.positions.1",
            "their radii add to 0.6",
        ),
        // The piston takes room too: a rod in 1D, a wall along x above.
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[2.0], [5.2]] }\npiston = { mass = 5.0 }\n",
            "scene.placement.positions.1",
            "particle 1 at [5.2] (radius 0.5) overlaps the piston at x = 5 (half thickness 0.5)",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[2.0, 2.0], [5.7, 8.0]] }\npiston = { mass = 5.0, radius = 0.25 }\n",
            "scene.placement.positions.1",
            "particle 1 at [5.7, 8.0] (radius 0.5) overlaps the piston at x = 5 (half thickness 0.25)",
        ),
    ]);
}

/// Every other scene a run would refuse before it starts is refused by
/// validation too, with the same key and message.
#[test]
fn what_a_run_refuses_validation_refuses() {
    assert_refused_alike(&[
        // Shapes and species.
        refused(
            "dimension = 2\nbox = [10.0]\nspecies = [{ name = \"a\", count = 2 }]\n",
            "scene.box",
            "has 1 entries but the scene has dimension 2",
        ),
        refused(
            "box = [10.0, -3.0]\nspecies = [{ name = \"a\", count = 2 }]\n",
            "scene.box.1",
            "must be a positive number, got -3",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 0 }]\n",
            "scene.species",
            "the scene has no particles",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"piston\", count = 3 }]\n",
            "scene.species.0.name",
            "`piston` is the name the piston's observables use",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }, { name = \"a\", count = 1 }]\n",
            "scene.species.1.name",
            "species \"a\" is named twice",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2, radius = [0.6, 0.2] }]\n",
            "scene.species.0.radius",
            "range [0.6, 0.2] is reversed",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2, mass = 1e-320 }]\n",
            "scene.species.0.mass",
            "is too small: its inverse overflows",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2, region = { from = [0.5, 0.0], to = [0.5, 1.0] } }]\n",
            "scene.species.0.region",
            "axis 0: [0.5, 0.5] is not a part of the box",
        ),
        // Room: regions, lattices, rods, the piston, periodic boxes.
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2, region = { from = [0.0, 0.0], to = [0.05, 1.0] } }]\n",
            "scene.species.0.region",
            "a particle of radius 0.5 does not fit in its region along axis 0, which is 0.5 long",
        ),
        refused(
            "box = [0.8, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"compress\" }\n",
            "scene.species.0",
            "a particle of radius 0.5 does not fit in its region along axis 0, which is 0.8 long",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 90 }]\n",
            "scene.species.0.count",
            "random insertion jams at 0.547 in 2D",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 120 }]\nplacement = { kind = \"compress\" }\n",
            "scene.species.0.count",
            "compression reaches at most 0.88 in 2D",
        ),
        refused(
            "box = [19.22, 19.22]\nspecies = [{ name = \"a\", count = 420 }]\nplacement = { kind = \"lattice\" }\n",
            "scene.species.0.count",
            "at most 407 fit, packing fraction 0.86",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 11 }]\nplacement = { kind = \"lattice\" }\n",
            "scene.species.0.count",
            "11 particles of radius 0.5 (`a`) do not fit on a line lattice",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }, { name = \"b\", count = 3, region = { from = [0.0, 0.0], to = [0.5, 0.5] } }]\nplacement = { kind = \"lattice\" }\n",
            "scene.species.1.region",
            "species `a` and `b` have regions that overlap without being the same",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 11 }]\n",
            "scene.species.0.count",
            "rods of total length 11 do not fit in their region of length 10",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 10 }]\npiston = { mass = 5.0 }\n",
            "scene.species.0.count",
            "rods of total length 10 do not fit in their region of length 9 beside the piston",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 5 }, { name = \"b\", count = 5 }]\npiston = { mass = 5.0, per_side = 5 }\n",
            "scene.piston.per_side",
            "rods of total length 10 do not fit in their region of length 9 beside the piston",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 4, radius = 0.0 }]\nplacement = { kind = \"lattice\" }\npiston = { mass = 5.0, radius = 0.0 }\n",
            "scene.species.0",
            "species \"a\" would be on both sides of the piston (at x = 5, half thickness 0)",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2, region = { from = [0.0, 0.0], to = [0.8, 1.0] } }]\npiston = { mass = 5.0 }\n",
            "scene.species.0.region",
            "species \"a\" would be on both sides of the piston wall (at x = 5, half thickness 0.5): its region [0, 8] contains it",
        ),
        // A region the piston trims to less than a particle.
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2, region = { from = [0.4, 0.0], to = [0.5, 1.0] } }]\npiston = { mass = 5.0, position = 0.4, radius = 0.25 }\n",
            "scene.species.0.region",
            "a particle of radius 0.5 does not fit in its region along axis 0, which is 0.75 long",
        ),
        refused(
            "box = [10.0, 2.5]\nboundary = [\"walls\", \"periodic\"]\nspecies = [{ name = \"a\", count = 2 }]\n",
            "scene.box.1",
            "periodic axis 1 is 2.5 long, too short for particles of diameter 1",
        ),
        // Placement settings.
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }]\nplacement = { kind = \"lattice\", lattice = \"fcc\" }\n",
            "scene.placement.lattice",
            "\"fcc\" is not a lattice in 2D",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 10 }]\nplacement = { kind = \"compress\", growth_rate = -1.0 }\n",
            "scene.placement.growth_rate",
            "must be a positive number, got -1",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }]\nplacement = { kind = \"explicit\", positions = [[1.0, 1.0]] }\n",
            "scene.placement.positions",
            "has 1 entries for 3 particles",
        ),
        // Velocities.
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }]\nvelocities = { kind = \"equal\", velocity = [1.0] }\n",
            "scene.velocities.velocity",
            "has 1 entries but the scene has dimension 2",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }]\nvelocities = { kind = \"explicit\", velocities = [[1.0, 0.0]] }\n",
            "scene.velocities.velocities",
            "has 1 entries for 3 particles",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 1 }, { name = \"wall\", count = 2, mass = inf }]\nvelocities = { kind = \"maxwell\", zero_momentum = true, energy = 2.0 }\n",
            "scene.velocities.energy",
            "cannot rescale to energy 2",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3, mass = inf }]\nvelocities = { kind = \"uniform\", p = 1.0, zero_momentum = true }\n",
            "scene.velocities.zero_momentum",
            "no particle can move",
        ),
        // Zero momentum makes the gas drift against the piston, at a cost in energy.
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 2, radius = 0.0 }]\nvelocities = { kind = \"maxwell\", zero_momentum = true, energy = 1.0 }\npiston = { mass = 100.0, velocity = 1.0 }\n",
            "scene.velocities.energy",
            "1 is too small: balancing the piston's momentum alone gives the gas a kinetic energy of 2500",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 2, radius = 0.0, mass = [1.0, 2.0] }]\nvelocities = { kind = \"uniform\", p = 1.0, zero_momentum = true, energy = 1.0 }\npiston = { mass = 100.0, energy = 10.0 }\n",
            "scene.velocities.energy",
            "1 is too small: balancing the piston's momentum alone",
        ),
        // The piston.
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 2, radius = 0.0, region = { from = [0.0], to = [0.4] } }]\npiston = { mass = 5.0, position = 0.02 }\n",
            "scene.piston.position",
            "at 0.02 it is outside the box [0, 10]",
        ),
        refused(
            "box = [10.0, 10.0]\nboundary = [\"periodic\", \"walls\"]\nspecies = [{ name = \"a\", count = 2, region = { from = [0.0, 0.0], to = [0.4, 1.0] } }]\npiston = { mass = 5.0 }\n",
            "scene.boundary",
            "is periodic along x",
        ),
        refused(
            "box = [10.0]\nspecies = [{ name = \"a\", count = 2, radius = 0.0 }]\npiston = { mass = 5.0, energy = -1.0 }\n",
            "scene.piston.energy",
            "must be a number >= 0, got -1",
        ),
        // Thermal walls.
        refused(
            "box = [10.0, 10.0]\nboundary = [\"periodic\", \"walls\"]\nspecies = [{ name = \"a\", count = 2 }]\nthermal_walls = [{ axis = 0, side = \"low\", temperature = 1.0 }]\n",
            "scene.thermal_walls.0.axis",
            "axis 0 is periodic",
        ),
        refused(
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\nthermal_walls = [{ axis = 2, side = \"high\", temperature = 1.0 }]\n",
            "scene.thermal_walls.0.axis",
            "axis 2 does not exist in 2 dimensions",
        ),
    ]);
}

/// What both accept: every bundled preset, and scenes at the edges of the
/// rules (touching particles, positions folded across a periodic boundary,
/// a species of count 0, rods that exactly fill their region; rods that
/// fill the whole line are built, but their runs refused).
#[test]
fn good_scenes_pass_both() {
    let mut scenes: Vec<String> = bonkers::scene::presets::names()
        .iter()
        .map(|n| format!("preset = \"{n}\"\n"))
        .collect();
    scenes.extend(
        [
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[2.0, 2.0], [3.0, 2.0]] }\n",
            "box = [10.0, 10.0]\nboundary = [\"periodic\", \"walls\"]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[-4.0, 5.0], [12.0, 5.0]] }\n",
            "box = [10.0]\nboundary = [\"periodic\"]\nspecies = [{ name = \"a\", count = 3 }]\nplacement = { kind = \"explicit\", positions = [[-0.5], [5.0], [12.0]] }\n",
            "box = [10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[0.5], [9.5]] }\npiston = { mass = 5.0 }\n",
            "box = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 3 }, { name = \"none\", count = 0 }]\n",
            "box = [10.0]\nspecies = [{ name = \"a\", count = 4, radius = 0.5, region = { from = [0.0], to = [0.45] } }, { name = \"b\", count = 4, radius = 0.5, region = { from = [0.55], to = [1.0] } }]\npiston = { mass = 5.0 }\n",
            "box = [10.0]\nspecies = [{ name = \"a\", count = 2, radius = 0.0 }]\nvelocities = { kind = \"maxwell\", zero_momentum = true, energy = 2600.0 }\npiston = { mass = 100.0, velocity = 1.0 }\n",
            "box = [10.0, 3.1]\nboundary = [\"walls\", \"periodic\"]\nspecies = [{ name = \"a\", count = 2 }]\n",
        ]
        .map(String::from),
    );
    for scene in &scenes {
        let spec = resolve(&toml::from_str(scene).expect("scene TOML")).expect("resolves");
        assert_eq!(bonkers::scene::check::scene(&spec), Ok(()), "{scene}");
        build_any(&spec).unwrap_or_else(|e| panic!("{scene}\nbuilder: {e}"));
        if let Err(e) = bonkers::descriptor::load::parse("s.toml", &descriptor(scene)) {
            panic!("{scene}\nvalidation: {e}");
        }
    }
    // A line filled end to end is placed (at random or as a lattice), but
    // a run could never move on it: validation refuses the run.
    for scene in [
        "box = [10.0]\nspecies = [{ name = \"a\", count = 10 }]\n",
        "box = [10.0]\nspecies = [{ name = \"a\", count = 10 }]\nplacement = { kind = \"lattice\" }\n",
    ] {
        let spec = resolve(&toml::from_str(scene).expect("scene TOML")).expect("resolves");
        assert_eq!(bonkers::scene::check::scene(&spec), Ok(()), "{scene}");
        build_any(&spec).unwrap_or_else(|e| panic!("{scene}\nbuilder: {e}"));
        let err = bonkers::descriptor::load::parse("s.toml", &descriptor(scene)).unwrap_err();
        assert!(
            err.to_string()
                .contains("`scene.box.0`: 10 is the rods' diameters end to end (10)"),
            "{scene}\n{err}"
        );
    }
}

/// Random explicit positions, some overlapping and some not, across walls
/// and periodic boundaries: the scene's checks refuse exactly those the
/// engine refuses when the run starts.
#[test]
fn explicit_overlaps_are_found_as_the_engine_finds_them() {
    use bonkers::engine::{
        Axis, Chain, NeighbourList, Neighbourhood, Particle, SimBox, Simulation,
    };
    use rand::RngExt;

    fn trials<const D: usize, N: Neighbourhood<D>>(
        periodic: bool,
        rng: &mut ChaCha8Rng,
    ) -> [usize; 2] {
        let length = 12.0;
        let mut outcomes = [0, 0];
        for trial in 0..150 {
            let n = 2 + trial % 12;
            let radii: Vec<f64> = (0..n).map(|i| if i % 3 == 0 { 0.9 } else { 0.4 }).collect();
            // Inside the walls; anywhere within three periods when periodic.
            let at = |r: f64, rng: &mut ChaCha8Rng| {
                let u = rng.random::<f64>();
                if periodic {
                    -length + 3.0 * length * u
                } else {
                    r + (length - 2.0 * r) * u
                }
            };
            let pos: Vec<[f64; D]> = radii
                .iter()
                .map(|&r| std::array::from_fn(|_| at(r, rng)))
                .collect();
            let list: Vec<String> = pos
                .iter()
                .map(|p| format!("[{}]", p.map(|x| format!("{x:?}")).join(", ")))
                .collect();
            let boundary = if periodic {
                "\"periodic\""
            } else {
                "\"walls\""
            };
            let scene = format!(
                "box = [{}]\nboundary = [{}]\nspecies = [{{ name = \"big\", count = {}, radius = 0.9 }}, {{ name = \"small\", count = {}, radius = 0.4 }}]\nplacement = {{ kind = \"explicit\", positions = [{}] }}\n",
                vec![format!("{length:?}"); D].join(", "),
                vec![boundary; D].join(", "),
                radii.iter().filter(|&&r| r > 0.5).count(),
                radii.iter().filter(|&&r| r < 0.5).count(),
                // Species by species: the big ones first.
                (0..n)
                    .filter(|i| i % 3 == 0)
                    .chain((0..n).filter(|i| i % 3 != 0))
                    .map(|i| list[i].clone())
                    .collect::<Vec<_>>()
                    .join(", "),
            );
            let spec = resolve(&toml::from_str(&scene).unwrap()).unwrap();
            let checked = bonkers::scene::check::scene(&spec);
            // The engine, given the same particles (folded into the box, and
            // in order along a line, as the builder hands them over).
            let mut particles: Vec<Particle<D>> = pos
                .iter()
                .zip(&radii)
                .map(|(p, &r)| {
                    let p = p.map(|x| if periodic { x.rem_euclid(length) } else { x });
                    Particle::new(p, [0.0; D], 1.0, r)
                })
                .collect();
            if D == 1 {
                particles.sort_by(|a, b| a.pos[0].total_cmp(&b.pos[0]));
            }
            let sim_box = SimBox {
                size: [length; D],
                axes: [if periodic { Axis::Periodic } else { Axis::HARD }; D],
            };
            let engine = Simulation::<D, N, ()>::new(particles, sim_box, (), 1);
            assert_eq!(
                checked.is_ok(),
                engine.is_ok(),
                "{scene}\nchecks: {checked:?}\nengine: {:?}",
                engine.err()
            );
            if let Err(p) = checked {
                assert!(p.message.contains("overlap"), "{p}");
            }
            outcomes[usize::from(engine.is_ok())] += 1;
        }
        outcomes
    }

    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for periodic in [false, true] {
        let counts = [
            trials::<1, Chain>(periodic, &mut rng),
            trials::<2, NeighbourList<2>>(periodic, &mut rng),
            trials::<3, NeighbourList<3>>(periodic, &mut rng),
        ];
        for (d, [refused, accepted]) in counts.iter().enumerate() {
            assert!(
                *refused >= 10 && *accepted >= 10,
                "{}D, periodic {periodic}: {refused} refused, {accepted} accepted",
                d + 1
            );
        }
    }
}

/// `order = "alternating"` is one chain of rods: refused, by the checks, the
/// builder and validation alike (at the key's line and column), in 2D, with
/// unequal counts, with different regions, and with a piston; an order that
/// does not exist names the ones that do.
#[test]
fn alternating_order_needs_one_chain_of_rods() {
    let order = "placement = { kind = \"random\", order = \"alternating\" }\n";
    let two = "species = [{ name = \"a\", count = 3, radius = 0.0 }, { name = \"b\", count = 3, radius = 0.0 }]\n";
    let cases: Vec<(String, &str)> = vec![
        (
            format!("box = [10.0, 10.0]\n{two}{order}"),
            "this scene is 2D",
        ),
        (
            format!(
                "box = [10.0]\nspecies = [{{ name = \"a\", count = 3 }}, {{ name = \"b\", count = 2 }}]\n{order}"
            ),
            "`a` has 3 and `b` has 2",
        ),
        (
            format!(
                "box = [10.0]\nspecies = [{{ name = \"a\", count = 3 }}, {{ name = \"b\", count = 3, region = {{ from = [0.5], to = [1.0] }} }}]\n{order}"
            ),
            "`a` and `b` have different regions",
        ),
        (
            format!("box = [10.0]\n{two}piston = {{ mass = 5.0 }}\n{order}"),
            "the piston cuts the line in two",
        ),
    ];
    let leaked: Vec<Refused> = cases
        .into_iter()
        .map(|(scene, says)| refused(scene.leak(), "scene.placement.order", says))
        .collect();
    assert_refused_alike(&leaked);
    let err = bonkers::descriptor::load::parse(
        "s.toml",
        &descriptor(&format!(
            "box = [10.0]\n{two}placement = {{ kind = \"random\", order = \"zigzag\" }}\n"
        )),
    )
    .expect_err("an unknown order is refused");
    assert!(err.position.is_some(), "{err}");
    assert!(err.to_string().contains("alternating"), "{err}");
}
