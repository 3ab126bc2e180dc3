//! The section's figures: Z against packing fraction with the equations of
//! state, Z over the reference equation, pressure against time, Z against
//! 1/N, and the dense disks' pressure.

use super::equations;
use super::finite_size::Fit;
use super::phases::DISK_FLUID_ENDS;
use super::points::Point;
use crate::model::chart::{Layer, Paint, colour};
use crate::model::report::Figure;
use crate::studies::curves::{figure, markers, measured, polyline, sampled};

pub const NAMES: [&str; 3] = [
    "Rods (1D, walls)",
    "Disks (2D, periodic)",
    "Spheres (3D, periodic)",
];

/// The bulk points of dimension `d`: periodic boxes, and rods.
pub fn bulk(all: &[Point], d: usize) -> Vec<&Point> {
    all.iter()
        .filter(|p| p.dimension == d && p.bulk())
        .collect()
}

pub fn z_chart(all: &[Point]) -> Figure {
    let ideal = vec![(0.0, 1.0), (reach(all), 1.0)];
    let mut layers = vec![thin(ideal, black(), true, Some("ideal gas".into()))];
    for d in 1..=3 {
        let pts = bulk(all, d);
        if pts.is_empty() {
            continue;
        }
        let paint = colour(d - 1);
        for (i, e) in equations::of(d).iter().enumerate() {
            // Each curve up to where it is meant to hold (rods: to the data),
            // and never past where its formula means anything.
            let end = (reach(pts.iter().copied()).min(e.holds_below.max(0.3) + 0.05))
                .min(e.defined_below);
            let faded = paint.faded(if i == 0 { 1.0 } else { 0.6 });
            let label = Some(format!("{}D: {}", d, e.name));
            layers.push(thin(sampled(0.0, end, 200, e.z), faded, i > 0, label));
        }
        layers.extend(at_eta(&pts, paint, NAMES[d - 1], |p| {
            (p.z.mean, p.error().0)
        }));
    }
    let labels = (
        "Equation of state: Z = βP/ρ".into(),
        "packing fraction η",
        "Z = βP/ρ",
    );
    figure("pressure_z.svg", labels, (false, true), layers)
}

/// None when no point has a reference equation that holds (the disks'
/// loop study, say): an empty chart says nothing.
pub fn deviation_chart(all: &[Point]) -> Option<Figure> {
    let mut layers = Vec::new();
    for d in 1..=3 {
        // Fluid points where the reference equation holds.
        let pts: Vec<&Point> = (bulk(all, d).into_iter())
            .filter(|p| p.reference_holds())
            .collect();
        if pts.is_empty() {
            continue;
        }
        let paint = colour(d - 1);
        let [reference, others @ ..] = equations::of(d) else {
            continue;
        };
        for e in others {
            let over = |eta| (e.z)(eta) / (reference.z)(eta) - 1.0;
            let end = reach(pts.iter().copied()).min(e.holds_below + 0.05);
            let label = Some(format!("{}D: {}", d, e.name));
            layers.push(thin(
                sampled(0.0, end, 200, over),
                paint.faded(0.6),
                true,
                label,
            ));
        }
        layers.extend(at_eta(&pts, paint, NAMES[d - 1], |p| {
            let r = (reference.z)(p.eta);
            (p.z.mean / r - 1.0, p.error().0 / r)
        }));
    }
    let title = "Z over the reference equation, minus 1 (fluid points, finite N)";
    let labels = (title.into(), "packing fraction η", "Z / Z_reference − 1");
    (!layers.is_empty()).then(|| figure("pressure_deviation.svg", labels, (false, false), layers))
}

/// The pressure of a few runs against time, each over its own mean.
pub fn time_chart(examples: &[(&Point, &str)]) -> Figure {
    let mut layers = Vec::new();
    for (i, (p, label)) in examples.iter().enumerate() {
        let Some((t, v)) = &p.example else {
            continue;
        };
        let mean = v.iter().sum::<f64>() / v.len() as f64;
        let points = t.iter().zip(v).map(|(t, v)| (*t, v / mean)).collect();
        let (paint, label) = (colour(i).faded(0.7), Some(label.to_string()));
        layers.push(thin(points, paint, false, label));
    }
    let title = "Pressure against time (one replica each, per sampling interval)";
    let labels = (title.into(), "time t (σ√(m/kT))", "P(t) / mean P");
    figure("pressure_time.svg", labels, (false, false), layers)
}

pub fn finite_size_chart(fits: &[Fit]) -> Figure {
    let mut layers = Vec::new();
    for (i, f) in fits.iter().enumerate() {
        let paint = colour(i);
        let r = (equations::of(f.dimension)[0].z)(f.eta);
        let rel = |z: f64| z / r - 1.0;
        let xmax = f.data.iter().map(|d| 1.0 / d.0 as f64).fold(0.0, f64::max);
        let fitted = sampled(0.0, xmax, 20, |x| rel(f.z_inf + f.slope * x));
        layers.push(thin(fitted, paint.faded(0.6), true, None));
        // The points at 1/N, and the extrapolation at 0.
        let bars = f.data.iter().map(|&(n, z, e)| (1.0 / n as f64, z, e));
        let bars = bars.chain([(0.0, f.z_inf, f.z_inf_err)]);
        let bars = bars
            .map(|(x, z, e)| (x, rel(z - e), rel(z), rel(z + e)))
            .collect();
        layers.push(Layer::ErrorBars { bars, paint });
        let points = f.data.iter().map(|&(n, z, _)| (1.0 / n as f64, rel(z)));
        let label = format!("{}D, η = {:.3}", f.dimension, f.eta);
        layers.push(markers(points.collect(), paint, Some(label)));
    }
    let zero = vec![(0.0, 0.0), (1.0 / 64.0, 0.0)];
    layers.push(thin(zero, black(), true, Some("reference equation".into())));
    let title = "Finite size: Z against 1/N, extrapolated to N → ∞ (at 1/N = 0)";
    let labels = (title.into(), "1/N", "Z / Z_reference − 1");
    figure("pressure_finite_size.svg", labels, (false, false), layers)
}

/// βPσ² = Z ρ of the dense disks of one size, with the fluid's equation as
/// far as the fluid goes.
pub fn dense_disks_chart(pts: &[&Point]) -> Figure {
    let rho = |eta: f64| 4.0 * eta / std::f64::consts::PI;
    let paint = colour(1);
    // A line joins the means; the fluid's equation (at N → ∞) is drawn up to
    // where the fluid ends, not beyond: it knows nothing of the hexatic phase.
    let means = pts.iter().map(|p| (p.eta, p.z.mean * rho(p.eta))).collect();
    let mut layers = vec![thin(means, paint.faded(0.5), true, None)];
    let fluid = &equations::of(2)[0];
    let first = pts.iter().map(|p| p.eta).fold(f64::INFINITY, f64::min);
    if first < DISK_FLUID_ENDS {
        let points = sampled(first, DISK_FLUID_ENDS, 200, |eta| (fluid.z)(eta) * rho(eta));
        let label = Some(format!("{} (fluid, N → ∞)", fluid.name));
        layers.push(thin(points, colour(0), false, label));
    }
    layers.extend(at_eta(pts, paint, "disks", |p| {
        (p.z.mean * rho(p.eta), p.error().0 * rho(p.eta))
    }));
    let n = pts.first().map_or(0, |p| p.particles);
    let title = format!("Disks near the liquid-hexatic transition, N = {n}");
    let labels = (title, "packing fraction η", "βPσ²");
    figure("pressure_dense_disks.svg", labels, (false, false), layers)
}

fn black() -> Paint {
    Paint::solid((0, 0, 0))
}

/// A little beyond the densest of `pts`: where the curves end.
fn reach<'a>(pts: impl IntoIterator<Item = &'a Point>) -> f64 {
    pts.into_iter().map(|p| p.eta).fold(0.0, f64::max) * 1.02
}

/// A line one pixel wide.
fn thin(points: Vec<(f64, f64)>, paint: Paint, dashed: bool, label: Option<String>) -> Layer {
    polyline(points, paint, 1, dashed, label)
}

/// The points at their η: `y` gives each one's value and error.
fn at_eta(
    pts: &[&Point],
    paint: Paint,
    label: &str,
    y: impl Fn(&Point) -> (f64, f64),
) -> [Layer; 2] {
    let bars = pts.iter().map(|p| {
        let (m, e) = y(p);
        (p.eta, m - e, m, m + e)
    });
    measured(bars, paint, label)
}
