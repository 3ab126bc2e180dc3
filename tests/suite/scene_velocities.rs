//! Initial velocities: the Maxwellian draw (KS), equal and explicit kinds,
//! radii drawn from a range, and the piston as a particle (its energy in
//! units of kT, its default velocity, and zero total momentum with it).

use crate::scene_stats::{P_MIN, ks_p, normal_cdf};
use bonkers::model::scene::SceneSpec;
use bonkers::scene::{Built, build, resolve};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn built<const D: usize>(text: &str, seed: u64) -> Result<Built<D>, String> {
    let spec: SceneSpec = toml::from_str(text).expect("scene TOML");
    build::<D>(&resolve(&spec)?, &mut ChaCha8Rng::seed_from_u64(seed))
}

/// Each component times sqrt(m / kT) is a standard normal, whatever the
/// mass (masses drawn from [1, 9]).
#[test]
fn maxwell_velocities_are_gaussian_with_variance_kt_over_m() {
    let b = built::<2>(
        r#"
box = [200.0, 200.0]
species = [{ name = "a", count = 3000, mass = [1.0, 9.0], radius = 0.0 }]
velocities = { kind = "maxwell", temperature = 1.7 }
"#,
        11,
    )
    .unwrap();
    for k in 0..2 {
        let z: Vec<f64> = b
            .particles
            .iter()
            .map(|p| p.vel[k] * (p.mass() / 1.7).sqrt())
            .collect();
        let p = ks_p(z, normal_cdf);
        assert!(p > P_MIN, "axis {k}: KS p = {p}");
        println!("Maxwell axis {k}: KS p = {p:.3}");
    }
    // The same test rejects the wrong temperature.
    let z: Vec<f64> = b
        .particles
        .iter()
        .map(|p| p.vel[0] * p.mass().sqrt())
        .collect();
    assert!(ks_p(z, normal_cdf) < 1e-10);
}

/// The Imperial start: each momentum component uniform on [-p, p],
/// whatever the mass (masses drawn from [1, 9]; KS on m v / p, uniform on
/// [-1, 1]), the expansion theory's `Speeds::Uniform(p / m)`.
#[test]
fn uniform_momenta_are_uniform_up_to_p_max() {
    let b = built::<3>(
        r#"
box = [200.0, 200.0, 200.0]
species = [{ name = "a", count = 3000, mass = [1.0, 9.0], radius = 0.0 }]
velocities = { kind = "uniform", p = 2.5 }
"#,
        12,
    )
    .unwrap();
    let uniform = |x: f64| ((x + 1.0) / 2.0).clamp(0.0, 1.0);
    for k in 0..3 {
        let u: Vec<f64> = b
            .particles
            .iter()
            .map(|p| p.vel[k] * p.mass() / 2.5)
            .collect();
        assert!(u.iter().all(|x| x.abs() <= 1.0));
        let p = ks_p(u, uniform);
        assert!(p > P_MIN, "axis {k}: KS p = {p}");
    }
    // The same test rejects velocities (rather than momenta) uniform.
    let u: Vec<f64> = b.particles.iter().map(|p| p.vel[0] / 2.5).collect();
    assert!(ks_p(u, uniform) < 1e-10);
}

#[test]
fn equal_and_explicit_velocities_are_taken_as_given() {
    let b = built::<3>(
        r#"
box = [10.0, 10.0, 10.0]
species = [{ name = "a", count = 20, mass = [1.0, 3.0] }]
velocities = { kind = "equal", velocity = [0.5, -0.25, 2.0] }
"#,
        1,
    )
    .unwrap();
    assert!(b.particles.iter().all(|p| p.vel == [0.5, -0.25, 2.0]));
    let b = built::<2>(
        r#"
box = [10.0, 10.0]
species = [{ name = "a", count = 2 }, { name = "b", count = 1, mass = 3.0 }]
placement = { kind = "explicit", positions = [[2.0, 2.0], [5.0, 5.0], [8.0, 8.0]] }
velocities = { kind = "explicit", velocities = [[1.0, 0.0], [0.0, -2.0], [0.5, 0.5]] }
"#,
        1,
    )
    .unwrap();
    let v: Vec<[f64; 2]> = b.particles.iter().map(|p| p.vel).collect();
    assert_eq!(v, [[1.0, 0.0], [0.0, -2.0], [0.5, 0.5]]);
    assert_eq!(b.particles[2].mass(), 3.0);
}

/// Radii drawn from [0.2, 0.6] are uniform on it (KS), and the placement
/// respects each one (no overlaps: the engine accepts the scene).
#[test]
fn radii_drawn_from_a_range_are_uniform_and_respected() {
    let b = built::<2>(
        r#"
box = [80.0, 80.0]
species = [{ name = "a", count = 2000, radius = [0.2, 0.6] }]
"#,
        4,
    )
    .unwrap();
    let r: Vec<f64> = b.particles.iter().map(|p| p.radius).collect();
    assert!(r.iter().all(|x| (0.2..=0.6).contains(x)));
    let p = ks_p(r, |x| ((x - 0.2) / 0.4).clamp(0.0, 1.0));
    assert!(p > P_MIN, "radii KS p = {p}");
    println!("radii: KS p = {p:.3}");
    bonkers::engine::Disks::new(b.particles, b.sim_box, (), 1).expect("no overlaps");
}

/// `piston.energy` is a multiple of kT: at temperature 2, energy 3 gives the
/// piston 6. With zero_momentum the total momentum, piston included, is
/// zero and the gas still has exactly the energy asked for.
#[test]
fn piston_energy_is_in_units_of_kt_and_momentum_balances_it() {
    let b = built::<1>(
        r#"
box = [40.0]
species = [
  { name = "left", count = 10, radius = 0.0, region = { from = [0.0], to = [0.5] } },
  { name = "right", count = 10, mass = 2.0, radius = 0.0, region = { from = [0.5], to = [1.0] } },
]
velocities = { kind = "maxwell", temperature = 2.0 }
piston = { mass = 30.0, energy = 3.0, radius = 0.0 }
"#,
        1,
    )
    .unwrap();
    let p = &b.particles[b.piston.unwrap()];
    assert!((p.kinetic_energy() - 6.0).abs() < 1e-12);
    assert!(p.vel[0] > 0.0);

    let b = built::<1>(
        r#"
box = [40.0]
species = [
  { name = "left", count = 10, radius = 0.0, region = { from = [0.0], to = [0.5] } },
  { name = "right", count = 10, mass = 2.0, radius = 0.0, region = { from = [0.5], to = [1.0] } },
]
velocities = { kind = "maxwell", zero_momentum = true, energy = 25.0 }
piston = { mass = 30.0, energy = 2.0, radius = 0.0 }
"#,
        2,
    )
    .unwrap();
    let piston = b.piston.unwrap();
    let momentum: f64 = b.particles.iter().map(|p| p.mass() * p.vel[0]).sum();
    assert!(momentum.abs() < 1e-12, "total momentum {momentum}");
    let gas: f64 = b
        .particles
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != piston)
        .map(|(_, p)| p.kinetic_energy())
        .sum();
    assert!((gas - 25.0).abs() < 1e-12, "gas energy {gas}");
    // kT from the gas's energy: 2 E / (d N) = 2.5, so the piston has 2 kT = 5.
    assert!((b.particles[piston].kinetic_energy() - 5.0).abs() < 1e-12);
}

/// With no velocity or energy of its own the piston is drawn like the
/// others: the common velocity for "equal" (MacKay's start), a Maxwellian
/// draw with its own mass for "maxwell" (KS over seeds).
#[test]
fn a_piston_without_its_own_velocity_moves_like_the_gas() {
    let b = built::<1>("preset = \"mackay-piston\"", 1).unwrap();
    assert!(b.particles.iter().all(|p| p.vel == [1.0]));
    let scene = r#"
box = [12.0]
species = [{ name = "a", count = 3, radius = 0.0, region = { from = [0.0], to = [0.5] } }]
velocities = { kind = "maxwell", temperature = 0.5 }
piston = { mass = 8.0, position = 0.75, radius = 0.0 }
"#;
    let z: Vec<f64> = (0..2000)
        .map(|seed| {
            let b = built::<1>(scene, seed).unwrap();
            b.particles[b.piston.unwrap()].vel[0] * (8.0f64 / 0.5).sqrt()
        })
        .collect();
    let p = ks_p(z, normal_cdf);
    assert!(p > P_MIN, "piston velocity KS p = {p}");
    println!("piston draw: KS p = {p:.3}");
}
