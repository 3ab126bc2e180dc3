//! Statistical regression tests of the piston study (seeded; thresholds are
//! four standard errors of the ensemble, never tuned to one outcome).

use bonkers::analysis::summary::Stats;
use bonkers::study::descriptor::parse;
use bonkers::study::plan::plan;

/// Run every planned run of a descriptor and collect one scalar per run.
fn ensemble(text: &str, results: &[&str]) -> Vec<Stats> {
    let loaded = parse("test.toml", text).expect("valid descriptor");
    let runs = plan(&loaded).expect("plan");
    let outputs: Vec<_> = runs
        .iter()
        .map(|r| bonkers::simulate::run(r).expect("run"))
        .collect();
    results
        .iter()
        .map(|name| {
            Stats::of(
                &outputs
                    .iter()
                    .map(|o| o.scalar(name).unwrap_or(f64::NAN))
                    .collect::<Vec<_>>(),
            )
        })
        .collect()
}

fn descriptor(mass: f64, duration: f64, replicas: u32) -> String {
    format!(
        r#"
[study]
name = "piston-test"
replicas = {replicas}
seed = 99

[scene]
preset = "mackay-piston"
velocities = {{ kind = "maxwell", temperature = 1.0 }}
piston = {{ mass = {mass}, position = 0.5, radius = 0.0, energy = 5.0 }}

[run]
duration = {duration}
sample_every = 0.5

[analysis.piston]
"#
    )
}

/// A heavy piston (M/m = 1000) moves slowly enough for each gas to follow its
/// adiabat: the measured frequency matches the nonlinear adiabatic one within
/// its error bar, and is clearly not the isothermal one (which it exceeds by
/// about sqrt(3) in the small-amplitude limit).
#[test]
fn heavy_piston_oscillates_at_the_adiabatic_frequency() {
    let stats = ensemble(
        &descriptor(1000.0, 3000.0, 10),
        &["frequency_ratio", "frequency_ratio_isothermal"],
    );
    let (adiabatic, isothermal) = (&stats[0], &stats[1]);
    assert_eq!(adiabatic.n, 10, "every run measured a frequency");
    assert!(
        (adiabatic.mean - 1.0).abs() <= 4.0 * adiabatic.stderr,
        "omega/omega_adiabatic = {} +- {}",
        adiabatic.mean,
        adiabatic.stderr
    );
    assert!(
        (isothermal.mean - 1.0).abs() > 4.0 * isothermal.stderr,
        "omega/omega_isothermal = {} +- {}",
        isothermal.mean,
        isothermal.stderr
    );
    assert!(isothermal.mean > 1.2);
}

/// A piston of mass 30 gives up its excess within ~50 time units; averaged
/// over a long run its share of the kinetic energy is 1/N_free = 1/11.
#[test]
fn long_time_piston_share_is_equipartition() {
    let stats = ensemble(
        &descriptor(30.0, 20000.0, 12),
        &["piston_share", "relaxation_time"],
    );
    let share = &stats[0];
    let expected = 1.0 / 11.0;
    assert!(
        (share.mean - expected).abs() <= 4.0 * share.stderr,
        "share {} +- {} vs {expected}",
        share.mean,
        share.stderr
    );
    assert!(
        share.stderr < 0.02,
        "the test must be able to tell: stderr {}",
        share.stderr
    );
    assert_eq!(stats[1].n, 12, "every run relaxed");
}
