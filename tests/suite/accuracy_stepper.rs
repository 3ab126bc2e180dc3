//! The fixed-step integrator behind the `Dynamics` trait: it must stop where
//! told, feed observers the same kinds of events as the exact engine (pair
//! collisions with an impulse along the line of centres, wall hits with an
//! impulse normal to the wall, samples at their times), in time order, and
//! conserve energy to round-off (its bounces are elastic).

use crate::common;

use bonkers::engine::{
    Dynamics, Observer, PairCollision, Particle, SimBox, Snapshot, Stepper, Stop, WallHit,
};

#[derive(Default)]
struct Log {
    last: f64,
    out_of_order: bool,
    collisions: u64,
    wall_hits: u64,
    /// Largest |impulse x separation| / (|impulse| |separation|): 0 when
    /// every pair impulse is along the line of centres.
    off_line: f64,
    /// Largest share of a wall impulse across the wall's normal.
    off_normal: f64,
    sample_times: Vec<f64>,
}

impl Log {
    fn saw(&mut self, t: f64) {
        self.out_of_order |= t < self.last;
        self.last = t;
    }
}

impl<const D: usize> Observer<D> for Log {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        self.saw(e.time);
        self.collisions += 1;
        let (p, r) = (e.impulse_i, e.separation);
        let dot: f64 = (0..D).map(|k| p[k] * r[k]).sum();
        let np: f64 = (0..D).map(|k| p[k] * p[k]).sum::<f64>().sqrt();
        let nr: f64 = (0..D).map(|k| r[k] * r[k]).sum::<f64>().sqrt();
        self.off_line = self.off_line.max(1.0 - dot.abs() / (np * nr));
    }
    fn wall_hit(&mut self, e: &WallHit<D>) {
        self.saw(e.time);
        self.wall_hits += 1;
        let total: f64 = e.impulse.iter().map(|x| x.abs()).sum();
        self.off_normal = self.off_normal.max(1.0 - e.impulse[e.axis].abs() / total);
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        self.saw(s.time);
        self.sample_times.push(s.time);
    }
}

fn run<const D: usize>(
    name: &str,
    particles: Vec<Particle<D>>,
    sim_box: SimBox<D>,
    dt: f64,
) -> Log {
    let n = particles.len();
    let stepper = Stepper::new(particles, sim_box, Log::default(), 3, dt, true).unwrap();
    let mut sim: Box<dyn Dynamics<D, Log>> = Box::new(stepper);
    let energy0 = sim.kinetic_energy();
    sim.advance(Stop::Time(1.0));
    assert_eq!(sim.time(), 1.0, "{name}: stops exactly");
    sim.sample_every(Some(0.25));
    sim.advance(Stop::Time(41.0));
    assert_eq!(
        sim.time(),
        41.0,
        "{name}: stops exactly at a time off the step grid"
    );
    let counts = sim.counts();
    assert!(
        counts.collisions > 500,
        "{name}: {} collisions",
        counts.collisions
    );
    // Each advance ends with a step shortened onto its stop.
    let steps = (1.0 / dt).ceil() as u64 + (40.0 / dt).ceil() as u64;
    assert_eq!(
        counts.events,
        steps * n as u64,
        "{name}: one move per particle per step"
    );
    let drift = (sim.kinetic_energy() - energy0).abs() / energy0;
    let bound = 4.0 * f64::EPSILON * (counts.collisions + n as u64) as f64;
    assert!(
        drift <= bound,
        "{name}: energy drift {drift:e} over {bound:e}"
    );
    let before = sim.counts().collisions;
    sim.advance(Stop::Collisions(100));
    let after = sim.counts();
    assert!(after.collisions >= before + 100, "{name}: collision stop");
    assert!(sim.time() > 41.0);
    let diagnostics = sim.diagnostics();
    let names: Vec<&str> = diagnostics.iter().map(|(n, _)| *n).collect();
    for want in [
        "steps",
        "overlap_depth_max",
        "repeat_collisions",
        "stuck_pairs",
    ] {
        assert!(names.contains(&want), "{name}: diagnostics {names:?}");
    }
    let log = sim.into_observer();
    assert_eq!(
        log.collisions, after.collisions,
        "{name}: every collision observed"
    );
    assert_eq!(
        log.wall_hits, after.wall_hits,
        "{name}: every wall hit observed"
    );
    assert!(!log.out_of_order, "{name}: hooks out of time order");
    assert!(
        log.off_line < 1e-12,
        "{name}: pair impulse off the line of centres"
    );
    // Samples at 1, 1.25, ..., 41 (and on, in the collision-stopped part).
    let timed: Vec<f64> = log
        .sample_times
        .iter()
        .copied()
        .filter(|&t| t <= 41.0)
        .collect();
    assert_eq!(timed.len(), 161, "{name}: samples");
    for (k, t) in timed.iter().enumerate() {
        assert!(
            (t - (1.0 + 0.25 * k as f64)).abs() < 1e-12,
            "{name}: sample {k} at {t}"
        );
    }
    log
}

#[test]
fn disks_between_walls_give_both_kinds_of_events() {
    let (particles, _) = common::lattice::<2>(10, 1.6, 4);
    let log = run("disks", particles, SimBox::hard([16.0; 2]), 0.003);
    assert!(log.wall_hits > 100);
    assert!(
        log.off_normal < 1e-12,
        "wall impulse along the wall's normal only"
    );
}

#[test]
fn periodic_spheres_and_walled_rods_step_too() {
    let (spheres, sphere_box) = common::lattice::<3>(5, 1.5, 8);
    let log = run("spheres", spheres, sphere_box, 0.01);
    assert_eq!(log.wall_hits, 0, "no walls, no wall hits");

    let mut rng = common::rng(5);
    let rods: Vec<Particle<1>> = (0..30)
        .map(|i| {
            Particle::new(
                [1.0 + 2.0 * i as f64],
                [common::gaussian(&mut rng)],
                1.0,
                0.4,
            )
        })
        .collect();
    let log = run("rods", rods, SimBox::hard([60.0]), 0.002);
    assert!(log.wall_hits > 10);
}

#[test]
fn what_a_fixed_step_cannot_move_is_refused_with_the_reason() {
    let point = vec![Particle::new([1.0, 1.0], [1.0, 0.0], 1.0, 0.0)];
    let err = Stepper::new(point, SimBox::hard([4.0; 2]), (), 1, 0.1, true).unwrap_err();
    assert!(err.0.contains("radius 0"), "{}", err.0);
    let plane = vec![
        Particle::new([1.0, 1.0], [1.0, 0.0], 1.0, 0.5),
        Particle::plane(3.0, 0.0, 10.0, 0.1),
    ];
    let err = Stepper::new(plane, SimBox::hard([6.0; 2]), (), 1, 0.1, true).unwrap_err();
    assert!(err.0.contains("plane"), "{}", err.0);
    let one = vec![Particle::new([1.0, 1.0], [1.0, 0.0], 1.0, 0.5)];
    let err = Stepper::new(one, SimBox::hard([4.0; 2]), (), 1, 0.0, true).unwrap_err();
    assert!(err.0.contains("dt"), "{}", err.0);
}

/// The Imperial project's sticking case (five disks of radius 3, dt = 0.25
/// as in the seed): without the approach check overlapping disks bounce
/// back into each other and stay stuck (98 step ends in a row); with it,
/// none is stuck and every overlap clears within a few step ends (3 here,
/// where a third disk pushes one of a separating pair back once).
#[test]
fn the_seeds_sticking_case_sticks_only_without_the_fix() {
    let positions = [
        [45.0, 50.0],
        [55.0, 60.0],
        [35.0, 39.75],
        [65.0, 70.25],
        [54.0, 30.0],
    ];
    let velocities = [[1.0, 1.0], [0.0, 0.0], [2.0, 2.0], [-1.0, -1.0], [0.5, 2.5]];
    let diagnostics = |approach_check: bool| {
        let particles: Vec<Particle<2>> = positions
            .iter()
            .zip(velocities)
            .map(|(&x, v)| Particle::new(x, v, 1.0, 3.0))
            .collect();
        let mut sim = Stepper::new(
            particles,
            SimBox::hard([100.0; 2]),
            (),
            1,
            0.25,
            approach_check,
        )
        .unwrap();
        sim.advance(Stop::Time(125.0));
        let d = sim.diagnostics();
        let get = |name: &str| d.iter().find(|(n, _)| *n == name).unwrap().1;
        (get("stuck_pairs"), get("overlap_steps_max"))
    };
    let (stuck, longest) = diagnostics(false);
    eprintln!("without the fix: {stuck} stuck pairs, longest overlap {longest} steps");
    assert!(stuck >= 1.0 && longest > 10.0);
    let (stuck, longest) = diagnostics(true);
    eprintln!("with the fix: {stuck} stuck pairs, longest overlap {longest} steps");
    assert!(stuck == 0.0 && longest < 10.0);
}
