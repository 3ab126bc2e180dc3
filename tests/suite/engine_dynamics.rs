//! The run loop's view of the engine: a run driven only through the
//! `Dynamics` trait (as `runner::execute::simulate` drives it) must reach its stop,
//! count what it did, conserve energy to round-off and feed its observer the
//! events and samples the trait's contract promises, in time order.

use crate::common;

use bonkers::engine::{
    Chain, Dynamics, NeighbourList, Neighbourhood, Observer, PairCollision, Particle, SimBox,
    Simulation, Snapshot, Stop, WallHit, degrees_of_freedom,
};

/// What an observer saw, with a switch like the runner's `recording`.
#[derive(Default)]
struct Log {
    recording: bool,
    /// Time of the last hook called, and whether any came earlier than it.
    last: f64,
    out_of_order: bool,
    collisions: u64,
    wall_hits: u64,
    sample_times: Vec<f64>,
    sample_energies: Vec<f64>,
}

impl Log {
    fn saw(&mut self, time: f64) {
        self.out_of_order |= time < self.last;
        self.last = time;
    }
}

impl<const D: usize> Observer<D> for Log {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        if self.recording {
            self.saw(e.time);
            self.collisions += 1;
        }
    }
    fn wall_hit(&mut self, e: &WallHit<D>) {
        if self.recording {
            self.saw(e.time);
            self.wall_hits += 1;
        }
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        if self.recording {
            self.saw(s.time);
            self.sample_times.push(s.time);
            self.sample_energies.push(s.kinetic_energy());
        }
    }
}

/// Round-off bound on the relative energy change: each elastic collision
/// changes the total by a few ulps at most (walls reflect exactly), and the
/// total is a sum over the particles.
fn round_off(collisions: u64, particles: usize) -> f64 {
    4.0 * f64::EPSILON * (collisions as f64 + particles as f64)
}

/// Box a system behind the trait, as the runner's factory does.
fn dynamics<const D: usize, N: Neighbourhood<D> + 'static>(
    particles: Vec<Particle<D>>,
    sim_box: SimBox<D>,
) -> Box<dyn Dynamics<D, Log>> {
    let sim: Simulation<D, N, Log> =
        Simulation::new(particles, sim_box, Log::default(), 7).unwrap();
    Box::new(sim)
}

/// The runner's loop: equilibrate unrecorded, then record a measurement of
/// `duration` sampled every `every`, then `collisions` more pair collisions.
/// Checks everything the trait promises on the way; hands back the log.
fn drive<const D: usize>(
    name: &str,
    mut sim: Box<dyn Dynamics<D, Log>>,
    particles: usize,
    duration: f64,
    every: f64,
    collisions: u64,
) -> Log {
    let energy0 = sim.kinetic_energy();
    sim.advance(Stop::Time(10.0));
    assert_eq!(sim.time(), 10.0, "{name}: equilibration ends at its stop");
    let before = sim.counts();
    assert!(before.collisions > 0, "{name}: nothing collided");
    assert_eq!(
        sim.observer_mut().collisions,
        0,
        "{name}: recorded while off"
    );

    sim.observer_mut().recording = true;
    sim.sample_every(Some(every));
    let start = sim.time();
    let stop = start + duration;
    sim.advance(Stop::Time(stop));
    assert_eq!(sim.time(), stop, "{name}: the run ends exactly at its stop");
    let after = sim.counts();
    let made = after.collisions - before.collisions;
    assert!(made > 1000, "{name}: only {made} collisions");
    assert!(after.events >= after.collisions + after.wall_hits);
    let energy1 = sim.kinetic_energy();
    let drift = (energy1 - energy0).abs() / energy0;
    assert!(
        drift <= round_off(after.collisions, particles),
        "{name}: energy {energy0} -> {energy1} (relative {drift:e})"
    );

    let log = sim.observer_mut();
    assert_eq!(log.collisions, made, "{name}: every collision was observed");
    assert_eq!(log.wall_hits, after.wall_hits - before.wall_hits);
    assert!(!log.out_of_order, "{name}: hooks called out of time order");
    assert!(log.last <= stop, "{name}: an event after the stop");
    // Samples at start, start + every, ..., stop (duration is a multiple).
    let expected = (duration / every).round() as usize + 1;
    assert_eq!(log.sample_times.len(), expected, "{name}: samples");
    assert_eq!(after.samples - before.samples, expected as u64);
    for (k, (&t, &e)) in log
        .sample_times
        .iter()
        .zip(&log.sample_energies)
        .enumerate()
    {
        let want = start + k as f64 * every;
        assert!(
            (t - want).abs() <= 1e-12 * stop,
            "{name}: sample {k} at {t}"
        );
        assert!((e - energy0).abs() <= round_off(after.collisions, particles) * energy0);
    }

    // By a number of collisions: exactly that many more, all observed.
    sim.advance(Stop::Collisions(collisions));
    assert_eq!(sim.counts().collisions, after.collisions + collisions);
    assert!(sim.time() > stop);
    let log = sim.into_observer();
    assert_eq!(
        log.collisions,
        made + collisions,
        "{name}: observer handed back"
    );
    assert!(!log.out_of_order);
    log
}

/// Rods of three masses between walls: the chain of neighbours.
#[test]
fn rods_run_through_the_trait() {
    let mut rng = common::rng(3);
    let n = 40;
    let particles: Vec<Particle<1>> = (0..n)
        .map(|i| {
            let mass = 1.0 + 0.5 * (i % 3) as f64;
            Particle::new(
                [1.0 + 2.0 * i as f64],
                [common::gaussian(&mut rng)],
                mass,
                0.4,
            )
        })
        .collect();
    let sim_box = SimBox::hard([2.0 * n as f64]);
    let sim = dynamics::<1, Chain>(particles, sim_box);
    assert_eq!(sim.degrees_of_freedom(), n as f64, "d N with walls");
    assert_eq!(sim.sim_box(), &sim_box);
    let log = drive("rods", sim, n, 500.0, 0.25, 20_000);
    assert!(log.wall_hits > 0, "wall hits observed");
}

/// Periodic disks and spheres: neighbour lists; momentum conserved along
/// every axis, so d (N - 1) degrees of freedom.
#[test]
fn disks_and_spheres_run_through_the_trait() {
    let (disks, disk_box) = common::lattice::<2>(12, 1.5, 5);
    let sim = dynamics::<2, NeighbourList<2>>(disks, disk_box);
    assert_eq!(sim.degrees_of_freedom(), 2.0 * (144.0 - 1.0));
    drive("disks", sim, 144, 100.0, 0.5, 20_000);

    let (spheres, sphere_box) = common::lattice::<3>(6, 1.4, 6);
    let sim = dynamics::<3, NeighbourList<3>>(spheres, sphere_box);
    assert_eq!(sim.degrees_of_freedom(), 3.0 * (216.0 - 1.0));
    drive("spheres", sim, 216, 50.0, 0.5, 20_000);
}

/// Disks in a walled box either side of a movable plane (the 2D piston):
/// the engine with plane support, wall hits observed too.
#[test]
fn disks_beside_a_plane_run_through_the_trait() {
    let (mut particles, _) = common::lattice::<2>(10, 1.6, 9);
    // Lattice columns sit at 7.2 and 8.8: the plane at 8 (0.25 thick either
    // side) is clear of both.
    particles.push(Particle::plane(8.0, 0.3, 20.0, 0.25));
    let sim_box = SimBox::hard([16.0; 2]);
    let expected = degrees_of_freedom(&particles, &sim_box);
    let sim = dynamics::<2, NeighbourList<2, true>>(particles, sim_box);
    assert_eq!(sim.degrees_of_freedom(), expected);
    assert_eq!(expected, 2.0 * 100.0 + 1.0, "d per disk, 1 for the plane");
    let log = drive("plane", sim, 101, 200.0, 1.0, 20_000);
    assert!(log.wall_hits > 0, "wall hits observed");
}
