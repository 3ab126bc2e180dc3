//! Statistical regression tests of the piston study (seeded; thresholds are
//! four standard errors of the ensemble, never tuned to one outcome).

use crate::piston_common::{
    assert_equipartition, ensemble, geometry, measure_with, result, scalar, stats,
};
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::stats::summary::Stats;

fn descriptor(mass: f64, duration: f64, replicas: u32, equilibrate: f64) -> String {
    format!(
        r#"
[study]
name = "piston-test"
replicas = {replicas}
seed = 99

[scene]
preset = "mackay-piston"
velocities = {{ kind = "maxwell", temperature = 1.0 }}
piston = {{ mass = {mass}, position = 0.5, radius = 0.0, energy = 10.0 }}

[run]
duration = {duration}
equilibrate = {equilibrate}
sample_every = 0.5

[analysis.piston]
"#
    )
}

/// Measured over predicted frequency is 1 within 4 standard errors, and the
/// ensemble can tell: the isothermal prediction differs from the adiabatic
/// one by more than 4 standard errors.
fn assert_adiabatic(runs: &[(RunSpec, RunOutput)]) {
    let adiabatic = stats(runs, scalar("frequency_ratio_inertia"));
    let separation = stats(runs, |o| {
        Some(o.scalar("omega_adiabatic")? / o.scalar("omega_isothermal")?)
    });
    eprintln!(
        "omega/omega_ad = {} +- {} (n = {}); omega_ad/omega_iso = {}",
        adiabatic.mean, adiabatic.stderr, adiabatic.n, separation.mean
    );
    assert_eq!(
        adiabatic.n as usize,
        runs.len(),
        "every run measured a frequency"
    );
    assert!(
        (adiabatic.mean - 1.0).abs() <= 4.0 * adiabatic.stderr,
        "omega/omega_adiabatic = {} +- {}",
        adiabatic.mean,
        adiabatic.stderr
    );
    assert!(
        4.0 * adiabatic.stderr < (separation.mean - 1.0).abs(),
        "the error bar {} cannot tell adiabatic from isothermal (omega_ad/omega_iso = {})",
        adiabatic.stderr,
        separation.mean
    );
}

/// A heavy piston (M = 10^4, M/M_gas ~ 800) moves slowly enough for each gas
/// to follow its adiabat: the measured frequency matches the nonlinear
/// adiabatic one, at the amplitude of each measured period, within its
/// error bar (0.005%), and is clearly not the isothermal one. That error bar
/// resolves the gases' inertia, which lowers the frequency by M_gas/6M ~
/// 0.02%: the prediction carries it (M + M_gas/3).
#[test]
fn heavy_piston_oscillates_at_the_adiabatic_frequency() {
    let runs = ensemble(&descriptor(10_000.0, 4000.0, 10, 0.0));
    assert_adiabatic(&runs);
    let isothermal = stats(&runs, scalar("frequency_ratio_isothermal"));
    eprintln!(
        "omega/omega_iso = {} +- {}",
        isothermal.mean, isothermal.stderr
    );
    assert!(
        (isothermal.mean - 1.0).abs() > 4.0 * isothermal.stderr,
        "omega/omega_isothermal = {} +- {}",
        isothermal.mean,
        isothermal.stderr
    );
}

/// The theory follows the runs as recorded, after equilibration: after 500
/// time units the piston is elsewhere in its swing, and the prediction made
/// from the recorded samples still matches.
#[test]
fn theory_starts_after_equilibration() {
    let runs = ensemble(&descriptor(10_000.0, 4000.0, 8, 500.0));
    assert_adiabatic(&runs);
}

/// Rods of diameter 1 take 5 of each side's 12 units: the gases follow the
/// Tonks adiabat P (X - N sigma)^3 = const. The measured frequency matches
/// the prediction with the excluded length, and the ensemble rejects the
/// point-particle prediction that ignores it (by more than 4 standard errors).
#[test]
fn rods_with_diameter_follow_the_tonks_adiabat() {
    let text = r#"
[study]
name = "tonks-piston"
replicas = 8
seed = 7

[scene]
dimension = 1
box = [24.0]
boundary = ["walls"]
species = [
  { name = "left", count = 5, mass = [0.9, 1.1], radius = 0.5, region = { from = [0.0], to = [0.5] } },
  { name = "right", count = 5, mass = [1.5, 1.7], radius = 0.5, region = { from = [0.5], to = [1.0] } },
]
placement = { kind = "lattice" }
velocities = { kind = "maxwell", temperature = 1.0 }
piston = { mass = 10000.0, position = 0.5, radius = 0.5, energy = 10.0 }

[run]
duration = 4000.0
# At most 4000 samples, so the stored series hold every one (see below).
sample_every = 2.0

[analysis.piston]
"#;
    let runs = ensemble(text);
    let tonks = stats(&runs, scalar("frequency_ratio_inertia"));
    assert_eq!(tonks.n, 8);
    assert!(
        (tonks.mean - 1.0).abs() <= 4.0 * tonks.stderr,
        "omega/omega_Tonks = {} +- {}",
        tonks.mean,
        tonks.stderr
    );
    // The same runs measured again with the rods' length given back as
    // free length: the point-particle prediction.
    let points: Vec<f64> = runs
        .iter()
        .map(|(spec, out)| {
            let mut g = geometry::<1>(spec);
            // Measured again with the run's own geometry, the run's result.
            let again = measure_with(spec, out, &g);
            let ratio = out.scalar("frequency_ratio_inertia").expect("ratio");
            assert!((result(&again, "frequency_ratio_inertia") / ratio - 1.0).abs() < 1e-12);
            for room in &mut g.rooms {
                (room.radius, room.excluded) = (0.0, 0.0);
            }
            result(&measure_with(spec, out, &g), "frequency_ratio_inertia")
        })
        .collect();
    let point = Stats::of(&points);
    eprintln!(
        "omega/omega_Tonks = {} +- {}; omega/omega_point = {} +- {}",
        tonks.mean, tonks.stderr, point.mean, point.stderr
    );
    assert!(
        (point.mean - 1.0).abs() > 4.0 * point.stderr.max(tonks.stderr),
        "ignoring the rods' length gives omega/omega_point = {} +- {}",
        point.mean,
        point.stderr
    );
}

/// A piston of mass 30 gives up its excess within ~100 time units; averaged
/// over a long run its share of the kinetic energy is 1/N_free = 1/11, and
/// its oscillator energy the microcanonical mean the relaxation time is
/// measured against.
#[test]
fn long_time_piston_share_is_equipartition() {
    let runs = ensemble(&descriptor(30.0, 20000.0, 12, 0.0));
    assert_eq!(runs.len(), 12);
    assert_equipartition(&runs, 1, 5, 1.0 / 11.0);
}
