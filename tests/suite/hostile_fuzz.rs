//! The bundled studies mutated as a hostile tester would (keys deleted,
//! types swapped, extreme numbers, long strings, deep nesting), fed to
//! validation in-process and to `study validate` / a cheap `study run` as
//! subprocesses. A fixed seed and case count keep it to a few seconds in CI
//! and the same descriptors every time. Asserts: no panic, exit code 0, 1
//! or 2, time and memory bounded, nothing written outside OUT.

use crate::bounded::{config, names, study};
use crate::study_common::PISTON;
use bonkers::descriptor::load::{Loaded, parse, quick};
use bonkers::runner::pipeline;
use bonkers::runner::plan::estimate;
use bonkers::runner::plan::plan;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{RngAlgorithm, TestRng, TestRunner};
use std::time::{Duration, Instant};

const STUDIES: [&str; 9] = [
    PISTON,
    include_str!("../../studies/quickstart.toml"),
    include_str!("../../studies/piston.toml"),
    include_str!("../../studies/pressure.toml"),
    include_str!("../../studies/mixing.toml"),
    include_str!("../../studies/mixing-2d.toml"),
    include_str!("../../studies/equilibrium.toml"),
    include_str!("../../studies/expansion.toml"),
    include_str!("../../studies/accuracy.toml"),
];

/// One change to a descriptor's table, at the key or item that `at` picks
/// among all of them.
#[derive(Debug, Clone)]
enum Mutation {
    Delete {
        at: u64,
    },
    Swap {
        at: u64,
        to: u8,
    },
    Extreme {
        at: u64,
        to: u8,
    },
    LongString {
        at: u64,
        len: usize,
    },
    Nest {
        at: u64,
        depth: usize,
    },
    /// A number scaled by a modest factor: often still valid, so runs too.
    Scale {
        at: u64,
        by: u8,
    },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        1 => any::<u64>().prop_map(|at| Mutation::Delete { at }),
        1 => (any::<u64>(), any::<u8>()).prop_map(|(at, to)| Mutation::Swap { at, to }),
        // Numbers are the likeliest to be hostile: twice the weight.
        2 => (any::<u64>(), any::<u8>()).prop_map(|(at, to)| Mutation::Extreme { at, to }),
        1 => (any::<u64>(), prop_oneof![Just(300usize), Just(5000), Just(100_000)])
            .prop_map(|(at, len)| Mutation::LongString { at, len }),
        1 => (any::<u64>(), 1usize..400).prop_map(|(at, depth)| Mutation::Nest { at, depth }),
        2 => (any::<u64>(), any::<u8>()).prop_map(|(at, by)| Mutation::Scale { at, by }),
    ]
}

/// A bundled study and the mutations to make, serialized back to TOML.
fn descriptor() -> impl Strategy<Value = (usize, Vec<Mutation>)> {
    (
        0..STUDIES.len(),
        proptest::collection::vec(mutation(), 1..4),
    )
}

/// Every path to a key or array item of `value`, parents before children.
fn paths(value: &toml::Value, here: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    let children: Vec<(String, &toml::Value)> = match value {
        toml::Value::Table(t) => t.iter().map(|(k, v)| (k.clone(), v)).collect(),
        toml::Value::Array(a) => a
            .iter()
            .enumerate()
            .map(|(i, v)| (i.to_string(), v))
            .collect(),
        _ => return,
    };
    for (key, child) in children {
        here.push(key);
        out.push(here.clone());
        paths(child, here, out);
        here.pop();
    }
}

/// The slot at `path` and its key in its parent.
fn parent<'a>(root: &'a mut toml::Value, path: &[String]) -> Option<&'a mut toml::Value> {
    let mut at = root;
    for key in &path[..path.len() - 1] {
        at = match at {
            toml::Value::Table(t) => t.get_mut(key)?,
            toml::Value::Array(a) => a.get_mut(key.parse::<usize>().ok()?)?,
            _ => return None,
        };
    }
    Some(at)
}

fn slot<'a>(root: &'a mut toml::Value, path: &[String]) -> Option<&'a mut toml::Value> {
    let last = path.last()?;
    match parent(root, path)? {
        toml::Value::Table(t) => t.get_mut(last),
        toml::Value::Array(a) => a.get_mut(last.parse::<usize>().ok()?),
        _ => None,
    }
}

const EXTREMES: [f64; 10] = [
    0.0,
    -1.0,
    5e-324,
    1e-300,
    1e300,
    1e308,
    -1e308,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
];
const WHOLE: [i64; 6] = [
    0,
    -1,
    i64::MAX,
    i64::MIN,
    4_294_967_296,
    1_000_000_000_000_000_000,
];

fn apply(root: &mut toml::Value, m: &Mutation) {
    let mut all = Vec::new();
    paths(root, &mut Vec::new(), &mut all);
    let at = match m {
        Mutation::Delete { at }
        | Mutation::Swap { at, .. }
        | Mutation::Extreme { at, .. }
        | Mutation::LongString { at, .. }
        | Mutation::Nest { at, .. }
        | Mutation::Scale { at, .. } => *at,
    };
    if all.is_empty() {
        return;
    }
    let path = &all[(at % all.len() as u64) as usize];
    if let Mutation::Delete { .. } = m {
        let last = path.last().unwrap();
        match parent(root, path) {
            Some(toml::Value::Table(t)) => {
                t.remove(last);
            }
            Some(toml::Value::Array(a)) => {
                if let Ok(i) = last.parse::<usize>()
                    && i < a.len()
                {
                    a.remove(i);
                }
            }
            _ => {}
        }
        return;
    }
    let Some(value) = slot(root, path) else {
        return;
    };
    *value = match m {
        Mutation::Swap { to, .. } => match to % 8 {
            0 => toml::Value::String("x".into()),
            1 => toml::Value::Integer(3),
            2 => toml::Value::Float(2.5),
            3 => toml::Value::Boolean(true),
            4 => toml::Value::Array(Vec::new()),
            5 => toml::Value::Array(vec![
                toml::Value::Integer(1),
                toml::Value::String("a".into()),
            ]),
            6 => toml::Value::Table(toml::Table::new()),
            _ => toml::Value::Datetime("1979-05-27".parse().unwrap()),
        },
        Mutation::Extreme { to, .. } => {
            let i = usize::from(*to);
            if i % 3 == 0 {
                toml::Value::Integer(WHOLE[i / 3 % WHOLE.len()])
            } else {
                toml::Value::Float(EXTREMES[i % EXTREMES.len()])
            }
        }
        Mutation::LongString { len, .. } => {
            toml::Value::String("é/\\\"x\n\u{0}".chars().cycle().take(*len).collect())
        }
        Mutation::Nest { depth, .. } => {
            let mut v = value.clone();
            for level in 0..*depth {
                v = if level % 2 == 0 {
                    toml::Value::Array(vec![v])
                } else {
                    let mut t = toml::Table::new();
                    t.insert("a".into(), v);
                    toml::Value::Table(t)
                };
            }
            v
        }
        Mutation::Scale { by, .. } => {
            let by = [0.5, 2.0, 3.0][usize::from(*by) % 3];
            match &*value {
                toml::Value::Float(x) => toml::Value::Float(x * by),
                toml::Value::Integer(n) => toml::Value::Integer((*n as f64 * by).round() as i64),
                other => other.clone(),
            }
        }
        Mutation::Delete { .. } => unreachable!(),
    };
}

/// The mutated descriptor's text; None if the mutation leaves no TOML
/// document (a root that is not a table cannot be written).
fn mutated(study: usize, mutations: &[Mutation]) -> Option<String> {
    let mut root = toml::Value::Table(STUDIES[study].parse().unwrap());
    for m in mutations {
        apply(&mut root, m);
    }
    toml::to_string(&root).ok()
}

/// Validation in-process as `study validate` does it, `--quick` too; what
/// a cheap plan would cost, if it is one (estimated seconds).
fn validate(text: &str) -> Option<f64> {
    let loaded = parse("f.toml", text).ok()?;
    let mut cheapest = None;
    let quick = quick(&loaded).ok();
    for loaded in std::iter::once(loaded).chain(quick) {
        if let Some(seconds) = planned(&loaded) {
            cheapest = Some(seconds);
        }
    }
    cheapest
}

fn planned(loaded: &Loaded) -> Option<f64> {
    pipeline::confirm_size(loaded, false).ok()?;
    let specs = plan(loaded).ok()?;
    pipeline::confirm_cost(loaded, &specs, false).ok()?;
    let _ = bonkers::cli::describe_plan(loaded, &specs, 2);
    let seconds: f64 = estimate::by_point(&specs)
        .iter()
        .map(|(_, c, n)| c.map_or(f64::INFINITY, |c| c.seconds() * n))
        .sum();
    (specs.len() <= 64).then_some(seconds)
}

proptest! {
    #![proptest_config(config(160))]

    /// In-process: never a panic, and each descriptor validated (and
    /// planned, if it gets that far) within seconds.
    #[test]
    fn mutated_studies_validate_without_panic_in_bounded_time((study, mutations) in descriptor()) {
        if let Some(text) = mutated(study, &mutations) {
            let clock = Instant::now();
            let _ = validate(&text);
            let seconds = clock.elapsed().as_secs_f64();
            prop_assert!(seconds < 10.0, "{seconds} s for study {study} with {mutations:?}");
        }
    }
}

/// Subprocesses: a few mutated descriptors through `study validate`, and
/// those cheap enough through `study run --quick`, from an empty working
/// folder: exit 0, 1 or 2, no panic, and files only in OUT.
#[test]
fn mutated_studies_through_the_command_stay_in_their_folder() {
    let mut runner = TestRunner::new_with_rng(
        config(1),
        TestRng::from_seed(RngAlgorithm::ChaCha, &[18; 32]),
    );
    let (mut validated, mut ran) = (0, 0);
    for i in 0..12 {
        // The small test study as it is, then mutated (cheap enough to run).
        let mutations = match i {
            0 => Vec::new(),
            _ => descriptor().new_tree(&mut runner).unwrap().current().1,
        };
        let Some(text) = mutated(0, &mutations) else {
            continue;
        };
        let dir = tempfile::tempdir().unwrap();
        let (input, cwd) = (dir.path().join("in"), dir.path().join("cwd"));
        std::fs::create_dir(&input).unwrap();
        std::fs::create_dir(&cwd).unwrap();
        let file = input.join("f.toml");
        std::fs::write(&file, &text).unwrap();
        let file = file.to_str().unwrap();
        let (code, err) = study(&["validate", file], &cwd, Duration::from_secs(30));
        assert!(
            (0..=2).contains(&code),
            "validate exit {code}: {err}\n{mutations:?}"
        );
        assert!(!err.contains("panicked"), "{err}");
        validated += 1;
        let cheap = validate(&text).is_some_and(|s| s < 0.5);
        if code == 0 && cheap {
            let out = dir.path().join("out");
            let args = ["run", file, "--quick", "--quiet", "--threads", "2", "--out"];
            let mut args = args.to_vec();
            args.push(out.to_str().unwrap());
            let (code, err) = study(&args, &cwd, Duration::from_secs(60));
            assert!(
                (0..=2).contains(&code),
                "run exit {code}: {err}\n{mutations:?}"
            );
            assert!(!err.contains("panicked"), "{err}");
            ran += 1;
        }
        assert_eq!(
            names(&cwd),
            Vec::<String>::new(),
            "written in the working folder"
        );
        assert_eq!(
            names(&input),
            vec!["f.toml".to_string()],
            "written beside the descriptor"
        );
        let top = names(dir.path());
        assert!(
            top.iter()
                .all(|n| ["in", "cwd", "out"].contains(&n.as_str())),
            "{top:?}"
        );
    }
    assert!(validated >= 8, "only {validated} descriptors validated");
    assert!(ran >= 1, "no mutated study was cheap enough to run");
}
