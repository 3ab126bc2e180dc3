//! Hostile input (issue 18): a plan costs time and memory in proportion to
//! its size; what cannot stay finite, finish, or be written is refused at
//! validate, at its key and line:col; every message has its place and
//! numbers a reader can read. Devices, thread counts and scene checks are
//! in `study_cli.rs`; the fuzz test over mutated studies is `hostile_fuzz.rs`.

use crate::study_common::{PISTON, run_options, write_descriptor};
use bonkers::descriptor::errors::DescriptorError;
use bonkers::descriptor::load::parse;
use bonkers::model::scene::Placement;
use bonkers::runner::pipeline;
use bonkers::runner::plan::plan;
use std::process::Command;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// What `study validate` does, in-process: parse, size, plan, cost, words.
pub(crate) fn validate(text: &str) -> Result<String, DescriptorError> {
    let loaded = parse("s.toml", text)?;
    pipeline::confirm_size(&loaded, false)?;
    let specs = plan(&loaded)?;
    pipeline::confirm_cost(&loaded, &specs, false)?;
    Ok(bonkers::cli::describe_plan(&loaded, &specs, 2))
}

pub(crate) fn edit(from: &str, to: &str) -> String {
    edit_of(PISTON, from, to)
}

pub(crate) fn edit_of(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "no {from:?} in the descriptor");
    text.replacen(from, to, 1)
}

/// PISTON without its sweep and `[quick]`: its own values are what runs.
pub(crate) fn unswept() -> String {
    let head = &PISTON[..PISTON.find("[sweep]").unwrap()];
    let tail = &PISTON[PISTON.find("[run]").unwrap()..PISTON.find("[quick]").unwrap()];
    format!("{head}{tail}")
}

/// PISTON with `parameters` as its whole sweep and no `[quick]`.
pub(crate) fn swept(parameters: &str) -> String {
    let head = &PISTON[..PISTON.find("[sweep.parameters]").unwrap()];
    let tail = &PISTON[PISTON.find("[run]").unwrap()..PISTON.find("[quick]").unwrap()];
    format!("{head}[sweep.parameters]\n{parameters}\n\n{tail}")
}

pub(crate) struct Case {
    pub what: &'static str,
    pub text: String,
    pub expect: &'static [&'static str],
}

pub(crate) fn case(what: &'static str, text: String, expect: &'static [&'static str]) -> Case {
    Case { what, text, expect }
}

/// Each case is refused with a message that says all of `expect`, and no
/// number in it runs to more digits than the largest TOML integer has.
pub(crate) fn refused(cases: &[Case]) {
    for c in cases {
        let err = match validate(&c.text) {
            Ok(plan) => panic!("{}: accepted:\n{plan}", c.what),
            Err(e) => e.to_string(),
        };
        for e in c.expect {
            assert!(err.contains(e), "{}: expected {e:?} in:\n{err}", c.what);
        }
        let longest = err
            .split(|ch: char| !ch.is_ascii_digit())
            .map(str::len)
            .max()
            .unwrap_or(0);
        assert!(
            longest <= 19,
            "{}: a number of {longest} digits in:\n{err}",
            c.what
        );
    }
}

/// Item 2: a sweep of 8000 explicit values plans in a few seconds at most
/// (it took minutes and gigabytes when each run copied the descriptor, its
/// sweep list included), replicas share their point's descriptor, and
/// every point shares the explicit positions rather than copying them.
#[test]
fn planning_is_linear_in_the_plan() {
    let values: Vec<String> = (0..8000)
        .map(|i| format!("{:?}", 100.0 + 0.5 * f64::from(i)))
        .collect();
    let text = swept(&format!("\"run.duration\" = [{}]", values.join(", ")));
    let clock = Instant::now();
    let loaded = parse("s.toml", &text).unwrap();
    let specs = plan(&loaded).unwrap();
    let seconds = clock.elapsed().as_secs_f64();
    assert_eq!(specs.len(), 8000 * 3);
    assert!(seconds < 5.0, "8000 points took {seconds} s to plan");
    for point in specs.chunks(3) {
        assert!(
            point
                .iter()
                .all(|s| Arc::ptr_eq(&s.descriptor, &point[0].descriptor))
        );
        assert!(
            point
                .iter()
                .all(|s| Arc::ptr_eq(&s.params, &point[0].params))
        );
    }

    // 20000 explicit positions, 50 sweep points and 2 replicas.
    let n = 20_000;
    let positions: Vec<String> = (0..n).map(|i| format!("[{}.0]", 2 * i + 1)).collect();
    let durations: Vec<String> = (1..=50).map(|i| format!("{i}.0")).collect();
    let text = format!(
        "[study]\nname = \"explicit\"\nreplicas = 2\n\n[scene]\nbox = [{}.0]\n\
         species = [{{ name = \"gas\", count = {n} }}]\n\
         placement = {{ kind = \"explicit\", positions = [{}] }}\n\n\
         [sweep.parameters]\n\"run.duration\" = [{}]\n\n[run]\nduration = 1.0\n",
        2 * n + 10,
        positions.join(", "),
        durations.join(", ")
    );
    let clock = Instant::now();
    let loaded = parse("s.toml", &text).unwrap();
    let specs = plan(&loaded).unwrap();
    let seconds = clock.elapsed().as_secs_f64();
    assert_eq!(specs.len(), 100);
    assert!(seconds < 5.0, "took {seconds} s");
    let list = |p: &Option<Placement>| match p {
        Some(Placement::Explicit { positions }) => positions.as_ptr(),
        other => panic!("not explicit: {other:?}"),
    };
    let base = list(&loaded.descriptor.scene.placement);
    assert!(
        specs
            .iter()
            .all(|s| list(&s.descriptor.scene.placement) == base)
    );
    // A point that sets a position gets a list of its own, the rest unchanged.
    let text = text.replace(
        "\"run.duration\" = [",
        "\"scene.placement.positions.0\" = [[1.0], [1.5]]\n\"run.duration\" = [",
    );
    let loaded = parse("s.toml", &text).unwrap();
    let specs = plan(&loaded).unwrap();
    let Some(Placement::Explicit { positions }) = &specs.last().unwrap().descriptor.scene.placement
    else {
        panic!("not explicit")
    };
    assert_eq!(positions.len(), n);
    assert_eq!((positions[0][0], positions[1][0]), (1.5, 3.0));
}

/// Item 3: what cannot stay finite is refused where it is set; what could
/// never finish is refused by its estimate, placed at what sets its length.
#[test]
fn numbers_that_cannot_stay_finite_or_finish_are_refused() {
    let tens = ["[1e300]"; 10].join(", ");
    refused(&[
        case(
            "equal velocities of 1e200",
            edit(
                "kind = \"maxwell\"\ntemperature = 1.0",
                "kind = \"equal\"\nvelocity = [1e200]",
            ),
            &[
                "s.toml:24:1: `scene.velocities.velocity`",
                "kinetic energy of inf",
                "1e150",
            ],
        ),
        case(
            "explicit velocities of 1e300",
            edit_of(
                &unswept(),
                "kind = \"maxwell\"\ntemperature = 1.0",
                &format!("kind = \"explicit\"\nvelocities = [{tens}]"),
            ),
            &[
                "s.toml:24:1: `scene.velocities.velocities`",
                "kinetic energy of inf",
            ],
        ),
        case(
            "temperature 1e308",
            edit("temperature = 1.0", "temperature = 1e308"),
            &[
                "s.toml:24:1: `scene.velocities.temperature`",
                "kinetic energy of inf",
            ],
        ),
        case(
            "gas energy 1e300",
            edit("temperature = 1.0", "temperature = 1.0\nenergy = 1e300"),
            &[
                "s.toml:25:1: `scene.velocities.energy`",
                "kinetic energy of 1e300",
            ],
        ),
        case(
            "piston velocity 1e200",
            edit("position = 0.5", "position = 0.5\nvelocity = 1e200"),
            &[
                "s.toml:21:1: `scene.piston.velocity`",
                "kinetic energy of inf",
            ],
        ),
        case(
            "piston mass 1e-300 (a sweep value)",
            edit("[1.0, 10.0, 100.0]", "[1.0, 1e-300, 100.0]"),
            &[
                "s.toml:34:1: `run.duration` = 100: one run would take ~",
                "more than a run can finish (at most 1e15",
                "`scene.piston.mass` = 1e-300",
                "nearly all are the piston's: with mass 1e-300",
            ],
        ),
        case(
            "collisions = 10^18",
            edit("duration = 100.0", "collisions = 1000000000000000000"),
            &[
                "s.toml:34:1: `run.collisions` = 1e18",
                "more than a run can finish",
            ],
        ),
        case(
            "duration = 1e300",
            edit("duration = 100.0", "duration = 1e300"),
            &[
                "s.toml:34:1: `run.duration`: 1e300 is longer than a run's clock can count",
                "1e12",
            ],
        ),
        case(
            "equilibrate = 1e300",
            edit("equilibrate = 10.0", "equilibrate = 1e300"),
            &["s.toml:35:1: `run.equilibrate`: 1e300 is longer"],
        ),
        case(
            "a long duration swept",
            edit(
                "\"scene.piston.mass\" = [",
                "\"run.duration\" = [10.0, 1e13]\n\"scene.piston.mass\" = [",
            ),
            &[
                "s.toml:30:1: sweep parameter `run.duration`",
                "1e13 is longer",
            ],
        ),
        case(
            "speeds that make too many collisions in a case",
            format!(
                "{}\n[[case]]\nname = \"fast\"\n[case.set]\n\"scene.velocities.temperature\" = 1e40\n",
                unswept()
            ),
            &[
                "s.toml:27:1: `run.duration` = 100",
                "more than a run can finish",
                "(case \"fast\")",
            ],
        ),
    ]);
}

/// Item 3: a plan of runs that each can finish but together take more than
/// 1000 CPU-hours by the estimate needs `--yes`.
#[test]
fn plans_estimated_beyond_a_thousand_cpu_hours_need_yes() {
    let text = edit(
        "duration = 100.0\nequilibrate = 10.0\nsample_every = 0.5",
        "duration = 3e11",
    )
    .replace("series = [\"piston_position\"]\n", "");
    let err = validate(&text).unwrap_err().to_string();
    for says in ["s.toml:26:2:", "CPU-hours", "--yes"] {
        assert!(err.contains(says), "expected {says:?} in:\n{err}");
    }
    let loaded = parse("s.toml", &text).unwrap();
    let specs = plan(&loaded).unwrap();
    pipeline::confirm_cost(&loaded, &specs, true).unwrap();
}

/// Item 7: names become folder, file and column names; longer ones than
/// file systems take are refused at validate.
#[test]
fn names_too_long_for_file_names_are_refused() {
    let long_study = "s".repeat(300);
    let long_species = "g".repeat(5000);
    let long_case = "c".repeat(150);
    refused(&[
        case(
            "a 300-byte study name",
            edit(
                "name = \"piston-test\"",
                &format!("name = \"{long_study}\""),
            ),
            &[
                "s.toml:3:1: `study.name`",
                "is 300 bytes long",
                "at most 100",
            ],
        ),
        case(
            "a 5000-byte species name with a per-species series",
            edit("name = \"gas\"", &format!("name = \"{long_species}\"")).replace(
                "series = [\"piston_position\"]",
                "series = [\"kinetic_energy_by_species\"]",
            ),
            &["s.toml:14:1: `scene.species.0.name`", "is 5000 bytes long"],
        ),
        case(
            "a 150-byte case name",
            format!("{}\n[[case]]\nname = \"{long_case}\"\n", unswept()),
            &["`case.0.name`", "is 150 bytes long"],
        ),
    ]);
}

/// Item 7: names at the limit are written: a real (short) run whose
/// per-species series carry 100-byte species names publishes its tables
/// and plots.
#[test]
fn names_at_the_limit_are_written() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = ("a".repeat(100), "b".repeat(100));
    let text = format!(
        "[study]\nname = \"{}\"\n\n[scene]\nbox = [30.0]\nspecies = [\n  \
         {{ name = \"{a}\", count = 4, region = {{ from = [0.0], to = [0.5] }} }},\n  \
         {{ name = \"{b}\", count = 4, mass = 2.0, region = {{ from = [0.5], to = [1.0] }} }},\n]\n\n\
         [run]\nduration = 20.0\nsample_every = 1.0\n\n[observe]\n\
         series = [\"kinetic_energy_by_species\", \"mean_squared_displacement\"]\n",
        "n".repeat(100)
    );
    validate(&text).unwrap();
    let file = write_descriptor(dir.path(), &text);
    let out = dir.path().join("out");
    let options = run_options(&out, 1);
    let stop = AtomicBool::new(false);
    let outcome = pipeline::run_study(
        &file,
        &options,
        &bonkers::runner::execute::simulate::run,
        &stop,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(outcome.failed, 0);
    assert!(out.join("series.parquet").is_file());
    let longest = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().len())
        .max()
        .unwrap();
    assert!(
        longest > 100 && longest < 255,
        "longest file name {longest}"
    );
}

/// Item 10: every message has its place; limits are said as they are;
/// a date, a repeated key and deep nesting are named; numbers are short.
#[test]
fn messages_have_a_place_and_say_what_is_expected() {
    let deep = format!("{PISTON}\n[{}]\n", vec!["a"; 3000].join("."));
    let deep_line = deep.lines().count();
    let err = validate(&deep).unwrap_err();
    assert_eq!(err.position, Some((deep_line, 1)), "{err}");
    assert!(
        err.message.contains("nested too deeply (3000 levels)"),
        "{err}"
    );
    refused(&[
        case(
            "replicas = 10^18",
            edit("replicas = 3", "replicas = 1000000000000000000"),
            &[
                "s.toml:5:12: `study.replicas`",
                "expected a whole number from 0 to 4294967295",
            ],
        ),
        case(
            "a date as seed",
            edit("seed = 42", "seed = 1979-05-27"),
            &[
                "s.toml:6:8: `study.seed`",
                "date-time 1979-05-27",
                "expected a whole number from 0 to",
            ],
        ),
        case(
            "a key given twice",
            edit("seed = 42", "seed = 42\nseed = 43"),
            &["s.toml:7:1: duplicate key `seed`", "keep one `seed = ...`"],
        ),
        case(
            "a negative 1e300",
            edit("temperature = 1.0", "temperature = -1e300"),
            &["s.toml:24:1: `scene.velocities.temperature`: must be a positive number, got -1e300"],
        ),
        case(
            "a sweep value of 1e-320",
            edit("[1.0, 10.0, 100.0]", "[1.0, 1e-320]"),
            &["s.toml:30:1: sweep parameter `scene.piston.mass`: value 1e-320 makes"],
        ),
        case(
            "more runs than --yes lets by",
            edit("replicas = 3", "replicas = 20000"),
            &["s.toml:26:2: the plan has 120000 runs", "--yes"],
        ),
    ]);
    // Past --yes, the plan itself refuses more than it can hold.
    for (text, at) in [
        (
            edit("replicas = 3", "replicas = 4000000"),
            "s.toml:26:2: the plan has 24000000 runs",
        ),
        (
            edit_of(&unswept(), "replicas = 3", "replicas = 4000000"),
            "s.toml:5:1: the plan has 4000000 runs",
        ),
    ] {
        let err = plan(&parse("s.toml", &text).unwrap())
            .unwrap_err()
            .to_string();
        assert!(err.contains(at), "expected {at:?} in:\n{err}");
    }
}

/// Item 11: compression is 2D/3D only; a sweep value listed twice, also as
/// 10 and 10.0, is refused; so is a zip point repeated that way.
#[test]
fn minor_cases_are_refused() {
    refused(&[
        case(
            "compress in 1D",
            edit(
                "boundary = [\"walls\"]",
                "boundary = [\"walls\"]\nplacement = { kind = \"compress\" }",
            ),
            &[
                "s.toml:12:15: `scene.placement.kind`",
                "2D/3D",
                "kind = \"random\"",
            ],
        ),
        case(
            "10 and 10.0 in one list",
            swept("\"run.duration\" = [10, 10.0]"),
            &[
                "`sweep.parameters.run.duration`: value 10.0 (as 10) is listed twice (items 0 and 1)",
                "same settings",
            ],
        ),
        case(
            "a zip point repeated as 10 and 10.0",
            swept("\"run.duration\" = [10, 10.0]\n\"scene.piston.mass\" = [2.0, 2]")
                .replace("mode = \"product\"", "mode = \"zip\""),
            &[
                "sweep point 1",
                "has the same values as point 0",
                "same settings",
            ],
        ),
    ]);
}

/// Item 11: a study that cannot create its folder leaves none of the
/// folders it made on the way (no empty `reports/`).
#[test]
fn a_study_that_cannot_start_leaves_no_empty_folders() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), &unswept());
    let cwd = dir.path().join("cwd");
    std::fs::create_dir(&cwd).unwrap();
    let out = format!("reports/{}/out", "x".repeat(300));
    let run = Command::new(env!("CARGO_BIN_EXE_study"))
        .args(["run", file.to_str().unwrap(), "--quiet", "--out", &out])
        .current_dir(&cwd)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{err}");
    assert!(err.contains("cannot create the output directory"), "{err}");
    assert_eq!(std::fs::read_dir(&cwd).unwrap().count(), 0, "left behind");
}
