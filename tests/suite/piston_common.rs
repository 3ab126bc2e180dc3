//! Shared by the piston tests: run a descriptor's ensemble, and the
//! statistics of a result over its runs.
#![allow(dead_code)]

use bonkers::descriptor::load::parse;
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::runner::plan::plan;
use bonkers::stats::summary::Stats;
use bonkers::studies::piston::state::{Geometry, Samples};
use bonkers::studies::piston::{Options, measure};
use bonkers::theory::piston_equilibrium::oscillator_share;
use rand::SeedableRng;

/// Run every planned run of a descriptor.
pub fn ensemble(text: &str) -> Vec<(RunSpec, RunOutput)> {
    let loaded = parse("test.toml", text).expect("valid descriptor");
    plan(&loaded)
        .expect("plan")
        .into_iter()
        .map(|r| {
            let out = bonkers::runner::execute::simulate::run(&r).expect("run");
            (r, out)
        })
        .collect()
}

/// Statistics of one scalar (or of a function of the scalars) over the runs.
pub fn stats(runs: &[(RunSpec, RunOutput)], f: impl Fn(&RunOutput) -> Option<f64>) -> Stats {
    let v: Vec<f64> = runs
        .iter()
        .map(|(_, o)| f(o).unwrap_or(f64::NAN))
        .filter(|v| v.is_finite())
        .collect();
    Stats::of(&v)
}

pub fn scalar(name: &str) -> impl Fn(&RunOutput) -> Option<f64> + '_ {
    move |o| o.scalar(name)
}

/// `|mean - 1| <= 4 standard errors`, with the numbers in the message.
pub fn assert_one(s: &Stats, what: &str) {
    assert!(
        (s.mean - 1.0).abs() <= 4.0 * s.stderr,
        "{what} = {} +- {} (n = {})",
        s.mean,
        s.stderr,
        s.n
    );
}

/// `|mean - 1| > 4 standard errors`: the ensemble rejects this prediction.
pub fn assert_not_one(s: &Stats, what: &str) {
    assert!(
        (s.mean - 1.0).abs() > 4.0 * s.stderr,
        "{what} = {} +- {} should differ from 1",
        s.mean,
        s.stderr
    );
}

/// The geometry a run's analysis saw (its scene rebuilt from its seed).
pub fn geometry<const D: usize>(spec: &RunSpec) -> Geometry {
    let scene = bonkers::scene::resolve(&spec.descriptor.scene).expect("scene");
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(spec.seed);
    let built = bonkers::scene::build::<D>(&scene, &mut rng).expect("build");
    Geometry::of(&built).expect("piston")
}

/// A run's piston results measured again with another geometry (the
/// stored series must hold every sample: at most 4000 of them).
pub fn measure_with(spec: &RunSpec, out: &RunOutput, g: &Geometry) -> Vec<(&'static str, f64)> {
    let samples = Samples::of(out).expect("piston series");
    assert!(samples.len() <= bonkers::runner::execute::simulate::MAX_STORED_POINTS);
    measure(g, &samples, &Options::of(&spec.descriptor))
}

/// One result of `measure_with`.
pub fn result(results: &[(&'static str, f64)], name: &str) -> f64 {
    results
        .iter()
        .find(|(n, _)| *n == name)
        .map_or(f64::NAN, |r| r.1)
}

/// Long-time equipartition of a relaxed ensemble with `per_side` gas
/// particles on each side in `dimension` D: the piston's share of the kinetic
/// energy is `expected` (1/N_free), its oscillator energy the microcanonical
/// mean, each within 4 standard errors, and every run relaxed.
pub fn assert_equipartition(
    runs: &[(RunSpec, RunOutput)],
    dimension: usize,
    per_side: usize,
    expected: f64,
) {
    let share = stats(runs, scalar("piston_share"));
    let oscillator = stats(runs, scalar("oscillator_share"));
    let (theory, theory_se) = oscillator_share(
        dimension,
        per_side,
        per_side,
        bonkers::studies::piston::DRAWS,
    );
    eprintln!(
        "piston share {} +- {} ({expected}); oscillator share {} +- {} ({theory} +- {theory_se})",
        share.mean, share.stderr, oscillator.mean, oscillator.stderr
    );
    assert!(
        4.0 * share.stderr < expected,
        "the test must be able to tell: stderr {}",
        share.stderr
    );
    assert!(
        (share.mean - expected).abs() <= 4.0 * share.stderr,
        "share {} +- {} vs {expected}",
        share.mean,
        share.stderr
    );
    let se = oscillator.stderr.hypot(theory_se);
    assert!(
        (oscillator.mean - theory).abs() <= 4.0 * se,
        "oscillator share {} +- {} vs {theory} +- {theory_se}",
        oscillator.mean,
        oscillator.stderr
    );
    assert_eq!(
        stats(runs, scalar("relaxation_time")).n,
        runs.len() as u64,
        "every run relaxed"
    );
}
