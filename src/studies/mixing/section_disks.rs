//! The 2D half of the mixing section (Imperial "Mixing"): per point the
//! counts of each species on each side against time beside the diffusive
//! prediction, the mixing time against density and mass ratio, the
//! measured self-diffusion coefficient against Enskog's.

use super::section::Point;
use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::report::Figure;
use crate::stats::format::{count, num, pm};
use crate::studies::curves::mean_with_band;
use crate::theory::mixing::{slowest_mode_time, step_excess, step_mixing_time};
use std::fmt::Write;

fn label(p: &Point) -> String {
    let base = format!(
        "N = {}, η = {}, m_B/m_A = {}",
        num(p.first("particles")),
        num(p.first("packing_fraction")),
        num(p.first("mass_ratio"))
    );
    match &p.spec.case {
        Some(c) => format!("{base} (case {c})"),
        None => base,
    }
}

/// The two species' names, from the point's descriptor.
fn species(p: &Point) -> Option<(String, String)> {
    let scene = crate::scene::resolve(&p.spec.descriptor.scene).ok()?;
    Some((
        scene.species.first()?.name.clone(),
        scene.species.get(1)?.name.clone(),
    ))
}

/// The periodic-box point at the same packing fraction and mass ratio as
/// a mixing point: its fluid's self-diffusion coefficient.
fn bulk<'a>(p: &Point, all: &'a [Point<'a>]) -> Option<&'a Point<'a>> {
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * a.abs().max(b.abs());
    all.iter().find(|q| {
        q.first("diffusion").is_finite()
            && close(q.first("packing_fraction"), p.first("packing_fraction"))
            && close(q.first("mass_ratio"), p.first("mass_ratio"))
    })
}

/// The diffusive prediction of a mixing point's mixing time from its bulk
/// point's D: (time, standard error from D's).
pub fn predicted(p: &Point, all: &[Point]) -> (f64, f64) {
    let Some(q) = bulk(p, all) else {
        return (f64::NAN, f64::NAN);
    };
    let d = q.stat("diffusion");
    let room = room(p);
    let tau = step_mixing_time(slowest_mode_time(room, d.mean));
    (tau, tau * d.stderr / d.mean)
}

/// The bulk fluid's velocity memory time D m/kT (m the mean of the two
/// species' masses, kT = 1 in reduced units): diffusion holds only beyond it.
fn memory(p: &Point, all: &[Point]) -> f64 {
    let Some(q) = bulk(p, all) else {
        return f64::NAN;
    };
    let kt = super::disks::temperature(&q.spec.descriptor).unwrap_or(f64::NAN);
    let mean_mass = mean_mass(q);
    q.stat("diffusion").mean * mean_mass / kt
}

/// The mean mass of the disks of a point, from its descriptor.
fn mean_mass(p: &Point) -> f64 {
    let Ok(scene) = crate::scene::resolve(&p.spec.descriptor.scene) else {
        return f64::NAN;
    };
    let (mut total, mut count) = (0.0, 0.0);
    for s in &scene.species {
        let [lo, hi] = s.mass.bounds();
        total += 0.5 * (lo + hi) * s.count as f64;
        count += s.count as f64;
    }
    total / count
}

/// The centres' room along x: the box less a mean diameter.
fn room(p: &Point) -> f64 {
    let scene = crate::scene::resolve(&p.spec.descriptor.scene).ok();
    let length = scene
        .as_ref()
        .and_then(|s| s.box_size.as_ref()?.first().copied())
        .unwrap_or(f64::NAN);
    let radii: Vec<f64> = scene
        .map(|s| s.species.iter().map(|k| k.radius.bounds()[0]).collect())
        .unwrap_or_default();
    length - 2.0 * radii.iter().sum::<f64>() / radii.len().max(1) as f64
}

pub fn write(points: &[Point], md: &mut String, figures: &mut Vec<Figure>) {
    md.push_str(INTRO);
    let (mixing, bulk_points): (Vec<&Point>, Vec<&Point>) =
        points.iter().partition(|p| !p.first("mixed").is_nan());
    let _ = writeln!(
        md,
        "| point | Kn = λ/L | runs | mixed | τ | τ diffusive (bulk D) | τ / τ diffusive | velocity memory D m̄/kT | late fraction of A on the left (½) | CPU s | collisions |\n\
         |---|---|---|---|---|---|---|---|---|---|---|"
    );
    for p in &mixing {
        let (k, n) = (p.mixed(), p.outs.len());
        let tau = p.stat("mixing_time");
        let tau_text = match k {
            0 => format!(
                "> {} (none mixed)",
                num(p.spec.descriptor.run.duration.unwrap_or(f64::NAN))
            ),
            k if k < n => format!("{} (censored: a lower bound)", pm(tau.mean, tau.stderr)),
            _ => pm(tau.mean, tau.stderr),
        };
        let (pred, pred_se) = predicted(p, points);
        let ratio = tau.mean / pred;
        let ratio_se = ratio * ((tau.stderr / tau.mean).powi(2) + (pred_se / pred).powi(2)).sqrt();
        let late = p.stat("late_left_fraction");
        let _ = writeln!(
            md,
            "| {} | {} | {n} | {k}/{n} | {tau_text} | {} | {} | {} | {} | {} | {} |",
            label(p),
            num(p.first("knudsen")),
            pm(pred, pred_se),
            if k == n {
                pm(ratio, ratio_se)
            } else {
                "—".into()
            },
            num(memory(p, points)),
            pm(late.mean, late.stderr),
            num(p.cpu()),
            count(p.collisions()),
        );
    }
    md.push('\n');
    if !bulk_points.is_empty() {
        md.push_str(BULK);
        let _ = writeln!(
            md,
            "| point | runs | D | D Enskog | D / D Enskog | fit start / (D m/kT) | CPU s | collisions |\n\
             |---|---|---|---|---|---|---|---|"
        );
        for p in &bulk_points {
            let s = |name: &str| {
                let st = p.stat(name);
                pm(st.mean, st.stderr)
            };
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} | {} | {} |",
                label(p),
                p.outs.len(),
                s("diffusion"),
                num(p.first("diffusion_enskog")),
                s("diffusion_ratio"),
                num(p.stat("memory_ratio").mean),
                num(p.cpu()),
                count(p.collisions()),
            );
        }
        md.push('\n');
    }
    for (i, p) in mixing.iter().enumerate() {
        if let Some(figure) = sides(p, i, predicted(p, points).0) {
            let _ = writeln!(
                md,
                "![{}: disks of each species in each half against time, ensemble mean ± standard error over {} runs; dashed: the diffusion equation with the bulk fluid's measured D.]({})\n",
                label(p),
                p.outs.len(),
                figure.file
            );
            figures.push(figure);
        }
    }
    against_density(&mixing, points, md, figures);
}

/// Counts of each species on each side against time for one point, with the
/// diffusive prediction for species A on the left.
fn sides(p: &Point, index: usize, tau_d: f64) -> Option<Figure> {
    let (a, b) = species(p)?;
    let mut layers = Vec::new();
    let names = [
        (format!("count.{a}.left"), format!("{a}, left")),
        (format!("count.{a}.right"), format!("{a}, right")),
        (format!("count.{b}.left"), format!("{b}, left")),
        (format!("count.{b}.right"), format!("{b}, right")),
    ];
    let mut times = Vec::new();
    let mut first_a = f64::NAN;
    for (i, (series, text)) in names.iter().enumerate() {
        let (t, mean) = p.mean_curve(series);
        if mean.is_empty() {
            return None;
        }
        if i == 0 {
            first_a = mean[0].mean;
            times = t.clone();
        }
        layers.extend(mean_with_band(&t, &mean, colour(i), text.clone()));
    }
    if tau_d.is_finite() {
        // The slowest mode's time from the 1/e time of the step's series.
        let slowest = slowest_from_mixing_time(tau_d);
        let total = first_a;
        layers.push(Layer::Line {
            points: times
                .iter()
                .map(|&t| (t, total * (0.5 + step_excess(t, slowest))))
                .collect(),
            paint: colour(6),
            width: 1,
            dashed: true,
            label: Some("diffusion (A, left)".into()),
        });
    }
    Some(Figure {
        file: format!("mixing_sides_{index}.svg"),
        chart: ChartSpec {
            title: format!("Two species mixing, {}", label(p)),
            x_label: "time t [σ √(m/kT)]".into(),
            y_label: "disks in the half".into(),
            x_log: false,
            y_log: false,
            layers,
        },
    })
}

/// tau_D such that `step_mixing_time(tau_D)` = `t` (it is proportional).
fn slowest_from_mixing_time(t: f64) -> f64 {
    t / crate::theory::mixing::step_mixing_time(1.0)
}

/// Mixing time against the packing fraction, per mass ratio: measured and
/// predicted by diffusion from the measured D.
fn against_density(mixing: &[&Point], all: &[Point], md: &mut String, figures: &mut Vec<Figure>) {
    let mut ratios: Vec<f64> = mixing.iter().map(|p| p.first("mass_ratio")).collect();
    ratios.sort_by(f64::total_cmp);
    ratios.dedup();
    let mut layers = Vec::new();
    for (i, &r) in ratios.iter().enumerate() {
        let mut at: Vec<&Point> = mixing
            .iter()
            .copied()
            .filter(|p| p.first("mass_ratio") == r && p.mixed() == p.outs.len())
            .collect();
        at.sort_by(|a, b| {
            a.first("packing_fraction")
                .total_cmp(&b.first("packing_fraction"))
        });
        let paint = colour(i);
        let mut bars = Vec::new();
        let mut measured = Vec::new();
        let mut diffusive = Vec::new();
        for p in &at {
            let eta = p.first("packing_fraction");
            let s = p.stat("mixing_time");
            let (d, _) = predicted(p, all);
            bars.push((eta, s.mean - s.stderr, s.mean, s.mean + s.stderr));
            measured.push((eta, s.mean));
            diffusive.push((eta, d));
        }
        layers.push(Layer::ErrorBars { bars, paint });
        layers.push(Layer::Markers {
            points: measured,
            paint,
            label: Some(format!("measured, m_B/m_A = {}", num(r))),
        });
        layers.push(Layer::Line {
            points: diffusive,
            paint,
            width: 1,
            dashed: true,
            label: Some(format!("diffusion from D, m_B/m_A = {}", num(r))),
        });
    }
    let file = "mixing_time_against_density.svg".to_string();
    let _ = writeln!(
        md,
        "![Mixing time of the two species against the packing fraction, per mass ratio: measured (mean ± standard error; fully mixed points only) and the diffusion equation's from the measured self-diffusion coefficient (dashed).]({file})\n"
    );
    figures.push(Figure {
        file,
        chart: ChartSpec {
            title: "2D mixing time against density".into(),
            x_label: "packing fraction η".into(),
            y_label: "mixing time [σ √(m/kT)]".into(),
            x_log: false,
            y_log: true,
            layers,
        },
    });
}

const INTRO: &str = "### Disks: two gases started apart\n\n\
> You can start a simulation with different particles on the left and right halves of the box (what \
distinguishes the particles could be a physical attribute such as mass, or a fictitious one such as \
colour). […] Plot the number of particles of each type on each side of the box as a function of time. \
(Imperial, \"Mixing\")\n\n\
Species A starts in the left half and B in the right half of a box with walls along x (periodic along \
y). The disks of each kind in each half are counted at every sample. When the mean free path λ is short against the box (Kn = λ/L ≪ 1) \
the two gases interdiffuse, and the diffusion equation between the walls predicts the whole curve from \
D alone. It holds only after the velocity memory time D m̄/kT, though (the mean-squared displacement is \
2D(t − D m̄/kT) beyond it, ballistic before): where that is not small against τ, as in a dilute gas, \
the disks still fly freely on the scale of the box and mix later than diffusion predicts; with no \
collisions at all D is infinite and the prediction zero, while free flight takes about L/v. D is measured in a periodic box of the same packing fraction and mass ratio \
(the bulk fluid: below), as the slope of the mean-squared displacement.\n\n";

const BULK: &str = "**The bulk fluid's self-diffusion**, in a fully periodic square box of the same area, \
packing fraction and mass ratio: D against Enskog's value for one kind of disk (A and B then differ only \
by colour, and interdiffusion is self-diffusion exactly). With unequal masses the prediction above uses \
the count-weighted mean of the two species' D (Darken's estimate of the interdiffusion coefficient for \
equal counts). Above the dilute limit D exceeds Enskog's value: correlated motion (the vortices behind \
the 2D long-time tail) carries the disks further than uncorrelated collisions would.\n\n";
