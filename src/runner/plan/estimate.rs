//! What `study validate` expects a plan to cost, before running it: every
//! event the engine handles, from the kinetic theory of a hard-particle gas
//! (pair collisions, wall hits, and in 2D and 3D the renewals of the
//! particles' neighbourhoods), and time from a nominal rate per thread.
//! Estimates, not promises: the dense, inhomogeneous or far-from-equilibrium
//! scenes differ from them.

use crate::descriptor::validate::resolved;
use crate::descriptor::validate_scene::{count, dimension};
use crate::engine::boundary::ball_volume;
use crate::model::descriptor::Descriptor;
use crate::model::dimension::{ForDimension, in_dimension};
use crate::model::run_spec::RunSpec;
use crate::model::scene::{Boundary, Drawn, Mass, PistonSpec, SceneSpec, Velocities};
use std::f64::consts::PI;

/// Nominal pair collisions per second on one thread in 1D, 2D and 3D: the
/// engine benchmarks of docs/performance.md (4.6 M/s for rods, 0.8 M/s for
/// disks, 0.3-0.4 M/s for spheres on one core), rounded down because small
/// systems with sampling and analyses do more per collision. Every other
/// event (a wall hit, a renewal) is counted at a collision's cost, which it
/// does not exceed.
pub const COLLISIONS_PER_SECOND: [f64; 3] = [3.0e6, 0.8e6, 0.3e6];

/// The expected cost of one run of a sweep point's descriptor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunCost {
    /// Pair collisions, equilibration included.
    pub collisions: f64,
    /// Every event: pair collisions, wall hits and renewals, equilibration
    /// included.
    pub events: f64,
    pub dimension: usize,
    /// Pair collisions per unit time (the piston's included).
    pub rate: f64,
    /// Events per unit time.
    pub event_rate: f64,
    /// Of the events per unit time, those of the piston with the gas (0
    /// without one).
    pub piston_share: f64,
    /// The thermal wall (its index in `scene.thermal_walls`) whose
    /// temperature sets the speeds, when one is hotter than the start.
    pub hot_wall: Option<usize>,
    /// How much faster that wall makes everything than the start's speeds:
    /// sqrt(T_wall / kT_start) (1 without one).
    pub heating: f64,
    /// Simulated time a run lasts, equilibration included: for one stopped
    /// by a collision count, that count at `rate` (infinite if no pair can
    /// meet).
    pub time: f64,
}

impl RunCost {
    /// Seconds on one thread at the nominal rate.
    pub fn seconds(&self) -> f64 {
        self.events / COLLISIONS_PER_SECOND[self.dimension.clamp(1, 3) - 1]
    }
}

/// Expected cost of one run; None when the scene does not resolve. The
/// events may be infinite (speeds or times beyond any run, or a collision
/// count no pair can give).
pub fn run_cost(d: &Descriptor) -> Option<RunCost> {
    let scene = resolved(&d.scene).ok()?;
    let rates = event_rates(&scene)?;
    let rate = rates.gas + rates.piston;
    let event_rate = rate + rates.walls + rates.renewals;
    let timed = |t: f64, r: f64| if t == 0.0 { 0.0 } else { r * t };
    let measured = match (d.run.duration, d.run.collisions) {
        (Some(t), _) => t,
        (None, Some(c)) if rate > 0.0 => c as f64 / rate,
        (None, Some(_)) => f64::INFINITY,
        (None, None) => return None,
    };
    let collisions = match (d.run.duration, d.run.collisions) {
        (None, Some(c)) => c as f64,
        _ => timed(measured, rate),
    };
    let eq = d.run.equilibrate;
    Some(RunCost {
        collisions: collisions + timed(eq, rate),
        events: timed(measured, event_rate) + timed(eq, event_rate),
        dimension: dimension(&scene),
        rate,
        event_rate,
        piston_share: if event_rate > 0.0 {
            rates.piston / event_rate
        } else {
            0.0
        },
        hot_wall: rates.hot_wall,
        heating: rates.heating,
        time: measured + eq,
    })
}

/// One estimate per sweep point or case (its replicas differ only in their
/// seeds): the index of its first run, its cost per run, and its runs.
pub fn by_point(specs: &[RunSpec]) -> Vec<(usize, Option<RunCost>, f64)> {
    let mut costs: Vec<(usize, Option<RunCost>, f64)> = Vec::new();
    for (i, spec) in specs.iter().enumerate() {
        if i == 0 || specs[i - 1].point_id != spec.point_id {
            costs.push((i, run_cost(&spec.descriptor), 0.0));
        }
        if let Some(last) = costs.last_mut() {
            last.2 += 1.0;
        }
    }
    costs
}

/// Events per unit time: collisions among the gas and of the piston with
/// the gas, wall hits, renewals; and the thermal wall that sets the speeds.
struct Rates {
    gas: f64,
    piston: f64,
    walls: f64,
    renewals: f64,
    hot_wall: Option<usize>,
    heating: f64,
}

/// The gas is its movable particles (mass finite); immovable ones are
/// obstacles. Pair collisions N z / 2 among the movable, with each one's
/// collision frequency z = rho <|v_rel|> in 1D (rho over the free length,
/// Tonks), rho 2 sigma <|v_rel|> g(sigma) for disks (a disk sweeps a strip 2
/// sigma wide) and rho pi sigma^2 <|v_rel|> g(sigma) for spheres, g at
/// contact from Henderson (2D) and Carnahan-Starling (3D); <|v_rel|> for the
/// mean mass, and against an obstacle the speed itself (1/sqrt 2 of it).
/// The piston meets the gas on both faces, each of area A (1 in 1D) at the
/// contact density rho g, with the flux of a Maxwellian relative velocity
/// along x: 2 rho g A sqrt(s^2 / (2 pi)), s^2 = kT/m + kT_p/M (kT_p = M
/// <v_p^2>, its start). The walls of an axis of length L are hit at the
/// same flux: 2 N g sqrt(kT / (2 pi m)) / L. In 2D and 3D each movable
/// particle renews its neighbourhood each time it has moved the engine's
/// shell: N <|v|> / shell. kT is the start's, or the hottest thermal
/// wall's if that is hotter (the gas heats up to it).
fn event_rates(scene: &SceneSpec) -> Option<Rates> {
    let d = dimension(scene);
    let size = scene.box_size.as_ref()?;
    let volume: f64 = size.iter().product();
    let species = 0..scene.species.len();
    let all: usize = species.clone().map(|i| count(scene, i)).sum();
    let movable = |i: usize| scene.species[i].mass != Drawn::Fixed(f64::INFINITY);
    let moving: usize = species
        .clone()
        .filter(|&i| movable(i))
        .map(|i| count(scene, i))
        .sum();
    let n = all + usize::from(scene.piston.is_some());
    let none = Rates {
        gas: 0.0,
        piston: 0.0,
        walls: 0.0,
        renewals: 0.0,
        hot_wall: None,
        heating: 1.0,
    };
    if moving == 0 && scene.piston.is_none() || volume <= 0.0 {
        return Some(none);
    }
    let weighted = |f: &dyn Fn(usize) -> f64, over: &dyn Fn(usize) -> bool| {
        let of: usize = species
            .clone()
            .filter(|&i| over(i))
            .map(|i| count(scene, i))
            .sum();
        species
            .clone()
            .filter(|&i| over(i))
            .map(|i| count(scene, i) as f64 * f(i))
            .sum::<f64>()
            / of.max(1) as f64
    };
    // The mean movable mass; infinite when nothing moves.
    let mass = if moving == 0 {
        f64::INFINITY
    } else {
        weighted(
            &|i| match scene.species[i].mass {
                Mass::Fixed(m) => m,
                Mass::Range([lo, hi]) => 0.5 * (lo + hi),
            },
            &movable,
        )
    };
    let sigma = weighted(
        &|i| scene.species[i].radius.bounds().iter().sum::<f64>(),
        &|_| true,
    );
    let (kt, hot_wall, heating) = temperature(scene, mass, moving);
    let rho = n as f64 / volume;
    let phi = rho * ball_volume(d, 0.5 * sigma);
    // Contact density over rho.
    let g = match d {
        1 => 1.0 / (1.0 - phi).max(1e-3),
        2 => (1.0 - 7.0 * phi / 16.0) / (1.0 - phi).max(1e-3).powi(2),
        _ => (1.0 - phi / 2.0) / (1.0 - phi).max(1e-3).powi(3),
    };
    let z = match d {
        1 => rho * g * 2.0 * (kt / (PI * mass)).sqrt(),
        2 => 2.0 * rho * sigma * (PI * kt / mass).sqrt() * g,
        _ => rho * PI * sigma * sigma * (16.0 * kt / (PI * mass)).sqrt() * g,
    };
    // Of each movable particle's partners, the shares that move and that
    // do not (all move in most scenes: the share 1 and 0).
    let others = all.saturating_sub(1).max(1) as f64;
    let (mobile, obstacles) = (
        moving.saturating_sub(1) as f64 / others,
        (all - moving) as f64 / others,
    );
    let gas_rate = if n < 2 {
        0.0
    } else {
        moving as f64 * z * (0.5 * mobile + obstacles / 2f64.sqrt())
    };
    let piston = match &scene.piston {
        Some(p) if all > 0 => {
            let face: f64 = size.iter().skip(1).product();
            let gas_spread = if mass.is_finite() { kt / mass } else { 0.0 };
            let spread = gas_spread + piston_kt(scene, p, kt) / p.mass;
            2.0 * rho * g * face * (spread / (2.0 * PI)).sqrt()
        }
        _ => 0.0,
    };
    let walled = |k: usize| {
        scene
            .boundary
            .as_ref()
            .and_then(|b| b.get(k))
            .is_none_or(|b| *b != Boundary::Periodic)
    };
    let flux = if mass.is_finite() {
        2.0 * moving as f64 * g * (kt / (2.0 * PI * mass)).sqrt()
    } else {
        0.0
    };
    let walls: f64 = (0..d).filter(|&k| walled(k)).map(|k| flux / size[k]).sum();
    let renewals = in_dimension(
        d,
        Renewals {
            scene,
            moving,
            kt,
            mass,
        },
    )
    .unwrap_or(0.0);
    // NaN: a mean mass or size that is not a number.
    let rates = [gas_rate, piston, walls, renewals];
    (!rates.iter().any(|r| r.is_nan())).then_some(Rates {
        gas: gas_rate,
        piston,
        walls,
        renewals,
        hot_wall,
        heating,
    })
}

/// Disks or spheres whose `moving` particles renew their neighbourhoods
/// each time they have moved the engine's shell (rods have no shell).
struct Renewals<'a> {
    scene: &'a SceneSpec,
    moving: usize,
    kt: f64,
    mass: f64,
}

impl ForDimension for Renewals<'_> {
    type Output = f64;
    fn run<const D: usize>(self) -> f64 {
        let Renewals {
            scene,
            moving,
            kt,
            mass,
        } = self;
        if D == 1 || moving == 0 {
            return 0.0;
        }
        // The mean speed in D dimensions.
        let speed = if D == 2 {
            (PI * kt / (2.0 * mass)).sqrt()
        } else {
            (8.0 * kt / (PI * mass)).sqrt()
        };
        let Ok(sim_box) = crate::scene::build::sim_box::<D>(scene) else {
            return 0.0;
        };
        let balls: usize = (0..scene.species.len()).map(|i| count(scene, i)).sum();
        let largest = scene
            .species
            .iter()
            .map(|sp| sp.radius.bounds()[1])
            .fold(0.0, f64::max);
        let points = balls + usize::from(scene.piston.is_some());
        match crate::engine::neighbours::layout(points, balls, largest, &sim_box) {
            Ok((shell, _)) => moving as f64 * speed / shell,
            // A box the engine cannot follow renews forever (refused at validate).
            Err(_) => f64::INFINITY,
        }
    }
}

/// M <v^2> of the piston at the start: from its `energy` or `velocity`, or
/// as the gas's rule draws it with the piston's mass.
fn piston_kt(scene: &SceneSpec, p: &PistonSpec, kt: f64) -> f64 {
    match (p.energy, p.velocity, &scene.velocities) {
        (Some(e), _, _) => 2.0 * e * kt,
        (None, Some(v), _) => p.mass * v * v,
        (None, None, Some(Velocities::Uniform { p: momentum, .. })) => {
            momentum * momentum / (3.0 * p.mass)
        }
        (None, None, Some(Velocities::Equal { velocity })) => {
            p.mass * velocity.first().map_or(0.0, |v| v * v)
        }
        (None, None, Some(Velocities::Explicit { .. })) => 0.0,
        _ => kt,
    }
}

/// kT of the initial velocities (or its equivalent m <v^2> / d for equal
/// or explicit ones; 1 where the scene does not say), or the hottest
/// thermal wall's if that is hotter, with that wall's index and
/// sqrt(T_wall / kT) (1 if none).
fn temperature(scene: &SceneSpec, mass: f64, gas: usize) -> (f64, Option<usize>, f64) {
    let d = dimension(scene) as f64;
    let from_speeds = |v2: f64| mass * v2 / d;
    let kt = match &scene.velocities {
        Some(Velocities::Maxwell {
            energy: Some(e), ..
        })
        | Some(Velocities::Uniform {
            energy: Some(e), ..
        }) => 2.0 * e / (d * gas.max(1) as f64),
        Some(Velocities::Maxwell { temperature, .. }) => *temperature,
        // Momentum components uniform in [-p, p]: m <v_x^2> = p^2 / (3 m).
        Some(Velocities::Uniform { p, .. }) => p * p / (3.0 * mass),
        Some(Velocities::Equal { velocity }) => from_speeds(velocity.iter().map(|v| v * v).sum()),
        Some(Velocities::Explicit { velocities }) => from_speeds(
            velocities
                .iter()
                .map(|v| v.iter().map(|x| x * x).sum::<f64>())
                .sum::<f64>()
                / velocities.len().max(1) as f64,
        ),
        None => 1.0,
    };
    // Speeds too large to square give no finite kT: so many collisions.
    let kt = match kt {
        kt if kt.is_nan() || kt <= 0.0 => 1.0,
        kt => kt,
    };
    let hottest = scene
        .thermal_walls
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.temperature.total_cmp(&b.1.temperature));
    match hottest {
        Some((i, w)) if w.temperature > kt => (w.temperature, Some(i), (w.temperature / kt).sqrt()),
        _ => (kt, None, 1.0),
    }
}
