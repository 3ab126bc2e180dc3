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
    assert_says(2, &format!("dimension = 2\n{s}"), &["scene.box is missing"]);
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
