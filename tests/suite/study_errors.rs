//! Every descriptor error path, table-driven: each case edits the valid test
//! descriptor and expects the message to give the file:line:col of the key
//! at fault, the key, what is wrong and (where one is close) what is right.

use crate::study_common::PISTON;
use bonkers::descriptor::load::parse;
use bonkers::runner::plan::plan;

/// One edit of PISTON and what its error must say.
struct Case {
    what: &'static str,
    text: String,
    expect: &'static [&'static str],
}

fn edit(from: &str, to: &str) -> String {
    assert!(PISTON.contains(from), "PISTON has no {from:?}");
    PISTON.replacen(from, to, 1)
}

/// PISTON without its sweep (so base values are what runs).
fn unswept() -> String {
    let head = &PISTON[..PISTON.find("[sweep]").unwrap()];
    let tail = &PISTON[PISTON.find("[run]").unwrap()..];
    let tail = tail.replace(
        "\"sweep.parameters.scene.piston.mass\" = [1.0, 100.0]\n",
        "",
    );
    format!("{head}{tail}")
}

fn case(what: &'static str, text: String, expect: &'static [&'static str]) -> Case {
    Case { what, text, expect }
}

fn check(cases: &[Case]) {
    for c in cases {
        let msg = match parse("s.toml", &c.text) {
            Ok(_) => panic!("{}: accepted", c.what),
            Err(e) => e.to_string(),
        };
        for part in c.expect {
            assert!(
                msg.contains(part),
                "{}: expected {part:?} in:\n{msg}",
                c.what
            );
        }
    }
}

#[test]
fn run_section() {
    check(&[
        case(
            "collisions = 0",
            edit("duration = 100.0", "collisions = 0"),
            &["s.toml:34:1: `run.collisions`: must be at least 1"],
        ),
        case(
            "negative equilibration",
            edit("equilibrate = 10.0", "equilibrate = -1.0"),
            &["s.toml:35:1: `run.equilibrate`: must be a number >= 0, got -1"],
        ),
        case(
            "zero sampling interval",
            edit("sample_every = 0.5", "sample_every = 0.0"),
            &["s.toml:36:1: `run.sample_every`: must be a positive number"],
        ),
        case(
            "more samples than a run keeps",
            edit("sample_every = 0.5", "sample_every = 1e-6"),
            &[
                "s.toml:36:1: `run.sample_every`: 1e-6 gives 1.0e8 samples over the duration 100; a run keeps at most 1e7",
                "`sample_every = 0.001`",
            ],
        ),
    ]);
}

#[test]
fn scene_shapes_and_species() {
    check(&[
        case(
            "boundary length",
            edit("boundary = [\"walls\"]", "boundary = [\"walls\", \"walls\"]"),
            &["s.toml:11:1: `scene.boundary`: has 2 entries but the scene has dimension 1"],
        ),
        case(
            "box length without a dimension",
            edit("dimension = 1\nbox = [40.0]", "box = [40.0, 40.0]"),
            // The box says 2D; the one-entry boundary is then what is wrong.
            &["s.toml:10:1: `scene.boundary`: has 1 entries but the scene has dimension 2"],
        ),
        case(
            "empty species name",
            edit("name = \"gas\"", "name = \"\""),
            &["s.toml:14:1: `scene.species.0.name`: must not be empty"],
        ),
        case(
            "duplicate species name",
            edit(
                "to = [0.45] }\n[scene.piston]",
                "to = [0.45] }\n[[scene.species]]\nname = \"gas\"\ncount = 2\n[scene.piston]",
            ),
            &[
                "s.toml:19:1: `scene.species.1.name`: species \"gas\" is named twice",
                "give each species its own name",
            ],
        ),
        case(
            "negative radius",
            edit("mass = 1.0\n", "mass = 1.0\nradius = -0.5\n"),
            &["s.toml:17:1: `scene.species.0.radius`: must be a number >= 0, got -0.5"],
        ),
        case(
            "zero mass",
            edit("mass = 1.0", "mass = 0.0"),
            &["s.toml:16:1: `scene.species.0.mass`: must be a positive number, got 0"],
        ),
        case(
            "reversed mass range",
            edit("mass = 1.0", "mass = [2.0, 1.0]"),
            &[
                "s.toml:16:1: `scene.species.0.mass`: range [2, 1] is reversed",
                "lo <= hi",
            ],
        ),
        case(
            "a mass whose inverse overflows",
            edit("mass = 1.0", "mass = 1e-320"),
            &[
                "s.toml:16:1: `scene.species.0.mass`: 1e-320 is too small: its inverse overflows",
                "from 1e-300 up",
            ],
        ),
        case(
            "more particles than a run can hold",
            edit("count = 10\nmass = 1.0", "count = 60000000\nmass = 1.0")
                .replace("\"scene.species.0.count\" = { from = 5, to = 15, steps = 2 }\n", ""),
            &["`scene.species`: 60000000 particles are more than one run can hold (50000000 at most)"],
        ),
        case(
            "disks denser than random insertion reaches",
            edit(
                "dimension = 1\nbox = [40.0]\nboundary = [\"walls\"]",
                "dimension = 2\nbox = [6.0, 6.0]\nboundary = [\"walls\", \"walls\"]",
            )
            .replace("[[scene.species]]\nname = \"gas\"\ncount = 10\nmass = 1.0\nregion = { from = [0.0], to = [0.45] }\n", "")
            .replace("\"scene.species.0.count\" = { from = 5, to = 15, steps = 2 }\n", "")
            .replace("[scene.piston]", "[[scene.species]]\nname = \"disk\"\ncount = 30\n\n[scene.piston]"),
            &[
                "`scene.species.0.count`: the particles would fill packing fraction 0.6545 of their region; random insertion jams at 0.547 in 2D",
                "kind = \"compress\"",
            ],
        ),
        case(
            "disks denser than compression reaches",
            edit(
                "dimension = 1\nbox = [40.0]\nboundary = [\"walls\"]",
                "dimension = 2\nbox = [6.0, 6.0]\nboundary = [\"walls\", \"walls\"]\nplacement = { kind = \"compress\" }",
            )
            .replace("[[scene.species]]\nname = \"gas\"\ncount = 10\nmass = 1.0\nregion = { from = [0.0], to = [0.45] }\n", "")
            .replace("\"scene.species.0.count\" = { from = 5, to = 15, steps = 2 }\n", "")
            .replace("[scene.piston]", "[[scene.species]]\nname = \"disk\"\ncount = 45\n\n[scene.piston]"),
            &[
                "`scene.species.0.count`: the particles would fill packing fraction 0.9817 of their region; compression reaches at most 0.88 in 2D",
                "kind = \"lattice\"",
            ],
        ),
        case(
            "mass range with a negative end",
            edit("mass = 1.0", "mass = [-1.0, 1.0]"),
            &["s.toml:16:1: `scene.species.0.mass`: must be a positive number, got -1"],
        ),
        case(
            "region outside the box",
            edit("region = { from = [0.0], to = [0.45] }", "region = { from = [0.5], to = [0.2] }"),
            &[
                "s.toml:17:1: `scene.species.0.region`: axis 0: [0.5, 0.2] is not a part of the box",
                "0 <= from < to <= 1",
            ],
        ),
        case(
            "region with too many axes",
            edit(
                "region = { from = [0.0], to = [0.45] }",
                "region = { from = [0.0, 0.0], to = [0.5, 0.5] }",
            ),
            &["s.toml:17:12: `scene.species.0.region.from`: has 2 entries but the scene has dimension 1"],
        ),
        case(
            "a 2D gas on both sides of the piston wall",
            edit(
                "dimension = 1\nbox = [40.0]\nboundary = [\"walls\"]",
                "dimension = 2\nbox = [40.0, 40.0]\nboundary = [\"walls\", \"walls\"]",
            )
            .replace(
                "from = [0.0], to = [0.45]",
                "from = [0.0, 0.0], to = [0.6, 1.0]",
            ),
            &[
                "`scene.species.0.region`: species \"gas\" would be on both sides of the piston wall (at x = 20, half thickness 0.5): its region [0, 24] contains it",
                "`region = { from = [0.0], to = [0.48] }`",
            ],
        ),
        case(
            "rods that do not fit their region",
            edit("{ from = 5, to = 15, steps = 2 }", "{ from = 5, to = 19, steps = 2 }"),
            &[
                "s.toml:31:1: sweep parameter `scene.species.0.count`: value 19 makes `scene.species.0.count` invalid: rods of total length 19 do not fit in their region of length 18",
            ],
        ),
        case(
            "no species",
            edit("[[scene.species]]\nname = \"gas\"\ncount = 10\nmass = 1.0\nregion = { from = [0.0], to = [0.45] }\n", "")
                .replace("\"scene.species.0.count\" = { from = 5, to = 15, steps = 2 }\n", ""),
            &["s.toml:8:2: `scene.species`: the scene has no particles"],
        ),
        case(
            "no box",
            edit("box = [40.0]\n", ""),
            &["s.toml:8:2: `scene.box`: is missing", "box = [20.0]"],
        ),
        case(
            "explicit positions, one short",
            edit(
                "[scene.velocities]",
                "[scene.placement]\nkind = \"explicit\"\npositions = [[1.0], [2.0]]\n\n[scene.velocities]",
            ),
            &[
                "s.toml:24:1: `scene.placement.positions`: has 2 entries for 5 particles (at sweep point `scene.piston.mass` = 1.0, `scene.species.0.count` = 5)",
                "one position per particle",
            ],
        ),
        case(
            "a lattice that 1D does not have",
            edit(
                "[scene.velocities]",
                "[scene.placement]\nkind = \"lattice\"\nlattice = \"fcc\"\n\n[scene.velocities]",
            ),
            &[
                "s.toml:24:1: `scene.placement.lattice`: \"fcc\" is not a lattice in 1D",
                "use \"line\"",
            ],
        ),
    ]);
}

#[test]
fn velocities_piston_and_thermal_walls() {
    let thermal = |axis: &str, temperature: &str| {
        format!(
            "{PISTON}\n[[scene.thermal_walls]]\naxis = {axis}\nside = \"low\"\ntemperature = {temperature}\n"
        )
    };
    check(&[
        case(
            "zero temperature",
            edit("temperature = 1.0", "temperature = 0.0"),
            &["s.toml:24:1: `scene.velocities.temperature`: must be a positive number"],
        ),
        case(
            "negative energy",
            edit("temperature = 1.0\n", "temperature = 1.0\nenergy = -1.0\n"),
            &["s.toml:25:1: `scene.velocities.energy`: must be a positive number"],
        ),
        case(
            "negative momentum range",
            edit(
                "kind = \"maxwell\"\ntemperature = 1.0",
                "kind = \"uniform\"\np = -1.0",
            ),
            &["s.toml:24:1: `scene.velocities.p`: must be a positive number"],
        ),
        case(
            "equal velocities with two components in 1D",
            edit(
                "kind = \"maxwell\"\ntemperature = 1.0",
                "kind = \"equal\"\nvelocity = [1.0, 0.0]",
            ),
            &[
                "s.toml:24:1: `scene.velocities.velocity`: has 2 entries but the scene has dimension 1",
            ],
        ),
        case(
            "negative piston mass",
            unswept().replacen("mass = 5.0", "mass = -5.0", 1),
            &["s.toml:19:1: `scene.piston.mass`: must be a positive number, got -5"],
        ),
        case(
            "negative piston radius",
            edit("position = 0.5\n", "position = 0.5\nradius = -1.0\n"),
            &["s.toml:21:1: `scene.piston.radius`: must be a number >= 0, got -1"],
        ),
        case(
            "piston at the wall",
            edit("position = 0.5", "position = 1.0"),
            &[
                "s.toml:20:1: `scene.piston.position`: must be a fraction of the box between 0 and 1",
            ],
        ),
        case(
            "2D piston wall across a periodic x axis",
            edit(
                "dimension = 1\nbox = [40.0]\nboundary = [\"walls\"]",
                "dimension = 2\nbox = [40.0, 40.0]\nboundary = [\"periodic\", \"walls\"]",
            )
            .replace(
                "from = [0.0], to = [0.45]",
                "from = [0.0, 0.0], to = [0.45, 1.0]",
            ),
            &[
                "s.toml:11:1: `scene.boundary`: is periodic along x, but a piston wall slides along x between walls",
            ],
        ),
        case(
            "thermal wall on an axis that does not exist",
            thermal("1", "2.0"),
            &[
                "s.toml:48:1: `scene.thermal_walls.0.axis`: axis 1 does not exist in 1 dimensions",
                "axes count from 0",
            ],
        ),
        case(
            "thermal wall on a periodic axis",
            thermal("0", "2.0").replacen("[\"walls\"]", "[\"periodic\"]", 1),
            &[
                "s.toml:48:1: `scene.thermal_walls.0.axis`: axis 0 is periodic",
                "make `scene.boundary.0` \"walls\"",
            ],
        ),
        case(
            "thermal wall at zero temperature",
            thermal("0", "0.0"),
            &["s.toml:50:1: `scene.thermal_walls.0.temperature`: must be a positive number"],
        ),
    ]);
}

#[test]
fn presets() {
    let with_preset = |preset: &str, extra: &str| {
        let head = &PISTON[..PISTON.find("[scene]").unwrap()];
        let tail = &PISTON[PISTON.find("[run]").unwrap()..];
        let tail = tail.replace(
            "\"sweep.parameters.scene.piston.mass\" = [1.0, 100.0]\n",
            "",
        );
        format!("{head}[scene]\npreset = \"{preset}\"\n{extra}\n{tail}")
    };
    check(&[
        case(
            "unknown preset",
            with_preset("mackay-pistn", ""),
            &[
                "s.toml:9:1: `scene.preset`: unknown scene preset \"mackay-pistn\"",
                "did you mean \"mackay-piston\"?",
            ],
        ),
        case(
            "a preset's box against a new dimension",
            with_preset("mackay-piston", "dimension = 2"),
            &[
                "s.toml:9:1: `scene.box`: has 1 entries but the scene has dimension 2",
                "`scene.box` comes from preset \"mackay-piston\"",
            ],
        ),
        case(
            "piston_position in a preset without a piston",
            with_preset("mackay-ten", ""),
            &[
                "s.toml:", // [observe] series line, checked below
                "`observe.series.0`: `piston_position` needs a piston in the scene",
                "add `[scene.piston]`",
            ],
        ),
    ]);
    // The preset's explicit positions count its own particles.
    let msg = parse(
        "s.toml",
        &with_preset("mackay-cradle", "species = [{ name = \"one\", count = 3 }]").replace(
            "series = [\"piston_position\"]",
            "series = [\"kinetic_energy\"]",
        ),
    )
    .unwrap_err()
    .to_string();
    assert!(
        msg.contains("s.toml:9:1: `scene.placement.positions`: has 8 entries for 3 particles"),
        "{msg}"
    );
    assert!(msg.contains("comes from preset \"mackay-cradle\""), "{msg}");
    // A good preset with overrides is fine.
    assert!(parse("s.toml", &with_preset("mackay-piston", "")).is_ok());
}

#[test]
fn observables_and_analyses() {
    check(&[
        case(
            "unknown series",
            edit(
                "series = [\"piston_position\"]",
                "series = [\"piston_postion\"]",
            ),
            &[
                "s.toml:40:11: `observe.series.0`: unknown series observable `piston_postion`",
                "did you mean `piston_position`?",
            ],
        ),
        case(
            "positions of every particle at too many samples",
            edit(
                "series = [\"piston_position\"]",
                "series = [\"piston_position\", \"positions\"]",
            )
            .replace("sample_every = 0.5", "sample_every = 1e-5"),
            &[
                "s.toml:31:1: sweep parameter `scene.species.0.count`: value 15 makes `observe.series.1` invalid: the series would hold 1.6e8 values per run (16 columns in all, of them `positions`: 15 columns, at 1.0e7 samples); a run keeps at most 1e8",
                "sample less often",
            ],
        ),
        case(
            "a 2D bond order in a 1D scene",
            edit(
                "series = [\"piston_position\"]",
                "series = [\"piston_position\", \"psi6\"]",
            ),
            &[
                "s.toml:40:30: `observe.series.1`: `psi6` is defined in 2D scenes; this scene is 1D",
                "spheres have `q6`",
            ],
        ),
        case(
            "a 3D bond order in a 1D scene",
            edit(
                "series = [\"piston_position\"]",
                "series = [\"piston_position\", \"q6\"]",
            ),
            &["`observe.series.1`: `q6` is defined in 3D scenes; this scene is 1D"],
        ),
        case(
            "a scalar listed as a series",
            edit("series = [\"piston_position\"]", "series = [\"wall_heat\"]"),
            &[
                "`observe.series.0`",
                "`wall_heat` is a scalars observable: list it under `scalars`",
            ],
        ),
        case(
            "unknown scalar",
            edit(
                "scalars = [\"wall_pressure\"]",
                "scalars = [\"wall_presure\"]",
            ),
            &[
                "s.toml:39:12: `observe.scalars.0`: unknown scalars observable",
                "did you mean `wall_pressure`?",
            ],
        ),
        case(
            "unknown histogram",
            edit("series = [\"piston_position\"]", "histograms = [\"speed\"]"),
            &[
                "s.toml:40:15: `observe.histograms.0`: unknown histograms observable `speed`",
                "scaled_velocity_x",
            ],
        ),
        case(
            "listed twice",
            edit(
                "scalars = [\"wall_pressure\"]",
                "scalars = [\"wall_pressure\", \"wall_pressure\"]",
            ),
            &["s.toml:39:29: `observe.scalars.1`: `wall_pressure` is listed twice"],
        ),
        case(
            "series without sampling",
            edit("sample_every = 0.5\n", ""),
            &[
                "s.toml:39:11: `observe.series.0`: `piston_position` needs samples",
                "sample_every",
            ],
        ),
        case(
            "wall pressure in a periodic box",
            edit("boundary = [\"walls\"]", "boundary = [\"periodic\"]"),
            &["s.toml:39:12: `observe.scalars.0`: `wall_pressure` needs walls"],
        ),
        case(
            "a movie of one frame",
            edit(
                "series = [\"piston_position\"]\n",
                "series = [\"piston_position\"]\nmovie = { duration = 20.0, frames = 1 }\n",
            ),
            &[
                "s.toml:41:28: `observe.movie.frames`: 1 frames",
                "a whole number from 2 to 2000",
            ],
        ),
        case(
            "a movie of no time",
            edit(
                "series = [\"piston_position\"]\n",
                "series = [\"piston_position\"]\nmovie = { duration = -1.0, frames = 10 }\n",
            ),
            &[
                "s.toml:41:11: `observe.movie.duration`: -1 is not a simulated time to film",
                "a number > 0",
            ],
        ),
        case(
            "wall heat without thermal walls",
            edit("scalars = [\"wall_pressure\"]", "scalars = [\"wall_heat\"]"),
            &[
                "s.toml:39:12: `observe.scalars.0`: `wall_heat` needs thermal walls",
                "[[scene.thermal_walls]]",
            ],
        ),
        case(
            "unknown analysis",
            format!("{PISTON}\n[analysis.pistn]\n"),
            &[
                "s.toml:47:11: `analysis.pistn`: unknown analysis `pistn`",
                "did you mean `piston`?",
            ],
        ),
        case(
            "misspelt option",
            format!("{PISTON}\n[analysis.piston]\nwindow_period = 4\n"),
            &[
                "s.toml:48:1: `analysis.piston.window_period`: unknown option `window_period` of the piston analysis",
                "did you mean `window_periods`?",
            ],
        ),
        case(
            "option of the wrong type",
            format!("{PISTON}\n[analysis.piston]\nlate_fraction = \"half\"\n"),
            &[
                "s.toml:48:1: `analysis.piston.late_fraction`: must be a number > 0 and <= 1, got a string",
            ],
        ),
        case(
            "option out of range",
            format!("{PISTON}\n[analysis.piston]\nwindow_periods = -2\n"),
            &["s.toml:48:1: `analysis.piston.window_periods`: must be a number > 0, got -2"],
        ),
        case(
            "piston analysis without samples",
            format!("{PISTON}\n[analysis.piston]\n")
                .replace("sample_every = 0.5\n", "")
                .replace("series = [\"piston_position\"]", "series = []"),
            &[
                "s.toml:46:11: `analysis.piston`: the piston analysis needs samples",
                "sample_every",
            ],
        ),
    ]);
}

#[test]
fn sweeps() {
    check(&[
        case(
            "empty parameters",
            edit("\"scene.piston.mass\" = [1.0, 10.0, 100.0]\n\"scene.species.0.count\" = { from = 5, to = 15, steps = 2 }\n", "")
                .replace("\"sweep.parameters.scene.piston.mass\" = [1.0, 100.0]\n", ""),
            &["s.toml:29:8: `sweep.parameters`: is empty", "or remove [sweep]"],
        ),
        case(
            "non-finite range",
            edit("{ from = 5, to = 15, steps = 2 }", "{ from = nan, to = 15.0, steps = 2 }"),
            &["s.toml:31:1: `sweep.parameters.scene.species.0.count`: range bounds must be finite numbers"],
        ),
        case(
            "a repeated value",
            edit("[1.0, 10.0, 100.0]", "[1.0, 10.0, 1.0]"),
            &["s.toml:30:1: `sweep.parameters.scene.piston.mass`: value 1.0 is listed twice", "same seeds"],
        ),
        case(
            "a range that repeats one value",
            edit("{ from = 5, to = 15, steps = 2 }", "{ from = 5, to = 5, steps = 2 }"),
            &["s.toml:31:1:", "repeats one value"],
        ),
        case(
            "a swept value against another key",
            edit("[1.0, 10.0, 100.0]", "[1.0, 10.0, 100.0]\n\"scene.dimension\" = [1, 2]"),
            &[
                "s.toml:31:1: sweep parameter `scene.dimension`: value 2 makes `scene.box` invalid: has 1 entries but the scene has dimension 2",
            ],
        ),
    ]);
}

#[test]
fn quick_is_checked_without_quick() {
    check(&[
        case(
            "a negative duration in [quick]",
            edit("\"run.duration\" = 10.0", "\"run.duration\" = -1.0"),
            &[
                "s.toml:44:1:",
                "[quick]",
                "`run.duration`: must be a positive number",
            ],
        ),
        case(
            "a misspelt key in [quick]",
            edit("\"run.duration\" = 10.0", "\"run.durration\" = 10.0"),
            &[
                "s.toml:44:1: [quick] (applied by --quick): `run.durration` = 10.0: unknown key `durration`",
                "did you mean `duration`?",
            ],
        ),
        case(
            "an unknown observable in [quick]",
            format!("{PISTON}\"observe.series\" = [\"speed\"]\n"),
            &[
                "s.toml:46:1:",
                "[quick]",
                "unknown series observable `speed`",
            ],
        ),
    ]);
}

/// A combination the per-key checks cannot see: every value works with the
/// first of the other key, but not the last with the last. The plan checks
/// every point and names it.
#[test]
fn a_failing_sweep_point_is_named_before_anything_runs() {
    let text = edit(
        "\"scene.piston.mass\" = [1.0, 10.0, 100.0]\n\"scene.species.0.count\" = { from = 5, to = 15, steps = 2 }",
        "\"scene.boundary\" = [[\"walls\"], [\"periodic\"]]\n\"scene.thermal_walls\" = [[], [{ axis = 0, side = \"low\", temperature = 1.0 }]]",
    )
    .replace("scalars = [\"wall_pressure\"]", "scalars = [\"virial_pressure\"]")
    .replace("\"sweep.parameters.scene.piston.mass\" = [1.0, 100.0]\n", "");
    let loaded = parse("s.toml", &text).expect("every value is fine on its own");
    let msg = plan(&loaded).unwrap_err().to_string();
    assert!(
        msg.starts_with("s.toml:29:8: sweep point 3 (`scene.boundary` = [\"periodic\"], `scene.thermal_walls` = ["),
        "{msg}"
    );
    assert!(
        msg.contains("`scene.thermal_walls.0.axis`: axis 0 is periodic"),
        "{msg}"
    );
}

#[test]
fn a_plan_over_the_hard_limit_is_refused_at_its_sweep() {
    let loaded = parse("s.toml", &edit("replicas = 3", "replicas = 2000000")).unwrap();
    let msg = plan(&loaded).unwrap_err().to_string();
    assert!(
        msg.starts_with("s.toml:26:2: the plan has 12000000 runs, more than the 2000000"),
        "{msg}"
    );
    assert!(msg.contains("split the study"), "{msg}");
}
