//! The expansion's charts of the left fraction and its relaxation time.

use super::group::Group;
use crate::model::chart::{ChartSpec, Layer, Paint, colour};
use crate::studies::curves::{self, bar, chart, markers, mean_with_band, polyline, sampled};

/// The charts show the first this many collisionless relaxation times (the
/// expansion and, in a fluid, its sloshing); the rest is noise about 1/2.
pub const SHOWN: f64 = 8.0;

/// Paints of the two theories, after the measured curves' colours.
const FREE: usize = 6;
const DIFFUSIVE: usize = 7;
const THERMAL: usize = 5;

const LEFT: &str = "fraction of the particles in the left half";

/// One gas (N, radius) at several p_max, against t p_max / m: hard
/// particles have no energy scale, so the curves of one gas coincide on
/// this axis if the relaxation time is inverse in p_max, and the
/// collisionless and diffusive (Enskog) predictions are one curve each.
pub fn scaled(gas: &[&Group], title: &str) -> ChartSpec {
    let mut layers = Vec::new();
    let Some(first) = gas.first() else {
        return ChartSpec::default();
    };
    let p0 = first.p_max();
    // Scaled time = t p / m; m = 1 in the bundled gas, taken from the kinds.
    let mass = first.gas.as_ref().map_or(1.0, |g| g.kinds[0].1);
    let span = SHOWN * first.tau_free() * p0 / mass;
    for (i, g) in gas.iter().enumerate() {
        let speed = g.p_max() / mass;
        let n = g.t.iter().take_while(|&&t| t * speed <= span).count();
        let x: Vec<f64> = g.t[..n].iter().map(|t| t * speed).collect();
        let label = format!("{} (mean ± standard error)", g.start_text());
        layers.extend(mean_with_band(&x, &g.mean[..n], colour(i), label));
    }
    // The theories at p0, drawn against t p0 / m.
    let at_p0 = |f: &dyn Fn(f64) -> f64, paint, label: &str| {
        theory(sampled(0.0, span, 400, |x| f(x * mass / p0)), paint, label)
    };
    if let Some(free) = first.free() {
        layers.push(at_p0(&|t| free.left_fraction(t), FREE, "collisionless"));
    }
    if let Some(thermal) = first.free_thermal() {
        let label = "collisionless, Maxwellian at the same kT";
        layers.push(at_p0(&|t| thermal.left_fraction(t), THERMAL, label));
    }
    let d = first.stat("diffusion_enskog").mean;
    if let (Some(g), true) = (&first.gas, d.is_finite()) {
        let diffusive = g.diffusive(d);
        let label = "diffusive (Enskog D)";
        layers.push(at_p0(&|t| diffusive.left_fraction(t), DIFFUSIVE, label));
    }
    let title = format!("Left fraction during the expansion, {title}");
    let labels = (title, "scaled time t p_max / m [σ]", LEFT);
    chart(labels, (false, false), layers)
}

/// One case's left fraction against time, with the collisionless curve.
pub fn single(g: &Group) -> ChartSpec {
    let tau = g.tau_free();
    let span = Some(SHOWN * tau)
        .filter(|s| s.is_finite())
        .unwrap_or(f64::INFINITY);
    let n = g.t.iter().take_while(|&&x| x <= span).count();
    let label = "measured (mean ± standard error)".to_string();
    let mut layers = mean_with_band(&g.t[..n], &g.mean[..n], colour(0), label).to_vec();
    if let Some(free) = g.free() {
        let points = g.t[..n].iter().map(|&t| (t, free.left_fraction(t)));
        layers.push(theory(points.collect(), FREE, "collisionless"));
    }
    let title = format!("Left fraction during the expansion, {}", g.label());
    chart((title, "time t [σ √(m/kT)]", LEFT), (false, false), layers)
}

/// The measured relaxation times of groups at x, times a scale, as error
/// bars and markers.
fn measured(groups: &[(f64, &Group, f64)], paint: Paint, label: &str) -> [Layer; 2] {
    let bars = groups.iter().map(|&(x, g, scale)| {
        let (_, low, t, high) = bar(x, &g.stat("relaxation_time"));
        (x, low * scale, t * scale, high * scale)
    });
    curves::measured(bars, paint, label)
}

/// Relaxation time against p_max, log-log, one colour per gas (N,
/// radius), with the collisionless time of each gas (dashed).
pub fn tau_against_p(gases: &[(String, Vec<&Group>)]) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, (label, gs)) in gases.iter().enumerate() {
        let at: Vec<(f64, &Group, f64)> = gs.iter().map(|g| (g.p_max(), *g, 1.0)).collect();
        layers.extend(measured(&at, colour(i), label));
        let free = gs.iter().map(|g| (g.p_max(), g.tau_free())).collect();
        layers.push(polyline(free, colour(i).faded(0.6), 1, true, None));
    }
    let title = "Relaxation time against the largest initial momentum (dashed: collisionless)";
    let labels = (title, "p_max [√(m kT₀)]", "relaxation time τ [σ √(m/kT₀)]");
    chart(labels, (true, true), layers)
}

/// The relaxation time in units of the box crossing time L m / p_max
/// against the Knudsen number: the collisionless theory holds on the right
/// (a constant), the diffusive one (τ p / L ∝ 1/Kn) would on the left.
pub fn tau_against_knudsen(sweep: &[&Group], measured_d: Option<(f64, f64)>) -> ChartSpec {
    let mut at = Vec::new();
    let (mut free, mut diffusive) = (Vec::new(), Vec::new());
    for g in sweep {
        let Some(gas) = &g.gas else { continue };
        let scale = g.p_max() / (gas.kinds[0].1 * gas.length);
        let kn = gas.knudsen();
        at.push((kn, *g, scale));
        free.push((kn, g.tau_free() * scale));
        diffusive.push((kn, g.stat("relaxation_time_diffusive").mean * scale));
    }
    free.sort_by(|a, b| a.0.total_cmp(&b.0));
    diffusive.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut layers = measured(&at, colour(0), "measured (every sweep point)").to_vec();
    layers.push(theory(free, FREE, "collisionless"));
    let label = Some("diffusive, Enskog D".into());
    layers.push(markers(diffusive, colour(DIFFUSIVE), label));
    if let Some(point) = measured_d {
        let label = Some("diffusive, measured D".into());
        layers.push(markers(vec![point], colour(3), label));
    }
    let title = "Relaxation time over the crossing time L m / p_max, against Kn = λ / L";
    let labels = (title, "Knudsen number Kn = λ / L", "τ p_max / (m L)");
    chart(labels, (true, true), layers)
}

/// A theory's curve: dashed, two pixels wide, in the `paint`th colour.
fn theory(points: Vec<(f64, f64)>, paint: usize, label: &str) -> Layer {
    polyline(points, colour(paint), 2, true, Some(label.into()))
}
