//! Statistical regression tests of the piston study (seeded; thresholds are
//! four standard errors of the ensemble, never tuned to one outcome).

use bonkers::analysis::piston_state::Geometry;
use bonkers::analysis::summary::Stats;
use bonkers::study::descriptor::parse;
use bonkers::study::output::RunOutput;
use bonkers::study::plan::plan;
use bonkers::study::plan_types::RunSpec;
use bonkers::theory::piston::{Law, PistonSystem};
use bonkers::theory::piston_equilibrium::oscillator_share;
use rand::SeedableRng;

/// Run every planned run of a descriptor.
fn ensemble(text: &str) -> Vec<(RunSpec, RunOutput)> {
    let loaded = parse("test.toml", text).expect("valid descriptor");
    plan(&loaded)
        .expect("plan")
        .into_iter()
        .map(|r| {
            let out = bonkers::simulate::run(&r).expect("run");
            (r, out)
        })
        .collect()
}

/// Statistics of one scalar (or of a function of the scalars) over the runs.
fn stats(runs: &[(RunSpec, RunOutput)], f: impl Fn(&RunOutput) -> Option<f64>) -> Stats {
    let v: Vec<f64> = runs
        .iter()
        .map(|(_, o)| f(o).unwrap_or(f64::NAN))
        .filter(|v| v.is_finite())
        .collect();
    Stats::of(&v)
}

fn scalar(name: &str) -> impl Fn(&RunOutput) -> Option<f64> + '_ {
    move |o| o.scalar(name)
}

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
    let adiabatic = stats(runs, scalar("frequency_ratio"));
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
/// adiabatic one within its error bar (the gases' inertia shifts it by
/// M_gas/6M ~ 0.02%, below the error bar), and is clearly not the
/// isothermal one.
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

/// The theory starts from the state after equilibration: after 500 time
/// units the piston is elsewhere in its swing, and the prediction made from
/// the first recorded sample still matches.
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
sample_every = 0.5

[analysis.piston]
"#;
    let runs = ensemble(text);
    let tonks = stats(&runs, scalar("frequency_ratio"));
    assert_eq!(tonks.n, 8);
    assert!(
        (tonks.mean - 1.0).abs() <= 4.0 * tonks.stderr,
        "omega/omega_Tonks = {} +- {}",
        tonks.mean,
        tonks.stderr
    );
    // The same starting state with the rods' length given back as free length.
    let points: Vec<f64> = runs
        .iter()
        .map(|(spec, out)| {
            let scene = bonkers::scene::resolve(&spec.descriptor.scene).expect("scene");
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(spec.seed);
            let built = bonkers::scene::build::<1>(&scene, &mut rng).expect("build");
            let g = Geometry::of(&built).expect("piston");
            let p = built.piston.expect("piston");
            let energy = |side: usize| -> f64 {
                built
                    .particles
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| (*i > p) as usize == side && *i != p)
                    .map(|(_, q)| q.kinetic_energy())
                    .sum()
            };
            let with_rods = g.system(
                built.particles[p].pos[0],
                built.particles[p].kinetic_energy(),
                energy(0),
                energy(1),
                1.0,
            );
            // This is the state the run's theory started from.
            let ad = out.scalar("omega_adiabatic").expect("omega");
            assert!((with_rods.omega(Law::Adiabatic) / ad - 1.0).abs() < 1e-9);
            let mut points = with_rods;
            points.left.free_volume += g.occupied[0];
            points.right.free_volume += g.occupied[1];
            out.scalar("frequency").expect("frequency")
                / PistonSystem::omega(&points, Law::Adiabatic)
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
    let share = stats(&runs, scalar("piston_share"));
    let expected = 1.0 / 11.0;
    assert!(
        (share.mean - expected).abs() <= 4.0 * share.stderr,
        "share {} +- {} vs {expected}",
        share.mean,
        share.stderr
    );
    assert!(
        4.0 * share.stderr < expected,
        "the test must be able to tell: stderr {}",
        share.stderr
    );
    let oscillator = stats(&runs, scalar("oscillator_share"));
    let (theory, theory_se) = oscillator_share(1, 5, 5, bonkers::analysis::piston::DRAWS);
    eprintln!(
        "piston share {} +- {} (1/11); oscillator share {} +- {} ({theory} +- {theory_se})",
        share.mean, share.stderr, oscillator.mean, oscillator.stderr
    );
    let se = oscillator.stderr.hypot(theory_se);
    assert!(
        (oscillator.mean - theory).abs() <= 4.0 * se,
        "oscillator share {} +- {} vs {theory} +- {theory_se}",
        oscillator.mean,
        oscillator.stderr
    );
    assert_eq!(
        stats(&runs, scalar("relaxation_time")).n,
        12,
        "every run relaxed"
    );
}
