//! Plan expansion: sweep modes, ranges, replicas, run ids and seeds.

use crate::study_common::PISTON;
use bonkers::descriptor::load::{apply_overrides, parse};
use bonkers::descriptor::sweep::{count, expand_values};
use bonkers::runner::plan::plan;
use bonkers::runner::plan::seeds::run_seed;
use std::collections::HashSet;

fn with_sweep(sweep: &str) -> String {
    let head = PISTON.split("[sweep]").next().unwrap();
    let tail = &PISTON[PISTON.find("[run]").unwrap()..];
    format!("{head}{sweep}\n{tail}")
}

#[test]
fn product_is_cartesian_and_last_key_varies_fastest() {
    let loaded = parse("p.toml", PISTON).unwrap();
    let specs = plan(&loaded).unwrap();
    assert_eq!(count(&loaded), (6, 18));
    assert_eq!(specs.len(), 18);
    let point = |i: usize| specs[i * 3].params.clone();
    assert_eq!(point(0)[0].1, toml::Value::Float(1.0));
    assert_eq!(point(0)[1].1, toml::Value::Integer(5));
    assert_eq!(point(1)[1].1, toml::Value::Integer(15));
    assert_eq!(point(2)[0].1, toml::Value::Float(10.0));
    // The swept values reach the run's descriptor.
    assert_eq!(specs[3].descriptor.scene.species[0].count, 15);
    assert_eq!(
        specs[6].descriptor.scene.piston.as_ref().unwrap().mass,
        10.0
    );
}

#[test]
fn run_ids_follow_points_and_replicas() {
    let specs = plan(&parse("p.toml", PISTON).unwrap()).unwrap();
    for (i, s) in specs.iter().enumerate() {
        assert_eq!(s.run_id, i as u64);
        assert_eq!(s.run_id, s.point_id * 3 + u64::from(s.replica));
    }
}

#[test]
fn zip_pairs_values() {
    let text = with_sweep(
        "[sweep]\nmode = \"zip\"\n[sweep.parameters]\n\"scene.piston.mass\" = [1.0, 2.0, 3.0]\n\"run.duration\" = [10.0, 20.0, 30.0]\n",
    );
    // (without the [quick] sweep of two masses, which zip would refuse)
    let text = text.replace(
        "\"sweep.parameters.scene.piston.mass\" = [1.0, 100.0]\n",
        "",
    );
    let loaded = parse("z.toml", &text).unwrap();
    let specs = plan(&loaded).unwrap();
    assert_eq!(count(&loaded), (3, 9));
    assert_eq!(specs[3].descriptor.run.duration, Some(20.0));
    assert_eq!(specs[3].descriptor.scene.piston.as_ref().unwrap().mass, 2.0);
}

#[test]
fn ranges_linear_and_log() {
    let text = with_sweep(
        "[sweep.parameters]\n\"scene.piston.mass\" = { from = 1.0, to = 1000.0, steps = 4, scale = \"log\" }\n\"run.duration\" = { from = 0.5, to = 2.0, steps = 4 }\n",
    );
    let loaded = parse("r.toml", &text).unwrap();
    let sweep = loaded.descriptor.sweep.as_ref().unwrap();
    let masses = expand_values(&sweep.parameters["scene.piston.mass"]);
    let m: Vec<f64> = masses
        .iter()
        .map(|v| v.as_float().or(v.as_integer().map(|i| i as f64)).unwrap())
        .collect();
    for (got, want) in m.iter().zip([1.0, 10.0, 100.0, 1000.0]) {
        assert!((got - want).abs() < 1e-9 * want, "{got} vs {want}");
    }
    let durations = expand_values(&sweep.parameters["run.duration"]);
    assert_eq!(
        durations,
        vec![
            toml::Value::Float(0.5),
            toml::Value::Integer(1),
            toml::Value::Float(1.5),
            toml::Value::Integer(2)
        ]
    );
    assert_eq!(plan(&loaded).unwrap().len(), 16 * 3);
}

#[test]
fn no_sweep_is_one_point() {
    let text = with_sweep("");
    let loaded = parse("n.toml", &text).unwrap();
    let specs = plan(&loaded).unwrap();
    assert_eq!(specs.len(), 3);
    assert!(specs.iter().all(|s| s.point_id == 0 && s.params.is_empty()));
}

#[test]
fn seeds_are_distinct_and_deterministic() {
    let a = plan(&parse("p.toml", PISTON).unwrap()).unwrap();
    let b = plan(&parse("p.toml", PISTON).unwrap()).unwrap();
    assert_eq!(
        a.iter().map(|s| s.seed).collect::<Vec<_>>(),
        b.iter().map(|s| s.seed).collect::<Vec<_>>()
    );
    let mut seen = HashSet::new();
    for study in 0..4u64 {
        for point in 0..200u64 {
            for replica in 0..50u32 {
                assert!(
                    seen.insert(run_seed(study, point, replica)),
                    "seed collision"
                );
            }
        }
    }
    // Another study seed gives other streams.
    let other = parse("p.toml", &PISTON.replace("seed = 42", "seed = 43")).unwrap();
    assert_ne!(plan(&other).unwrap()[0].seed, a[0].seed);
}

#[test]
fn overrides_create_tables_and_index_arrays() {
    let mut t: toml::Table = PISTON.parse().unwrap();
    apply_overrides(&mut t, "scene.species.0.count", toml::Value::Integer(7)).unwrap();
    apply_overrides(&mut t, "analysis.piston.bins", toml::Value::Integer(20)).unwrap();
    assert_eq!(t["scene"]["species"][0]["count"].as_integer(), Some(7));
    assert_eq!(t["analysis"]["piston"]["bins"].as_integer(), Some(20));
    let err =
        apply_overrides(&mut t, "scene.species.3.count", toml::Value::Integer(1)).unwrap_err();
    assert!(err.contains("has 1 item(s)"), "{err}");
    let err = apply_overrides(&mut t, "study.name.x", toml::Value::Integer(1)).unwrap_err();
    assert!(err.contains("not a table"), "{err}");
    assert!(apply_overrides(&mut t, "a..b", toml::Value::Integer(1)).is_err());
}

#[test]
fn quick_and_replicas_overrides() {
    use bonkers::descriptor::load::{quick, with_replicas};
    let loaded = parse("p.toml", PISTON).unwrap();
    let q = quick(&loaded).unwrap();
    assert_eq!(q.descriptor.study.replicas, 1);
    assert_eq!(q.descriptor.run.duration, Some(10.0));
    // 2 masses x 2 counts.
    assert_eq!(plan(&q).unwrap().len(), 4);
    let r = with_replicas(&q, 5).unwrap();
    assert_eq!(plan(&r).unwrap().len(), 20);
    assert!(r.text_as_run().contains("replicas = 5"));
}

/// Seeds come from the point's values, not its index: a value inserted into
/// a sweep leaves every other point's seeds as they were.
#[test]
fn inserting_a_sweep_value_keeps_the_other_points_seeds() {
    let seeds = |text: &str| -> std::collections::HashMap<String, Vec<u64>> {
        let mut by_point = std::collections::HashMap::new();
        for s in plan(&parse("p.toml", text).unwrap()).unwrap() {
            by_point
                .entry(format!("{:?}", s.params))
                .or_insert_with(Vec::new)
                .push(s.seed);
        }
        by_point
    };
    let before = seeds(PISTON);
    let after = seeds(&PISTON.replace("[1.0, 10.0, 100.0]", "[1.0, 3.0, 10.0, 100.0]"));
    assert_eq!((before.len(), after.len()), (6, 8));
    for (point, s) in &before {
        assert_eq!(after.get(point), Some(s), "{point}");
    }
    // Point (mass 10, count 5) moved from id 2 to id 4; its seeds stayed.
    let id_of = |text: &str| {
        plan(&parse("p.toml", text).unwrap())
            .unwrap()
            .into_iter()
            .find(|s| {
                s.params[0].1 == toml::Value::Float(10.0)
                    && s.params[1].1 == toml::Value::Integer(5)
            })
            .map(|s| (s.point_id, s.seed))
            .unwrap()
    };
    let (id_before, seed_before) = id_of(PISTON);
    let (id_after, seed_after) =
        id_of(&PISTON.replace("[1.0, 10.0, 100.0]", "[1.0, 3.0, 10.0, 100.0]"));
    assert_eq!((id_before, id_after), (2, 4));
    assert_eq!(seed_before, seed_after);
    // Replicas of a point get different seeds; more replicas keep the first ones.
    let three = seeds(PISTON);
    let five = seeds(&PISTON.replace("replicas = 3", "replicas = 5"));
    for (point, s) in &three {
        assert_eq!(&five[point][..3], &s[..]);
    }
}
