//! Thermal walls: the emission law (KS tests against the flux-weighted
//! Maxwellian), and a gas between them reaching the wall temperature.

use crate::common;

use bonkers::engine::thermal::emit;
use bonkers::engine::{Axis, Disks, Observer, Particle, SimBox, Simulation, Snapshot, Stop, Wall};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use statrs::distribution::{ContinuousCDF, Normal};

/// Kolmogorov–Smirnov distance between a sample and a CDF.
fn ks(mut xs: Vec<f64>, cdf: impl Fn(f64) -> f64) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len() as f64;
    xs.iter()
        .enumerate()
        .map(|(i, &x)| {
            let f = cdf(x);
            (f - i as f64 / n).abs().max((f - (i + 1) as f64 / n).abs())
        })
        .fold(0.0, f64::max)
}

/// The normal speed leaving a wall at temperature T has the flux-weighted
/// (Rayleigh) law F(v) = 1 - exp(-m v^2 / 2kT), not the Gaussian's; each
/// tangential component is Gaussian with variance kT/m. Critical KS distance
/// at significance 0.001: 1.95 / sqrt(n).
#[test]
fn emitted_velocities_follow_the_flux_weighted_maxwellian() {
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let (kt, mass, n) = (1.5, 2.0, 20_000);
    let draws: Vec<[f64; 3]> = (0..n)
        .map(|_| emit::<3>(&mut rng, kt, 1.0 / mass, 1, -1.0))
        .collect();
    let critical = 1.95 / (n as f64).sqrt();
    assert!(draws.iter().all(|v| v[1] <= 0.0), "always into the box");
    let normal: Vec<f64> = draws.iter().map(|v| -v[1]).collect();
    let d = ks(normal.clone(), |v| 1.0 - (-mass * v * v / (2.0 * kt)).exp());
    assert!(d < critical, "normal speeds: KS {d} >= {critical}");
    // A plain Gaussian speed law is rejected by the same test.
    let half_gauss = Normal::new(0.0, (kt / mass).sqrt()).unwrap();
    let d_wrong = ks(normal, |v| 2.0 * half_gauss.cdf(v) - 1.0);
    assert!(
        d_wrong > 10.0 * critical,
        "the test can tell the laws apart: {d_wrong}"
    );
    for k in [0, 2] {
        let d = ks(draws.iter().map(|v| v[k]).collect(), |v| half_gauss.cdf(v));
        assert!(d < critical, "tangential axis {k}: KS {d} >= {critical}");
    }
}

struct Kinetic(Vec<f64>);
impl Observer<2> for Kinetic {
    fn sample(&mut self, s: &Snapshot<2>) {
        self.0.push(s.kinetic_energy());
    }
}

/// Disks between two walls at kT = 2 (starting at kT = 0.5) reach kT = 2:
/// the mean of 20 block averages is within 4 standard errors of it.
#[test]
fn a_gas_between_thermal_walls_reaches_the_wall_temperature() {
    let mut rng = common::rng(12);
    let mut particles = Vec::new();
    for i in 0..10 {
        for j in 0..10 {
            let vel = [
                0.5f64.sqrt() * common::gaussian(&mut rng),
                0.5f64.sqrt() * common::gaussian(&mut rng),
            ];
            particles.push(Particle::new(
                [1.5 + 3.0 * i as f64, 1.5 + 3.0 * j as f64],
                vel,
                1.0,
                0.5,
            ));
        }
    }
    let hot = Wall::Thermal { temperature: 2.0 };
    let sim_box = SimBox {
        size: [30.0, 30.0],
        axes: [
            Axis::Walls {
                low: hot,
                high: hot,
            },
            Axis::HARD,
        ],
    };
    let mut sim: Disks<Kinetic> =
        Simulation::new(particles, sim_box, Kinetic(Vec::new()), 3).unwrap();
    sim.run(Stop::Time(300.0));
    sim.observer.0.clear();
    sim.sample_every(Some(1.0));
    sim.run(Stop::Time(300.0 + 4000.0));
    let temps: Vec<f64> = sim.observer.0.iter().map(|k| k / 100.0).collect(); // 2K / (d N), d N = 200
    let blocks: Vec<f64> = temps
        .chunks(200)
        .map(|c| c.iter().sum::<f64>() / c.len() as f64)
        .collect();
    let n = blocks.len() as f64;
    let mean = blocks.iter().sum::<f64>() / n;
    let se = (blocks.iter().map(|b| (b - mean).powi(2)).sum::<f64>() / (n - 1.0) / n).sqrt();
    assert!(
        (mean - 2.0).abs() < 4.0 * se,
        "kT = {mean} +- {se}, walls at 2"
    );
    assert!(se < 0.05, "error bar small enough to mean something: {se}");
}
