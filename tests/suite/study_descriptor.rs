//! Descriptor errors: each path names file:line:col, what is wrong and what
//! would be right; and no input makes the parser panic.

use crate::study_common::PISTON;
use bonkers::descriptor::load::{
    apply_overrides, edit_distance, parse, quick, with_overrides, with_replicas,
};
use proptest::prelude::*;

/// The error text for `text` as a user sees it.
fn error(text: &str) -> String {
    parse("s.toml", text)
        .expect_err("should be rejected")
        .to_string()
}

fn assert_has(msg: &str, parts: &[&str]) {
    for p in parts {
        assert!(msg.contains(p), "expected {p:?} in:\n{msg}");
    }
}

#[test]
fn valid_descriptor_parses() {
    let loaded = parse("s.toml", PISTON).unwrap();
    assert_eq!(loaded.descriptor.study.name, "piston-test");
    assert_eq!(loaded.descriptor.study.replicas, 3);
}

#[test]
fn syntax_error_has_line_and_column() {
    let msg = error("[study]\nname = \"x\nreplicas = 2\n");
    assert!(msg.starts_with("s.toml:2:"), "{msg}");
}

#[test]
fn unknown_key_suggests_the_closest() {
    let msg = error(&PISTON.replace("replicas = 3", "replicaz = 3"));
    assert_has(
        &msg,
        &[
            "s.toml:5:1: unknown key `replicaz` in [study]",
            "did you mean `replicas`?",
            "`seed`",
        ],
    );
    let msg = error(&PISTON.replace("sample_every", "sampel_every"));
    assert_has(
        &msg,
        &[
            "unknown key `sampel_every` in [run]",
            "did you mean `sample_every`?",
        ],
    );
    let msg = error(&PISTON.replace("[scene.piston]\nmass", "[scene.piston]\nmasss"));
    assert_has(&msg, &["in [scene.piston]", "did you mean `mass`?"]);
    // Nothing close: no guess, but the valid keys.
    let msg = error(&PISTON.replace("replicas = 3", "zzzzzzzz = 3"));
    assert!(!msg.contains("did you mean"), "{msg}");
    assert_has(&msg, &["valid keys here"]);
    let msg = error(&format!("{PISTON}\n[sweeep]\n"));
    assert_has(&msg, &["unknown key `sweeep`", "did you mean `sweep`?"]);
}

#[test]
fn unknown_variant_and_wrong_type() {
    let msg = error(&PISTON.replace("kind = \"maxwell\"", "kind = \"maxwel\""));
    assert_has(
        &msg,
        &[
            "s.toml:23:8:",
            "`scene.velocities.kind`",
            "did you mean \"maxwell\"?",
        ],
    );
    let msg = error(&PISTON.replace("count = 10", "count = \"ten\""));
    assert_has(
        &msg,
        &[
            "s.toml:15:9:",
            "`scene.species.0.count`",
            "expected a whole number from 0 to 9223372036854775807",
        ],
    );
    let msg = error(&PISTON.replace("boundary = [\"walls\"]", "boundary = [\"wall\"]"));
    assert_has(&msg, &["did you mean \"walls\"?"]);
}

#[test]
fn missing_keys() {
    let msg = error(&PISTON.replace("name = \"piston-test\"\n", ""));
    assert_has(&msg, &["missing required key `name`", "add `name = ...`"]);
    let msg = error(&PISTON.replace("duration = 100.0\n", ""));
    assert_has(
        &msg,
        &[
            "s.toml:33:2:",
            "`run`",
            "neither how long",
            "duration = 1000.0",
        ],
    );
}

#[test]
fn semantic_errors_point_at_their_key() {
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "replicas = 3",
            "replicas = 0",
            &["s.toml:5:1:", "`study.replicas`: must be at least 1"],
        ),
        (
            "duration = 100.0",
            "duration = -1.0",
            &["s.toml:34:1:", "`run.duration`: must be a positive number"],
        ),
        (
            "sample_every = 0.5",
            "sample_every = 0.0",
            &["`run.sample_every`: must be a positive number"],
        ),
        (
            "dimension = 1",
            "dimension = 4",
            &["s.toml:9:1:", "must be 1, 2 or 3"],
        ),
        (
            "box = [40.0]",
            "box = [40.0, 3.0]",
            &["`scene.box`: has 2 entries but the scene has dimension 1"],
        ),
        (
            "box = [40.0]",
            "box = [-40.0]",
            &["`scene.box.0`: must be a positive number"],
        ),
        (
            "name = \"piston-test\"",
            "name = \"../x\"",
            &["cannot name an output folder"],
        ),
        (
            "position = 0.5",
            "position = 1.5",
            &["`scene.piston.position`"],
        ),
    ];
    for (from, to, parts) in cases {
        assert_has(&error(&PISTON.replacen(from, to, 1)), parts);
    }
}

#[test]
fn sweep_errors() {
    let msg = error(&PISTON.replace("\"scene.piston.mass\" =", "\"scene.piston.mas\" ="));
    assert_has(
        &msg,
        &[
            "s.toml:30:1:",
            "sweep parameter `scene.piston.mas`",
            "unknown key `mas`",
            "did you mean `mass`?",
        ],
    );
    let msg = error(&PISTON.replace("\"scene.piston.mass\" =", "\"scene.pistn.mass\" ="));
    assert_has(&msg, &["unknown key `pistn`", "did you mean `piston`?"]);
    let msg = error(&PISTON.replace("\"scene.piston.mass\" =", "\"scen.piston.mass\" ="));
    assert_has(
        &msg,
        &["not a key path that can be swept", "did you mean `scene"],
    );
    let msg = error(&PISTON.replace("[1.0, 10.0, 100.0]", "[1.0, \"heavy\"]"));
    assert_has(&msg, &["value \"heavy\"", "invalid type"]);
    let msg = error(&PISTON.replace("[1.0, 10.0, 100.0]", "[1.0, -2.0]"));
    assert_has(&msg, &["value -2.0 makes `scene.piston.mass` invalid"]);
    let msg = error(&PISTON.replace("\"scene.piston.mass\" =", "\"study.seed\" ="));
    assert_has(&msg, &["`study.seed` is not a key path that can be swept"]);
    let msg = error(&PISTON.replace("steps = 2 }", "steps = 1000000000000 }"));
    assert_has(
        &msg,
        &[
            "1000000000000 values are more sweep points than a study can plan (at most 100000)",
            "split the study",
        ],
    );
    let msg = error(&PISTON.replace("[1.0, 10.0, 100.0]", "[]"));
    assert_has(&msg, &["s.toml:30:1:", "has no values"]);
    // A range that is not whole in the middle cannot sweep a count.
    let msg = error(&PISTON.replace("steps = 2 }", "steps = 4 }"));
    assert_has(&msg, &["value 8.333", "expected a whole number"]);
    let msg = error(&PISTON.replace("steps = 2 }", "steps = 0 }"));
    assert_has(&msg, &["steps >= 1"]);
    let msg = error(&PISTON.replace(
        "[1.0, 10.0, 100.0]",
        "{ from = 0.0, to = 10.0, steps = 3, scale = \"log\" }",
    ));
    assert_has(&msg, &["log range needs positive bounds"]);
    let msg = error(&PISTON.replace("mode = \"product\"", "mode = \"zip\""));
    assert_has(
        &msg,
        &[
            "s.toml:27:1:",
            "zip needs equally long parameters",
            "has 3 values",
        ],
    );
    let msg = error(&PISTON.replace("[1.0, 10.0, 100.0]", "\"heavy\""));
    assert_has(&msg, &["must be a list of values or a range"]);
    let msg = error(&PISTON.replace("\"scene.species.0.count\"", "\"scene.species.4.count\""));
    assert_has(&msg, &["index 4 does not exist"]);
}

#[test]
fn override_errors_name_their_origin() {
    let loaded = parse("s.toml", PISTON).unwrap();
    // `[quick]` is checked by `parse` (see study_errors.rs); `--replicas`
    // and other overrides when applied.
    let err = with_replicas(&loaded, 0).unwrap_err();
    assert_has(
        &err.to_string(),
        &[
            "after applying --replicas",
            "`study.replicas`: must be at least 1",
        ],
    );
    let err = with_overrides(
        &loaded,
        &[("run.sample_every".to_string(), toml::Value::Float(-1.0))],
        "--test",
    )
    .unwrap_err();
    assert_has(
        &err.to_string(),
        &[
            "after applying --test",
            "`run.sample_every`: must be a positive number",
        ],
    );
    let no_quick = parse("s.toml", &PISTON[..PISTON.find("[quick]").unwrap()]).unwrap();
    assert_has(
        &quick(&no_quick).unwrap_err().to_string(),
        &["no [quick] table"],
    );
}

#[test]
fn missing_file_is_an_input_error() {
    let err =
        bonkers::descriptor::load::load(std::path::Path::new("/nonexistent/x.toml")).unwrap_err();
    assert_has(
        &err.to_string(),
        &[
            "/nonexistent/x.toml: cannot read the descriptor",
            "study list",
        ],
    );
}

#[test]
fn edit_distance_basics() {
    assert_eq!(edit_distance("kitten", "sitting"), 3);
    assert_eq!(edit_distance("", "abc"), 3);
    assert_eq!(edit_distance("same", "same"), 0);
}

/// Small edits of the valid descriptor: drop, duplicate or change a byte.
fn mutate(text: &str, pos: usize, kind: u8, byte: u8) -> String {
    let mut b = text.as_bytes().to_vec();
    if b.is_empty() {
        return String::new();
    }
    let i = pos % b.len();
    match kind % 4 {
        0 => {
            b.remove(i);
        }
        1 => b.insert(i, byte),
        2 => b[i] = byte,
        _ => b.truncate(i),
    }
    String::from_utf8_lossy(&b).into_owned()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,200}") {
        let _ = parse("p.toml", &text).map(|l| l.to_owned());
    }

    #[test]
    fn toml_like_text_never_panics(text in "(\\[[a-z.]{1,12}\\]\n|[a-z_\"\\.]{1,14} = (-?[0-9]{1,4}(\\.[0-9])?|\"[a-z]{0,6}\"|\\[[0-9., ]{0,10}\\]|\\{ ?[a-z]{1,5} = [0-9]{1,3} ?\\})\n){0,12}") {
        let _ = parse("p.toml", &text);
    }

    #[test]
    fn mutated_descriptors_never_panic(edits in proptest::collection::vec((any::<usize>(), any::<u8>(), any::<u8>()), 1..4)) {
        let mut text = PISTON.to_string();
        for (pos, kind, byte) in edits {
            text = mutate(&text, pos, kind, byte);
        }
        if let Ok(loaded) = parse("p.toml", &text) {
            let _ = bonkers::descriptor::sweep::count(&loaded);
            if bonkers::descriptor::sweep::count(&loaded).1 < 10_000 {
                let _ = bonkers::runner::plan::plan(&loaded);
            }
            let _ = quick(&loaded);
        }
    }

    #[test]
    fn overrides_never_panic(path in "[a-z0-9._]{0,20}", v in any::<i64>()) {
        let mut t: toml::Table = PISTON.parse().unwrap();
        let _ = apply_overrides(&mut t, &path, toml::Value::Integer(v));
    }
}
