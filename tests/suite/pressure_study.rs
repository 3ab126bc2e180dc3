//! Statistical regression tests of the pressure study (seeded; thresholds
//! are four standard errors over independent replicas, never tuned to one
//! outcome), and the equations of state at known values.

use bonkers::descriptor::load::parse;
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::runner::plan::plan;
use bonkers::stats::summary::Stats;
use bonkers::theory::{
    carnahan_starling, carnahan_starling_kolafa, disk_virial, hansen_goos, henderson,
    kolafa_rottner, sphere_virial, tonks,
};

/// Every planned run of a descriptor.
fn ensemble(text: &str) -> Vec<(RunSpec, RunOutput)> {
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

fn stats(runs: &[(RunSpec, RunOutput)], name: &str) -> Stats {
    let v: Vec<f64> = runs.iter().filter_map(|(_, o)| o.scalar(name)).collect();
    assert_eq!(v.len(), runs.len(), "every run gives {name}");
    Stats::of(&v)
}

/// `|Z - theory| <= 4 standard errors`, with the numbers in the message.
fn assert_matches(z: &Stats, theory: f64, what: &str) {
    eprintln!(
        "{what}: Z = {} +- {} (n = {}), theory {theory}",
        z.mean, z.stderr, z.n
    );
    assert!(
        (z.mean - theory).abs() <= 4.0 * z.stderr,
        "{what}: Z = {} +- {} against {theory}",
        z.mean,
        z.stderr
    );
}

/// `count` rods of diameter 1 between walls `length` apart.
fn rods(count: usize, length: f64, duration: f64) -> String {
    format!(
        r#"
[study]
name = "pressure-rods"
replicas = 8
seed = 31

[scene]
box = [{length}]
velocities = {{ kind = "maxwell", temperature = 1.0 }}
[[scene.species]]
name = "gas"
count = {count}

[run]
duration = {duration}

[observe]
scalars = ["wall_pressure"]

[analysis.pressure]
"#
    )
}

/// Tonks' Z = 1/(1 - eta) is exact for rods between walls at any N, with
/// eta = N sigma / L: checked at three densities, with few and many rods.
#[test]
fn rods_match_tonks() {
    for (count, length, duration) in [
        (20, 100.0, 20_000.0),
        (50, 100.0, 5_000.0),
        (40, 50.0, 5_000.0),
    ] {
        let runs = ensemble(&rods(count, length, duration));
        let eta = stats(&runs, "packing_fraction").mean;
        assert!((eta - count as f64 / length).abs() < 1e-12);
        let z = stats(&runs, "Z");
        assert!(z.stderr < 0.02 * z.mean, "resolved to 2 %: {z:?}");
        assert_matches(&z, tonks::z(eta), &format!("{count} rods at eta = {eta}"));
        // The summary's theory is Tonks' at the descriptor's packing.
        let theory = bonkers::studies::theory(&runs[0].0.descriptor, "Z").unwrap();
        assert!((theory - tonks::z(eta)).abs() < 1e-12);
    }
}

/// `count` balls in a periodic box (`d` = 2 or 3) at packing fraction
/// `eta`, recording the virial pressure series.
fn balls(d: usize, count: usize, eta: f64, duration: f64, seed: u64) -> String {
    balls_n(d, count, eta, duration, seed, 8)
}

/// `balls` with `replicas` runs.
fn balls_n(d: usize, count: usize, eta: f64, duration: f64, seed: u64, replicas: u32) -> String {
    let v = if d == 2 {
        std::f64::consts::PI / 4.0
    } else {
        std::f64::consts::PI / 6.0
    };
    let length = (count as f64 * v / eta).powf(1.0 / d as f64);
    let lengths = vec![length.to_string(); d].join(", ");
    let periodic = vec!["\"periodic\""; d].join(", ");
    format!(
        r#"
[study]
name = "pressure-balls"
replicas = {replicas}
seed = {seed}

[scene]
box = [{lengths}]
boundary = [{periodic}]
velocities = {{ kind = "maxwell", temperature = 1.0, zero_momentum = true }}
[[scene.species]]
name = "gas"
count = {count}

[run]
equilibrate = 20.0
duration = {duration}
sample_every = 0.5

[observe]
series = ["virial_pressure"]

[analysis.pressure]
"#
    )
}

/// Z(N) = Z + b/N through two sizes: the extrapolated Z with its error.
fn extrapolate(small: (usize, &Stats), large: (usize, &Stats)) -> Stats {
    let (x1, x2) = (1.0 / small.0 as f64, 1.0 / large.0 as f64);
    let mean = (x1 * large.1.mean - x2 * small.1.mean) / (x1 - x2);
    let stderr = (x1 * large.1.stderr).hypot(x2 * small.1.stderr) / (x1 - x2);
    eprintln!(
        "Z({}) = {} +- {}, Z({}) = {} +- {} -> Z = {mean} +- {stderr}",
        small.0, small.1.mean, small.1.stderr, large.0, large.1.mean, large.1.stderr
    );
    Stats {
        mean,
        stderr,
        ..*large.1
    }
}

/// Disks at packing fraction 0.3 in periodic squares: Z from the collision
/// virial with 64 and 1024 disks, extrapolated linearly in 1/N (a finite
/// box lowers Z by ~0.7/N here), matches the virial series through B10
/// with its tail, and Henderson's equation (they differ by 2.5e-4), within
/// four standard errors.
///
/// The 2e-4 precision bound (4.1e-4 in Z) sits below the finite-size
/// correction the extrapolation removes at 1024 disks (0.7/1024 = 6.8e-4),
/// so the extrapolated Z is resolved beyond it. The error model
/// (`studies/pressure/error.rs`, sigma_Z per run = c sqrt(4 (Z - 1) /
/// (sqrt(pi) d N T))) gives per run 7.7e-4 c (1024 disks, 2000 time units)
/// and 3.1e-3 c (64 disks); over 16 runs each, weighted 16/15 and 1/15 by
/// the extrapolation, an expected SE of 2.1e-4 c: the bound is 2.0x above
/// it at c = 1, 1.8x at the c = 1.07 two seeds gave at 1800 time units
/// (SE 2.0e-4 and 2.6e-4; this seed at 2000: 2.2e-4). The former 8 runs of
/// 1500 expected 3.4e-4, only 1.2x under the bound, and an 8-run SE itself
/// scatters by ~27 %.
#[test]
fn disks_match_the_virial_series_at_moderate_density() {
    let eta: f64 = 0.3;
    let small = ensemble(&balls_n(2, 64, eta, 2000.0, 37, 16));
    let large = ensemble(&balls_n(2, 1024, eta, 2000.0, 37, 16));
    for runs in [&small, &large] {
        assert!((stats(runs, "packing_fraction").mean - eta).abs() < 1e-12);
    }
    let z = extrapolate((64, &stats(&small, "Z")), (1024, &stats(&large, "Z")));
    assert!(z.stderr < 2e-4 * z.mean, "resolved to 2e-4: {z:?}");
    assert_matches(
        &z,
        disk_virial::resummed(eta),
        "disks extrapolated, virial series",
    );
    assert_matches(&z, henderson::z(eta), "disks extrapolated, Henderson");
    assert_matches(
        &z,
        kolafa_rottner::z(eta),
        "disks extrapolated, Kolafa-Rottner",
    );
    // Far from the ideal gas: the excess pressure is resolved.
    assert!(z.mean - 1.0 > 1000.0 * z.stderr);
}

/// Dense disks, packing fraction 0.6, compressed to it: Z extrapolated from
/// 256 and 1024 disks matches Kolafa and Rottner's equation within four
/// standard errors, and not the virial series through B10 with its tail,
/// which is 0.2 % (0.013) high there.
///
/// Power: the full study's 256 disks at 0.6 (16 runs of 1500 time units)
/// gave a standard error of 0.0011; 16 runs of 1000 give ~0.0013 at 256 and
/// ~0.00065 at 1024, so ~0.001 extrapolated (weights 4/3 and 1/3): the
/// series is expected ~13 standard errors away, asserted at more than 5.
#[test]
fn dense_disks_match_kolafa_rottner_not_the_virial_series() {
    let eta: f64 = 0.6;
    let dense = |count| {
        balls_n(2, count, eta, 1000.0, 41, 16)
            .replace("equilibrate = 20.0", "equilibrate = 100.0")
            .replace(
                "[[scene.species]]",
                "placement = { kind = \"compress\" }\n[[scene.species]]",
            )
    };
    let small = ensemble(&dense(256));
    let large = ensemble(&dense(1024));
    let z = extrapolate((256, &stats(&small, "Z")), (1024, &stats(&large, "Z")));
    assert!(z.stderr < 2e-3, "{z:?}");
    assert_matches(&z, kolafa_rottner::z(eta), "dense disks, Kolafa-Rottner");
    let series = disk_virial::resummed(eta);
    assert!(
        series - z.mean > 5.0 * z.stderr,
        "{z:?} against the series {series}"
    );
}

/// Spheres at packing fraction 0.3, extrapolated in 1/N from 128 and 1024
/// (a finite box lowers Z by ~1.1/N here): Hansen-Goos's equation, the
/// resummed virial series and Carnahan-Starling-Kolafa (all within 1e-4 of
/// each other here) hold within four standard errors, and Carnahan-
/// Starling, 0.25 % lower, is excluded by more than three: the data prefer
/// the accurate equation.
///
/// Sized so that exclusion is a sure detection: Hansen-Goos minus
/// Carnahan-Starling is 0.0101. The error model (`studies/pressure/
/// error.rs`, c ~ 1 for spheres at 0.3) gives per run sigma_Z = 2.3e-3 for
/// 1024 spheres over 400 time units and 7.6e-3 for 128 over 300; 8 runs
/// each, weighted 8/7 and 1/7 by the extrapolation, expect SE 1.0e-3 c, so
/// z ~ 10 / c against Carnahan-Starling: this seed gave 3.9830 ± 0.0009 (z
/// = 10.9), seed 42 3.9849 ± 0.0014 (z = 7.7); pooled, c ~ 1.2, z ~ 8.
/// The former 128 and 512 over 300 expected SE 2.0e-3 (z ~ 5; measured
/// 2.6e-3, z = 2.1): a sizes ratio of 8 instead of 4 also amplifies the
/// large box's error less (8/7 instead of 4/3).
#[test]
fn spheres_match_hansen_goos_not_carnahan_starling() {
    let eta: f64 = 0.3;
    let small = ensemble(&balls_n(3, 128, eta, 300.0, 41, 8));
    let large = ensemble(&balls_n(3, 1024, eta, 400.0, 41, 8));
    let z = extrapolate((128, &stats(&small, "Z")), (1024, &stats(&large, "Z")));
    assert_matches(&z, hansen_goos::z(eta), "spheres, Hansen-Goos");
    assert_matches(&z, sphere_virial::resummed(eta), "spheres, virial series");
    assert_matches(&z, carnahan_starling_kolafa::z(eta), "spheres, CSK");
    let cs = carnahan_starling::z(eta);
    let hg = hansen_goos::z(eta);
    assert!(
        (z.mean - cs) / z.stderr > 3.0,
        "Carnahan-Starling {cs} not excluded: {z:?}"
    );
    assert!((z.mean - hg).abs() < (z.mean - cs).abs());
}

/// In a box with walls the wall pressure and the collision virial (with the
/// walls' own virial term) are the same pressure: run by run they agree
/// within four standard errors of their difference, to 1e-3.
#[test]
fn wall_and_virial_pressure_agree() {
    let text = balls(2, 256, 0.3, 500.0, 43)
        .replace("\"periodic\", \"periodic\"", "\"walls\", \"walls\"")
        .replace(
            "series = [\"virial_pressure\"]",
            "series = [\"wall_pressure\", \"virial_pressure\"]",
        );
    assert!(text.contains("boundary = [\"walls\", \"walls\"]"));
    let runs = ensemble(&text);
    let diff: Vec<f64> = runs
        .iter()
        .map(|(_, o)| o.scalar("Z_wall").unwrap() - o.scalar("Z_virial").unwrap())
        .collect();
    let d = Stats::of(&diff);
    let wall = stats(&runs, "Z_wall");
    eprintln!(
        "Z_wall = {} +- {}, wall - virial = {} +- {}",
        wall.mean, wall.stderr, d.mean, d.stderr
    );
    assert!(d.mean.abs() <= 4.0 * d.stderr, "{d:?}");
    assert!(d.stderr < 1e-3 * wall.mean && d.mean.abs() < 1e-3 * wall.mean);
    // Z is the wall's; the walls' surface term puts it well above the bulk.
    assert_eq!(stats(&runs, "Z").mean, wall.mean);
    assert!(wall.mean > disk_virial::resummed(0.3) + 50.0 * wall.stderr);
}

/// The equations of state at values computed by hand from their formulas.
#[test]
fn equations_at_known_values() {
    assert!((tonks::z(0.75) - 4.0).abs() < 1e-12);
    assert!((henderson::z(0.5) - 4.125).abs() < 1e-12);
    // 1 + 2 eta + 3.128018 eta^2 + 4.257854 eta^3 + ... at eta = 0.1.
    assert!((disk_virial::z(0.1, 10) - 1.236_143_6).abs() < 1e-7);
    assert!((carnahan_starling::z(0.3) - 1.363 / 0.343).abs() < 1e-12);
    assert!((carnahan_starling_kolafa::z(0.3) - (1.39 - 0.0234) / 0.343).abs() < 1e-12);
    // The sphere equations give B2 = 4 eta and B3 = 10 eta^2 exactly.
    for z in [
        carnahan_starling::z,
        carnahan_starling_kolafa::z,
        hansen_goos::z,
    ] {
        let h: f64 = 1e-3;
        assert!(((z(h) - 1.0 - 4.0 * h) / (h * h) - 10.0).abs() < 0.05);
    }
}

/// Equal rods between walls: the scatter of Z over 64 replicas is what the
/// wall-hit phase model (each run's `Z_run_stderr`) predicts, within four
/// standard errors of a standard deviation from 64 samples (1/sqrt(126)),
/// and the block error, which assumes a 1/sqrt(T) convergence, is several
/// times too large.
#[test]
fn rods_scatter_as_the_wall_hit_model_says() {
    let text = rods(100, 500.0, 2000.0)
        .replace("replicas = 8", "replicas = 64")
        .replace(
            "scalars = [\"wall_pressure\"]",
            "series = [\"wall_pressure\"]",
        )
        .replace("duration = 2000", "duration = 2000\nsample_every = 2.0");
    assert!(text.contains("series = [\"wall_pressure\"]") && text.contains("sample_every"));
    let runs = ensemble(&text);
    let z = stats(&runs, "Z");
    let model = stats(&runs, "Z_run_stderr").mean;
    let blocks = stats(&runs, "Z_block_stderr").mean;
    let ratio = z.std / model;
    eprintln!(
        "rods: Z sd {} over 64, model {model}, blocks {blocks}",
        z.std
    );
    assert!((ratio - 1.0).abs() < 4.0 / 126f64.sqrt(), "{ratio}");
    assert!(blocks > 3.0 * z.std, "{blocks} against {}", z.std);
    assert_matches(&z, tonks::z(0.2), "100 rods at eta = 0.2");
}

/// The bundled studies and their quick forms are valid, and every point but
/// the walled disks (no bulk equation) has an equation of state in the
/// summary; the loop study's points are all dense disks (no fluid equation
/// holds there, but the summary still shows the virial series' value).
#[test]
fn bundled_descriptor_plans() {
    let text = std::fs::read_to_string("studies/pressure-loop.toml").unwrap();
    let loaded = parse("studies/pressure-loop.toml", &text).expect("valid");
    let quick = bonkers::descriptor::load::quick(&loaded).expect("quick");
    for (loaded, runs) in [(&loaded, 128), (&quick, 6)] {
        let planned = plan(loaded).expect("plan");
        assert_eq!(planned.len(), runs);
        for r in &planned {
            let scene = bonkers::scene::resolve(&r.descriptor.scene).unwrap();
            let eta = bonkers::studies::pressure::described_packing(&scene).unwrap();
            assert!((0.69 - 1e-9..=0.73 + 1e-9).contains(&eta), "{eta}");
            assert_eq!(scene.species[0].count, 1024);
        }
    }
    let text = std::fs::read_to_string("studies/pressure.toml").unwrap();
    let loaded = parse("studies/pressure.toml", &text).expect("valid");
    let quick = bonkers::descriptor::load::quick(&loaded).expect("quick");
    for (loaded, runs, walled) in [(&loaded, 384, 16), (&quick, 40, 4)] {
        let planned = plan(loaded).expect("plan");
        assert_eq!(planned.len(), runs);
        let without: Vec<_> = planned
            .iter()
            .filter(|r| bonkers::studies::theory(&r.descriptor, "Z").is_none())
            .collect();
        assert_eq!(without.len(), walled);
        for r in &planned {
            if let Some(theory) = bonkers::studies::theory(&r.descriptor, "Z") {
                assert!(theory > 1.0 && theory < 30.0, "{theory}");
            }
        }
    }
}
