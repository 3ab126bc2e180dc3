//! Statistical regression tests of the pressure study (seeded; thresholds
//! are four standard errors over independent replicas, never tuned to one
//! outcome), and the equations of state at known values.

use bonkers::descriptor::load::parse;
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::runner::plan::plan;
use bonkers::stats::summary::Stats;
use bonkers::theory::{carnahan_starling, disk_virial, henderson, kolafa_labik_malijevsky, tonks};

/// Every planned run of a descriptor.
fn ensemble(text: &str) -> Vec<(RunSpec, RunOutput)> {
    let loaded = parse("test.toml", text).expect("valid descriptor");
    plan(&loaded)
        .expect("plan")
        .into_iter()
        .map(|r| {
            let out = bonkers::runner::simulate::run(&r).expect("run");
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

/// `count` disks in a periodic square at packing fraction `eta`.
fn disks(count: usize, eta: f64, duration: f64) -> String {
    let length = (count as f64 * std::f64::consts::PI / 4.0 / eta).sqrt();
    format!(
        r#"
[study]
name = "pressure-disks"
replicas = 8
seed = 37

[scene]
box = [{length}, {length}]
boundary = ["periodic", "periodic"]
velocities = {{ kind = "maxwell", temperature = 1.0, zero_momentum = true }}
[[scene.species]]
name = "gas"
count = {count}

[run]
equilibrate = 20.0
duration = {duration}
sample_every = 1.0

[observe]
scalars = ["virial_pressure"]

[analysis.pressure]
"#
    )
}

/// Disks at packing fraction 0.3 in periodic squares: Z from the collision
/// virial, extrapolated linearly in 1/N from 64 and 256 disks (a finite box
/// lowers Z by ~0.7/N here), matches Henderson's equation and the virial
/// series to B10 (which agree to 3e-4) within four standard errors.
#[test]
fn disks_match_henderson_at_moderate_density() {
    let eta: f64 = 0.3;
    let small = ensemble(&disks(64, eta, 4000.0));
    let large = ensemble(&disks(256, eta, 1000.0));
    for runs in [&small, &large] {
        assert!((stats(runs, "packing_fraction").mean - eta).abs() < 1e-12);
    }
    let (z64, z256) = (stats(&small, "Z"), stats(&large, "Z"));
    eprintln!(
        "Z(64) = {} +- {}, Z(256) = {} +- {}",
        z64.mean, z64.stderr, z256.mean, z256.stderr
    );
    // Z(N) = Z + c/N through both points.
    let mean = (4.0 * z256.mean - z64.mean) / 3.0;
    let stderr = (16.0 * z256.stderr.powi(2) + z64.stderr.powi(2)).sqrt() / 3.0;
    let z = Stats {
        mean,
        stderr,
        ..z256
    };
    assert!(z.stderr < 1e-3 * z.mean, "resolved to 0.1 %: {z:?}");
    assert_matches(&z, henderson::z(eta), "disks extrapolated, Henderson");
    assert_matches(
        &z,
        disk_virial::z(eta, 10),
        "disks extrapolated, virial series",
    );
    // Far from the ideal gas: the excess pressure is resolved.
    assert!(z.mean - 1.0 > 100.0 * z.stderr);
}

/// The equations of state at values computed by hand from their formulas.
#[test]
fn equations_at_known_values() {
    assert!((tonks::z(0.75) - 4.0).abs() < 1e-12);
    assert!((henderson::z(0.5) - 4.125).abs() < 1e-12);
    // 1 + 2 eta + 3.128018 eta^2 + 4.257854 eta^3 + ... at eta = 0.1.
    assert!((disk_virial::z(0.1, 10) - 1.236_143_6).abs() < 1e-7);
    assert!((carnahan_starling::z(0.3) - 1.363 / 0.343).abs() < 1e-12);
    assert!((kolafa_labik_malijevsky::z(0.3) - (1.39 - 0.0234) / 0.343).abs() < 1e-12);
    // Both sphere equations give B2 = 4 eta and B3 = 10 eta^2 exactly.
    for z in [carnahan_starling::z, kolafa_labik_malijevsky::z] {
        let h: f64 = 1e-3;
        assert!(((z(h) - 1.0 - 4.0 * h) / (h * h) - 10.0).abs() < 0.05);
    }
}

/// The bundled study and its quick form are valid, and every point has an
/// equation of state in the summary.
#[test]
fn bundled_descriptor_plans() {
    let text = std::fs::read_to_string("studies/pressure.toml").unwrap();
    let loaded = parse("studies/pressure.toml", &text).expect("valid");
    let runs = plan(&loaded).expect("plan");
    assert_eq!(runs.len(), 72);
    for r in &runs {
        let theory = bonkers::studies::theory(&r.descriptor, "Z").expect("theory");
        assert!(theory > 1.0 && theory < 6.0, "{theory}");
    }
}
