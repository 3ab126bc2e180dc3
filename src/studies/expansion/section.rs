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
use crate::stats::groups::first_seen;
use crate::stats::named::named;
use crate::stats::power_law::{PowerLaw, log_point};
use crate::stats::table::table_row;
use crate::theory::expansion_rods::Collisionless;

const INTRO: &str = include_str!("intro.md");
const METHODS: &str = include_str!("methods.md");
const CAPTIONS: &str = include_str!("captions.md");
const EXPONENTS: &str = include_str!("exponents.md");
const POINTS: &str = include_str!("points.md");

/// Beyond this many collisionless relaxation times the curves are compared
/// no further: both are within noise of 1/2 there.
pub const COMPARED: f64 = 3.0;

/// |z| below which a measurement agrees with a prediction.
const AGREE: f64 = 4.0;

/// A sweep's gas (N, radius) and its points, one per p_max.
type GasPoints<'a> = (String, Vec<&'a Group<'a>>);

/// Largest |mean - theory| of a group's mean curve against a collisionless
/// curve, over that curve's own standard error of a mean over the group's
/// runs of its particles, sqrt(f (1 - f) / (n runs)) (free particles are
/// independent, each on the left with probability f), over the samples up
/// to `COMPARED` of its relaxation times. The error under the hypothesis
/// tested, not the runs' scatter: with a handful of runs that scatter is
/// itself uncertain, and its Student tails over hundreds of samples would
/// reject the theory by chance.
fn free_z(g: &Group, free: Option<Collisionless>) -> f64 {
    let Some(free) = free else {
        return f64::NAN;
    };
    let until = COMPARED * free.relaxation_time();
    (g.t.iter().zip(&g.mean))
        .filter(|(t, _)| **t > 0.0 && **t <= until)
        .map(|(t, s)| {
            let f = free.left_fraction(*t);
            let se = (f * (1.0 - f) / (g.particles() * s.n as f64)).sqrt();
            if se > 0.0 {
                ((s.mean - f) / se).abs()
            } else {
                0.0
            }
        })
        .fold(0.0, f64::max)
}

/// Power of p_max in the relaxation time of one gas (weights from the
/// runs' standard errors) and its standard error.
fn exponent(gs: &[&Group]) -> (f64, f64) {
    let logs: Vec<_> = (gs.iter())
        .filter_map(|g| log_point(g.p_max(), &g.stat("relaxation_time")))
        .collect();
    let fit = PowerLaw::fit(&logs, 2);
    (fit.exponent, fit.error)
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
    let sweep: Vec<&Group> = all.iter().filter(|g| g.spec.case.is_none()).collect();
    let case = |g: &Group| g.spec.case.clone().unwrap_or_default();
    let profiled = |g: &Group| case(g).starts_with("profiles");
    let measures_d = |g: &Group| g.stat("diffusion_measured").n > 0;
    let expansion_cases: Vec<&Group> = (all.iter())
        .filter(|g| g.spec.case.is_some() && !profiled(g) && !measures_d(g))
        .collect();
    // The sweep's gases (N, radius), each at its values of p_max.
    let gas = |g: &Group| format!("N = {}, radius {}", g.particles(), num(g.radius()));
    let gases: Vec<GasPoints> = first_seen(sweep.iter().copied(), |a, b| gas(a) == gas(b))
        .into_iter()
        .map(|gs| (gas(gs[0]), gs))
        .collect();
    let mut figures = Vec::new();
    let mut md = String::from(INTRO);
    let diffusion = all.iter().find(|g| measures_d(g));
    let measured_point = diffusion.and_then(|g| diffusion_text(&mut md, g));
    if sweep.iter().any(|g| g.p_max().is_finite()) {
        let knudsen = tau_against_knudsen(&sweep, measured_point);
        for (name, chart) in [("p_max", tau_against_p(&gases)), ("knudsen", knudsen)] {
            let file = format!("expansion_tau_{name}.svg");
            figures.push(Figure { file, chart });
        }
        md.push_str(&exponent_table(&gases));
    }
    left_fractions(&mut md, &mut figures, &gases, &expansion_cases);
    md.push_str(&points_table(sweep.iter().chain(&expansion_cases)));
    for g in all.iter().filter(|g| profiled(g)) {
        if let Some((fs, text)) = profiles::section(g, &case(g)) {
            md.push_str(&text);
            figures.extend(fs);
        }
    }
    md.push_str(&methods());
    Ok(crate::studies::parts::section(
        "Expansion of the gas",
        md,
        figures,
        RESULTS,
    ))
}

fn methods() -> String {
    let values = [("agree", num(AGREE)), ("compared", num(COMPARED))];
    fill(METHODS, &values)
}

/// The caption or sentence named `name`, filled, as a paragraph.
fn caption(name: &str, values: &[(&str, String)]) -> String {
    fill(named(CAPTIONS, name), values) + "\n\n"
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
    md.push_str(&caption(
        "diffusion",
        &[
            ("case", g.spec.case.clone().unwrap_or_default()),
            ("label", g.label()),
            ("measured", pm(measured.mean, measured.stderr)),
            ("runs", measured.n.to_string()),
            ("enskog", num(enskog)),
            ("ratio", num(measured.mean / enskog)),
            ("tau", num(tau(measured.mean))),
            ("tau_enskog", num(tau(enskog))),
        ],
    ));
    Some((gas?.knudsen(), tau(measured.mean) * crossing_scale(g)))
}

/// Per gas the power of p_max in τ, and whether τ ∝ 1/p_max.
fn exponent_table(gases: &[GasPoints]) -> String {
    let mut rows = String::new();
    let mut inverse = Verdicts::default();
    for (label, gs) in gases {
        let (a, se) = exponent(gs);
        let (g, scale) = (gs[0], crossing_scale(gs[0]));
        rows.push_str(&table_row(&[
            label.clone(),
            num(g.stat("knudsen").mean),
            gs.len().to_string(),
            pm(a, se),
            num(z(a, -1.0, se)),
            num(g.stat("relaxation_time").mean * scale),
            num(g.tau_free() * scale),
        ]));
        inverse.add(format!("{label} (a = {})", pm(a, se)), z(a, -1.0, se));
    }
    let all_inverse = inverse.differ.is_empty() && !inverse.agree.is_empty();
    let inverse_text = match all_inverse {
        true => format!("\n{}", named(CAPTIONS, "inverse")),
        false => String::new(),
    };
    fill(
        EXPONENTS,
        &[
            ("rows", rows),
            ("inverse", inverse_text),
            ("agree", num(AGREE)),
            ("agreeing", list(&inverse.agree)),
            ("differing", list(&inverse.differ)),
        ],
    )
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
        let values = [("label", label.clone()), ("file", file.clone())];
        md.push_str(&caption("scaled", &values));
        let chart = scaled(gs, label);
        figures.push(Figure { file, chart });
    }
    singles.extend(
        cases
            .iter()
            .map(|g| (g.spec.case.clone().unwrap_or_default(), *g)),
    );
    for (name, g) in &singles {
        let file = format!("expansion_left_fraction_{name}.svg");
        let runs = g.outs.len().to_string();
        let values = [("label", g.label()), ("runs", runs), ("file", file.clone())];
        md.push_str(&caption("single", &values));
        let chart = single(g);
        figures.push(Figure { file, chart });
    }
}

/// Every point and case, and which of them each prediction describes.
fn points_table<'a>(groups: impl Iterator<Item = &'a &'a Group<'a>>) -> String {
    let mut rows = String::new();
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
        let s0 = g.stat("compressibility").mean;
        // "mean ± se (z)" of a result against its theory.
        let with_z = |name: &str, theory: f64| {
            let s = g.stat(name);
            format!(
                "{} ({})",
                pm(s.mean, s.stderr),
                num(z(s.mean, theory, s.stderr))
            )
        };
        let runs = g.outs.len();
        rows.push_str(&table_row(&[
            g.label(),
            g.dimension().to_string(),
            num(kn),
            runs.to_string(),
            format!("{} ({}/{runs})", pm(tau.mean, tau.stderr), tau.n),
            num(g.tau_of_mean()),
            num(tau_free),
            num(tau.mean / tau_free),
            num(zf),
            num(free_z(g, g.free_thermal())),
            num(tau_diffusive),
            with_z("late_mean", 0.5),
            with_z("late_variance_ratio", s0),
            num(s0),
            num(g.cpu()),
            count(g.collisions()),
        ]));
    }
    fill(
        POINTS,
        &[
            ("rows", rows),
            ("agree", num(AGREE)),
            ("compared", num(COMPARED)),
            ("free_agree", list(&free.agree)),
            ("free_differ", list(&free.differ)),
            ("diffusive_agree", list(&diffusive.agree)),
            ("diffusive_differ", list(&diffusive.differ)),
        ],
    )
}

#[cfg(test)]
mod tests {
    use crate::stats::fill::unfilled;
    use crate::stats::named::names;

    /// Every text is filled, with no points too; the captions are the ones
    /// the code names.
    #[test]
    fn every_placeholder_is_filled() {
        assert!(unfilled(&super::methods()).is_empty());
        assert!(unfilled(super::INTRO).is_empty());
        assert!(unfilled(&super::exponent_table(&[])).is_empty());
        assert!(unfilled(&super::points_table(std::iter::empty())).is_empty());
        let captions: Vec<&str> = names(super::CAPTIONS).collect();
        assert_eq!(captions, ["diffusion", "inverse", "scaled", "single"]);
    }
}
