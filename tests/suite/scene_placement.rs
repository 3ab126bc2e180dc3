//! Placement: exact uniform random rods in 1D (species mixed, regions and the
//! piston respected), uniform random insertion in 3D, and lattices that keep
//! every particle inside its walls. Each seeded statistical test compares a
//! p-value with `P_MIN` (a true law fails one run in ten thousand).

use crate::scene_stats::{P_MIN, chi_square_p, ks_p};
use bonkers::engine::{Disks, Rods, Spheres};
use bonkers::model::scene::SceneSpec;
use bonkers::scene::{Built, build, resolve};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn built<const D: usize>(text: &str, seed: u64) -> Result<Built<D>, String> {
    let spec: SceneSpec = toml::from_str(text).expect("scene TOML");
    build::<D>(&resolve(&spec)?, &mut ChaCha8Rng::seed_from_u64(seed))
}

/// Rods of two species and two sizes sharing a line. Whatever the order,
/// the free coordinates u_k = x_(k) - r_(k) - (rods' length left of k) are
/// the order statistics of n uniforms on [0, L - total length], so pooled
/// over configurations they are uniform (KS). The species are shuffled along
/// the line: the leftmost rod is of the first species in half the seeds
/// (binomial, within 4 standard deviations).
#[test]
fn random_rods_are_exactly_uniform_and_species_mix() {
    let text = r#"
box = [20.0]
species = [
  { name = "a", count = 6, radius = 0.5 },
  { name = "b", count = 6, radius = [0.2, 0.4] },
]
placement = { kind = "random" }
"#;
    let seeds = 400;
    let mut free = Vec::new();
    let mut a_first = 0;
    for seed in 0..seeds {
        let b = built::<1>(text, seed).unwrap();
        let total: f64 = b.particles.iter().map(|p| 2.0 * p.radius).sum();
        let mut left = 0.0;
        for p in &b.particles {
            free.push((p.pos[0] - p.radius - left) / (20.0 - total));
            left += 2.0 * p.radius;
        }
        a_first += usize::from(b.particles[0].species == 0);
        Rods::new(b.particles, b.sim_box, (), 1).expect("no overlaps, inside the walls");
    }
    let p = ks_p(free, |u| u.clamp(0.0, 1.0));
    assert!(p > P_MIN, "free coordinates not uniform: KS p = {p}");
    let n = seeds as f64;
    let z = (a_first as f64 - n / 2.0) / (n / 4.0).sqrt();
    assert!(
        z.abs() < 4.0,
        "leftmost rod of species a in {a_first} of {seeds} seeds (z = {z})"
    );
    println!("rods: KS p = {p:.3}, leftmost a: {a_first}/{seeds}");
}

/// Rod A in [0, 6], rod B in [4, 10] (radius 0.25, box 10): the allowed
/// (x_A, x_B) set has area 29, of which 0.5 has B left of A. Sampled
/// jointly and exactly, B is left of A with probability 1/58.
#[test]
fn rods_in_overlapping_regions_are_placed_jointly() {
    let text = r#"
box = [10.0]
species = [
  { name = "a", count = 1, radius = 0.25, region = { from = [0.0], to = [0.6] } },
  { name = "b", count = 1, radius = 0.25, region = { from = [0.4], to = [1.0] } },
]
"#;
    let seeds = 20_000;
    let mut b_first = 0;
    for seed in 0..seeds {
        let b = built::<1>(text, seed).unwrap();
        for p in &b.particles {
            let (lo, hi) = if p.species == 0 {
                (0.0, 6.0)
            } else {
                (4.0, 10.0)
            };
            assert!(p.pos[0] - 0.25 >= lo && p.pos[0] + 0.25 <= hi);
        }
        assert!(b.particles[1].pos[0] - b.particles[0].pos[0] >= 0.5);
        b_first += usize::from(b.particles[0].species == 1);
    }
    let (n, q) = (seeds as f64, 1.0 / 58.0);
    let z = (b_first as f64 - n * q) / (n * q * (1.0 - q)).sqrt();
    assert!(
        z.abs() < 4.0,
        "B left of A in {b_first} of {seeds} (z = {z})"
    );
    println!(
        "B left of A: {b_first}/{seeds}, expected {:.1} (z = {z:.2})",
        n * q
    );
}

/// Eight rods (diameter 1) anywhere in a box of 12 with a piston of
/// diameter 1 in the middle: with k rods on the left the configuration
/// volume is C(8, k) (5.5 - k)^k (k - 2.5)^(8 - k), so k is 3, 4 or 5 with
/// those weights (chi-square), and no rod ever overlaps the piston.
#[test]
fn random_rods_keep_clear_of_the_piston() {
    let text = r#"
box = [12.0]
species = [{ name = "gas", count = 8, radius = 0.5 }]
piston = { mass = 10.0, position = 0.5, radius = 0.5 }
"#;
    let weight = |k: i32| {
        let c = [1.0, 8.0, 28.0, 56.0, 70.0, 56.0, 28.0, 8.0, 1.0][k as usize];
        c * (5.5 - k as f64).powi(k) * (k as f64 - 2.5).powi(8 - k)
    };
    let seeds = 1500;
    let mut counts = [0.0; 3];
    for seed in 0..seeds {
        let b = built::<1>(text, seed).unwrap();
        let piston = b.piston.unwrap();
        let k = piston as i32;
        assert!((3..=5).contains(&k), "{k} rods left of the piston");
        counts[(k - 3) as usize] += 1.0;
        Rods::new(b.particles, b.sim_box, (), 1).expect("no overlaps");
    }
    let total: f64 = (3..=5).map(weight).sum();
    let expected: Vec<f64> = (3..=5).map(|k| seeds as f64 * weight(k) / total).collect();
    let p = chi_square_p(&counts, &expected, 0);
    assert!(
        p > P_MIN,
        "rods left of the piston {counts:?}, expected {expected:?}: p = {p}"
    );
    println!("piston split: {counts:?} vs {expected:?}, p = {p:.3}");
}

/// Random insertion in a periodic box is translation invariant, so every
/// particle's position is uniform; the last one inserted (the one most
/// constrained by the others) is tested on each axis (chi-square, 10 bins,
/// one configuration per seed so the samples are independent).
#[test]
fn random_spheres_are_uniform_in_a_periodic_box() {
    let text = r#"
box = [6.0, 6.0, 6.0]
boundary = ["periodic", "periodic", "periodic"]
species = [{ name = "a", count = 80, radius = 0.5 }]
"#;
    let seeds = 3000;
    let mut bins = [[0.0; 10]; 3];
    for seed in 0..seeds {
        let b = built::<3>(text, seed).unwrap();
        let last = b.particles.last().unwrap().pos;
        for k in 0..3 {
            assert!((0.0..6.0).contains(&last[k]));
            bins[k][(last[k] / 0.6) as usize] += 1.0;
        }
        if seed < 20 {
            let sim = Spheres::new(b.particles, b.sim_box, (), 1).expect("no overlaps");
            assert_eq!(sim.max_overlap(), 0.0);
        }
    }
    for (k, counts) in bins.iter().enumerate() {
        let p = chi_square_p(counts, &[seeds as f64 / 10.0; 10], 0);
        assert!(p > P_MIN, "axis {k}: {counts:?}, p = {p}");
        println!("3D axis {k}: chi-square p = {p:.3}");
    }
}

/// Hexagonal and fcc lattices in walled boxes at densities where sites at a
/// quarter cell from the edge used to put particles through the walls: every
/// particle now lies inside, radius included, and none overlap.
#[test]
fn lattices_keep_every_particle_inside_the_walls() {
    for (lattice, n, l) in [("hexagonal", 400, 19.22), ("square", 400, 20.0)] {
        let text = format!(
            "box = [{l}, {l}]\nspecies = [{{ name = \"a\", count = {n} }}]\nplacement = {{ kind = \"lattice\", lattice = \"{lattice}\" }}\n"
        );
        let b = built::<2>(&text, 1).unwrap();
        assert_eq!(b.particles.len(), n);
        let sim = Disks::new(b.particles, b.sim_box, (), 1).expect("inside and apart");
        assert!(sim.max_wall_violation() < 1e-12, "{lattice}");
        assert!(sim.max_overlap() < 1e-12, "{lattice}");
    }
    for (lattice, n, l) in [("fcc", 250, 6.05), ("cubic", 216, 6.0)] {
        let text = format!(
            "box = [{l}, {l}, {l}]\nspecies = [{{ name = \"a\", count = {n} }}]\nplacement = {{ kind = \"lattice\", lattice = \"{lattice}\" }}\n"
        );
        let b = built::<3>(&text, 1).unwrap();
        let sim = Spheres::new(b.particles, b.sim_box, (), 1).expect("inside and apart");
        assert!(sim.max_wall_violation() < 1e-12, "{lattice}");
        assert!(sim.max_overlap() < 1e-12, "{lattice}");
    }
}

/// When they do not fit, the error names the most that do and their density.
#[test]
fn a_lattice_too_full_says_how_many_fit() {
    let err = built::<2>(
        "box = [19.22, 19.22]\nspecies = [{ name = \"a\", count = 420 }]\nplacement = { kind = \"lattice\" }\n",
        1,
    )
    .unwrap_err();
    assert!(
        err.contains("at most 407 fit") && err.contains("packing fraction 0.86"),
        "{err}"
    );
}

/// Two species with no region share one lattice: no overlaps, and the
/// sites are dealt out at random (both species in each half of the box). A
/// species of count 0 is simply absent.
#[test]
fn species_sharing_a_region_share_one_lattice() {
    let text = r#"
box = [12.0, 12.0]
boundary = ["periodic", "periodic"]
species = [
  { name = "a", count = 60 },
  { name = "b", count = 60, mass = 2.0 },
  { name = "none", count = 0 },
]
placement = { kind = "lattice" }
"#;
    let b = built::<2>(text, 3).unwrap();
    assert_eq!(b.particles.len(), 120);
    assert_eq!(b.species, ["a", "b", "none"]);
    for half in [0.0, 6.0] {
        for s in 0..2 {
            let n = b
                .particles
                .iter()
                .filter(|p| p.species == s && p.pos[0] >= half && p.pos[0] < half + 6.0)
                .count();
            assert!(
                n > 10,
                "species {s} has {n} particles in the half at {half}"
            );
        }
    }
    let sim = Disks::new(b.particles, b.sim_box, (), 1).expect("no overlaps");
    assert!(sim.max_overlap() < 1e-12);
}

/// `order = "alternating"`: the species take turns along the line, in
/// species order from x = 0, whatever the seed, and the gaps are still
/// uniform: the free coordinates (as in the test above) pooled over seeds
/// pass a KS test against the uniform law.
#[test]
fn alternating_rods_take_turns_with_uniform_gaps() {
    let text = r#"
box = [20.0]
species = [
  { name = "light", count = 6, mass = 1.0, radius = 0.5 },
  { name = "heavy", count = 6, mass = 3.0, radius = [0.2, 0.4] },
]
placement = { kind = "random", order = "alternating" }
"#;
    let mut free = Vec::new();
    for seed in 0..400 {
        let b = built::<1>(text, seed).unwrap();
        let species: Vec<usize> = b.particles.iter().map(|p| p.species as usize).collect();
        let turns: Vec<usize> = (0..12).map(|k| k % 2).collect();
        assert_eq!(species, turns, "seed {seed}");
        let total: f64 = b.particles.iter().map(|p| 2.0 * p.radius).sum();
        let mut left = 0.0;
        for p in &b.particles {
            free.push((p.pos[0] - p.radius - left) / (20.0 - total));
            left += 2.0 * p.radius;
        }
        Rods::new(b.particles, b.sim_box, (), 1).expect("no overlaps, inside the walls");
    }
    let p = ks_p(free, |u| u.clamp(0.0, 1.0));
    assert!(p > P_MIN, "free coordinates not uniform: KS p = {p}");
    println!("alternating rods: KS p = {p:.3}");
}
