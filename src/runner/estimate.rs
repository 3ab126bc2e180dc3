//! What `study validate` expects a plan to cost, before running it: pair
//! collisions from the kinetic theory of a hard-particle gas, and time from a
//! nominal collision rate per thread. Estimates, not promises: the dense,
//! inhomogeneous or far-from-equilibrium scenes differ from them.

use crate::descriptor::validate::resolved;
use crate::descriptor::validate_scene::{count, dimension};
use crate::engine::boundary::ball_volume;
use crate::model::descriptor::Descriptor;
use crate::model::run_spec::RunSpec;
use crate::model::scene::{Mass, PistonSpec, SceneSpec, Velocities};
use std::f64::consts::PI;

/// Nominal pair collisions per second on one thread in 1D, 2D and 3D: the
/// engine benchmarks of docs/performance.md (4.6 M/s for rods, 0.8 M/s for
/// disks, 0.3-0.4 M/s for spheres on one core), rounded down because small
/// systems with sampling and analyses do more per collision.
pub const COLLISIONS_PER_SECOND: [f64; 3] = [3.0e6, 0.8e6, 0.3e6];

/// The expected cost of one run of a sweep point's descriptor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunCost {
    /// Pair collisions, equilibration included.
    pub collisions: f64,
    pub dimension: usize,
    /// Pair collisions per unit time (the piston's included).
    pub rate: f64,
    /// Of the collisions per unit time, those of the piston (0 without one).
    pub piston_share: f64,
}

impl RunCost {
    /// Seconds on one thread at the nominal rate.
    pub fn seconds(&self) -> f64 {
        self.collisions / COLLISIONS_PER_SECOND[self.dimension.clamp(1, 3) - 1]
    }
}

/// Expected cost of one run; None when the scene does not resolve. The
/// collisions may be infinite (speeds or times beyond any run).
pub fn run_cost(d: &Descriptor) -> Option<RunCost> {
    let scene = resolved(&d.scene).ok()?;
    let Rates { gas, piston } = collision_rates(&scene)?;
    let rate = gas + piston;
    let timed = |t: f64| if t == 0.0 { 0.0 } else { rate * t };
    let measured = match (d.run.duration, d.run.collisions) {
        (Some(t), _) => timed(t),
        (None, Some(c)) => c as f64,
        (None, None) => return None,
    };
    Some(RunCost {
        collisions: measured + timed(d.run.equilibrate),
        dimension: dimension(&scene),
        rate,
        piston_share: if rate > 0.0 { piston / rate } else { 0.0 },
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

/// Collisions per unit time: among the gas, and of the piston with the gas.
struct Rates {
    gas: f64,
    piston: f64,
}

/// N z / 2 for the gas, with each particle's collision frequency z = rho
/// <|v_rel|> in 1D (rho over the free length, Tonks), rho 2 sigma <|v_rel|>
/// g(sigma) for disks (a disk sweeps a strip 2 sigma wide) and rho pi sigma^2 <|v_rel|> g(sigma) for spheres, g
/// at contact from Henderson (2D) and Carnahan-Starling (3D); <|v_rel|> for
/// the mean mass. The piston meets the gas on both faces, each of area A
/// (1 in 1D) at the contact density rho g, with the flux of a Maxwellian
/// relative velocity along x: 2 rho g A sqrt(s^2 / (2 pi)), s^2 = kT/m +
/// kT_p/M (kT_p = M <v_p^2>, its start).
fn collision_rates(scene: &SceneSpec) -> Option<Rates> {
    let d = dimension(scene);
    let size = scene.box_size.as_ref()?;
    let volume: f64 = size.iter().product();
    let gas: usize = (0..scene.species.len()).map(|i| count(scene, i)).sum();
    let n = gas + usize::from(scene.piston.is_some());
    if n < 2 || volume <= 0.0 {
        return Some(Rates {
            gas: 0.0,
            piston: 0.0,
        });
    }
    let weighted = |f: &dyn Fn(usize) -> f64| {
        (0..scene.species.len())
            .map(|i| count(scene, i) as f64 * f(i))
            .sum::<f64>()
            / gas.max(1) as f64
    };
    let mass = weighted(&|i| match scene.species[i].mass {
        Mass::Fixed(m) if m.is_finite() => m,
        Mass::Fixed(_) => f64::NAN,
        Mass::Range([lo, hi]) => 0.5 * (lo + hi),
    });
    let sigma = weighted(&|i| scene.species[i].radius.bounds().iter().sum::<f64>());
    let kt = temperature(scene, mass, gas);
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
    let gas_rate = 0.5 * gas as f64 * z;
    let piston = match &scene.piston {
        Some(p) if gas > 0 => {
            let face: f64 = size.iter().skip(1).product();
            let spread = kt / mass + piston_kt(scene, p, kt) / p.mass;
            2.0 * rho * g * face * (spread / (2.0 * PI)).sqrt()
        }
        _ => 0.0,
    };
    // NaN: a mean mass that is not a number (immovable particles).
    (!gas_rate.is_nan() && !piston.is_nan()).then_some(Rates {
        gas: gas_rate,
        piston,
    })
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
/// or explicit ones); 1 where the scene does not say.
fn temperature(scene: &SceneSpec, mass: f64, gas: usize) -> f64 {
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
    match kt {
        kt if kt.is_nan() || kt <= 0.0 => 1.0,
        kt => kt,
    }
}
