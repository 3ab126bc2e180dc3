//! Statistical regression tests of the expansion study (seeded; thresholds
//! are four standard errors of the ensemble, never tuned to one outcome).

use crate::study_common::{ensemble, stats};
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::stats::line::line;
use bonkers::stats::summary::Stats;
use bonkers::studies::expansion::{Draw, Gas};
use bonkers::theory::expansion::FreeExpansion;

const MAXWELL: &str = r#"{ kind = "maxwell", temperature = 1.0 }"#;

fn descriptor(count: usize, radius: f64, duration: f64, replicas: u32) -> String {
    with_velocities(count, radius, duration, replicas, MAXWELL, "")
}

/// A 2D expansion with the given velocity rule and any extra tables.
fn with_velocities(
    count: usize,
    radius: f64,
    duration: f64,
    replicas: u32,
    velocities: &str,
    extra: &str,
) -> String {
    format!(
        r#"
[study]
name = "expansion-test"
replicas = {replicas}
seed = 5

[scene]
dimension = 2
box = [40.0, 40.0]
velocities = {velocities}

[[scene.species]]
name = "gas"
count = {count}
radius = {radius}
region = {{ from = [0.0, 0.0], to = [0.5, 1.0] }}

[run]
duration = {duration}
sample_every = 0.5

[analysis.expansion]
{extra}
"#
    )
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
/// its relaxation time is the free one: Maxwellian velocities.
#[test]
fn dilute_expansion_is_collisionless() {
    let runs = ensemble(&descriptor(100, 0.01, 60.0, 24));
    collisionless(&runs, Draw::Maxwell(1.0));
}

/// The same with the Imperial start, momenta uniform in [-p_max, p_max].
#[test]
fn dilute_uniform_expansion_is_collisionless() {
    let uniform = r#"{ kind = "uniform", p = 1.5 }"#;
    let runs = ensemble(&with_velocities(100, 0.01, 60.0, 24, uniform, ""));
    collisionless(&runs, Draw::Uniform(1.5));
}

fn collisionless(runs: &[(RunSpec, RunOutput)], draw: Draw) {
    let gas = Gas::of_descriptor(&runs[0].0.descriptor).expect("scene");
    assert!(gas.knudsen() > 5.0, "Kn = {}", gas.knudsen());
    assert_eq!(
        bonkers::studies::expansion::draw(&runs[0].0.descriptor),
        Some(draw)
    );
    let free = gas.free(draw);
    for i in [10, 20, 30, 40, 60] {
        let (t, s) = at_sample(runs, i);
        let theory = free.left_fraction(t);
        eprintln!("t = {t}: {} +- {} against {theory}", s.mean, s.stderr);
        assert!(
            (s.mean - theory).abs() <= 4.0 * s.stderr,
            "t = {t}: left fraction {} +- {}, collisionless {theory}",
            s.mean,
            s.stderr
        );
    }
    let ratio = stats(runs, "relaxation_ratio");
    eprintln!("tau / tau_free = {} +- {}", ratio.mean, ratio.stderr);
    assert!((ratio.mean - 1.0).abs() <= 4.0 * ratio.stderr);
}

/// Hard particles have no energy scale, so the relaxation time is inverse
/// in p_max, dilute (collisionless) and dense (a fluid, Kn ~ 0.07) alike:
/// the weighted slope of ln tau against ln p_max is -1 within 4 of its
/// standard errors; dilute, each point's time is also the exact free one.
#[test]
fn relaxation_time_is_inverse_in_p_max() {
    let sweep = "[sweep.parameters]\n\"scene.velocities.p\" = [0.5, 1.0, 2.0]\n";
    let uniform = r#"{ kind = "uniform", p = 1.0 }"#;
    for (count, radius, replicas) in [(100, 0.01, 16), (200, 0.5, 12)] {
        let runs = ensemble(&with_velocities(
            count, radius, 160.0, replicas, uniform, sweep,
        ));
        let (mut x, mut y, mut w) = (Vec::new(), Vec::new(), Vec::new());
        for p in [0.5, 1.0, 2.0] {
            let at: Vec<(RunSpec, RunOutput)> = runs
                .iter()
                .filter(|(s, _)| s.params[0].1.as_float() == Some(p))
                .cloned()
                .collect();
            let tau = stats(&at, "relaxation_time");
            assert_eq!(tau.n, replicas as u64, "every run relaxes");
            eprintln!("N = {count}, p = {p}: tau = {} +- {}", tau.mean, tau.stderr);
            x.push(f64::ln(p));
            y.push(tau.mean.ln());
            w.push((tau.mean / tau.stderr).powi(2));
            if radius < 0.1 {
                let ratio = stats(&at, "relaxation_ratio");
                assert!((ratio.mean - 1.0).abs() <= 4.0 * ratio.stderr, "p = {p}");
            }
        }
        let (slope, se, _) = line(&x, &y, Some(&w));
        eprintln!("N = {count}, radius {radius}: tau ~ p^({slope} +- {se})");
        assert!((slope + 1.0).abs() <= 4.0 * se, "{slope} +- {se}");
    }
}

/// Disks of diameter 1 at 400 in the box (Kn ~ 0.04) are a fluid: the
/// ensemble tells them from free particles at the free relaxation time;
/// the split still settles at N/2, with the fluctuations of a hard-disk
/// fluid (S(0) from Henderson's equation of state), far below binomial.
#[test]
fn dense_split_reaches_half_with_fluid_fluctuations() {
    let runs = ensemble(&descriptor(400, 0.5, 600.0, 8));
    let gas = Gas::of_descriptor(&runs[0].0.descriptor).expect("scene");
    let free = gas.free(Draw::Maxwell(1.0));
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

/// `count` rods of radius `radius` expanding from the left half of a 1D
/// box of 40, the Imperial start with p_max = 1.
fn rods(count: usize, radius: f64, replicas: u32, seed: u64, duration: f64) -> String {
    format!(
        r#"
[study]
name = "expansion-rods"
replicas = {replicas}
seed = {seed}

[scene]
dimension = 1
box = [40.0]
velocities = {{ kind = "uniform", p = 1.0 }}

[[scene.species]]
name = "gas"
count = {count}
radius = {radius}
region = {{ from = [0.0], to = [0.5] }}

[run]
duration = {duration}
sample_every = 0.5

[analysis.expansion]
"#
    )
}

/// Equal point rods swap velocities when they meet, which is the same as
/// passing through: thousands of collisions, and the split is exactly the
/// collisionless one (1D, the Imperial start).
#[test]
fn point_rods_expand_as_if_free() {
    let text = rods(100, 0.0, 24, 3, 80.0);
    let runs = ensemble(&text);
    assert!(runs.iter().all(|(_, o)| o.collisions > 1000));
    let gas = Gas::of_descriptor(&runs[0].0.descriptor).expect("scene");
    let free = gas.free(Draw::Uniform(1.0));
    for i in [20, 40, 60, 100, 160] {
        let (t, s) = at_sample(&runs, i);
        let theory = free.left_fraction(t);
        eprintln!("t = {t}: {} +- {} against {theory}", s.mean, s.stderr);
        assert!((s.mean - theory).abs() <= 4.0 * s.stderr, "t = {t}");
    }
}

/// Ten rods of length 1: they collide but never pass, and their split is
/// Tonks' mapping of free points in the box less their length (exact).
#[test]
fn finite_rods_expand_as_their_mapped_points() {
    let text = rods(10, 0.5, 200, 4, 60.0);
    let runs = ensemble(&text);
    let gas = Gas::of_descriptor(&runs[0].0.descriptor).expect("scene");
    let rods = gas.free(Draw::Uniform(1.0));
    assert!(matches!(
        rods,
        bonkers::theory::expansion_rods::Collisionless::Rods(_)
    ));
    let points = bonkers::theory::expansion::FreeExpansion::with(
        40.0,
        0.5,
        bonkers::theory::expansion::Speeds::Uniform(1.0),
    );
    let mut apart = 0.0f64;
    for i in [10, 20, 30, 40, 60, 80, 120] {
        let (t, s) = at_sample(&runs, i);
        let theory = rods.left_fraction(t);
        eprintln!(
            "t = {t}: {} +- {} against rods {theory}, free disks {}",
            s.mean,
            s.stderr,
            points.left_fraction(t)
        );
        assert!((s.mean - theory).abs() <= 4.0 * s.stderr, "t = {t}");
        apart = apart.max((s.mean - points.left_fraction(t)).abs() / s.stderr);
    }
    // And the mapping matters: free particles of the same size are off.
    assert!(apart > 4.0, "{apart}");
}

/// `temperature_x` in a gas at rest filling its box: the slabs hold every
/// particle at every sample, and their kT about each slab's mean velocity,
/// pooled with weights n - 1, is the gas's kT (the Maxwellian's 1, within
/// 4 standard errors over the runs).
#[test]
fn slab_temperatures_of_a_gas_at_rest_are_its_temperature() {
    let extra = "[observe]\nseries = [\"temperature_x\"]\n";
    let text = with_velocities(200, 0.5, 40.0, 12, MAXWELL, extra)
        .replace("to = [0.5, 1.0]", "to = [1.0, 1.0]");
    let runs = ensemble(&text);
    let pooled: Vec<f64> = runs
        .iter()
        .map(|(_, o)| {
            let slab = |what: &str, b: usize| &o.series(&format!("{what}_x.{b}")).unwrap().value;
            let samples = slab("count", 0).len();
            let (mut weight, mut sum) = (0.0, 0.0);
            for i in 0..samples {
                let total: f64 = (0..16).map(|b| slab("count", b)[i]).sum();
                assert_eq!(total, 200.0, "every particle in a slab");
                for b in 0..16 {
                    let (c, kt) = (slab("count", b)[i], slab("temperature", b)[i]);
                    if kt.is_finite() {
                        weight += c - 1.0;
                        sum += (c - 1.0) * kt;
                    }
                }
            }
            sum / weight
        })
        .collect();
    let s = Stats::of(&pooled);
    eprintln!("pooled slab kT = {} +- {}", s.mean, s.stderr);
    assert!((s.mean - 1.0).abs() <= 4.0 * s.stderr);
}

/// The bundled study and its quick form plan; the collisionless theory
/// covers every run that starts in the left half (uniform and Maxwellian
/// starts, 1D, 2D, 3D); the movie
/// films the densest gas at p_max = 1.
#[test]
fn bundled_descriptor_plans() {
    use bonkers::descriptor::load::{parse, quick};
    use bonkers::runner::plan::plan;
    let text = std::fs::read_to_string("studies/expansion.toml").unwrap();
    let loaded = parse("studies/expansion.toml", &text).expect("valid");
    let fast = quick(&loaded).expect("quick");
    for (loaded, runs) in [(&loaded, 24 * 12 + 5 * 12 + 3 * 48 + 6), (&fast, 128)] {
        let planned = plan(loaded).expect("plan");
        assert_eq!(planned.len(), runs);
        // All but the case that fills the box to measure diffusion.
        for r in &planned {
            let tau = bonkers::studies::theory(&r.descriptor, "relaxation_time");
            let fills = r.case.as_deref() == Some("diffusion");
            assert_eq!(
                tau.is_some_and(|t| t > 0.0),
                !fills,
                "run {}: {tau:?}",
                r.run_id
            );
        }
        let movie = loaded.descriptor.observe.movie.as_ref().expect("movie").run;
        let filmed = &planned[movie as usize];
        let gas = Gas::of_descriptor(&filmed.descriptor).unwrap();
        assert_eq!(
            (gas.particles, gas.diameter),
            (if runs == 128 { 200 } else { 400 }, 1.0)
        );
        assert_eq!(
            bonkers::studies::expansion::draw(&filmed.descriptor),
            Some(Draw::Uniform(1.0))
        );
    }
}
