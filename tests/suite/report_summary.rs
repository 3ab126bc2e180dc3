//! Ensemble statistics on synthetic runs with known answers.

use bonkers::model::descriptor::Descriptor;
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::stats::summary::summarize;

fn descriptor() -> Descriptor {
    toml::from_str(
        "[study]\nname = \"t\"\nreplicas = 4\nseed = 1\n[scene]\ndimension = 1\n[run]\nduration = 1.0\n",
    )
    .expect("minimal descriptor parses")
}

fn run(point: u64, replica: u32, mass: f64, scalars: &[(&str, f64)]) -> (RunSpec, RunOutput) {
    let spec = RunSpec {
        run_id: point * 100 + u64::from(replica),
        point_id: point,
        replica,
        seed: 7 + point * 100 + u64::from(replica),
        params: vec![("scene.piston.mass".into(), toml::Value::Float(mass))].into(),
        case: None,
        descriptor: descriptor().into(),
    };
    let out = RunOutput {
        scalars: scalars.iter().map(|(n, v)| (n.to_string(), *v)).collect(),
        collisions: 1000,
        wall_seconds: 0.5,
        ..RunOutput::default()
    };
    (spec, out)
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-4
}

#[test]
fn mean_std_stderr_ci_and_z() {
    let runs: Vec<_> = [1.0, 2.0, 3.0, 4.0]
        .iter()
        .enumerate()
        .map(|(i, v)| run(0, i as u32, 10.0, &[("x", *v)]))
        .collect();
    let theory = |_: &Descriptor, name: &str| (name == "x").then_some(2.0);
    let rows = summarize(&runs, &theory);
    assert_eq!(rows.len(), 1);
    let r = &rows[0];
    assert_eq!((r.n, r.point_id, r.result.as_str()), (4, 0, "x"));
    assert_eq!(r.params, vec![("scene.piston.mass".to_string(), 10.0)]);
    assert!(close(r.mean, 2.5));
    assert!(close(r.std, 1.2910));
    assert!(close(r.stderr, 0.6455));
    // t(0.975, 3) = 3.1824
    assert!(close(r.ci_high, 2.5 + 3.1824 * 0.645_497));
    assert!(close(r.ci_low, 2.5 - 3.1824 * 0.645_497));
    assert_eq!(r.theory, Some(2.0));
    assert!(close(r.z.unwrap_or(f64::NAN), 0.5 / 0.645_497));
    assert!(close(r.seconds, 2.0));
    assert_eq!(r.collisions, 4000);
}

#[test]
fn nan_results_leave_n_and_order_is_deterministic() {
    let runs = vec![
        run(1, 0, 5.0, &[("b", 1.0), ("a", f64::NAN)]),
        run(0, 0, 1.0, &[("b", 3.0), ("a", 1.0)]),
        run(1, 1, 5.0, &[("b", 2.0), ("a", 4.0)]),
        run(0, 1, 1.0, &[("b", 5.0), ("a", 3.0)]),
        run(1, 2, 5.0, &[("b", 3.0)]),
    ];
    let rows = summarize(&runs, &|_: &Descriptor, _: &str| None);
    let keys: Vec<(u64, &str)> = rows
        .iter()
        .map(|r| (r.point_id, r.result.as_str()))
        .collect();
    assert_eq!(keys, vec![(0, "a"), (0, "b"), (1, "a"), (1, "b")]);
    let a1 = &rows[2];
    assert_eq!(a1.n, 1, "NaN and missing values are not counted");
    assert_eq!(a1.mean, 4.0);
    assert!(a1.std.is_nan() && a1.z.is_none());
    assert_eq!(rows[3].n, 3);
    assert!(close(rows[3].mean, 2.0));
    // Cost counts every run of the point, measured or not.
    assert_eq!(rows[2].collisions, 3000);
}

#[test]
fn zero_spread_and_all_nan() {
    let runs: Vec<_> = (0..3)
        .map(|i| {
            run(
                0,
                i,
                1.0,
                &[("flat", 2.0), ("off", 3.0), ("none", f64::NAN)],
            )
        })
        .collect();
    let theory = |_: &Descriptor, _: &str| Some(2.0);
    let rows = summarize(&runs, &theory);
    let get = |n: &str| rows.iter().find(|r| r.result == n).expect("row exists");
    assert_eq!(get("flat").z, Some(0.0), "exact agreement is z = 0");
    assert_eq!(
        get("off").z,
        None,
        "no spread: no statistical scale for the deviation"
    );
    let none = get("none");
    assert_eq!(none.n, 0);
    assert!(none.mean.is_nan() && none.z.is_none());
}

#[test]
fn empty_input_gives_no_rows() {
    assert!(summarize(&[], &|_: &Descriptor, _: &str| Some(1.0)).is_empty());
}
