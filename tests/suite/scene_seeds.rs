//! The seeds' own claims, tested on their bundled scenes with seeded runs.

use crate::scene_stats::{P_MIN, block_mean, ks_p};
use bonkers::engine::{Disks, Observer, Rods, Snapshot, Stop};
use bonkers::model::scene::SceneSpec;
use bonkers::scene::{Built, build, resolve};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn built<const D: usize>(text: &str, seed: u64) -> Built<D> {
    let spec: SceneSpec = toml::from_str(text).expect("scene TOML");
    build::<D>(
        &resolve(&spec).unwrap(),
        &mut ChaCha8Rng::seed_from_u64(seed),
    )
    .unwrap()
}

/// Every particle's x and speed at each sample.
#[derive(Default)]
struct Record {
    x: Vec<Vec<f64>>,
    v: Vec<Vec<f64>>,
}

impl<const D: usize> Observer<D> for Record {
    fn sample(&mut self, s: &Snapshot<D>) {
        self.x
            .push((0..s.particles.len()).map(|i| s.position(i)[0]).collect());
        self.v.push(
            s.particles
                .iter()
                .map(|p| p.vel.iter().map(|c| c * c).sum::<f64>().sqrt())
                .collect(),
        );
    }
}

/// MacKay's ten particles (masses ~1 left, ~4 right): at equilibrium "the
/// standard deviations of v1 and v10 should be in the ratio 2:1, because the
/// mass ratio is 1:4", and "changing the particle masses ... has no effect at
/// all on their typical positions". With the total energy fixed, each
/// particle has <m v^2> = 2E/N, so sqrt(<v^2>_light / <v^2>_heavy) =
/// sqrt(sum 1/m light / sum 1/m heavy) (about 2 for these masses); and ten
/// point rods uniform in a box of 11 have mean positions 1, 2, ..., 10
/// whatever their masses. Both within 4 standard errors (jackknife and
/// block averages over 50 blocks of a long seeded run).
#[test]
fn mackay_ten_light_rods_move_twice_as_fast_and_sit_where_heavy_ones_would() {
    let b = built::<1>("preset = \"mackay-ten\"", 2026);
    let light: Vec<usize> = (0..10).filter(|&i| b.particles[i].species == 0).collect();
    let heavy: Vec<usize> = (0..10).filter(|&i| b.particles[i].species == 1).collect();
    assert_eq!((light.len(), heavy.len()), (5, 5));
    let inv = |g: &[usize]| g.iter().map(|&i| b.particles[i].inv_mass).sum::<f64>();
    let expected = (inv(&light) / inv(&heavy)).sqrt();
    assert!((expected - 2.0).abs() < 0.1, "masses ~1 and ~4: {expected}");

    let mut sim = Rods::new(b.particles, b.sim_box, Record::default(), 1).unwrap();
    sim.run(Stop::Time(1000.0));
    sim.sample_every(Some(2.0));
    sim.run(Stop::Time(1000.0 + 200_000.0));
    let rec = sim.into_observer();

    let blocks = 50;
    let size = rec.v.len() / blocks;
    let group = |g: &[usize], s: &Vec<f64>| g.iter().map(|&i| s[i] * s[i]).sum::<f64>();
    let sums: Vec<(f64, f64)> = (0..blocks)
        .map(|k| {
            rec.v[k * size..(k + 1) * size]
                .iter()
                .fold((0.0, 0.0), |(a, h), s| {
                    (a + group(&light, s), h + group(&heavy, s))
                })
        })
        .collect();
    let (ta, th) = sums.iter().fold((0.0, 0.0), |(a, h), s| (a + s.0, h + s.1));
    let ratio = (ta / th).sqrt();
    let leave_one_out: Vec<f64> = sums
        .iter()
        .map(|s| ((ta - s.0) / (th - s.1)).sqrt())
        .collect();
    let mean = leave_one_out.iter().sum::<f64>() / blocks as f64;
    let n = blocks as f64;
    let se = ((n - 1.0) / n
        * leave_one_out
            .iter()
            .map(|r| (r - mean).powi(2))
            .sum::<f64>())
    .sqrt();
    println!("mackay-ten: rms velocity ratio {ratio:.4} +- {se:.4}, expected {expected:.4}");
    assert!(
        (ratio - expected).abs() < 4.0 * se,
        "ratio {ratio} +- {se}, expected {expected}"
    );
    assert!(se < 0.02, "the run is long enough to tell: se {se}");

    for k in 0..10 {
        let xs: Vec<f64> = rec.x.iter().map(|s| s[k]).collect();
        let (m, se) = block_mean(&xs, blocks);
        let want = (k + 1) as f64;
        println!(
            "  rod {k} ({}): <x> = {m:.3} +- {se:.3}, expected {want}",
            if light.contains(&k) { "light" } else { "heavy" }
        );
        assert!(
            (m - want).abs() < 4.0 * se,
            "rod {k}: <x> = {m} +- {se}, expected {want}"
        );
    }
}

/// Imperial's 200 disks all start with velocity (0.5, 0.5); the speeds
/// relax to the 2D Maxwell (Rayleigh) law F(v) = 1 - exp(-m v^2 / 2kT) with
/// kT = E / N. Speeds from 20 snapshots about ten collision times apart
/// (KS; the same test rejects a 20% wrong temperature).
#[test]
fn imperial_200_speeds_relax_to_the_2d_maxwell_law() {
    let b = built::<2>("preset = \"imperial-200\"", 7);
    let kt = b.particles.iter().map(|p| p.kinetic_energy()).sum::<f64>() / b.particles.len() as f64;
    assert!((kt - 0.25).abs() < 1e-12);
    let mut sim = Disks::new(b.particles, b.sim_box, Record::default(), 1).unwrap();
    sim.run(Stop::Time(1000.0));
    sim.sample_every(Some(300.0));
    sim.run(Stop::Time(1000.0 + 19.5 * 300.0));
    let rec = sim.into_observer();
    assert_eq!(rec.v.len(), 20);
    let speeds: Vec<f64> = rec.v.concat();
    let rayleigh = |kt: f64| move |v: f64| 1.0 - (-v * v / (2.0 * kt)).exp();
    let p = ks_p(speeds.clone(), rayleigh(kt));
    println!("imperial-200: KS p = {p:.3} over {} speeds", speeds.len());
    assert!(p > P_MIN, "speeds are not Rayleigh: KS p = {p}");
    assert!(
        ks_p(speeds, rayleigh(1.2 * kt)) < P_MIN,
        "the test has power"
    );
}
