//! Exact results: what hard-particle dynamics must give with no statistics at all.

use crate::common;

use bonkers::engine::{NeighbourList, Snapshot};
use bonkers::engine::{Observer, Particle, Rods, SimBox, Simulation, Stop, WallHit};

/// Sums the impulse delivered to each wall.
struct WallImpulse<const D: usize> {
    on_high: [f64; D],
    on_low: [f64; D],
}

impl<const D: usize> Default for WallImpulse<D> {
    fn default() -> Self {
        WallImpulse {
            on_high: [0.0; D],
            on_low: [0.0; D],
        }
    }
}

impl<const D: usize> Observer<D> for WallImpulse<D> {
    fn wall_hit(&mut self, e: &WallHit<D>) {
        let push = -e.impulse[e.axis];
        if e.high {
            self.on_high[e.axis] += push
        } else {
            self.on_low[e.axis] -= push
        }
    }
}

/// Tonks gas of unequal masses between walls, started far from equilibrium
/// (one rod moving, the rest at rest). Collisions now share energy, and the
/// wall pressure is P L' = 2K only as an equilibrium average: the
/// microcanonical phase volume is L'^N E^(N/2) up to constants, and the
/// mechanical pressure is (dPhi/dL)/(dPhi/dE) = 2E/L' (Tonks 1936 with
/// walls). Measured over 25 blocks after a burn-in, within 4 standard errors.
#[test]
fn tonks_pressure_holds_in_equilibrium_at_unequal_masses() {
    use rand::RngExt;
    let mut rng = common::rng(12);
    let (n, length) = (20usize, 60.0);
    let particles: Vec<Particle<1>> = (0..n)
        .map(|i| {
            let v = if i == 0 { 3.0 } else { 0.0 };
            Particle::new([1.5 + 2.9 * i as f64], [v], rng.random_range(0.5..2.0), 0.5)
        })
        .collect();
    let mut sim: Rods<WallImpulse<1>> =
        Simulation::new(particles, SimBox::hard([length]), WallImpulse::default(), 1).unwrap();
    let kinetic = sim.kinetic_energy();
    let free = length - n as f64;
    let (burn_in, block, blocks) = (2_000.0, 2_000.0, 25);
    sim.run(Stop::Time(burn_in));
    let mut ratios = Vec::new();
    for b in 1..=blocks {
        let before = sim.observer.on_high[0] + sim.observer.on_low[0];
        sim.run(Stop::Time(burn_in + b as f64 * block));
        let push = sim.observer.on_high[0] + sim.observer.on_low[0] - before;
        ratios.push(push / (2.0 * block) * free / (2.0 * kinetic));
    }
    let mean = ratios.iter().sum::<f64>() / blocks as f64;
    let var = ratios.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / (blocks - 1) as f64;
    let stderr = (var / blocks as f64).sqrt();
    // The blocks must resolve the law to a percent, or the test says nothing.
    assert!(
        stderr < 0.01,
        "P L'/2K = {mean} +- {stderr}: too noisy to test"
    );
    assert!(
        (mean - 1.0).abs() < 4.0 * stderr,
        "P L'/2K = {mean} +- {stderr}"
    );
    assert!((sim.kinetic_energy() / kinetic - 1.0).abs() < 1e-12);
}

/// 1D, equal masses: a collision swaps velocities, so the set of velocities
/// only ever gets permuted (and reflected at walls: the set of speeds stays),
/// to round-off, over 200,000 collisions.
#[test]
fn equal_masses_in_1d_only_permute_speeds() {
    let mut rng = common::rng(7);
    let n = 50;
    let particles: Vec<Particle<1>> = (0..n)
        .map(|i| {
            Particle::new(
                [1.0 + 2.0 * i as f64],
                [common::gaussian(&mut rng)],
                1.0,
                0.5,
            )
        })
        .collect();
    let mut speeds0: Vec<f64> = particles.iter().map(|p| p.vel[0].abs()).collect();
    speeds0.sort_by(f64::total_cmp);
    let mut sim = Rods::new(particles, SimBox::hard([2.0 * n as f64 + 1.0]), (), 1).unwrap();
    sim.run(Stop::Collisions(200_000));
    let mut speeds1: Vec<f64> = sim.particles().iter().map(|p| p.vel[0].abs()).collect();
    speeds1.sort_by(f64::total_cmp);
    // A swap written as v_i - (v_i - v_j) is exact only up to round-off.
    for (a, b) in speeds0.iter().zip(&speeds1) {
        assert!((a - b).abs() <= 1e-12 * speeds0[n - 1], "{a} vs {b}");
    }
}

/// Tonks gas of equal-mass rods between walls: each rod's speed is carried
/// from rod to rod like a point particle bouncing in the free length
/// L - N sigma, so the time-averaged force on a wall is exactly 2 K / (L - N sigma).
/// Over a finite time T each of the N "speed carriers" may be short of one
/// hit, which bounds the error: |F T - 2K T / L_free| <= sum 2 m |v|.
/// This is the integrable ghost gas: it holds for any velocities, so it
/// checks the bookkeeping of impulses, not equilibrium (for that, see
/// `tonks_pressure_holds_in_equilibrium_at_unequal_masses`).
#[test]
fn tonks_gas_wall_pressure_times_free_length_is_twice_the_kinetic_energy() {
    let mut rng = common::rng(11);
    let (n, length) = (20usize, 60.0);
    let particles: Vec<Particle<1>> = (0..n)
        .map(|i| {
            Particle::new(
                [1.5 + 2.9 * i as f64],
                [common::gaussian(&mut rng)],
                1.0,
                0.5,
            )
        })
        .collect();
    let bound: f64 = particles.iter().map(|p| 2.0 * p.vel[0].abs()).sum();
    let mut sim: Rods<WallImpulse<1>> =
        Simulation::new(particles, SimBox::hard([length]), WallImpulse::default(), 1).unwrap();
    let kinetic = sim.kinetic_energy();
    let t_end = 20_000.0;
    sim.run(Stop::Time(t_end));
    let free = length - n as f64;
    for push in [sim.observer.on_high[0], sim.observer.on_low[0]] {
        let expected = 2.0 * kinetic / free * t_end;
        assert!(
            (push - expected).abs() <= bound,
            "impulse {push}, expected {expected} +- {bound}"
        );
        let pressure_times_free = push / t_end * free;
        assert!((pressure_times_free / (2.0 * kinetic) - 1.0).abs() < 1e-3);
    }
}

/// Point particles (radius 0) never meet, so each keeps |v_k| on each axis and
/// the force on a wall of axis k is exactly sum m v_k^2 / L_k: P V = sum m v_k^2.
fn ideal_gas<const D: usize>(seed: u64) {
    let mut rng = common::rng(seed);
    let size = [10.0; D];
    let particles: Vec<Particle<D>> = (0..200)
        .map(|_| {
            let pos = std::array::from_fn(|_| 10.0 * rand::RngExt::random::<f64>(&mut rng));
            let vel = std::array::from_fn(|_| common::gaussian(&mut rng));
            Particle::new(pos, vel, 1.0 + rand::RngExt::random::<f64>(&mut rng), 0.0)
        })
        .collect();
    let sum_mv2: [f64; D] = std::array::from_fn(|k| {
        particles
            .iter()
            .map(|p| p.vel[k] * p.vel[k] / p.inv_mass)
            .sum()
    });
    let bound: [f64; D] = std::array::from_fn(|k| {
        particles
            .iter()
            .map(|p| 2.0 * p.vel[k].abs() / p.inv_mass)
            .sum()
    });
    let mut sim: Simulation<D, NeighbourList<D>, WallImpulse<D>> =
        Simulation::new(particles, SimBox::hard(size), WallImpulse::default(), 1).unwrap();
    let t_end = 5_000.0;
    sim.run(Stop::Time(t_end));
    assert_eq!(sim.counts.collisions, 0);
    for k in 0..D {
        let area: f64 = (0..D).filter(|&a| a != k).map(|a| size[a]).product();
        let expected = sum_mv2[k] / size[k] * t_end;
        for push in [sim.observer.on_high[k], sim.observer.on_low[k]] {
            assert!(
                (push - expected).abs() <= bound[k],
                "axis {k}: {push} vs {expected} +- {}",
                bound[k]
            );
            let pv = push / t_end / area * size.iter().product::<f64>();
            assert!((pv / sum_mv2[k] - 1.0).abs() < 0.01);
        }
    }
}

#[test]
fn ideal_gas_wall_pressure_in_2d_and_3d() {
    ideal_gas::<2>(21);
    ideal_gas::<3>(31);
}

/// Samples do not perturb the dynamics: the same run with and without a
/// clock ends in the bit-identical state.
#[test]
fn sampling_does_not_perturb_the_dynamics() {
    struct Count(u64);
    impl Observer<2> for Count {
        fn sample(&mut self, _s: &Snapshot<2>) {
            self.0 += 1;
        }
    }
    let (ps, bx) = common::lattice::<2>(10, 1.3, 5);
    let mut a: Simulation<2, NeighbourList<2>, Count> =
        Simulation::new(ps.clone(), bx, Count(0), 1).unwrap();
    let mut b: Simulation<2, NeighbourList<2>, ()> = Simulation::new(ps, bx, (), 1).unwrap();
    a.sample_every(Some(0.0137));
    a.run(Stop::Time(50.0));
    b.run(Stop::Time(50.0));
    assert_eq!(a.observer.0, 3650, "samples at 0, Tc, 2Tc, ... up to 50");
    assert!(a.counts.collisions > 1000);
    assert_eq!(a.counts.collisions, b.counts.collisions);
    let state = |s: &[bonkers::engine::Particle<2>]| {
        s.iter().map(|p| (p.pos, p.vel, p.t)).collect::<Vec<_>>()
    };
    assert_eq!(
        state(&a.particles().to_vec()),
        state(&b.particles().to_vec())
    );
}

/// Temperature divides kinetic energy by the free degrees of freedom: d per
/// ball and one per plane, less one per axis along which momentum is
/// conserved (periodic, and nothing immovable to take momentum up).
#[test]
fn degrees_of_freedom_count_what_can_move() {
    use bonkers::engine::{Axis, Particle, SimBox, degrees_of_freedom};
    let balls: Vec<Particle<2>> = (0..5)
        .map(|i| Particle::new([1.0 + 2.0 * i as f64, 1.0], [1.0, 0.0], 1.0, 0.5))
        .collect();
    let walls = SimBox::hard([20.0, 20.0]);
    let periodic = SimBox::periodic([20.0, 20.0]);
    let mut mixed = periodic;
    mixed.axes[0] = Axis::HARD;
    assert_eq!(degrees_of_freedom(&balls, &walls), 10.0);
    assert_eq!(degrees_of_freedom(&balls, &periodic), 8.0);
    assert_eq!(degrees_of_freedom(&balls, &mixed), 9.0);
    let mut with_plane = balls.clone();
    with_plane.push(Particle::plane(15.0, 0.0, 10.0, 0.1));
    assert_eq!(degrees_of_freedom(&with_plane, &mixed), 10.0);
    let mut anchored = balls;
    anchored.push(Particle::new([15.0, 15.0], [0.0, 0.0], f64::INFINITY, 0.5));
    assert_eq!(degrees_of_freedom(&anchored, &periodic), 10.0);
}
