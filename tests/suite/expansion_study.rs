//! Statistical regression tests of the expansion study (seeded; thresholds
//! are four standard errors of the ensemble, never tuned to one outcome).

use crate::study_common::ensemble;
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::stats::summary::Stats;
use bonkers::studies::expansion::Gas;
use bonkers::theory::expansion::FreeExpansion;

fn descriptor(count: usize, radius: f64, duration: f64, replicas: u32) -> String {
    format!(
        r#"
[study]
name = "expansion-test"
replicas = {replicas}
seed = 5

[scene]
dimension = 2
box = [40.0, 40.0]
velocities = {{ kind = "maxwell", temperature = 1.0 }}

[[scene.species]]
name = "gas"
count = {count}
radius = {radius}
region = {{ from = [0.0, 0.0], to = [0.5, 1.0] }}

[run]
duration = {duration}
sample_every = 0.5

[analysis.expansion]
"#
    )
}

fn stats(runs: &[(RunSpec, RunOutput)], name: &str) -> Stats {
    let v: Vec<f64> = runs
        .iter()
        .filter_map(|(_, o)| o.scalar(name))
        .filter(|v| v.is_finite())
        .collect();
    Stats::of(&v)
}

/// The ensemble's left fraction at sample `i`, over the runs.
fn at_sample(runs: &[(RunSpec, RunOutput)], i: usize) -> (f64, Stats) {
    let series: Vec<_> = runs
        .iter()
        .map(|(_, o)| o.series("left_fraction").expect("series"))
        .collect();
    let t = series[0].t[i];
    let v: Vec<f64> = series.iter().map(|s| s.value[i]).collect();
    (t, Stats::of(&v))
}

#[test]
fn theory_starts_left_and_ends_even() {
    let f = FreeExpansion::new(40.0, 0.5, 1.0, 1.0);
    assert_eq!(f.left_fraction(0.0), 1.0);
    assert!((f.left_fraction(1e-3) - 1.0).abs() < 1e-12);
    assert!((f.left_fraction(1e4) - 0.5).abs() < 1e-12);
    let tau = f.relaxation_time();
    let excess = f.left_fraction(tau) - 0.5;
    assert!((excess - 0.5 / std::f64::consts::E).abs() < 1e-9);
    // Free flight: the time scales as L sqrt(m / kT).
    let hot = FreeExpansion::new(40.0, 0.5, 1.0, 4.0);
    assert!((tau / hot.relaxation_time() - 2.0).abs() < 1e-9);
}

/// A dilute gas (mean free path ~ 7 box lengths) follows the collisionless
/// curve at several times, within 4 standard errors of the ensemble, and
/// its relaxation time is the free one.
#[test]
fn dilute_expansion_is_collisionless() {
    let runs = ensemble(&descriptor(100, 0.01, 60.0, 24));
    let gas = Gas::of_descriptor(&runs[0].0.descriptor).expect("scene");
    assert!(gas.knudsen() > 5.0, "Kn = {}", gas.knudsen());
    let free = gas.free(1.0);
    for i in [10, 20, 30, 40, 60] {
        let (t, s) = at_sample(&runs, i);
        let theory = free.left_fraction(t);
        eprintln!("t = {t}: {} +- {} against {theory}", s.mean, s.stderr);
        assert!(
            (s.mean - theory).abs() <= 4.0 * s.stderr,
            "t = {t}: left fraction {} +- {}, collisionless {theory}",
            s.mean,
            s.stderr
        );
    }
    let ratio = stats(&runs, "relaxation_ratio");
    eprintln!("tau / tau_free = {} +- {}", ratio.mean, ratio.stderr);
    assert!((ratio.mean - 1.0).abs() <= 4.0 * ratio.stderr);
}

/// Disks of diameter 1 at 400 in the box (Kn ~ 0.04) are a fluid: the
/// ensemble tells them from free particles at the free relaxation time;
/// the split still settles at N/2, with the fluctuations of a hard-disk
/// fluid (S(0) from Henderson's equation of state), far below binomial.
#[test]
fn dense_split_reaches_half_with_fluid_fluctuations() {
    let runs = ensemble(&descriptor(400, 0.5, 600.0, 8));
    let gas = Gas::of_descriptor(&runs[0].0.descriptor).expect("scene");
    let free = gas.free(1.0);
    let tau = free.relaxation_time();
    let i = (tau / 0.5).round() as usize;
    let (t, s) = at_sample(&runs, i);
    let theory = free.left_fraction(t);
    eprintln!(
        "t = {t}: {} +- {} against collisionless {theory}",
        s.mean, s.stderr
    );
    assert!((s.mean - theory).abs() > 4.0 * s.stderr);

    let late = stats(&runs, "late_mean");
    eprintln!("late mean {} +- {}", late.mean, late.stderr);
    assert!((late.mean - 0.5).abs() <= 4.0 * late.stderr);
    let var = stats(&runs, "late_variance_ratio");
    let s0 = gas.compressibility();
    eprintln!(
        "variance x 4N = {} +- {}, S(0) = {s0}",
        var.mean, var.stderr
    );
    assert!((var.mean - s0).abs() <= 4.0 * var.stderr);
    assert!(1.0 - var.mean > 4.0 * var.stderr, "below binomial");
}

/// A dilute split settles at N/2 with binomial fluctuations.
#[test]
fn dilute_split_is_binomial() {
    let runs = ensemble(&descriptor(50, 0.05, 800.0, 16));
    let late = stats(&runs, "late_mean");
    eprintln!("late mean {} +- {}", late.mean, late.stderr);
    assert!((late.mean - 0.5).abs() <= 4.0 * late.stderr);
    let var = stats(&runs, "late_variance_ratio");
    eprintln!("variance x 4N = {} +- {}", var.mean, var.stderr);
    assert!((var.mean - 1.0).abs() <= 4.0 * var.stderr);
}
