//! The cases that break event-driven codes: contact at the start, cradles,
//! extreme masses, grazing and tied events, dense packings, long runs, huge
//! boxes, and round-off overlaps.

use crate::common;

use bonkers::engine::{Disks, NeighbourList, Particle, Rods, SimBox, Simulation, Spheres, Stop};

fn relative_drift(e0: f64, e1: f64) -> f64 {
    (e1 - e0).abs() / e0
}

/// Newton's cradle: a chain of touching equal balls, one coming in from the
/// left: the momentum passes down the chain in zero-time events and the last
/// ball leaves with the incoming velocity; all others end at rest.
#[test]
fn newtons_cradle_passes_the_velocity_down_the_chain() {
    let mut particles = vec![Particle::new([1.0], [1.0], 1.0, 0.5)];
    for k in 0..8 {
        particles.push(Particle::new([3.0 + k as f64], [0.0], 1.0, 0.5));
    }
    let mut sim = Rods::new(particles, SimBox::hard([100.0]), (), 1).unwrap();
    sim.run(Stop::Time(5.0));
    let v: Vec<f64> = sim.particles().iter().map(|p| p.vel[0]).collect();
    assert_eq!(
        sim.counts.collisions, 8,
        "one collision per contact, no zero-time loop"
    );
    assert_eq!(v[8], 1.0);
    assert!(v[..8].iter().all(|&x| x == 0.0), "{v:?}");
}

/// Touching at the start in 2D: a square lattice at exact contact.
#[test]
fn particles_touching_at_the_start() {
    let (particles, bx) = common::lattice::<2>(12, 1.0, 3);
    let mut sim: Disks<()> = Simulation::new(particles, bx, (), 1).unwrap();
    let e0 = sim.kinetic_energy();
    sim.run(Stop::Collisions(200_000));
    assert!(relative_drift(e0, sim.kinetic_energy()) < 1e-12);
    assert!(sim.max_overlap() < 1e-10, "overlap {}", sim.max_overlap());
}

/// Masses from 1e-12 to 1e12, plus immovable particles at rest in the chain.
#[test]
fn extreme_mass_ratios_and_infinite_masses() {
    let mut rng = common::rng(5);
    let mut particles = Vec::new();
    for k in 0..40 {
        let mass = if k % 10 == 9 {
            f64::INFINITY
        } else {
            10f64.powi((k % 25) - 12)
        };
        let v = if mass.is_infinite() {
            0.0
        } else {
            common::gaussian(&mut rng) / mass.sqrt()
        };
        particles.push(Particle::new([1.0 + 2.0 * k as f64], [v], mass, 0.5));
    }
    let mut sim = Rods::new(particles, SimBox::hard([82.0]), (), 1).unwrap();
    let e0 = sim.kinetic_energy();
    sim.run(Stop::Collisions(2_000_000));
    assert!(
        relative_drift(e0, sim.kinetic_energy()) < 1e-10,
        "drift {}",
        relative_drift(e0, sim.kinetic_energy())
    );
    assert!(sim.max_overlap() < 1e-10);
    assert_eq!(sim.max_wall_violation(), 0.0);
    for (k, p) in sim.particles().iter().enumerate() {
        if k % 10 == 9 {
            assert_eq!(p.vel[0], 0.0, "immovable particles stay put");
        }
    }
}

#[test]
fn two_immovable_particles_that_could_meet_are_refused() {
    let particles = vec![
        Particle::new([1.0], [0.0], f64::INFINITY, 0.5),
        Particle::new([3.0], [-1.0], f64::INFINITY, 0.5),
    ];
    let err = Rods::new(particles, SimBox::hard([10.0]), (), 1).unwrap_err();
    assert!(err.to_string().contains("immovable"), "{err}");
}

#[test]
fn particles_at_rest_and_all_at_rest() {
    let particles = vec![
        Particle::new([1.0, 1.0], [0.0, 0.0], 1.0, 0.5),
        Particle::new([3.0, 1.0], [0.0, 0.0], 1.0, 0.5),
    ];
    let mut sim: Disks<()> = Simulation::new(particles, SimBox::hard([5.0, 5.0]), (), 1).unwrap();
    sim.run(Stop::Time(1e6));
    assert_eq!(sim.counts.events, 0);
    assert_eq!(sim.time(), 1e6);
    let particles = vec![
        Particle::new([1.0, 1.0], [1.0, 0.0], 1.0, 0.5),
        Particle::new([3.0, 1.0], [0.0, 0.0], 1.0, 0.5),
    ];
    let mut sim: Disks<()> = Simulation::new(particles, SimBox::hard([5.0, 5.0]), (), 1).unwrap();
    sim.run(Stop::Time(1.5));
    assert_eq!(sim.counts.collisions, 1);
    assert_eq!(sim.particles()[0].vel, [0.0, 0.0]);
    assert_eq!(sim.particles()[1].vel, [1.0, 0.0]);
}

/// Grazing: impact parameters within round-off of the contact distance.
#[test]
fn grazing_collisions_in_2d_and_3d() {
    for eps in [0.0, 1e-16, 1e-14, 1e-12, -1e-16, -1e-14] {
        let b = 1.0 - eps;
        let p2 = vec![
            Particle::new([2.0, 5.0], [1.0, 0.0], 1.0, 0.5),
            Particle::new([6.0, 5.0 + b], [0.0, 0.0], 1.0, 0.5),
        ];
        let mut s2: Disks<()> = Simulation::new(p2, SimBox::hard([10.0, 12.0]), (), 1).unwrap();
        let e0 = s2.kinetic_energy();
        s2.run(Stop::Time(3.9));
        assert!(relative_drift(e0, s2.kinetic_energy()) < 1e-14);
        assert!(s2.max_overlap() < 1e-10);
        let p3 = vec![
            Particle::new([2.0, 5.0, 5.0], [1.0, 0.0, 0.0], 1.0, 0.5),
            Particle::new(
                [6.0, 5.0 + b * 0.6, 5.0 + b * 0.8],
                [0.0, 0.0, 0.0],
                2.0,
                0.5,
            ),
        ];
        let mut s3: Spheres<()> =
            Simulation::new(p3, SimBox::hard([10.0, 12.0, 12.0]), (), 1).unwrap();
        let e0 = s3.kinetic_energy();
        s3.run(Stop::Time(3.9));
        assert!(relative_drift(e0, s3.kinetic_energy()) < 1e-14);
        assert!(s3.max_overlap() < 1e-10);
    }
}

/// Tied events: two particles hit a third from both sides at the same
/// instant, and a symmetric 2D arrangement; the outcome is fixed by the
/// deterministic order (time, then particle index) and repeats bit for bit.
#[test]
fn simultaneous_events_resolve_deterministically() {
    let build = || {
        vec![
            Particle::new([1.0, 5.0], [1.0, 0.0], 1.0, 0.5),
            Particle::new([5.0, 5.0], [0.0, 0.0], 1.0, 0.5),
            Particle::new([9.0, 5.0], [-1.0, 0.0], 1.0, 0.5),
            Particle::new([5.0, 1.0], [0.0, 1.0], 1.0, 0.5),
            Particle::new([5.0, 9.0], [0.0, -1.0], 1.0, 0.5),
        ]
    };
    let run = || {
        let mut s: Disks<()> = Simulation::new(build(), SimBox::hard([10.0, 10.0]), (), 1).unwrap();
        let e0 = s.kinetic_energy();
        s.run(Stop::Time(100.0));
        assert!(relative_drift(e0, s.kinetic_energy()) < 1e-14);
        assert!(s.max_overlap() < 1e-10);
        (
            s.counts,
            s.particles()
                .iter()
                .map(|p| (p.pos, p.vel))
                .collect::<Vec<_>>(),
        )
    };
    assert_eq!(run(), run());
}

/// The Imperial project's "sticking bug": five disks that a time-stepping
/// code traps together. Exact dynamics never leaves a pair overlapping.
#[test]
fn the_sticking_bug_case_never_sticks() {
    for masses in [[1.0; 5], [3.0, 2.0, 1.0, 4.0, 5.0]] {
        let spec = [
            ([45.0, 50.0], [1.0, 1.0]),
            ([55.0, 60.0], [0.0, 0.0]),
            ([35.0, 39.75], [2.0, 2.0]),
            ([65.0, 70.25], [-1.0, -1.0]),
            ([54.0, 30.0], [0.5, 2.5]),
        ];
        let particles = spec
            .iter()
            .zip(masses)
            .map(|((x, p), m)| Particle::new(*x, [p[0] / m, p[1] / m], m, 3.0))
            .collect();
        let mut sim: Disks<()> =
            Simulation::new(particles, SimBox::hard([100.0, 100.0]), (), 1).unwrap();
        let e0 = sim.kinetic_energy();
        for _ in 0..100 {
            sim.run(Stop::Time(sim.time() + 10.0));
            assert!(sim.max_overlap() < 1e-12);
        }
        assert!(relative_drift(e0, sim.kinetic_energy()) < 1e-13);
        assert!(sim.counts.collisions > 10);
    }
}

/// Dense states from lattices: 2D phi = 0.85, 3D phi = 0.55; millions of collisions.
#[test]
fn dense_disks_and_spheres_stay_exact() {
    let (ps, bx) = common::hexagonal(32, 32, 0.85, 9);
    let mut disks: Disks<()> = Simulation::new(ps, bx, (), 1).unwrap();
    let e0 = disks.kinetic_energy();
    disks.run(Stop::Collisions(2_000_000));
    assert!(relative_drift(e0, disks.kinetic_energy()) < 1e-11);
    assert!(
        disks.max_overlap() < 1e-10,
        "2D overlap {}",
        disks.max_overlap()
    );

    let (ps, bx) = common::fcc(7, 0.55, 10);
    let mut spheres: Spheres<()> = Simulation::new(ps, bx, (), 1).unwrap();
    let e0 = spheres.kinetic_energy();
    spheres.run(Stop::Collisions(2_000_000));
    assert!(relative_drift(e0, spheres.kinetic_energy()) < 1e-11);
    assert!(
        spheres.max_overlap() < 1e-10,
        "3D overlap {}",
        spheres.max_overlap()
    );
}

/// 10^8 collisions: relative energy drift below 1e-10, overlaps below 1e-10.
#[test]
fn a_hundred_million_collisions() {
    let mut rng = common::rng(77);
    let particles: Vec<Particle<1>> = (0..1000)
        .map(|i| {
            Particle::new(
                [0.6 + 1.2 * i as f64],
                [common::gaussian(&mut rng)],
                1.0 + 8.0 * rand::RngExt::random::<f64>(&mut rng),
                0.5,
            )
        })
        .collect();
    let mut sim = Rods::new(particles, SimBox::hard([1201.0]), (), 1).unwrap();
    let e0 = sim.kinetic_energy();
    sim.run(Stop::Collisions(100_000_000));
    assert!(
        relative_drift(e0, sim.kinetic_energy()) < 1e-10,
        "drift {}",
        relative_drift(e0, sim.kinetic_energy())
    );
    assert!(sim.max_overlap() < 1e-10);
    assert_eq!(sim.max_wall_violation(), 0.0);
}

/// A box 10^6 diameters wide: the cell grid stays small, nothing escapes.
#[test]
fn a_box_a_million_diameters_wide() {
    let mut rng = common::rng(3);
    let particles: Vec<Particle<2>> = (0..500)
        .map(|_| {
            let pos = [
                1.0 + (1e6 - 2.0) * rand::RngExt::random::<f64>(&mut rng),
                1.0 + 98.0 * rand::RngExt::random::<f64>(&mut rng),
            ];
            Particle::new(
                pos,
                [1e3 * common::gaussian(&mut rng), common::gaussian(&mut rng)],
                1.0,
                0.5,
            )
        })
        .collect();
    let mut sim: Simulation<2, NeighbourList<2>, ()> =
        Simulation::new(particles, SimBox::hard([1e6, 100.0]), (), 1).unwrap();
    let e0 = sim.kinetic_energy();
    sim.run(Stop::Time(1e4));
    assert!(sim.counts.events > 10_000);
    assert!(relative_drift(e0, sim.kinetic_energy()) < 1e-12);
    assert!(sim.max_overlap() < 1e-10);
    assert!(
        sim.max_wall_violation() < 1e-10,
        "{}",
        sim.max_wall_violation()
    );
}

/// Round-off left a pair overlapping while approaching, and a particle a hair
/// outside a wall moving out: both are turned back at once, never passing through.
#[test]
fn round_off_overlaps_never_pass_through() {
    let particles = vec![
        Particle::new([2.0, 2.0], [1.0, 0.0], 1.0, 0.5),
        Particle::new([3.0 - 1e-13, 2.0], [-1.0, 0.0], 1.0, 0.5),
    ];
    let mut sim: Disks<()> = Simulation::new(particles, SimBox::hard([5.0, 4.0]), (), 1).unwrap();
    sim.run(Stop::Time(0.1));
    assert_eq!(sim.counts.collisions, 1);
    assert!(sim.particles()[0].vel[0] < 0.0 && sim.particles()[1].vel[0] > 0.0);
    let particles = vec![Particle::new([0.5 - 1e-13, 2.0], [-1.0, 0.0], 1.0, 0.5)];
    let mut sim: Disks<()> = Simulation::new(particles, SimBox::hard([5.0, 4.0]), (), 1).unwrap();
    sim.run(Stop::Time(0.1));
    assert_eq!(sim.particles()[0].vel[0], 1.0);
    assert!(sim.max_wall_violation() < 1e-12);
}

#[test]
fn overlapping_or_outside_particles_are_refused_with_a_reason() {
    let overlapping = vec![
        Particle::new([2.0, 2.0], [0.0, 0.0], 1.0, 0.5),
        Particle::new([2.5, 2.0], [0.0, 0.0], 1.0, 0.5),
    ];
    let err = Disks::<()>::new(overlapping, SimBox::hard([5.0, 4.0]), (), 1)
        .unwrap_err()
        .to_string();
    assert!(err.contains("overlap"), "{err}");
    let outside = vec![Particle::new([7.0, 2.0], [0.0, 0.0], 1.0, 0.5)];
    let err = Disks::<()>::new(outside, SimBox::hard([5.0, 4.0]), (), 1)
        .unwrap_err()
        .to_string();
    assert!(err.contains("outside the box"), "{err}");
    let nan = vec![Particle::new([f64::NAN, 2.0], [0.0, 0.0], 1.0, 0.5)];
    assert!(Disks::<()>::new(nan, SimBox::hard([5.0, 4.0]), (), 1).is_err());
    let tiny = vec![Particle::new([1.0, 1.0], [0.0, 0.0], 1.0, 0.5)];
    let err = Disks::<()>::new(tiny, SimBox::periodic([2.0, 2.0]), (), 1)
        .unwrap_err()
        .to_string();
    assert!(err.contains("periodic"), "{err}");
}

/// Point rods (radius 0) in contact have no separation to take a direction
/// from, and round-off can put them a hair past each other: the chain order
/// decides. MacKay's start (all velocities equal, triple meetings at walls).
#[test]
fn point_rods_never_pass_each_other() {
    let mut rng = common::rng(8);
    let mut particles: Vec<Particle<1>> = (0..5)
        .map(|i| {
            Particle::new(
                [0.6 + 1.2 * i as f64],
                [1.0],
                0.9 + 0.2 * rand::RngExt::random::<f64>(&mut rng),
                0.0,
            )
        })
        .collect();
    particles.push(Particle::new([6.0], [1.0], 40.0, 0.0));
    particles.extend((0..5).map(|i| {
        Particle::new(
            [6.6 + 1.2 * i as f64],
            [1.0],
            1.5 + 0.2 * rand::RngExt::random::<f64>(&mut rng),
            0.0,
        )
    }));
    let mut sim = Rods::new(particles, SimBox::hard([12.0]), (), 1).unwrap();
    let e0 = sim.kinetic_energy();
    for k in 1..=2000 {
        sim.run(Stop::Time(k as f64));
        let snap = sim.snapshot();
        let x: Vec<f64> = (0..snap.particles.len())
            .map(|i| snap.position(i)[0])
            .collect();
        assert!(
            x.windows(2).all(|w| w[1] - w[0] >= -1e-9),
            "order broken at t = {k}: {x:?}"
        );
    }
    assert!(sim.counts.collisions > 10_000);
    assert!(relative_drift(e0, sim.kinetic_energy()) < 1e-12);
}
