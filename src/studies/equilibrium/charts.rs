//! The section's charts, as data: pooled histograms (mean over replicas
//! with ±1 standard error bars) beside the laws drawn as curves. The
//! section titles each.

use super::ensemble::{Ball, Ensemble};
use super::measure::{histogram, profile, radial_distribution};
use super::moments;
use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::run_output::{Histogram, RunOutput};
use crate::stats::replicas::fractions;
use crate::stats::summary::Stats;
use crate::studies::curves::{bar, chart, markers, mean_with_band, measured, polyline, sampled};
use crate::theory::maxwell::{MaxwellSpeed, normal_pdf};
use crate::theory::microcanonical::VelocityMarginal;

pub type Runs<'a> = [(&'a Ensemble, &'a RunOutput)];
/// Replica `r`'s histogram's name.
pub type Name<'a> = &'a dyn Fn(usize) -> String;
/// Which of a replica's balls a chart is of.
pub type Pick<'a> = &'a dyn Fn(&Ensemble) -> Option<Ball>;

/// The label of a pooled histogram's markers.
pub const MEASURED: &str = "measured (mean ± standard error over replicas)";

/// The y axis of the charts of pooled histograms.
const DENSITY: &str = "probability density";

/// A histogram pooled over replicas as a density in x' = (x - shift) /
/// unit (each replica its own shift and unit): at each bin centre (replica
/// 0's), the mean density and its standard error.
type Pooled = Vec<(f64, Stats)>;

fn pooled(runs: &Runs, name: Name, scale: &dyn Fn(usize) -> (f64, f64)) -> Option<Pooled> {
    let mut per: Vec<Vec<f64>> = Vec::new();
    let mut x = Vec::new();
    for (r, (_, out)) in runs.iter().enumerate() {
        let h = histogram(out, &name(r))?;
        let (shift, unit) = scale(r);
        let bins = h.lo.iter().zip(&h.hi);
        if x.is_empty() {
            x = bins
                .clone()
                .map(|(a, b)| (0.5 * (a + b) - shift) / unit)
                .collect();
        }
        let f = fractions(&h.count);
        per.push(
            f.iter()
                .zip(bins)
                .map(|(f, (a, b))| f / ((b - a) / unit))
                .collect(),
        );
    }
    let at = |b: usize| Stats::of(&per.iter().map(|p| p[b]).collect::<Vec<f64>>());
    Some(x.into_iter().enumerate().map(|(b, x)| (x, at(b))).collect())
}

fn means(p: &Pooled) -> Vec<(f64, f64)> {
    p.iter().map(|(x, s)| (*x, s.mean)).collect()
}

/// A pooled histogram: markers at its means over fainter error bars.
fn measured_pooled(p: &Pooled, i: usize, label: &str) -> Vec<Layer> {
    let bars = p.iter().map(|(x, s)| bar(*x, s)).collect();
    let paint = colour(i).faded(0.6);
    let markers = markers(means(p), colour(i), Some(label.into()));
    vec![Layer::ErrorBars { bars, paint }, markers]
}

/// `f` over [lo, hi], two pixels wide in the `i`th colour.
fn curve(f: impl Fn(f64) -> f64, span: (f64, f64), i: usize, dashed: bool, label: &str) -> Layer {
    let points = sampled(span.0, span.1, 400, f);
    polyline(points, colour(i), 2, dashed, Some(label.into()))
}

/// The unit Gaussian, dashed.
fn gaussian(span: (f64, f64)) -> Layer {
    curve(|u| normal_pdf(u, 0.0, 1.0), span, 6, true, "Gaussian")
}

/// From the first bin's low edge to the last's high one (equal widths).
fn range(p: &Pooled) -> (f64, f64) {
    let w = p.get(1).zip(p.first()).map_or(0.0, |(b, a)| b.0 - a.0);
    let (first, last) = (
        p.first().map_or(0.0, |f| f.0),
        p.last().map_or(1.0, |l| l.0),
    );
    (first - 0.5 * w, last + 0.5 * w)
}

/// v_x of one particle per replica (the one `pick` picks of its balls),
/// in units of its exact law's std about its centre: the exact law (f
/// degrees of freedom) beside the unit Gaussian. `suffixes` pick the
/// histograms ("" for the whole run, "_early"/"_late" for halves).
pub fn velocity(runs: &Runs, pick: Pick, suffixes: &[(&str, &str)]) -> Option<ChartSpec> {
    let dof = runs.first()?.0.dof;
    let mut layers = Vec::new();
    let mut span = (0.0, 0.0);
    for (k, (suffix, label)) in suffixes.iter().enumerate() {
        let ball = |r: usize| pick(runs[r].0).map_or((usize::MAX, f64::NAN), |b| (b.index, b.mass));
        let name = |r| format!("velocity_x{suffix}.{}", ball(r).0);
        let law = |r: usize| runs[r].0.velocity_law(ball(r).1);
        let p = pooled(runs, &name, &|r| (law(r).centre, law(r).std()))?;
        span = range(&p);
        layers.extend(measured_pooled(&p, k, label));
    }
    // Unit mass and kT = 1: the law in units of its std.
    let law = VelocityMarginal::free(1.0, 0.5 * dof, dof);
    let label = format!("exact, f = {dof}");
    layers.push(curve(|u| law.pdf(u), span, 6, false, &label));
    layers.push(gaussian(span));
    let x_label = "(vₓ − V) / √(kT/m)  (V, kT/m: the exact law's centre and variance)";
    Some(linear(x_label, DENSITY, layers))
}

/// Each particle's velocity std (Gaussian fit, mean over replicas) against
/// its mass, beside sqrt(kT/m) (exact for any N; with conserved momentum
/// times sqrt(1 - m/M)).
pub fn std_against_mass(runs: &Runs) -> Option<ChartSpec> {
    let mut bars = Vec::new();
    let mut theory = Vec::new();
    for ball in runs.first()?.0.by_rank() {
        let (i, name) = (ball.index, format!("velocity_x.{}", ball.index));
        let stds: Vec<f64> = (runs.iter())
            .filter_map(|(_, o)| histogram(o, &name))
            .map(|h| moments::of(h).std)
            .collect();
        let (masses, exact): (Vec<f64>, Vec<f64>) = (runs.iter())
            .filter_map(|(e, _)| e.ball(i).map(|b| (b.mass, e.velocity_law(b.mass).std())))
            .unzip();
        let s = Stats::of(&stds);
        if s.n == 0 {
            continue;
        }
        let mass = Stats::of(&masses).mean;
        bars.push(bar(mass, &s));
        theory.push((mass, Stats::of(&exact).mean));
    }
    theory.sort_by(|a, b| a.0.total_cmp(&b.0));
    if bars.is_empty() {
        return None;
    }
    let label = "exact: √(kT/m), kT = 2E/f".to_string();
    let mut layers = vec![polyline(theory, colour(6), 2, true, Some(label))];
    let label = "measured (Gaussian fit, mean ± standard error over replicas)";
    layers.extend(measured(bars, colour(0), label));
    Some(chart(("", "mass m", "std of vₓ"), (true, true), layers))
}

/// Every rod's position histogram (pooled) beside its order-statistics law.
pub fn positions(runs: &Runs) -> Option<ChartSpec> {
    let laws = runs.first()?.0.rod_laws()?;
    let mut layers = Vec::new();
    for (k, (ball, law)) in laws.iter().enumerate() {
        let name = |_| format!("position_x.{}", ball.index);
        let p = pooled(runs, &name, &|_| (0.0, 1.0))?;
        let label = (k == 0).then(|| "measured (mean over replicas)".into());
        layers.push(markers(means(&p), colour(k), label));
        let label = (k == 0).then(|| "order statistics (exact)".into());
        let (lo, hi) = range(&p);
        let points = sampled(lo, hi, 400, |x| law.pdf(x));
        layers.push(polyline(points, colour(k), 2, false, label));
    }
    let y_label = format!("{DENSITY} of each rod's x");
    Some(linear("x [σ]", &y_label, layers))
}

/// sqrt(m) v_x of all particles in units of sqrt(kT), beside the Gaussian.
pub fn scaled_vx(runs: &Runs) -> Option<ChartSpec> {
    let p = pooled(runs, &|_| "scaled_velocity_x".into(), &|r| in_kt(runs, r))?;
    let mut layers = measured_pooled(&p, 0, MEASURED);
    layers.push(gaussian(range(&p)));
    Some(linear("√m vₓ / √(kT), kT = 2E/f", DENSITY, layers))
}

/// sqrt(m)|v| in units of sqrt(kT), beside Maxwell-Boltzmann and the exact law.
pub fn speed(runs: &Runs) -> Option<ChartSpec> {
    let e = runs.first()?.0;
    let p = pooled(runs, &|_| "scaled_speed".into(), &|r| in_kt(runs, r))?;
    let (_, hi) = range(&p);
    let mb = MaxwellSpeed {
        kt: 1.0,
        dimension: e.dimension as f64,
    };
    let kt = e.kt().sqrt();
    let exact = e.speed_law(e.balls.first().map_or(1.0, |b| b.mass));
    let mut layers = measured_pooled(&p, 0, MEASURED);
    let mb = curve(|u| mb.pdf(u), (0.0, hi), 6, true, "Maxwell-Boltzmann");
    let label = "exact, finite N";
    let exact = curve(|u| exact.pdf(u * kt) * kt, (0.0, hi), 1, false, label);
    layers.extend([mb, exact]);
    Some(linear("√m |v| / √(kT), kT = 2E/f", DENSITY, layers))
}

/// The scale of replica `r`'s √m v histograms: units of √(kT), no shift.
fn in_kt(runs: &Runs, r: usize) -> (f64, f64) {
    (0.0, runs[r].0.kt().sqrt())
}

/// The density along x over the mean density (mean over replicas).
pub fn density(runs: &Runs) -> Option<ChartSpec> {
    let e = runs.first()?.0;
    let mean_n = e.balls.len() as f64 / e.volume;
    let (points, n) = mean_over(runs, "density_x", &|h| profile(e, h), f64::INFINITY)?;
    let points = points.into_iter().map(|(x, y)| (x, y / mean_n)).collect();
    let label = format!("mean over {n} replicas");
    let layers = vec![polyline(points, colour(0), 2, false, Some(label))];
    Some(linear("x [σ]", "n(x) / mean n", layers))
}

/// g(r), mean over replicas, up to `reach` σ.
pub fn radial(runs: &Runs, reach: f64) -> Option<ChartSpec> {
    let e = runs.first()?.0;
    let g = |h: &Histogram| radial_distribution(e, h);
    let (points, n) = mean_over(runs, "pair_distance", &g, reach)?;
    let label = format!("mean over {n} replicas (N(N − 1) normalisation)");
    let layers = vec![polyline(points, colour(0), 2, false, Some(label))];
    Some(linear("r [σ]", "g(r)", layers))
}

/// The mean over the replicas that have histogram `name` of `per` of it,
/// at the first one's bin centres up to `reach`, and how many there were.
fn mean_over(
    runs: &Runs,
    name: &str,
    per: &dyn Fn(&Histogram) -> Vec<f64>,
    reach: f64,
) -> Option<(Vec<(f64, f64)>, usize)> {
    let hists: Vec<&Histogram> = runs
        .iter()
        .filter_map(|(_, o)| histogram(o, name))
        .collect();
    let first = hists.first()?;
    let per: Vec<Vec<f64>> = hists.iter().map(|h| per(h)).collect();
    let mean = |b: usize| per.iter().map(|p| p[b]).sum::<f64>() / per.len() as f64;
    let centres = first.lo.iter().zip(&first.hi).map(|(a, b)| 0.5 * (a + b));
    let points = centres.enumerate().map(|(b, x)| (x, mean(b)));
    Some((points.take_while(|(x, _)| *x <= reach).collect(), per.len()))
}

/// A chart with linear axes (the section gives it its title).
fn linear(x_label: &str, y_label: &str, layers: Vec<Layer>) -> ChartSpec {
    chart(("", x_label, y_label), (false, false), layers)
}

/// MacKay's scatter plots, from the first replica's stored samples: each
/// (x series, y series, label) a set of markers.
pub fn scatter(
    runs: &Runs,
    sets: &[(String, String, String)],
    axes: (&str, &str),
) -> Option<ChartSpec> {
    let out = runs.first()?.1;
    let layers = sets.iter().enumerate().map(|(k, (x, y, label))| {
        let (x, y) = (out.series(x)?, out.series(y)?);
        let points = x.value.iter().copied().zip(y.value.iter().copied());
        Some(markers(
            points.collect(),
            colour(k).faded(0.5),
            Some(label.clone()),
        ))
    });
    Some(linear(axes.0, axes.1, layers.collect::<Option<_>>()?))
}

/// A series' mean over replicas with a ±1 standard error band, and a
/// reference level.
pub fn settling(
    t: &[f64],
    mean: &[Stats],
    y_label: &str,
    reference: Option<(f64, &str)>,
) -> ChartSpec {
    let label = "mean over replicas (band: ± standard error)".to_string();
    let mut layers = mean_with_band(t, mean, colour(0), label).to_vec();
    if let (Some((level, label)), Some(t0), Some(t1)) = (reference, t.first(), t.last()) {
        let points = vec![(*t0, level), (*t1, level)];
        layers.push(polyline(points, colour(6), 2, true, Some(label.into())));
    }
    linear("time t", y_label, layers)
}
