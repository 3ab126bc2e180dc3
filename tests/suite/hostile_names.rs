//! Hostile names and text, and what validate promises to check: a control
//! character anywhere in a descriptor is refused at its key; what a user
//! writes reaches report.md as text, never as markup, and the SVGs stay XML;
//! what a study needs is refused at validate, not by every run; numbers in
//! messages are short and blamed on the key that set them.

use crate::hostile_input::{case, edit, refused, swept, unswept, validate};
use crate::report_write::balanced;
use crate::study_common::{PISTON, run_options, write_descriptor};
use bonkers::descriptor::load::load;
use bonkers::runner::pipeline;
use std::path::Path;
use std::sync::atomic::AtomicBool;

/// `refused`, and no message carries a control character of the input
/// (it would reach the terminal raw).
fn refused_visibly(cases: &[crate::hostile_input::Case]) {
    refused(cases);
    for c in cases {
        let err = validate(&c.text).unwrap_err().to_string();
        assert!(
            !err.chars().any(|ch| ch.is_control() && ch != '\n'),
            "{}: a control character in:\n{err:?}",
            c.what
        );
    }
}

#[test]
fn control_characters_are_refused_at_their_key() {
    refused_visibly(&[
        case(
            "NUL in the study name",
            edit("name = \"piston-test\"", "name = \"piston\\u0000\""),
            &["s.toml:3:1: `study.name`", "U+0000", "\"piston\\0\""],
        ),
        case(
            "ESC in the description",
            edit("Piston frequency", "\\u001b[31mPiston frequency"),
            &["s.toml:4:1: `study.description`", "U+001B"],
        ),
        case(
            "ESC in a species name",
            edit("name = \"gas\"", "name = \"g\\u001bas\""),
            &["s.toml:14:1: `scene.species.0.name`", "U+001B"],
        ),
        case(
            "BEL in a case name",
            format!("{}\n[[case]]\nname = \"c\\u0007\"\n", unswept()),
            &["`case.0.name`", "U+0007"],
        ),
        case(
            "C1 (U+009B, the one-byte CSI) in an observable name",
            edit("\"piston_position\"]", "\"piston_position\", \"x\\u009b\"]"),
            &["s.toml:40:30: `observe.series.1`", "U+009B"],
        ),
        case(
            "a swept species name",
            swept("\"scene.species.0.name\" = [\"a\", \"b\\u0000\"]"),
            &["`sweep.parameters.scene.species.0.name.1`", "U+0000"],
        ),
        case(
            "a key",
            swept("\"run.dura\\u001btion\" = [1.0]"),
            &["`sweep.parameters.run.dura\\u{1b}tion`: the key", "U+001B"],
        ),
        case(
            "a [quick] value",
            edit(
                "\"run.duration\" = 10.0",
                "\"observe.series\" = [\"\\u0000\"]",
            ),
            &["`quick.observe.series.0`", "U+0000"],
        ),
        case(
            "a line break in a name",
            edit("name = \"gas\"", "name = \"g\\nas\""),
            &["`scene.species.0.name`", "U+000A"],
        ),
    ]);
    // The description is prose: it may break lines.
    validate(&edit(
        "description = \"Piston frequency against piston mass\"",
        "description = \"\"\"Piston frequency\n\tagainst piston mass\"\"\"",
    ))
    .unwrap();
}

/// A descriptor with markup in every user text the report shows: the
/// description, species names (also swept) and so the observables, plots and
/// tables that name them.
const MARKUP: &str = r##"[study]
name = "hostile"
description = """# Not a heading
<script>alert(1)</script> <img src=x onerror=alert(1)> a | b *bold* _it_ [link](http://x) `tick` &amp; ~~s~~

- not a list"""

[scene]
box = [20.0]
species = [
  { name = "a|b<i>`x`", count = 3, region = { from = [0.0], to = [0.5] } },
  { name = "<img src=x onerror=alert(1)>", count = 2, mass = 2.0, region = { from = [0.5], to = [1.0] } },
]

[sweep.parameters]
"scene.species.0.name" = ["a|b<i>`x`", "1. [x](y) | z"]

[run]
duration = 20.0
sample_every = 1.0

[observe]
series = ["kinetic_energy_by_species"]
scalars = ["wall_pressure"]
"##;

/// Outside code spans, every `<` is escaped; each table row has its
/// header's number of cells.
fn markdown_is_text(md: &str) {
    for line in md.lines() {
        let (mut code, mut escaped) = (false, false);
        for c in line.chars() {
            match c {
                _ if escaped => escaped = false,
                '\\' => escaped = true,
                '`' => code = !code,
                '<' | '>' if !code => panic!("raw {c:?} in {line:?}"),
                _ => {}
            }
        }
        assert!(
            !line.starts_with("# Not") && !line.starts_with("- not"),
            "markup: {line:?}"
        );
    }
    let cells = |row: &str| {
        let mut escaped = false;
        row.chars()
            .filter(|&c| {
                let pipe = c == '|' && !escaped;
                escaped = c == '\\' && !escaped;
                pipe
            })
            .count()
    };
    let mut header = None;
    for line in md.lines() {
        match (line.starts_with('|'), header) {
            (true, None) => header = Some(cells(line)),
            (true, Some(n)) => assert_eq!(cells(line), n, "cells of {line:?}"),
            (false, _) => header = None,
        }
    }
}

/// Well-formed XML as far as text can break it: no character XML forbids,
/// every `&` an entity, no `<` that does not open a tag, tags balanced.
fn svg_is_xml(file: &Path) {
    let svg = std::fs::read_to_string(file).unwrap();
    let what = file.display();
    assert!(
        !svg.chars().any(|c| c.is_control() && !"\t\n\r".contains(c)),
        "{what}: a control character"
    );
    for (i, _) in svg.match_indices('&') {
        let entity = &svg[i..svg[i..].find(';').map_or(svg.len(), |e| i + e + 1)];
        let known = ["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"].contains(&entity)
            || (entity.starts_with("&#") && entity.len() <= 10);
        assert!(known, "{what}: a bare & at {entity:?}");
    }
    for (i, _) in svg.match_indices('<') {
        let next = svg[i + 1..].chars().next().unwrap_or(' ');
        assert!(
            next.is_ascii_alphabetic() || "/?!".contains(next),
            "{what}: a `<` that opens no tag at {}",
            &svg[i..(i + 20).min(svg.len())]
        );
    }
    balanced(&svg).unwrap_or_else(|e| panic!("{what}: {e}"));
}

#[test]
fn user_text_reaches_the_report_as_text() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), MARKUP);
    let out = dir.path().join("out");
    let outcome = pipeline::run_study(
        &file,
        &run_options(&out, 2),
        &bonkers::runner::execute::simulate::run,
        &AtomicBool::new(false),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(outcome.failed, 0);
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    markdown_is_text(&md);
    for shown in [
        "\\# Not a heading \\<script\\>alert(1)\\</script\\>",
        "a \\| b \\*bold\\* \\_it\\_ \\[link\\](http://x) \\`tick\\` \\&amp; \\~\\~s\\~\\~",
        "\\- not a list",
        "a\\|b\\<i\\>\\`x\\`",
        "| name=1. \\[x\\](y) \\| z |",
    ] {
        assert!(md.contains(shown), "no {shown:?} in:\n{md}");
    }
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    for raw in ["<script>alert", "<img src", "<i>", "<h1>Not"] {
        assert!(!html.contains(raw), "{raw:?} in index.html");
    }
    assert!(html.contains("&lt;script&gt;alert(1)&lt;/script&gt;"));
    let svgs: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "svg"))
        .collect();
    assert!(!svgs.is_empty());
    for svg in &svgs {
        svg_is_xml(svg);
    }
    let named = svgs.iter().any(|p| {
        std::fs::read_to_string(p)
            .unwrap()
            .contains("&lt;img src=x onerror=alert(1)&gt;")
    });
    assert!(named, "no plot names the species");
}

/// A 1D gas of five rods between walls, with `extra` appended.
fn rods(extra: &str) -> String {
    format!(
        "[study]\nname = \"rods\"\n\n[scene]\nbox = [20.0]\n\
         species = [{{ name = \"gas\", count = 5 }}]\n{extra}\n\n\
         [run]\nduration = 50.0\nsample_every = 1.0\n"
    )
}

const HOT_AND_COLD: &str = "thermal_walls = [\n  \
    { axis = 0, side = \"low\", temperature = 2.0 },\n  \
    { axis = 0, side = \"high\", temperature = 1.0 },\n]";

#[test]
fn what_a_study_needs_is_checked_before_running() {
    let disks = |species: &str, boundary: &str| {
        format!(
            "[study]\nname = \"disks\"\n\n[scene]\nbox = [20.0, 20.0]\nboundary = {boundary}\n\
             species = [{species}]\n\n[run]\nduration = 10.0\nsample_every = 1.0\n\n\
             [analysis.mixing]\n"
        )
    };
    let one = "{ name = \"a\", count = 10, radius = 0.5 }";
    let two = "{ name = \"a\", count = 10, radius = 0.5, region = { from = [0.0, 0.0], to = [0.5, 1.0] } }, \
               { name = \"b\", count = 10, radius = 0.5, region = { from = [0.5, 0.0], to = [1.0, 1.0] } }";
    refused(&[
        case(
            "heat conduction without wall_heat",
            rods(&format!("{HOT_AND_COLD}\n\n[analysis.heat]")),
            &[
                "s.toml:12:11: `analysis.heat`",
                "`scalars = [\"wall_heat\"]`",
            ],
        ),
        case(
            "heat conduction without the profile",
            rods(&format!(
                "{HOT_AND_COLD}\n\n[observe]\nscalars = [\"wall_heat\"]\n\n[analysis.heat]"
            )),
            &["`analysis.heat`", "`histograms = [\"energy_x\"]`"],
        ),
        case(
            "pressure with no pressure observed",
            rods("\n[analysis.pressure]"),
            &[
                "s.toml:8:11: `analysis.pressure`",
                "`wall_pressure` or `virial_pressure`",
            ],
        ),
        case(
            "pressure beside a piston",
            format!(
                "{}\n[analysis.pressure]\n",
                unswept().replace("series = [\"piston_position\"]\n", "")
            ),
            &["`analysis.pressure`", "without a piston"],
        ),
        case(
            "2D mixing with one species",
            disks(one, "[\"walls\", \"periodic\"]"),
            &["`analysis.mixing`", "needs two species"],
        ),
        case(
            "2D mixing with an empty second species",
            disks(
                &two.replacen("count = 10", "count = 0", 2)
                    .replacen("count = 0", "count = 10", 1),
                "[\"walls\", \"periodic\"]",
            ),
            &["`analysis.mixing`", "needs two species"],
        ),
        case(
            "1D mixing on a ring",
            rods("boundary = [\"periodic\"]\n\n[analysis.mixing]"),
            &["`analysis.mixing`", "needs walls"],
        ),
    ]);
    // What they need given, they validate.
    for ok in [
        rods(&format!(
            "{HOT_AND_COLD}\n\n[observe]\nscalars = [\"wall_heat\"]\nhistograms = [\"energy_x\"]\n\n[analysis.heat]"
        )),
        rods("\n[observe]\nscalars = [\"wall_pressure\"]\n\n[analysis.pressure]"),
        disks(two, "[\"walls\", \"periodic\"]"),
    ] {
        validate(&ok).unwrap_or_else(|e| panic!("{e}\n{ok}"));
    }
}

#[test]
fn quick_and_presets_refuse_what_they_would_ignore() {
    refused(&[
        case(
            "a [quick] key into [quick] itself",
            edit("\"run.duration\" = 10.0", "\"quick.a\" = 1"),
            &[
                "s.toml:44:1: [quick] (applied by --quick): `quick.a` = 1",
                "is not a key `[quick]` can set",
                "`study.replicas`, `sweep.mode`",
            ],
        ),
        case(
            "a [quick] seed",
            edit("\"run.duration\" = 10.0", "\"study.seed\" = 7"),
            &["s.toml:44:1:", "`study.seed` is not a key `[quick]` can set"],
        ),
        case(
            "a [quick] case name",
            format!(
                "{}\n[[case]]\nname = \"c\"\n",
                edit("\"run.duration\" = 10.0", "\"case.0.name\" = \"d\"")
            ),
            &["`case.0.name` is not a key `[quick]` can set"],
        ),
        case(
            "a preset with no species",
            "[study]\nname = \"p\"\n\n[scene]\npreset = \"mackay-ten\"\nspecies = []\n\n[run]\nduration = 10.0\n".into(),
            &[
                "s.toml:6:1: `scene.species` is empty",
                "leave `species` out to keep those of preset \"mackay-ten\"",
            ],
        ),
    ]);
    // What the bundled studies' [quick] tables set is still taken.
    validate(&format!(
        "{}\n[[case]]\nname = \"c\"\n",
        edit(
            "\"run.duration\" = 10.0",
            "\"case.0.replicas\" = 1\n\"run.duration\" = 10.0"
        )
    ))
    .unwrap();
}

#[test]
fn messages_are_short_and_blame_the_key_that_set_them() {
    refused(&[
        case(
            "a box of 1e-320",
            rods("").replace("box = [20.0]", "box = [1e-320]"),
            &["s.toml:5:8: `scene.box.0`", "1e-320 long", "diameter 1"],
        ),
        case(
            "a piston of radius 1e6",
            edit("position = 0.5", "position = 0.5\nradius = 1e6"),
            &["s.toml:21:1: `scene.piston.radius`: 1000000 is more than half the box length 40"],
        ),
        case(
            "mass = []",
            edit("mass = 1.0", "mass = []"),
            &[
                "s.toml:16:8: `scene.species.0.mass`: must be a number or a range `[lo, hi]`",
                "`mass = [1.0, 9.0]`",
            ],
        ),
        case(
            "mass = [1, inf]",
            edit("mass = 1.0", "mass = [1, inf]"),
            &[
                "s.toml:16:1: `scene.species.0.mass`: range [1, inf]: a range draws finite masses",
                "`mass = inf` makes the species immovable",
            ],
        ),
        case(
            "scale = \"exp\"",
            swept("\"run.duration\" = { from = 10.0, to = 100.0, steps = 3, scale = \"exp\" }"),
            &[
                "`sweep.parameters.run.duration`: range key `scale` = \"exp\" is not a scale",
                "`scale = \"log\"`",
            ],
        ),
    ]);
    for (what, text) in [
        ("mass = []", edit("mass = 1.0", "mass = []")),
        ("mass = [1, inf]", edit("mass = 1.0", "mass = [1, inf]")),
    ] {
        let err = validate(&text).unwrap_err().to_string();
        assert!(
            !err.contains("untagged") && !err.contains("got inf"),
            "{what}: {err}"
        );
    }

    // Bytes that are not UTF-8: the first is placed.
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), "");
    let mut bytes = PISTON.as_bytes().to_vec();
    let at = PISTON.find("\"gas\"").unwrap() + 2;
    bytes[at] = 0xFF;
    std::fs::write(&file, bytes).unwrap();
    let err = load(&file).unwrap_err();
    assert_eq!(err.position, Some((14, 10)), "{err}");
    assert!(err.to_string().contains("byte 0xFF is not UTF-8"), "{err}");
}

/// Validate says "ok" only next to a known cost. Immovable rods are
/// obstacles the estimate counts (a rod between two of them is costed, and
/// ok); a plan whose cost cannot be known (its runs made to say neither a
/// duration nor a collision count, which validation itself refuses) is only
/// valid, and says so.
#[test]
fn validate_says_ok_only_with_a_cost() {
    let walls = rods("").replace(
        "species = [{ name = \"gas\", count = 5 }]",
        "species = [\n  { name = \"wall\", count = 2, mass = inf },\n  \
             { name = \"gas\", count = 1 },\n]\n\
             placement = { kind = \"explicit\", positions = [[1.0], [19.0], [10.0]] }",
    );
    let said = validate(&walls).unwrap_or_else(|e| panic!("{e}"));
    assert!(said.starts_with("s.toml: ok — rods\n"), "{said}");
    assert!(said.contains("estimated collisions: ~"), "{said}");
    let said = validate(&rods("")).unwrap();
    assert!(said.starts_with("s.toml: ok — rods\n"), "{said}");

    let loaded = bonkers::descriptor::load::parse("s.toml", &rods("")).unwrap();
    let mut specs = bonkers::runner::plan::plan(&loaded).unwrap();
    let run = &mut std::sync::Arc::make_mut(&mut specs[0].descriptor).run;
    (run.duration, run.collisions) = (None, None);
    let said = bonkers::cli::describe_plan(&loaded, &specs, 2);
    assert!(said.contains("cost: unknown for 1 of 1 points"), "{said}");
    assert!(
        said.starts_with("s.toml: valid, cost unknown — rods\n"),
        "{said}"
    );
}
