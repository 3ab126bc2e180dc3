//! The fixed step converges to the exact answer as dt -> 0, at first order
//! (a wall or pair overlap is found up to one step late, so the path between
//! bounces is longer by half a step's travel on average), while the exact
//! engine gives the same answers to round-off (ideal gas) or within its
//! statistical error (Tonks' rods).

use crate::common;

use bonkers::engine::{
    Chain, Dynamics, Observer, Particle, SimBox, Simulation, Stepper, Stop, WallHit,
};
use bonkers::stats::line::log_slope;
use bonkers::stats::summary::Stats;

/// Momentum the walls received.
#[derive(Default)]
struct Impulse(f64);

impl<const D: usize> Observer<D> for Impulse {
    fn wall_hit(&mut self, e: &WallHit<D>) {
        self.0 += e.impulse.iter().map(|x| x * x).sum::<f64>().sqrt();
    }
}

/// Force on the walls over `duration` (momentum per unit time).
fn force<const D: usize>(mut sim: Box<dyn Dynamics<D, Impulse>>, duration: f64) -> f64 {
    sim.advance(Stop::Time(duration));
    sim.into_observer().0 / duration
}

fn stepped<const D: usize>(
    p: Vec<Particle<D>>,
    b: SimBox<D>,
    dt: f64,
) -> Box<dyn Dynamics<D, Impulse>> {
    Box::new(Stepper::new(p, b, Impulse::default(), 1, dt, true).unwrap())
}

/// Disks on separate lanes moving along x only never meet: an ideal gas
/// whose wall force over any time can be counted in closed form. Random
/// speeds and starts spread each disk's step-end overshoots of the walls
/// over a step's travel.
const LANES: usize = 100;
const WIDTH: f64 = 5.0;
const RADIUS: f64 = 0.4;

fn lanes() -> (Vec<Particle<2>>, SimBox<2>) {
    let mut rng = common::rng(17);
    let particles = (0..LANES)
        .map(|i| {
            let v = 0.2 + common::gaussian(&mut rng).abs();
            let x = RADIUS + (WIDTH - 2.0 * RADIUS) * rand::RngExt::random::<f64>(&mut rng);
            Particle::new([x, 0.5 + i as f64], [v, 0.0], 1.0, RADIUS)
        })
        .collect();
    (particles, SimBox::hard([WIDTH, LANES as f64]))
}

/// Force on the walls over [0, T] for disks bouncing freely between them:
/// 2 m v at each hit, the first when a disk first reaches the far wall, then
/// one every free length over v.
fn counted(particles: &[Particle<2>], duration: f64) -> f64 {
    let free = WIDTH - 2.0 * RADIUS;
    let impulse: f64 = particles
        .iter()
        .map(|p| {
            let v = p.vel[0];
            let first = (WIDTH - RADIUS - p.pos[0]) / v;
            let hits = ((duration - first) / (free / v)).floor() + 1.0;
            2.0 * v * hits.max(0.0)
        })
        .sum();
    impulse / duration
}

#[test]
fn ideal_gas_wall_force_is_exact_for_events_and_first_order_for_steps() {
    let (particles, sim_box) = lanes();
    let duration = 4000.0;
    let expected = counted(&particles, duration);
    let sim: Simulation<2, bonkers::engine::NeighbourList<2>, Impulse> =
        Simulation::new(particles.clone(), sim_box, Impulse::default(), 1).unwrap();
    let exact = force(Box::new(sim), duration);
    let round_off = (exact / expected - 1.0).abs();
    eprintln!("exact engine: {exact} against {expected} counted ({round_off:e})");
    assert!(
        round_off < 1e-12,
        "the exact engine is off by {round_off:e}"
    );

    // A fixed step finds a disk up to one step's travel past a wall and
    // sends it back from there: on average the path of a round trip grows
    // by v dt (half a step's travel at each wall, there and back), so the
    // long-time force is the sum of 2 m v^2 / (free + v dt).
    let free = WIDTH - 2.0 * RADIUS;
    let mut errors = Vec::new();
    for dt in [0.08, 0.04, 0.02] {
        let got = force(stepped(particles.clone(), sim_box, dt), duration);
        let long_time: f64 = particles
            .iter()
            .map(|p| 2.0 * p.vel[0].powi(2) / free)
            .sum();
        let model: f64 = particles
            .iter()
            .map(|p| 2.0 * p.vel[0].powi(2) / (free + p.vel[0] * dt))
            .sum();
        let error = 1.0 - got / expected;
        let predicted = 1.0 - model / long_time;
        eprintln!("dt {dt}: force {got}, relative error {error:e}, overshoot model {predicted:e}");
        assert!(
            (error / predicted - 1.0).abs() < 0.2,
            "dt {dt}: error {error:e} against {predicted:e}"
        );
        errors.push((dt, error));
    }
    // Each error is off its model by the spread of 100 disks' overshoots
    // (~6 %), so the slope over two octaves is known to ~0.06.
    let order = log_slope(&errors, 3).expect("errors at three steps or more");
    eprintln!("observed order {order}");
    assert!((order - 1.0).abs() < 0.15, "order {order}");
}

/// N rods of diameter 1 between walls: `P (L - N) = N kT` exactly (Tonks),
/// with kT = 2K/N.
fn tonks_error(n: usize, length: f64, dt: Option<f64>, seed: u64, duration: f64) -> f64 {
    let mut rng = common::rng(seed);
    let gap = (length - n as f64) / n as f64;
    let particles: Vec<Particle<1>> = (0..n)
        .map(|i| {
            let x = 0.5 + i as f64 * (1.0 + gap) + gap * 0.5;
            Particle::new([x], [common::gaussian(&mut rng)], 1.0, 0.5)
        })
        .collect();
    let sim_box = SimBox::hard([length]);
    let kinetic: f64 = particles.iter().map(Particle::kinetic_energy).sum();
    let kt = 2.0 * kinetic / n as f64;
    let tonks = 2.0 * n as f64 * kt / (length - n as f64);
    let got = match dt {
        Some(dt) => force(stepped(particles, sim_box, dt), duration),
        None => {
            let sim: Simulation<1, Chain, Impulse> =
                Simulation::new(particles, sim_box, Impulse::default(), seed).unwrap();
            force(Box::new(sim), duration)
        }
    };
    got / tonks - 1.0
}

#[test]
fn tonks_wall_pressure_is_approached_at_first_order() {
    let (n, length, duration) = (10, 20.0, 4000.0);
    let ensemble = |dt: Option<f64>| -> Stats {
        let errors: Vec<f64> = (0..8)
            .map(|s| tonks_error(n, length, dt, 100 + s, duration))
            .collect();
        Stats::of(&errors)
    };
    let exact = ensemble(None);
    eprintln!("exact: {} +- {}", exact.mean, exact.stderr);
    assert!(
        exact.mean.abs() < 4.0 * exact.stderr,
        "exact engine against Tonks"
    );
    let mut errors = Vec::new();
    for dt in [0.08, 0.04, 0.02] {
        let e = ensemble(Some(dt));
        eprintln!("dt {dt}: {} +- {}", e.mean, e.stderr);
        assert!(
            -e.mean > 4.0 * e.stderr,
            "dt {dt}: bias {} +- {} not resolved",
            e.mean,
            e.stderr
        );
        errors.push((dt, -e.mean));
    }
    let order = log_slope(&errors, 3).expect("errors at three steps or more");
    eprintln!("observed order {order}");
    assert!((order - 1.0).abs() < 0.25, "order {order}");
}
