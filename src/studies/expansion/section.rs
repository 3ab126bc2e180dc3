//! The expansion's part of the report: the relaxation time against p_max
//! and the Knudsen number beside the collisionless and diffusive
//! predictions; per gas the ensemble-mean left fraction; a table of every
//! point and case with the settled split and its z-scores and the cost;
//! the profiles and the measured diffusion coefficient of the cases. The
//! prose is in the Markdown beside it.

use super::RESULTS;
use super::charts::{scaled, single, tau_against_knudsen, tau_against_p};
use super::group::{Group, groups};
use super::profiles;
use crate::model::report::{Figure, ReportSection};
use crate::stats::ensemble::Runs;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::line::line;
use crate::stats::summary::Stats;
use crate::theory::expansion_rods::Collisionless;
use std::fmt::Write;

const INTRO: &str = include_str!("intro.md");
const METHODS: &str = include_str!("methods.md");

/// Beyond this many collisionless relaxation times the curves are compared
/// no further: both are within noise of 1/2 there.
pub const COMPARED: f64 = 3.0;

/// |z| below which a measurement agrees with a prediction.
const AGREE: f64 = 4.0;

/// A sweep's gas (N, radius) and its points, one per p_max.
type GasPoints<'a> = (String, Vec<&'a Group<'a>>);

/// Largest |mean - theory| over the collisionless prediction's own standard
/// error of a mean over `runs` runs of `n` particles, sqrt(f (1 - f) / (n
/// runs)) (free particles are independent, each on the left with
/// probability f), over the samples up to `until`. The error under the
/// hypothesis tested, not the runs' scatter: with a handful of runs that
/// scatter is itself uncertain, and its Student tails over hundreds of
/// samples would reject the theory by chance.
pub fn largest_z(
    t: &[f64],
    mean: &[Stats],
    theory: &dyn Fn(f64) -> f64,
    n: f64,
    until: f64,
) -> f64 {
    t.iter()
        .zip(mean)
        .filter(|(t, _)| **t > 0.0 && **t <= until)
        .map(|(t, s)| {
            let f = theory(*t);
            let se = (f * (1.0 - f) / (n * s.n as f64)).sqrt();
            if se > 0.0 {
                ((s.mean - f) / se).abs()
            } else {
                0.0
            }
        })
        .fold(0.0, f64::max)
}

/// Max |z| of a group's mean curve against a collisionless curve.
fn free_z(g: &Group, free: Option<Collisionless>) -> f64 {
    free.map_or(f64::NAN, |f| {
        let until = COMPARED * f.relaxation_time();
        largest_z(&g.t, &g.mean, &|t| f.left_fraction(t), g.particles(), until)
    })
}

/// Power of p_max in the relaxation time of one gas: the weighted slope of
/// ln tau against ln p_max (weights from the runs' standard errors) and its
/// standard error.
fn exponent(gs: &[&Group]) -> (f64, f64) {
    let (mut x, mut y, mut w) = (Vec::new(), Vec::new(), Vec::new());
    for g in gs {
        let tau = g.stat("relaxation_time");
        if tau.mean > 0.0 && tau.stderr > 0.0 && g.p_max() > 0.0 {
            x.push(g.p_max().ln());
            y.push(tau.mean.ln());
            w.push((tau.mean / tau.stderr).powi(2));
        }
    }
    let (slope, se, _) = line(&x, &y, Some(&w));
    (slope, se)
}

fn z(mean: f64, theory: f64, se: f64) -> f64 {
    (mean - theory) / se
}

/// The items, or "none".
fn list(v: &[String]) -> String {
    if v.is_empty() {
        "none".into()
    } else {
        v.join("; ")
    }
}

/// Names sorted by whether their |z| agrees; NaN in neither.
#[derive(Default)]
struct Verdicts {
    agree: Vec<String>,
    differ: Vec<String>,
}

impl Verdicts {
    fn add(&mut self, name: String, z: f64) {
        if z.abs() < AGREE {
            self.agree.push(name);
        } else if z.is_finite() {
            self.differ.push(name);
        }
    }
}

pub fn section(runs: &Runs) -> anyhow::Result<ReportSection> {
    let all = groups(runs);
    let sweep: Vec<&Group> = all.iter().filter(|g| g.case.is_none()).collect();
    let is = |g: &Group, prefix: &str| g.case.as_deref().is_some_and(|c| c.starts_with(prefix));
    let measures_d = |g: &Group| g.stat("diffusion_measured").n > 0;
    let expansion_cases: Vec<&Group> = (all.iter())
        .filter(|g| g.case.is_some() && !is(g, "profiles") && !measures_d(g))
        .collect();
    // The sweep's gases (N, radius), each at its values of p_max.
    let mut gases: Vec<GasPoints> = Vec::new();
    for g in &sweep {
        let label = format!("N = {}, radius {}", g.particles(), num(g.radius()));
        match gases.iter_mut().find(|(l, _)| *l == label) {
            Some((_, gs)) => gs.push(g),
            None => gases.push((label, vec![g])),
        }
    }
    let mut figures = Vec::new();
    let mut md = String::from(INTRO);
    let diffusion = all.iter().find(|g| measures_d(g));
    let measured_point = diffusion.and_then(|g| diffusion_text(&mut md, g));
    if sweep.iter().any(|g| g.p_max().is_finite()) {
        for (file, chart) in [
            ("expansion_tau_p_max.svg", tau_against_p(&gases)),
            (
                "expansion_tau_knudsen.svg",
                tau_against_knudsen(&sweep, measured_point),
            ),
        ] {
            let file = file.into();
            figures.push(Figure { file, chart });
        }
        md.push_str(
            "![Relaxation time against p_max, one colour per gas, with the collisionless time \
             (dashed).](expansion_tau_p_max.svg)\n\n\
             ![τ p_max / (m L) against the Knudsen number: the collisionless prediction (dashed) \
             is a constant, the diffusive one grows as 1/Kn.](expansion_tau_knudsen.svg)\n\n",
        );
        md.push_str(&exponent_table(&gases));
    }
    left_fractions(&mut md, &mut figures, &gases, &expansion_cases);
    md.push_str(&points_table(sweep.iter().chain(&expansion_cases)));
    for g in all.iter().filter(|g| is(g, "profiles")) {
        let name = g.case.clone().unwrap_or_default();
        if let Some((fs, text)) = profiles::section(g, &name) {
            let _ = writeln!(md, "**Profiles during the expansion**, case `{name}`:\n");
            md.push_str(&text);
            figures.extend(fs);
        }
    }
    md.push_str(&methods());
    Ok(ReportSection {
        title: "Expansion of the gas".into(),
        markdown: md,
        figures,
        presents: RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

fn methods() -> String {
    let values = [("agree", num(AGREE)), ("compared", num(COMPARED))];
    fill(METHODS, &values)
}

/// τ over the box crossing time L m / p_max of a gas's first point.
fn crossing_scale(g: &Group) -> f64 {
    (g.gas.as_ref()).map_or(f64::NAN, |gas| g.p_max() / (gas.kinds[0].1 * gas.length))
}

/// The diffusion coefficient measured in the case that records it, and
/// (Kn, scaled diffusive time) with it for the Knudsen chart.
fn diffusion_text(md: &mut String, g: &Group) -> Option<(f64, f64)> {
    let measured = g.stat("diffusion_measured");
    let enskog = g.stat("diffusion_enskog").mean;
    let gas = g.gas.as_ref();
    let tau = |d: f64| gas.map_or(f64::NAN, |gas| gas.diffusive(d).relaxation_time());
    let _ = writeln!(
        md,
        "**Diffusion coefficient** (case `{}`: {}, filling the box, y periodic): measured from the \
         mean-squared displacement along y, D = {} σ² per unit time over {} runs; Enskog's \
         (kinetic theory at the final density and kT = p_max²/3m) {}, ratio {}. The diffusive \
         relaxation time with the measured D is {} (Enskog's: {}); the measured one, at the same \
         gas in the left half (the sweep, same N, radius and p_max), is in the table.\n",
        g.case.as_deref().unwrap_or(""),
        g.label(),
        pm(measured.mean, measured.stderr),
        measured.n,
        num(enskog),
        num(measured.mean / enskog),
        num(tau(measured.mean)),
        num(tau(enskog)),
    );
    Some((gas?.knudsen(), tau(measured.mean) * crossing_scale(g)))
}

/// Per gas the power of p_max in τ, and whether τ ∝ 1/p_max.
fn exponent_table(gases: &[GasPoints]) -> String {
    let mut md = String::from(
        "| gas | Kn = λ/L | points | τ ∝ p_max^a: a | z (a = −1) | τ p_max / (m L), measured at the smallest p_max | collisionless |\n\
         |---|---|---|---|---|---|---|\n",
    );
    let mut inverse = Verdicts::default();
    for (label, gs) in gases {
        let (a, se) = exponent(gs);
        let (g, scale) = (gs[0], crossing_scale(gs[0]));
        let _ = writeln!(
            md,
            "| {label} | {} | {} | {} | {} | {} | {} |",
            num(g.stat("knudsen").mean),
            gs.len(),
            pm(a, se),
            num(z(a, -1.0, se)),
            num(g.stat("relaxation_time").mean * scale),
            num(g.tau_free() * scale)
        );
        inverse.add(format!("{label} (a = {})", pm(a, se)), z(a, -1.0, se));
    }
    if inverse.differ.is_empty() && !inverse.agree.is_empty() {
        md.push_str("\n**Yes, τ changes with p_max: τ ∝ 1/p_max for every gas swept.**");
    }
    let _ = writeln!(
        md,
        " The power a is −1 within {} standard errors for: {}. It is not for: {}.\n",
        num(AGREE),
        list(&inverse.agree),
        list(&inverse.differ)
    );
    md
}

/// The left fraction of each gas (on the scaled time axis when it was
/// started with uniform momenta), then of each case.
fn left_fractions<'a>(
    md: &mut String,
    figures: &mut Vec<Figure>,
    gases: &'a [GasPoints<'a>],
    cases: &[&'a Group<'a>],
) {
    let mut singles: Vec<(String, &Group)> = Vec::new();
    for (i, (label, gs)) in gases.iter().enumerate() {
        if !gs[0].p_max().is_finite() {
            singles.extend(gs.iter().enumerate().map(|(j, g)| (format!("{i}_{j}"), *g)));
            continue;
        }
        let file = format!("expansion_left_fraction_{i}.svg");
        let _ = writeln!(
            md,
            "![{label}: ensemble mean of the left fraction at each p_max (band: ±1 standard error) \
             against t p_max / m, with the collisionless and diffusive predictions (dashed).]({file})\n"
        );
        let chart = scaled(gs, label);
        figures.push(Figure { file, chart });
    }
    singles.extend(
        cases
            .iter()
            .map(|g| (g.case.clone().unwrap_or_default(), *g)),
    );
    for (name, g) in &singles {
        let file = format!("expansion_left_fraction_{name}.svg");
        let _ = writeln!(
            md,
            "![{}: ensemble mean of the left fraction (band: ±1 standard error over {} runs) and \
             the collisionless prediction (dashed).]({file})\n",
            g.label(),
            g.outs.len()
        );
        figures.push(Figure {
            file,
            chart: single(g),
        });
    }
}

/// Every point and case, and which of them each prediction describes.
fn points_table<'a>(groups: impl Iterator<Item = &'a &'a Group<'a>>) -> String {
    let mut md = String::from(
        "| gas | d | Kn = λ/L | runs | τ (runs reaching it) | τ of the mean curve | τ free | τ / τ free | \
         max \\|z\\| vs free, t ≤ 3 τ free | same vs free Maxwellian at the same kT | τ diffusive (Enskog D) | late mean (z vs ½) | \
         late variance × 4N (z vs S(0)) | S(0) | CPU s | collisions |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let (mut free, mut diffusive) = (Verdicts::default(), Verdicts::default());
    for g in groups {
        let tau = g.stat("relaxation_time");
        let tau_free = g.tau_free();
        let tau_diffusive = g.stat("relaxation_time_diffusive").mean;
        let zf = free_z(g, g.free());
        let kn = g.stat("knudsen").mean;
        let named = format!("{} (Kn = {})", g.label(), num(kn));
        free.add(named.clone(), zf);
        diffusive.add(named, z(tau.mean, tau_diffusive, tau.stderr));
        let late = g.stat("late_mean");
        let var = g.stat("late_variance_ratio");
        let s0 = g.stat("compressibility").mean;
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} ({}/{}) | {} | {} | {} | {} | {} | {} | {} ({}) | {} ({}) | {} | {} | {} |",
            g.label(),
            g.dimension(),
            num(kn),
            g.outs.len(),
            pm(tau.mean, tau.stderr),
            tau.n,
            g.outs.len(),
            num(g.tau_of_mean()),
            num(tau_free),
            num(tau.mean / tau_free),
            num(zf),
            num(free_z(g, g.free_thermal())),
            num(tau_diffusive),
            pm(late.mean, late.stderr),
            num(z(late.mean, 0.5, late.stderr)),
            pm(var.mean, var.stderr),
            num(z(var.mean, s0, var.stderr)),
            num(s0),
            num(g.outs.iter().map(|o| o.cpu_seconds).sum()),
            count(g.outs.iter().map(|o| o.collisions).sum()),
        );
    }
    let _ = writeln!(
        md,
        "\nThe collisionless curve holds within {0} of its standard errors at every sample up to {1} τ free at: {2}. \
         It does not at: {3}. The diffusive relaxation time (Enskog D) is within {0} standard errors of the measured τ at: {4}. \
         It is not at: {5}.\n",
        num(AGREE),
        num(COMPARED),
        list(&free.agree),
        list(&free.differ),
        list(&diffusive.agree),
        list(&diffusive.differ)
    );
    md
}

#[cfg(test)]
mod tests {
    use crate::stats::fill::unfilled;

    #[test]
    fn every_placeholder_is_filled() {
        assert!(unfilled(&super::methods()).is_empty());
        assert!(unfilled(super::INTRO).is_empty());
    }
}
