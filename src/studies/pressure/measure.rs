//! Z of one run, from the pressure it measured and its own temperature
//! kT = 2K/f: K the kinetic energy (conserved), f the free degrees of
//! freedom, dN with walls and d(N − 1) in a periodic box, whose centre of
//! mass carries no heat. Walls (`wall_pressure`): Z = P V / (N kT), for
//! rods Tonks' exact 1/(1 − η). Virial (`virial_pressure`): P V = 2K/d +
//! W/d, and Z = 1 + W / (d N kT) takes the ideal part as the canonical
//! ensemble's (methods.md, "Ensemble"). With walls the virial theorem has a
//! wall term: a wall pushes a particle at its centre, a radius from it, so
//! 2K + W = P_wall (d V − σ A / 2), A the walls' area: both measure P_wall.
//!
//! With the pressure series (`[observe] series`), Z is the mean over the
//! sampling intervals left after the MSER cut (`stats::mser`), with a
//! block-average error bar (`stats::blocking`); without, it is the run's
//! scalar. The run's own error estimate is that block error, except for
//! equal rods between walls (`rod_stderr`).

use super::packing;
use crate::engine::Particle;
use crate::model::run_output::RunOutput;
use crate::observe::Context;
use crate::stats::blocking::{blocked, drift};
use crate::stats::mser;
use crate::stats::summary::Stats;

/// What one run adds, in `RESULTS` order: Z (from the walls where there
/// are walls, else from the virial), Z from the walls and from the virial,
/// packing fraction and density; the time the MSER rule cut from the start
/// of the recorded series; the block-average standard error of Z, the block
/// length (time) it used and the estimate with blocks twice as long over it;
/// the run's own standard error of Z (the block error, or for equal rods
/// between walls the wall-hit model's; NaN without either); and the drift:
/// the mean of the second half of the kept series minus the first, over the
/// error of that difference (about N(0, 1) when equilibrated).
pub type Measured = [f64; super::RESULTS.len()];

pub fn measure<const D: usize>(
    particles: &[Particle<D>],
    ctx: &Context,
    out: &RunOutput,
) -> Result<Measured, String> {
    let movable: Vec<&Particle<D>> = particles.iter().filter(|p| p.inv_mass > 0.0).collect();
    let kinetic: f64 = movable
        .iter()
        .map(|p| 0.5 * p.vel.iter().map(|v| v * v).sum::<f64>() / p.inv_mass)
        .sum();
    let n = movable.len() as f64;
    // Mean diameter: exact for one size, which the study uses.
    let sigma = movable.iter().map(|p| 2.0 * p.radius).sum::<f64>() / n;
    let (kt, ideal) = (
        2.0 * kinetic / ctx.degrees_of_freedom,
        2.0 * kinetic / D as f64,
    );
    // d V / (d V - sigma A / 2): 1 without walls.
    let dv = D as f64 * ctx.volume;
    let wall_term = dv / (dv - 0.5 * sigma * ctx.wall_area);
    // Z from a pressure `p`: walls or virial (see the module doc).
    let z_wall = |p: f64| p * ctx.volume / (n * kt);
    let z_virial = |p: f64| 1.0 + (p * wall_term * ctx.volume - ideal) / (n * kt);
    let (eta, rho) = packing::of_particles(particles, ctx.volume);
    let series = |name: &str, f: &dyn Fn(f64) -> f64| -> Option<(Vec<f64>, f64)> {
        let s = out.series(name)?;
        let dt = s.t.get(1).map_or(f64::NAN, |t| t - s.t[0]);
        Some((s.value.iter().map(|&p| f(p)).collect(), dt))
    };
    let wall = series("wall_pressure", &z_wall);
    let virial = series("virial_pressure", &z_virial);
    let z_wall_scalar = out.scalar("wall_pressure").map(z_wall);
    let z_virial_scalar = out.scalar("virial_pressure").map(z_virial);

    let mut wall_z = z_wall_scalar.unwrap_or(f64::NAN);
    let mut virial_z = z_virial_scalar.unwrap_or(f64::NAN);
    // From the series, NaN without one: the cut, block error, block length,
    // doubling ratio and drift.
    let [
        mut cut_time,
        mut block,
        mut length,
        mut doubling,
        mut drifted,
    ] = [f64::NAN; 5];
    // Equal rods between walls: the mass of each, else None.
    let rod_mass = (D == 1 && ctx.wall_area > 0.0 && !movable.is_empty())
        .then(|| movable[0].inv_mass)
        .filter(|&im| movable.iter().all(|p| p.inv_mass == im))
        .map(|im| 1.0 / im);
    let mut measured_time = ctx.duration;
    let main = wall.as_ref().or(virial.as_ref());
    let z = if let Some((z, dt)) = main {
        let cut = mser::cut(z);
        let kept = &z[cut..];
        cut_time = cut as f64 * dt;
        measured_time = kept.len() as f64 * dt;
        if let Some(b) = blocked(kept) {
            (block, length, doubling) = (b.stderr, b.length as f64 * dt, b.doubling);
        }
        drifted = drift(kept);
        // The series' means over the same kept stretch.
        if let Some((w, _)) = &wall {
            wall_z = Stats::of(&w[cut..]).mean;
        }
        if let Some((v, _)) = &virial {
            virial_z = Stats::of(&v[cut..]).mean;
        }
        Stats::of(kept).mean
    } else {
        z_wall_scalar.or(z_virial_scalar).ok_or(
            "the pressure analysis needs `wall_pressure` (walls) or `virial_pressure` in [observe] scalars or series",
        )?
    };
    let own = match rod_mass {
        Some(mass) if wall.is_some() || z_wall_scalar.is_some() => {
            rod_stderr(ctx.volume, measured_time, kinetic, mass)
        }
        _ => block,
    };
    Ok([
        z, wall_z, virial_z, eta, rho, cut_time, block, length, doubling, own, drifted,
    ])
}

/// The standard error of Z of equal rods of mass `mass` between walls, a
/// box `length` long, over a measured `time` at kinetic energy `kinetic`.
/// Equal rods swap velocities, so the gas is N free "ghosts" each hitting
/// a wall every L'/|v| (L' the free length): over T the hits of ghost i are
/// off their exact mean by a Bernoulli step of variance 1/6 on average, so
/// σ_Z = (L/T) √(m / 12K), falling as 1/T; block averages, which assume
/// 1/√T, overstate it (7x for 100 rods at η = 0.2 over T = 2000; 256
/// replicas of those scatter by 0.0103, this gives 0.0102).
fn rod_stderr(length: f64, time: f64, kinetic: f64, mass: f64) -> f64 {
    length / time * (mass / (12.0 * kinetic)).sqrt()
}

#[cfg(test)]
mod tests {
    #[test]
    fn hundred_rods() {
        // 100 rods at kT = 1 (K = 50) in a box of 500 over 2000.
        assert!((super::rod_stderr(500.0, 2000.0, 50.0, 1.0) - 0.010_206).abs() < 1e-6);
    }
}
