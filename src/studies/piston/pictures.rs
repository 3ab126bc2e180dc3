//! MacKay's own eleven-particle case (the `[[case]]` named "mackay"): his
//! pictures (space-time diagram, the energy of each gas and of the piston
//! over the first 40 time units and the whole run) with the adiabatic
//! prediction drawn in, and his question answered in numbers.

use super::CAPTIONS;
use super::cases::{self, First};
use crate::model::chart::{Layer, Paint};
use crate::model::report::Figure;
use crate::stats::ensemble::Runs;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::named::named;
use crate::stats::summary::Stats;
use crate::studies::curves::{figure, polyline, show};
use crate::theory::piston::Law;
use crate::theory::piston_equilibrium::degrees_of_freedom;
use std::f64::consts::TAU;

const BLUE: (u8, u8, u8) = (0, 114, 178);
const GREEN: (u8, u8, u8) = (0, 158, 115);
pub(super) const PURPLE: (u8, u8, u8) = (204, 121, 167);
pub(super) const BLACK: (u8, u8, u8) = (0, 0, 0);
pub(super) const GREY: (u8, u8, u8) = (150, 150, 150);

/// A predicted piston path (t, x), its colour and its legend.
type PredictedPath = (Vec<(f64, f64)>, (u8, u8, u8), &'static str);

const ANSWER: &str = include_str!("text/mackay.md");
/// The answer's phrases that depend on the outcome, by name.
const OUTCOMES: &str = include_str!("text/outcomes.md");

fn colour(species: &str) -> (u8, u8, u8) {
    match species {
        "light" => BLUE,
        "heavy" => GREEN,
        _ => PURPLE,
    }
}

/// The `[[case]]` that runs MacKay's own eleven particles.
pub const CASE: &str = "mackay";

/// MacKay's case from its runs: his question answered, and his pictures.
/// Empty if the plan has no such case.
pub fn mackay_case(all: &Runs, figures: &mut Vec<Figure>) -> anyhow::Result<String> {
    let Some(case) = cases::case(all, CASE) else {
        return Ok(String::new());
    };
    let first = First::<1>::of(&case)?;
    let run = &case.spec.descriptor.run;
    let duration = run.duration.unwrap_or(f64::NAN);
    let paths = [
        (Law::Adiabatic, BLACK, "adiabatic theory (γ = 3)"),
        (Law::Isothermal, GREY, "isothermal (γ = 1)"),
    ]
    .map(|(law, rgb, label)| (first.start.trajectory(law, duration, 0.02), rgb, label));
    let [left, right] = first.geometry.particles;
    let values = answer(
        &|name| case.stat(name),
        case.outs.len(),
        (duration, run.sample_every.unwrap_or(f64::NAN)),
        (case.collisions(), case.cpu()),
        (first.geometry.mass, degrees_of_freedom(1, left + right)),
    );
    let mut md = fill(ANSWER, &values);
    let horizons = [40.0_f64.min(duration), duration];
    let caption =
        |name, horizon: f64| fill(named(CAPTIONS, name), &[("horizon", horizon.to_string())]);
    for horizon in horizons {
        let picture = spacetime(&first, &paths, horizon);
        md += &show(figures, picture, &caption("spacetime", horizon));
    }
    for horizon in horizons {
        let title =
            format!("Kinetic energy of each gas and of the piston, first {horizon} time units");
        let name = format!("mackay_energy_{horizon}.svg");
        let energy = energies(&first, horizon, title, &name);
        md += &show(figures, energy, &caption("energy", horizon));
    }
    Ok(md)
}

/// The numbers of MacKay's answer (`text/mackay.md`), from the results of
/// its `runs` replicas, their duration and sampling interval, their cost,
/// and the piston's mass and the free degrees of freedom.
fn answer(
    stat: &dyn Fn(&str) -> Stats,
    runs: usize,
    (duration, sample_every): (f64, f64),
    (collisions, seconds): (u64, f64),
    (mass, free): (f64, usize),
) -> Vec<(&'static str, String)> {
    let measured = stat("frequency");
    let period = |w: f64| TAU / w;
    // A prediction's row of the table: its ω and its period.
    let cells = |w: f64| format!("{} | {}", num(w), num(period(w)));
    let omega = |name: &str| stat(name).mean;
    let (ad, inertia) = (omega("omega_adiabatic"), omega("omega_adiabatic_inertia"));
    let (small, iso) = (omega("omega_adiabatic_small"), omega("omega_isothermal"));
    let start = omega("omega_adiabatic_start");
    let longer = 100.0 * (start / measured.mean - 1.0);
    let ratios = [
        "frequency_ratio",
        "frequency_ratio_inertia",
        "frequency_ratio_isothermal",
    ]
    .map(stat);
    let both = |s: &Stats| pm(s.mean, s.stderr);
    let pick = |yes: bool, this: &str, that: &str| (if yes { this } else { that }).to_string();
    // The same between two of the answer's phrases, by name.
    let phrase = |yes, this, that| pick(yes, named(OUTCOMES, this), named(OUTCOMES, that));
    let tau = stat("relaxation_time");
    let speed = stat("speed_ratio").mean;
    let harmonic = 100.0 * (small / ad - 1.0);
    let share = 100.0 * stat("initial_piston_share").mean;
    let measured_period = period(measured.mean);
    let period_error = measured.stderr * measured_period / measured.mean;
    let within = (measured.mean / start - 1.0).abs() <= 4.0 * measured.stderr / start;
    let adiabatic = fits(&ratios[0]) || fits(&ratios[1]);
    vec![
        ("share", format!("{share:.0}")),
        ("mass", num(mass)),
        ("free", free.to_string()),
        ("equipartition", format!("{:.0}", 100.0 / free as f64)),
        ("n_runs", runs.to_string()),
        ("duration", duration.to_string()),
        ("sample_every", sample_every.to_string()),
        ("coll", count(collisions)),
        ("secs", format!("{seconds:.2}")),
        ("harmonic", format!("{:.0}", harmonic.abs())),
        ("side", pick(harmonic < 0.0, "below", "above")),
        ("shape", phrase(harmonic.abs() > 5.0, "far", "nearly")),
        ("ad", cells(ad)),
        ("inr", cells(inertia)),
        ("st", cells(start)),
        ("sm", cells(small)),
        ("iso", cells(iso)),
        ("n", measured.n.to_string()),
        ("meas", both(&measured)),
        ("pmeas", pm(measured_period, period_error)),
        ("r_ad", both(&ratios[0])),
        ("r_in", both(&ratios[1])),
        ("r_iso", both(&ratios[2])),
        ("r_st", pm(measured.mean / start, measured.stderr / start)),
        ("longer", format!("{:.1}", longer.abs())),
        ("way", pick(longer < 0.0, "shorter", "longer")),
        ("within", phrase(within, "within", "off")),
        ("verdict", verdict(&ratios[0], &ratios[1], &ratios[2])),
        ("speed", num(speed)),
        // Whether the compression is slow (peak piston speed below 0.3 of
        // the gases' thermal speed) and whether the adiabatic frequency held.
        ("pace", pick(speed < 0.3, "slow", "not slow")),
        ("held", pick((speed < 0.3) == adiabatic, "and", "yet")),
        ("frequency", phrase(adiabatic, "holds", "departs")),
        ("tau", both(&tau)),
        ("taun", tau.n.to_string()),
        ("cycles", format!("{:.1}", tau.mean * measured.mean / TAU)),
    ]
}

/// A measured ratio agrees with 1 within four standard errors.
fn fits(s: &Stats) -> bool {
    (s.mean - 1.0).abs() <= 4.0 * s.stderr
}

/// Which theory the measurement agrees with, by the error bar (4 standard errors).
fn verdict(ad: &Stats, inertia: &Stats, iso: &Stats) -> String {
    let gap = |s: &Stats| format!("{:+.1}%", 100.0 * (s.mean - 1.0));
    let name = match (fits(ad), fits(inertia), fits(iso)) {
        (true, _, false) => "adiabatic",
        (false, true, false) => "inertia",
        (_, _, true) => "unclear",
        (false, false, false) => "none",
    };
    let closer = if (ad.mean - 1.0).abs() < (iso.mean - 1.0).abs() {
        "adiabatic"
    } else {
        "isothermal"
    };
    let values = [
        ("ad", gap(ad)),
        ("inertia", gap(inertia)),
        ("iso", gap(iso)),
        ("closer", closer.into()),
    ];
    fill(named(OUTCOMES, name), &values)
}

/// MacKay's space-time diagram with the predicted piston paths.
fn spacetime(first: &First<1>, paths: &[PredictedPath], horizon: f64) -> Figure {
    let built = &first.built;
    let before = |(t, x): (&f64, &f64)| (*t <= horizon).then_some((*x, *t));
    let mut layers: Vec<Layer> = (0..built.particles.len())
        .filter_map(|i| {
            let s = first.out.series(&format!("x.{i}"))?;
            let species = &built.species[built.particles[i].species as usize];
            let points = s.t.iter().zip(&s.value).filter_map(before).collect();
            let paint = Paint::solid(colour(species));
            let width = if species == "piston" { 3 } else { 1 };
            Some(polyline(points, paint, width, false, None))
        })
        .collect();
    for (path, rgb, label) in paths {
        let points = path.iter().map(|(t, x)| (t, x)).filter_map(before);
        let (paint, label) = (Paint::solid(*rgb), Some(label.to_string()));
        layers.push(polyline(points.collect(), paint, 2, true, label));
    }
    let name = format!("mackay_spacetime_{horizon}.svg");
    let title = format!("MacKay's piston: positions, first {horizon} time units");
    let labels = (title, "position x [σ]", "time t");
    figure(&name, labels, (false, false), layers)
}

/// Kinetic energy of each gas and the piston, with the oscillator energy
/// and its equilibrium level, up to `horizon`; written as `name`.
pub(super) fn energies<const D: usize>(
    first: &First<D>,
    horizon: f64,
    title: String,
    name: &str,
) -> Figure {
    let before = |(t, e): (&f64, &f64)| (*t <= horizon).then_some((*t, *e));
    let mut layers: Vec<Layer> = (first.out.series.iter())
        .filter_map(|s| {
            let species = s.observable.strip_prefix("kinetic_energy.")?;
            let points = s.t.iter().zip(&s.value).filter_map(before).collect();
            let (paint, label) = (Paint::solid(colour(species)), Some(species.to_string()));
            Some(polyline(points, paint, 2, false, label))
        })
        .collect();
    let oscillator = first.samples.t.iter().zip(&first.energy).filter_map(before);
    let label = Some("piston oscillator energy".into());
    let paint = Paint::solid(PURPLE).faded(0.6);
    layers.push(polyline(oscillator.collect(), paint, 1, true, label));
    let equilibrium = vec![(0.0, first.equilibrium), (horizon, first.equilibrium)];
    let label = Some("its equilibrium mean".into());
    layers.push(polyline(equilibrium, Paint::solid(GREY), 1, true, label));
    let labels = (title, "time t", "kinetic energy");
    figure(name, labels, (false, false), layers)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_placeholder_of_the_answer_is_filled() {
        let stat = |_: &str| Stats::of(&[0.9, 1.1]);
        let values = answer(&stat, 2, (200.0, 0.05), (10, 0.1), (40.0, 11));
        assert!(crate::stats::fill::unfilled(&fill(ANSWER, &values)).is_empty());
    }

    #[test]
    fn every_verdict_has_its_text() {
        let s = |mean: f64| Stats::of(&[mean - 0.001, mean + 0.001]);
        for (ad, inertia, iso) in [
            (1.0, 1.0, 1.5),
            (0.9, 1.0, 1.5),
            (1.0, 1.0, 1.0),
            (0.9, 0.8, 1.5),
        ] {
            let text = verdict(&s(ad), &s(inertia), &s(iso));
            assert!(!text.is_empty() && crate::stats::fill::unfilled(&text).is_empty());
        }
    }
}
