//! Scenes: placement, velocities, the seeds' bundled scenes, and the errors
//! for impossible requests.

use bonkers::engine::{
    Axis, Chain, NeighbourList, Observer, Particle, SimBox, Simulation, Stop, WallHit,
};
use bonkers::model::scene::SceneSpec;
use bonkers::scene::{Built, build, presets, resolve};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn scene(text: &str) -> Result<SceneSpec, String> {
    resolve(&toml::from_str(text).expect("scene TOML"))
}

fn built<const D: usize>(text: &str, seed: u64) -> Result<Built<D>, String> {
    build::<D>(&scene(text)?, &mut ChaCha8Rng::seed_from_u64(seed))
}

fn energy<const D: usize>(b: &Built<D>) -> f64 {
    b.particles.iter().map(|p| p.kinetic_energy()).sum()
}

/// Random placement in the left half of a 2D box: inside the region, no
/// overlaps, and uniform across it (chi-square over 10 bins of x, pooled over
/// 20 seeds: below 27.9, the 0.001 critical value for 9 degrees of freedom).
#[test]
fn random_placement_never_overlaps_and_fills_its_region_uniformly() {
    let text = r#"
dimension = 2
box = [80.0, 40.0]
species = [{ name = "gas", count = 150, radius = 0.5, region = { from = [0.0, 0.0], to = [0.5, 1.0] } }]
placement = { kind = "random" }
"#;
    let mut bins = [0.0f64; 10];
    for seed in 0..20 {
        let b = built::<2>(text, seed).unwrap();
        for (i, p) in b.particles.iter().enumerate() {
            assert!(p.pos[0] >= 0.5 && p.pos[0] <= 39.5 && p.pos[1] >= 0.5 && p.pos[1] <= 39.5);
            for q in &b.particles[i + 1..] {
                let d2 = (p.pos[0] - q.pos[0]).powi(2) + (p.pos[1] - q.pos[1]).powi(2);
                assert!(d2 >= 1.0 - 1e-12, "overlap");
            }
            bins[((p.pos[0] - 0.5) / 39.0 * 10.0).min(9.0) as usize] += 1.0;
        }
    }
    let expected: f64 = 20.0 * 150.0 / 10.0;
    let chi2: f64 = bins.iter().map(|o| (o - expected).powi(2) / expected).sum();
    assert!(chi2 < 27.9, "chi-square {chi2}, bins {bins:?}");
}

#[test]
fn lattices_fill_their_regions_without_overlap() {
    for (d, lattice) in [(2, "square"), (2, "hexagonal"), (3, "cubic"), (3, "fcc")] {
        let text = format!(
            "dimension = {d}\nbox = {:?}\nboundary = {:?}\nspecies = [{{ name = \"a\", count = 500, radius = 0.5 }}]\nplacement = {{ kind = \"lattice\", lattice = \"{lattice}\" }}\n",
            vec![if d == 2 { 24.0 } else { 9.0 }; d],
            vec!["periodic"; d]
        );
        let ok = if d == 2 {
            let b = built::<2>(&text, 1).unwrap();
            Simulation::<2, NeighbourList<2>, ()>::new(b.particles, b.sim_box, (), 1).map(|_| ())
        } else {
            let b = built::<3>(&text, 1).unwrap();
            Simulation::<3, NeighbourList<3>, ()>::new(b.particles, b.sim_box, (), 1).map(|_| ())
        };
        assert!(ok.is_ok(), "{lattice}: {:?}", ok.err());
    }
}

#[test]
fn velocities_zero_momentum_and_exact_energy() {
    let b = built::<3>(
        r#"
dimension = 3
box = [10.0, 10.0, 10.0]
species = [{ name = "a", count = 50, mass = [1.0, 9.0], radius = 0.3 }]
velocities = { kind = "maxwell", temperature = 2.0, zero_momentum = true, energy = 123.0 }
"#,
        5,
    )
    .unwrap();
    let p: Vec<f64> = (0..3)
        .map(|k| b.particles.iter().map(|q| q.vel[k] / q.inv_mass).sum())
        .collect();
    assert!(p.iter().all(|x| x.abs() < 1e-12), "{p:?}");
    assert!((energy(&b) - 123.0).abs() < 1e-12);
    let u = built::<2>("dimension = 2\nbox = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 30, mass = 2.0 }]\nvelocities = { kind = \"uniform\", p = 3.0 }\n", 2).unwrap();
    assert!(
        u.particles
            .iter()
            .all(|q| q.vel.iter().all(|v| v.abs() <= 1.5)),
        "momenta within [-p, p]"
    );
}

/// MacKay's piston start: all particles with equal velocities, so the piston
/// (mass 40) holds 20 / (20 + sum m / 2) of the energy: 74–77% for the
/// preset's gas masses (MacKay: "roughly 75%"); equipartition would be 1/11.
#[test]
fn mackay_piston_starts_with_about_three_quarters_of_the_energy() {
    let b = built::<1>("preset = \"mackay-piston\"", 1).unwrap();
    let p = b.piston.unwrap();
    assert_eq!(b.particles[p].mass(), 40.0);
    assert_eq!(b.particles.len(), 11);
    let share = b.particles[p].kinetic_energy() / energy(&b);
    assert!((0.74..=0.77).contains(&share), "{share}");
    assert!(b.particles.windows(2).all(|w| w[0].pos[0] <= w[1].pos[0]));
}

/// The cradle is MacKay's cradle2.m (walls at 0 and 35, eight rods at 14..21,
/// masses 4.123, 9.0123 and six 1s, the first two moving left at 2); it
/// conserves energy, and the system's momentum changes only by what the walls
/// give it.
#[test]
fn mackay_cradle_conserves_energy_and_balances_momentum_at_the_walls() {
    #[derive(Default)]
    struct WallMomentum(f64);
    impl Observer<1> for WallMomentum {
        fn wall_hit(&mut self, e: &WallHit<1>) {
            self.0 += e.impulse[0];
        }
    }
    let b = built::<1>("preset = \"mackay-cradle\"", 1).unwrap();
    assert_eq!(b.sim_box.size, [35.0]);
    let masses: Vec<f64> = b.particles.iter().map(|p| p.mass()).collect();
    assert_eq!(masses, [4.123, 9.0123, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
    let xs: Vec<f64> = b.particles.iter().map(|p| p.pos[0]).collect();
    assert_eq!(xs, [14.0, 15.0, 16.0, 17.0, 18.0, 19.0, 20.0, 21.0]);
    let vs: Vec<f64> = b.particles.iter().map(|p| p.vel[0]).collect();
    assert_eq!(vs, [-2.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    let e0 = energy(&b);
    let p0: f64 = b.particles.iter().map(|q| q.vel[0] / q.inv_mass).sum();
    let mut sim: Simulation<1, Chain, WallMomentum> =
        Simulation::new(b.particles, b.sim_box, WallMomentum::default(), 1).unwrap();
    sim.run(Stop::Time(6000.0));
    assert!(sim.counts.collisions > 10_000);
    assert!((sim.kinetic_energy() - e0).abs() < 1e-12 * e0);
    let p1 = sim.momentum()[0];
    assert!(
        (p1 - p0 - sim.observer.0).abs() < 1e-9 * sim.observer.0.abs().max(1.0),
        "{p0} + {} != {p1}",
        sim.observer.0
    );
}

#[test]
fn imperial_scenes_do_what_the_seed_says() {
    // Four disks against the four walls come back reversed.
    let b = built::<2>("preset = \"imperial-box\"", 1).unwrap();
    let v0: Vec<[f64; 2]> = b.particles.iter().map(|p| p.vel).collect();
    let mut sim: Simulation<2, NeighbourList<2>, ()> =
        Simulation::new(b.particles, b.sim_box, (), 1).unwrap();
    sim.run(Stop::Time(20.0));
    assert_eq!(sim.counts.wall_hits, 4);
    for (p, v) in sim.particles().iter().zip(&v0) {
        assert_eq!(p.vel, [-v[0], -v[1]]);
    }
    // Head-on, equal masses: the moving disk stops, the other takes its velocity.
    let b = built::<2>("preset = \"imperial-collision-1d\"", 1).unwrap();
    let mut sim: Simulation<2, NeighbourList<2>, ()> =
        Simulation::new(b.particles, b.sim_box, (), 1).unwrap();
    sim.run(Stop::Time(20.0));
    assert_eq!(sim.counts.collisions, 1);
    assert_eq!(sim.particles()[0].vel, [0.0, 0.0]);
    assert_eq!(sim.particles()[1].vel, [1.0, 0.0]);
    // Oblique, equal masses, one at rest: they leave at right angles.
    let b = built::<2>("preset = \"imperial-collision-2d\"", 1).unwrap();
    let mut sim: Simulation<2, NeighbourList<2>, ()> =
        Simulation::new(b.particles, b.sim_box, (), 1).unwrap();
    sim.run(Stop::Time(12.0));
    assert_eq!(sim.counts.collisions, 1);
    let (a, c) = (sim.particles()[0].vel, sim.particles()[1].vel);
    assert!((a[0] * c[0] + a[1] * c[1]).abs() < 1e-15);
    assert!(((a[0] + c[0]) - 1.0).abs() < 1e-15 && ((a[1] + c[1]) - 0.5).abs() < 1e-15);
    // The sticking-bug cases never leave two disks overlapping.
    for name in ["imperial-sticking", "imperial-sticking-masses"] {
        let b = built::<2>(&format!("preset = \"{name}\""), 1).unwrap();
        let mut sim: Simulation<2, NeighbourList<2>, ()> =
            Simulation::new(b.particles, b.sim_box, (), 1).unwrap();
        for k in 1..=200 {
            sim.run(Stop::Time(5.0 * k as f64));
            assert!(
                sim.max_overlap() < 1e-12,
                "{name} overlaps at t = {}",
                5 * k
            );
        }
        assert!(sim.counts.collisions > 10);
    }
    // 200 disks of radius 1 in a box of 100.
    let b = built::<2>("preset = \"imperial-200\"", 1).unwrap();
    let e0 = energy(&b);
    let mut sim: Simulation<2, NeighbourList<2>, ()> =
        Simulation::new(b.particles, b.sim_box, (), 1).unwrap();
    sim.run(Stop::Time(2000.0));
    assert!(sim.counts.collisions > 1000);
    assert!((sim.kinetic_energy() - e0).abs() < 1e-12 * e0);
}

#[test]
fn every_preset_builds_and_runs() {
    for p in presets::list() {
        let text = format!("preset = \"{}\"", p.name);
        let d = scene(&text).unwrap().dimension().unwrap();
        let ok = match d {
            1 => built::<1>(&text, 7)
                .and_then(|b| {
                    Simulation::<1, Chain, ()>::new(b.particles, b.sim_box, (), 1)
                        .map_err(|e| e.to_string())
                })
                .map(|mut s| s.run(Stop::Time(10.0))),
            // A piston wall needs the plane-aware engine.
            2 => built::<2>(&text, 7).and_then(|b| {
                if b.particles.iter().any(|p| p.is_plane()) {
                    Simulation::<2, NeighbourList<2, true>, ()>::new(b.particles, b.sim_box, (), 1)
                        .map(|mut s| s.run(Stop::Time(10.0)))
                } else {
                    Simulation::<2, NeighbourList<2>, ()>::new(b.particles, b.sim_box, (), 1)
                        .map(|mut s| s.run(Stop::Time(10.0)))
                }
                .map_err(|e| e.to_string())
            }),
            _ => unreachable!(),
        };
        assert!(ok.is_ok(), "{}: {:?}", p.name, ok.err());
    }
}

#[test]
fn impossible_requests_are_clear_errors() {
    let err = built::<2>("dimension = 2\nbox = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 500 }]\nplacement = { kind = \"random\" }\n", 1).unwrap_err();
    assert!(
        err.contains("lattice"),
        "suggests what can be done instead: {err}"
    );
    let err = built::<2>(
        "dimension = 2\nbox = [10.0]\nspecies = [{ name = \"a\", count = 5 }]\n",
        1,
    )
    .unwrap_err();
    assert!(err.contains("one per axis"), "{err}");
    let err = built::<1>("dimension = 1\nbox = [10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[1.0]] }\n", 1).unwrap_err();
    assert!(err.contains("one per particle"), "{err}");
    let err = built::<1>(
        "dimension = 1\nbox = [10.0]\nspecies = [{ name = \"a\", count = 1, mass = -1.0 }]\n",
        1,
    )
    .unwrap_err();
    assert!(err.contains("mass"), "{err}");
    // A gas on both sides of a 2D piston wall: say which side it belongs on.
    let err = built::<2>("dimension = 2\nbox = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 1 }]\npiston = { mass = 10.0 }\n", 1).unwrap_err();
    assert!(err.contains("inside the region of `a`"), "{err}");
    let err =
        resolve(&toml::from_str::<SceneSpec>("preset = \"mackay-pistn\"").unwrap()).unwrap_err();
    assert!(err.contains("mackay-piston"), "{err}");
    // Overlapping explicit positions are refused with both indices before
    // anything is built (the scene's checks, which validation runs too)...
    let err = built::<2>("dimension = 2\nbox = [10.0, 10.0]\nspecies = [{ name = \"a\", count = 2 }]\nplacement = { kind = \"explicit\", positions = [[2.0, 2.0], [2.5, 2.0]] }\n", 1).unwrap_err();
    assert!(err.contains("particles 0 and 1 overlap"), "{err}");
    // ...and by the engine, for particles made by hand.
    let disk = |x: f64| Particle::new([x, 2.0], [0.0; 2], 1.0, 0.5);
    let sim_box = SimBox {
        size: [10.0; 2],
        axes: [Axis::HARD; 2],
    };
    let err =
        Simulation::<2, NeighbourList<2>, ()>::new(vec![disk(2.0), disk(2.5)], sim_box, (), 1)
            .unwrap_err()
            .to_string();
    assert!(err.contains("particles 0 and 1 overlap"), "{err}");
}

/// In 2D and 3D the piston is a wall along x: one plane, each gas on its side.
#[test]
fn a_2d_piston_is_a_wall_between_two_gases() {
    let scene = "dimension = 2\nbox = [20.0, 10.0]\nspecies = [\n  { name = \"left\", count = 30, region = { from = [0.0, 0.0], to = [0.5, 1.0] } },\n  { name = \"right\", count = 30, region = { from = [0.5, 0.0], to = [1.0, 1.0] } },\n]\npiston = { mass = 50.0, radius = 0.25, energy = 3.0 }\nvelocities = { kind = \"maxwell\", temperature = 2.0 }\n";
    let b = built::<2>(scene, 4).unwrap();
    let k = b.piston.expect("a piston");
    let wall = &b.particles[k];
    assert!(wall.is_plane() && wall.vel[1] == 0.0);
    assert_eq!((wall.pos[0], 1.0 / wall.inv_mass), (10.0, 50.0));
    // energy = 3 kT at kT = 2.
    assert!((wall.kinetic_energy() - 6.0).abs() < 1e-12);
    for p in b.particles.iter().filter(|p| !p.is_plane()) {
        let left = b.species[p.species as usize] == "left";
        assert_eq!(p.pos[0] < 10.0, left);
        assert!((p.pos[0] - 10.0).abs() >= 0.25 + p.radius);
    }
    let mut sim: bonkers::engine::WithPlane<2, ()> =
        Simulation::new(b.particles, b.sim_box, (), 1).unwrap();
    let e0 = sim.kinetic_energy();
    sim.run(Stop::Time(100.0));
    assert!((sim.kinetic_energy() - e0).abs() < 1e-11 * e0);
}
