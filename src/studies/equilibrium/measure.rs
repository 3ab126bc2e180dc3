//! What one run adds: for rods, the lightest and heaviest particle's
//! Gaussian fit and excess kurtosis; for disks and spheres, kT, the
//! kurtosis of v_x, g at contact beside the pressure, and the density at
//! a wall beside the wall pressure. Each group is written when the run
//! observed what it needs, as NaN where the scene does not allow it.

use super::ensemble::{Ball, Ensemble};
use super::moments;
use crate::model::run_output::{Histogram, RunOutput};
use crate::observe::Context;
use crate::stats::quadratic::quadratic_at_zero;

pub fn histogram<'a>(out: &'a RunOutput, name: &str) -> Option<&'a Histogram> {
    out.histograms.iter().find(|h| h.observable == name)
}

pub fn measure(e: &Ensemble, ctx: &Context, out: &mut RunOutput) {
    let mut add = vec![("kT", e.kt())];
    // The lightest and the heaviest ball, each with its Gaussian fit.
    let fit = |b: Option<&Ball>| {
        let b = *b?;
        Some((
            b,
            moments::of(histogram(out, &format!("velocity_x.{}", b.index))?),
        ))
    };
    let by_mass = e.by_mass();
    if let (Some((light, l)), Some((heavy, h))) = (fit(by_mass.first()), fit(by_mass.last())) {
        let exact = e.velocity_law(light.mass).std() / e.velocity_law(heavy.mass).std();
        let ratio = l.std / h.std;
        add.extend([
            ("lightest_mass", light.mass),
            ("heaviest_mass", heavy.mass),
            ("std_lightest", l.std),
            ("std_heaviest", h.std),
            ("std_ratio", ratio),
            ("sqrt_mass_ratio", (heavy.mass / light.mass).sqrt()),
            ("std_ratio_exact", exact),
            ("std_ratio_over_exact", ratio / exact),
            ("kurtosis_lightest", l.excess_kurtosis),
            ("kurtosis_heaviest", h.excess_kurtosis),
        ]);
    }
    if let Some(h) = histogram(out, "scaled_velocity_x") {
        add.push(("kurtosis_vx", moments::of(h).excess_kurtosis));
    }
    if let Some(h) = histogram(out, "pair_distance") {
        let g = contact(e, h).unwrap_or(f64::NAN);
        let n = e.balls.len() as f64;
        let z = 1.0 + contact_factor(e.dimension) * e.packing() * (n - 1.0) / n * g;
        add.extend([
            ("packing_fraction", e.packing()),
            ("g_contact", g),
            ("Z_contact", z),
        ]);
        if let Some(p) = out.scalar("virial_pressure") {
            // The virial's kinetic part is 2K/d = (N - 1) kT when momentum
            // is conserved; the excess is the collisions' (as the pressure
            // study takes it).
            let kinetic = 0.5 * e.dof * e.kt();
            let zv = 1.0 + (p * ctx.volume - 2.0 * kinetic / e.dimension as f64) / (n * e.kt());
            add.extend([("Z_virial", zv), ("Z_contact_over_virial", z / zv)]);
        }
    }
    if let (Some(h), Some(p)) = (histogram(out, "density_x"), out.scalar("wall_pressure")) {
        let n = wall_density(e, h).unwrap_or(f64::NAN);
        add.extend([
            ("wall_density", n),
            ("contact_theorem_ratio", n * e.kt() / p),
        ]);
    }
    out.scalars
        .extend(add.into_iter().map(|(k, v)| (k.to_string(), v)));
}

/// Z = 1 + c phi g(sigma): c = 2 for disks, 4 for spheres, 1 for rods.
pub fn contact_factor(dimension: usize) -> f64 {
    [1.0, 2.0, 4.0][dimension.clamp(1, 3) - 1]
}

/// Volume of the shell between radii a and b in d dimensions.
pub fn shell(dimension: usize, a: f64, b: f64) -> f64 {
    let d = dimension.clamp(1, 3);
    [2.0, std::f64::consts::PI, 4.0 / 3.0 * std::f64::consts::PI][d - 1]
        * (b.powi(d as i32) - a.powi(d as i32))
}

/// g(r) at each bin: mean pairs per sample over an ideal gas's N(N-1)/2
/// shell/V (periodic boxes; finite N).
pub fn radial_distribution(e: &Ensemble, h: &Histogram) -> Vec<f64> {
    let n = e.balls.len() as f64;
    let pairs = 0.5 * n * (n - 1.0);
    per_bin(h, |a, b| pairs * shell(e.dimension, a, b) / e.volume)
}

/// Each bin's count over `norm(lo, hi)`.
fn per_bin(h: &Histogram, norm: impl Fn(f64, f64) -> f64) -> Vec<f64> {
    let bins = h.lo.iter().zip(&h.hi).zip(&h.count);
    bins.map(|((a, b), c)| c / norm(*a, *b)).collect()
}

/// Bins a contact value is extrapolated from: 0.16 sigma.
const CONTACT_BINS: usize = 8;

/// g at contact: a quadratic fitted to g over the first bins at and beyond
/// sigma, evaluated at sigma. None unless every axis is periodic and the
/// balls share one diameter.
pub fn contact(e: &Ensemble, h: &Histogram) -> Option<f64> {
    let sigma = 2.0 * e.balls.first()?.radius;
    if !e.periodic.iter().all(|p| *p) || e.balls.iter().any(|b| 2.0 * b.radius != sigma) {
        return None;
    }
    let g = radial_distribution(e, h);
    let beyond = (h.lo.iter().zip(&h.hi).zip(&g)).filter(|((a, _), _)| **a >= sigma - 1e-9);
    at_contact(beyond.map(|((a, b), g)| (0.5 * (a + b) - sigma, *g)))
}

/// A quadratic through the first `CONTACT_BINS` points (distance beyond
/// contact, value), at contact; None with fewer.
fn at_contact(points: impl Iterator<Item = (f64, f64)>) -> Option<f64> {
    let first: Vec<(f64, f64)> = points.take(CONTACT_BINS).collect();
    (first.len() == CONTACT_BINS).then(|| quadratic_at_zero(&first))
}

/// The centre density at a wall along x: the profile extrapolated to
/// contact (x = r) from both walls' first bins, per unit length (1D), area
/// (2D) or volume (3D). None unless x has walls and the balls share a
/// radius.
pub fn wall_density(e: &Ensemble, h: &Histogram) -> Option<f64> {
    let r = e.balls.first()?.radius;
    if e.periodic[0] || e.balls.iter().any(|b| b.radius != r) {
        return None;
    }
    let density = profile(e, h);
    let length = e.size[0];
    let end = |high: bool| {
        // Distances beyond contact; bins straddling contact are part
        // empty: start beyond them.
        let mut points: Vec<(f64, f64)> = (h.lo.iter().zip(&h.hi).zip(&density))
            .map(|((a, b), n)| (0.5 * (a + b), *n))
            .map(|(x, n)| ((if high { length - x } else { x }) - r, n))
            .filter(|(x, _)| *x >= 0.5 * (h.hi[0] - h.lo[0]))
            .collect();
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        at_contact(points.into_iter())
    };
    Some(0.5 * (end(false)? + end(true)?))
}

/// Number density along x at each bin of a density_x histogram.
pub fn profile(e: &Ensemble, h: &Histogram) -> Vec<f64> {
    let n = e.balls.len() as f64;
    let samples = h.count.iter().sum::<f64>() / n;
    let cross = e.volume / e.size[0];
    per_bin(h, |a, b| samples * (b - a) * cross)
}
