//! The 2D half of the mixing section (Imperial "Mixing"): per point the
//! counts of each species on each side against time beside the diffusive
//! prediction, the mixing time against density and mass ratio, the
//! measured self-diffusion coefficient against Enskog's.

use super::section::{Point, SENTENCES, all_mixed, distinct, label, mixed, tau_text};
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::named::named as sentence;
use crate::stats::summary::z_score;
use crate::stats::table::table_row;
use crate::studies::curves::{bar, figure, mean_with_band, measured, polyline, show};
use crate::studies::parts::stat_pm;
use crate::theory::mixing::{slowest_mode_time, step_excess, step_mixing_time};

const TEXT: &str = include_str!("disks.md");
pub(super) const BULK: &str = include_str!("bulk.md");

/// What names a 2D point: its size, packing fraction and mass ratio.
const LABEL: [(&str, &str); 3] = [
    ("N", "particles"),
    ("η", "packing_fraction"),
    ("m_B/m_A", "mass_ratio"),
];

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
    let tau = step_mixing_time(slowest_mode_time(room(p), d.mean));
    (tau, tau * d.stderr / d.mean)
}

/// The bulk fluid's velocity memory time D m/kT (m the mean of the two
/// species' masses, kT = 1 in reduced units): diffusion holds only beyond it.
fn memory(p: &Point, all: &[Point]) -> f64 {
    let Some(q) = bulk(p, all) else {
        return f64::NAN;
    };
    let kt = super::disks::temperature(&q.spec.descriptor).unwrap_or(f64::NAN);
    q.stat("diffusion").mean * mean_mass(q) / kt
}

/// The mean mass of the disks of a point, from its descriptor.
fn mean_mass(p: &Point) -> f64 {
    let Some(scene) = p.scene() else {
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
    let scene = p.scene();
    let length = scene
        .as_ref()
        .and_then(|s| s.box_size.as_ref()?.first().copied())
        .unwrap_or(f64::NAN);
    let radii: Vec<f64> = scene
        .map(|s| s.species.iter().map(|k| k.radius.bounds()[0]).collect())
        .unwrap_or_default();
    length - 2.0 * radii.iter().sum::<f64>() / radii.len().max(1) as f64
}

pub fn part(points: &[Point], figures: &mut Vec<Figure>) -> String {
    let (mixing, bulk_points): (Vec<&Point>, Vec<&Point>) =
        points.iter().partition(|p| !p.first("mixed").is_nan());
    let mut rows = String::new();
    for p in &mixing {
        let (k, n) = (mixed(p), p.outs.len());
        let tau = p.stat("mixing_time");
        let (pred, pred_se) = predicted(p, points);
        let ratio = tau.mean / pred;
        let ratio_se = ratio * ((tau.stderr / tau.mean).powi(2) + (pred_se / pred).powi(2)).sqrt();
        let ratio = match k == n {
            true => pm(ratio, ratio_se),
            false => "—".into(),
        };
        rows.push_str(&table_row(&[
            label(p, &LABEL),
            num(p.first("knudsen")),
            n.to_string(),
            format!("{k}/{n}"),
            tau_text(p),
            pm(pred, pred_se),
            ratio,
            num(memory(p, points)),
            stat_pm(p, "late_left_fraction"),
            num(p.cpu()),
            count(p.collisions()),
        ]));
    }
    let pictures: String = (mixing.iter().enumerate())
        .filter_map(|(i, p)| sides(p, i, predicted(p, points).0, figures))
        .collect();
    fill(
        TEXT,
        &[
            ("rows", rows),
            ("bulk", bulk_table(&bulk_points)),
            ("pictures", pictures),
            ("density_figure", against_density(&mixing, points, figures)),
        ],
    )
}

/// The periodic boxes' D against Enskog's, and what the ratio says.
fn bulk_table(bulk_points: &[&Point]) -> String {
    if bulk_points.is_empty() {
        return String::new();
    }
    let mut rows = String::new();
    // The points where D agrees with Enskog's, exceeds it and falls below.
    let mut at: [(&str, Vec<String>); 3] = ["agree", "above", "below"].map(|k| (k, Vec::new()));
    for p in bulk_points {
        rows.push_str(&table_row(&[
            label(p, &LABEL),
            p.outs.len().to_string(),
            stat_pm(p, "diffusion"),
            num(p.first("diffusion_enskog")),
            stat_pm(p, "diffusion_ratio"),
            num(p.stat("memory_ratio").mean),
            num(p.cpu()),
            count(p.collisions()),
        ]));
        let (eta, ratio) = (p.first("packing_fraction"), p.first("mass_ratio"));
        let point = format!("η = {} (m_B/m_A = {})", num(eta), num(ratio));
        match z_score(&p.stat("diffusion_ratio"), 1.0) {
            Some(z) if z >= 4.0 => at[1].1.push(point),
            Some(z) if z <= -4.0 => at[2].1.push(point),
            Some(_) => at[0].1.push(point),
            None => {}
        }
    }
    let verdict: Vec<String> = (at.iter().filter(|(_, at)| !at.is_empty()))
        .map(|(name, at)| fill(sentence(SENTENCES, name), &[("at", at.join(", "))]))
        .collect();
    let verdict = match verdict.is_empty() {
        true => String::new(),
        false => format!("{}.", verdict.join("; ")),
    };
    fill(BULK, &[("verdict", verdict), ("rows", rows)])
}

/// Counts of each species on each side against time for one point, with the
/// diffusive prediction for species A on the left; the figure's Markdown.
fn sides(p: &Point, index: usize, tau_d: f64, figures: &mut Vec<Figure>) -> Option<String> {
    let scene = p.scene()?;
    let (a, b) = (&scene.species.first()?.name, &scene.species.get(1)?.name);
    let curves = [(a, "left"), (a, "right"), (b, "left"), (b, "right")].map(|(species, side)| {
        (
            species,
            side,
            p.mean_curve(&format!("count.{species}.{side}")),
        )
    });
    if curves.iter().any(|(_, _, (_, mean))| mean.is_empty()) {
        return None;
    }
    let mut layers = Vec::new();
    for (i, (species, side, (t, mean))) in curves.iter().enumerate() {
        layers.extend(mean_with_band(
            t,
            mean,
            colour(i),
            format!("{species}, {side}"),
        ));
    }
    if tau_d.is_finite() {
        // The slowest mode's time from the 1/e time of the step's series
        // (they are proportional).
        let slowest = tau_d / step_mixing_time(1.0);
        let (times, total) = (&curves[0].2.0, curves[0].2.1[0].mean);
        let curve = times
            .iter()
            .map(|&t| (t, total * (0.5 + step_excess(t, slowest))));
        let label = Some("diffusion (A, left)".into());
        layers.push(polyline(curve.collect(), colour(6), 1, true, label));
    }
    let name = label(p, &LABEL);
    let values = [("label", name.clone()), ("runs", p.outs.len().to_string())];
    let caption = fill(sentence(SENTENCES, "sides"), &values);
    let axes = (
        format!("Two species mixing, {name}"),
        "time t [σ √(m/kT)]",
        "disks in the half",
    );
    let figure = figure(
        &format!("mixing_sides_{index}.svg"),
        axes,
        (false, false),
        layers,
    );
    Some(show(figures, figure, &caption))
}

/// Mixing time against the packing fraction, per mass ratio: measured and
/// predicted by diffusion from the measured D.
fn against_density(mixing: &[&Point], all: &[Point], figures: &mut Vec<Figure>) -> String {
    let eta = |p: &Point| p.first("packing_fraction");
    let mut layers = Vec::new();
    for (i, &r) in distinct(mixing.iter().copied(), "mass_ratio")
        .iter()
        .enumerate()
    {
        let mut at: Vec<&Point> = (mixing.iter().copied())
            .filter(|p| p.first("mass_ratio") == r && all_mixed(p))
            .collect();
        at.sort_by(|a, b| eta(a).total_cmp(&eta(b)));
        let measured_at = at.iter().map(|p| bar(eta(p), &p.stat("mixing_time")));
        let label = format!("measured, m_B/m_A = {}", num(r));
        layers.extend(measured(measured_at, colour(i), &label));
        let diffusive = at.iter().map(|p| (eta(p), predicted(p, all).0)).collect();
        let label = Some(format!("diffusion from D, m_B/m_A = {}", num(r)));
        layers.push(polyline(diffusive, colour(i), 1, true, label));
    }
    let labels = (
        "2D mixing time against density".into(),
        "packing fraction η",
        "mixing time [σ √(m/kT)]",
    );
    let figure = figure(
        "mixing_time_against_density.svg",
        labels,
        (false, true),
        layers,
    );
    show(figures, figure, sentence(SENTENCES, "density"))
}
