//! The expansion's charts of the left fraction and its relaxation time.

use super::group::Group;
use crate::model::chart::{ChartSpec, Layer, Paint, colour};
use crate::studies::curves::mean_with_band;

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
    let grid: Vec<f64> = (0..=400).map(|i| span * i as f64 / 400.0).collect();
    // The theories at p0, drawn against t p0 / m.
    let at = |t: f64| t * mass / p0;
    if let Some(free) = first.free() {
        let f = |x| free.left_fraction(at(x));
        layers.push(theory(&grid, f, FREE, "collisionless"));
    }
    if let Some(thermal) = first.free_thermal() {
        let f = |x| thermal.left_fraction(at(x));
        let label = "collisionless, Maxwellian at the same kT";
        layers.push(theory(&grid, f, THERMAL, label));
    }
    let d = first.stat("diffusion_enskog").mean;
    if let (Some(g), true) = (&first.gas, d.is_finite()) {
        let diffusive = g.diffusive(d);
        let f = |x| diffusive.left_fraction(at(x));
        layers.push(theory(&grid, f, DIFFUSIVE, "diffusive (Enskog D)"));
    }
    ChartSpec {
        title: format!("Left fraction during the expansion, {title}"),
        x_label: "scaled time t p_max / m [σ]".into(),
        y_label: LEFT.into(),
        layers,
        ..Default::default()
    }
}

/// One case's left fraction against time, with the collisionless curve.
pub fn single(g: &Group) -> ChartSpec {
    let tau = g.tau_free();
    let span = if tau.is_finite() {
        SHOWN * tau
    } else {
        f64::INFINITY
    };
    let n = g.t.iter().take_while(|&&x| x <= span).count();
    let label = "measured (mean ± standard error)".to_string();
    let mut layers = mean_with_band(&g.t[..n], &g.mean[..n], colour(0), label).to_vec();
    if let Some(free) = g.free() {
        let f = |t| free.left_fraction(t);
        layers.push(theory(&g.t[..n], f, FREE, "collisionless"));
    }
    ChartSpec {
        title: format!("Left fraction during the expansion, {}", g.label()),
        x_label: "time t [σ √(m/kT)]".into(),
        y_label: LEFT.into(),
        layers,
        ..Default::default()
    }
}

/// The measured relaxation times of groups at x, times a scale, as error
/// bars and markers.
fn measured(groups: &[(f64, &Group, f64)], paint: Paint, label: &str) -> [Layer; 2] {
    let tau = |g: &Group| g.stat("relaxation_time");
    let bar = |&(x, g, scale): &(f64, &Group, f64)| {
        let t = tau(g);
        let (low, high) = (t.mean - t.stderr, t.mean + t.stderr);
        (x, low * scale, t.mean * scale, high * scale)
    };
    [
        Layer::ErrorBars {
            bars: groups.iter().map(bar).collect(),
            paint,
        },
        Layer::Markers {
            points: (groups.iter().map(|&(x, g, scale)| (x, tau(g).mean * scale))).collect(),
            paint,
            label: Some(label.into()),
        },
    ]
}

/// Relaxation time against p_max, log-log, one colour per gas (N,
/// radius), with the collisionless time of each gas (dashed).
pub fn tau_against_p(gases: &[(String, Vec<&Group>)]) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, (label, gs)) in gases.iter().enumerate() {
        let at: Vec<(f64, &Group, f64)> = gs.iter().map(|g| (g.p_max(), *g, 1.0)).collect();
        layers.extend(measured(&at, colour(i), label));
        layers.push(Layer::Line {
            points: gs.iter().map(|g| (g.p_max(), g.tau_free())).collect(),
            paint: colour(i).faded(0.6),
            width: 1,
            dashed: true,
            label: None,
        });
    }
    ChartSpec {
        title: "Relaxation time against the largest initial momentum (dashed: collisionless)"
            .into(),
        x_label: "p_max [√(m kT₀)]".into(),
        y_label: "relaxation time τ [σ √(m/kT₀)]".into(),
        x_log: true,
        y_log: true,
        layers,
    }
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
    layers.push(Layer::Line {
        points: free,
        paint: colour(FREE),
        width: 2,
        dashed: true,
        label: Some("collisionless".into()),
    });
    let markers = |points, paint, label: &str| Layer::Markers {
        points,
        paint: colour(paint),
        label: Some(label.into()),
    };
    layers.push(markers(diffusive, DIFFUSIVE, "diffusive, Enskog D"));
    if let Some(point) = measured_d {
        layers.push(markers(vec![point], 3, "diffusive, measured D"));
    }
    ChartSpec {
        title: "Relaxation time over the crossing time L m / p_max, against Kn = λ / L".into(),
        x_label: "Knudsen number Kn = λ / L".into(),
        y_label: "τ p_max / (m L)".into(),
        x_log: true,
        y_log: true,
        layers,
    }
}

fn theory(x: &[f64], f: impl Fn(f64) -> f64, paint: usize, label: &str) -> Layer {
    Layer::Line {
        points: x.iter().map(|&x| (x, f(x))).collect(),
        paint: colour(paint),
        width: 2,
        dashed: true,
        label: Some(label.into()),
    }
}
