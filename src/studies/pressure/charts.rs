//! The section's figures as chart data: Z against packing fraction with the
//! equations of state, Z over the reference equation, pressure against time,
//! Z against 1/N, and the dense disks' pressure.

use super::equations::{self, Equation};
use super::finite_size::Fit;
use super::phases::DISK_FLUID_ENDS;
use super::points::Point;
use crate::model::chart::{ChartSpec, Layer, Paint, colour};

pub const NAMES: [&str; 3] = [
    "Rods (1D, walls)",
    "Disks (2D, periodic)",
    "Spheres (3D, periodic)",
];

/// `f` at 201 packing fractions from `first` to `top`.
fn curve(first: f64, top: f64, f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    (0..=200)
        .map(|k| {
            let eta = first + (top - first) * k as f64 / 200.0;
            (eta, f(eta))
        })
        .collect()
}

/// The bulk points of dimension `d`: periodic boxes, and rods.
pub fn bulk(all: &[Point], d: usize) -> Vec<&Point> {
    all.iter()
        .filter(|p| p.dimension == d && (d == 1 || !p.walls))
        .collect()
}

pub fn z_chart(all: &[Point]) -> ChartSpec {
    let top = all.iter().map(|p| p.eta).fold(0.0, f64::max) * 1.02;
    let ideal = vec![(0.0, 1.0), (top, 1.0)];
    let mut layers = vec![line(ideal, BLACK, true, Some("ideal gas".into()))];
    for d in 1..=3 {
        let pts = bulk(all, d);
        if pts.is_empty() {
            continue;
        }
        let paint = colour(d - 1);
        let reach = pts.iter().map(|p| p.eta).fold(0.0, f64::max) * 1.02;
        for (i, e) in equations::of(d).iter().enumerate() {
            // Each curve up to where it is meant to hold (rods: to the data),
            // and never past where its formula means anything.
            let end = reach
                .min(e.holds_below.max(0.3) + 0.05)
                .min(e.defined_below);
            let faded = paint.faded(if i == 0 { 1.0 } else { 0.6 });
            let label = Some(format!("{}D: {}", d, e.name));
            layers.push(line(curve(0.0, end, e.z), faded, i > 0, label));
        }
        markers(&mut layers, &pts, paint, NAMES[d - 1], |p| {
            (p.z.mean, p.error().0)
        });
    }
    ChartSpec {
        title: "Equation of state: Z = βP/ρ".into(),
        x_label: "packing fraction η".into(),
        y_label: "Z = βP/ρ".into(),
        y_log: true,
        layers,
        ..Default::default()
    }
}

/// None when no point has a reference equation that holds (the disks'
/// loop study, say): an empty chart says nothing.
pub fn deviation_chart(all: &[Point]) -> Option<ChartSpec> {
    let mut layers = Vec::new();
    for d in 1..=3 {
        // Fluid points where the reference equation holds.
        let eqs = equations::of(d);
        let reference: &Equation = &eqs[0];
        let pts: Vec<&Point> = bulk(all, d)
            .into_iter()
            .filter(|p| p.eta <= reference.holds_below)
            .collect();
        if pts.is_empty() {
            continue;
        }
        let paint = colour(d - 1);
        let reach = pts.iter().map(|p| p.eta).fold(0.0, f64::max) * 1.02;
        for e in &eqs[1..] {
            let over = |eta| (e.z)(eta) / (reference.z)(eta) - 1.0;
            let points = curve(0.0, reach.min(e.holds_below + 0.05), over);
            let label = Some(format!("{}D: {}", d, e.name));
            layers.push(line(points, paint.faded(0.6), true, label));
        }
        markers(&mut layers, &pts, paint, NAMES[d - 1], |p| {
            let r = (reference.z)(p.eta);
            (p.z.mean / r - 1.0, p.error().0 / r)
        });
    }
    if layers.is_empty() {
        return None;
    }
    Some(ChartSpec {
        title: "Z over the reference equation, minus 1 (fluid points, finite N)".into(),
        x_label: "packing fraction η".into(),
        y_label: "Z / Z_reference − 1".into(),
        layers,
        ..Default::default()
    })
}

/// The pressure of a few runs against time, each over its own mean.
pub fn time_chart(examples: &[(&Point, &str)]) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, (p, label)) in examples.iter().enumerate() {
        let Some((_, t, v)) = &p.example else {
            continue;
        };
        let mean = v.iter().sum::<f64>() / v.len() as f64;
        let points = t.iter().zip(v).map(|(t, v)| (*t, v / mean)).collect();
        layers.push(line(
            points,
            colour(i).faded(0.7),
            false,
            Some(label.to_string()),
        ));
    }
    ChartSpec {
        title: "Pressure against time (one replica each, per sampling interval)".into(),
        x_label: "time t (σ√(m/kT))".into(),
        y_label: "P(t) / mean P".into(),
        layers,
        ..Default::default()
    }
}

pub fn finite_size_chart(fits: &[Fit]) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, f) in fits.iter().enumerate() {
        let paint = colour(i);
        let r = (equations::of(f.dimension)[0].z)(f.eta);
        let rel = |z: f64| z / r - 1.0;
        let xmax = f.data.iter().map(|d| 1.0 / d.0 as f64).fold(0.0, f64::max);
        let xs = (0..=20).map(|k| xmax * k as f64 / 20.0);
        let fitted = xs.map(|x| (x, rel(f.z_inf + f.slope * x))).collect();
        layers.push(line(fitted, paint.faded(0.6), true, None));
        // The points at 1/N, and the extrapolation at 0.
        let bars = f.data.iter().map(|&(n, z, e)| (1.0 / n as f64, z, e));
        let bars = bars.chain([(0.0, f.z_inf, f.z_inf_err)]);
        layers.push(Layer::ErrorBars {
            bars: bars
                .map(|(x, z, e)| (x, rel(z - e), rel(z), rel(z + e)))
                .collect(),
            paint,
        });
        layers.push(Layer::Markers {
            points: f
                .data
                .iter()
                .map(|&(n, z, _)| (1.0 / n as f64, rel(z)))
                .collect(),
            paint,
            label: Some(format!("{}D, η = {:.3}", f.dimension, f.eta)),
        });
    }
    let zero = vec![(0.0, 0.0), (1.0 / 64.0, 0.0)];
    layers.push(line(zero, BLACK, true, Some("reference equation".into())));
    ChartSpec {
        title: "Finite size: Z against 1/N, extrapolated to N → ∞ (at 1/N = 0)".into(),
        x_label: "1/N".into(),
        y_label: "Z / Z_reference − 1".into(),
        layers,
        ..Default::default()
    }
}

/// βPσ² = Z ρ of the dense disks of one size, with the fluid's equation as
/// far as the fluid goes.
pub fn dense_disks_chart(pts: &[&Point]) -> ChartSpec {
    let rho = |eta: f64| 4.0 * eta / std::f64::consts::PI;
    let paint = colour(1);
    // A line joins the means; the fluid's equation (at N → ∞) is drawn up to
    // where the fluid ends, not beyond: it knows nothing of the hexatic phase.
    let means = pts.iter().map(|p| (p.eta, p.z.mean * rho(p.eta))).collect();
    let mut layers = vec![line(means, paint.faded(0.5), true, None)];
    let fluid = &equations::of(2)[0];
    let first = pts.iter().map(|p| p.eta).fold(f64::INFINITY, f64::min);
    if first < DISK_FLUID_ENDS {
        let points = curve(first, DISK_FLUID_ENDS, |eta| (fluid.z)(eta) * rho(eta));
        let label = Some(format!("{} (fluid, N → ∞)", fluid.name));
        layers.push(line(points, colour(0), false, label));
    }
    markers(&mut layers, pts, paint, "disks", |p| {
        (p.z.mean * rho(p.eta), p.error().0 * rho(p.eta))
    });
    ChartSpec {
        title: format!(
            "Disks near the liquid-hexatic transition, N = {}",
            pts.first().map_or(0, |p| p.particles)
        ),
        x_label: "packing fraction η".into(),
        y_label: "βPσ²".into(),
        layers,
        ..Default::default()
    }
}

const BLACK: Paint = Paint {
    rgb: (0, 0, 0),
    alpha: 1.0,
};

/// A line one pixel wide.
fn line(points: Vec<(f64, f64)>, paint: Paint, dashed: bool, label: Option<String>) -> Layer {
    Layer::Line {
        points,
        paint,
        width: 1,
        dashed,
        label,
    }
}

fn markers(
    layers: &mut Vec<Layer>,
    pts: &[&Point],
    paint: Paint,
    label: &str,
    y: impl Fn(&Point) -> (f64, f64),
) {
    layers.push(Layer::ErrorBars {
        bars: pts
            .iter()
            .map(|p| {
                let (m, e) = y(p);
                (p.eta, m - e, m, m + e)
            })
            .collect(),
        paint,
    });
    layers.push(Layer::Markers {
        points: pts.iter().map(|p| (p.eta, y(p).0)).collect(),
        paint,
        label: Some(label.into()),
    });
}
