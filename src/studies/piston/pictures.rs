//! MacKay's own eleven-particle case (the `[[case]]` named "mackay"): his
//! pictures (space-time diagram, the energy of each gas and of the piston
//! over the first 40 time units and the whole run) with the adiabatic
//! prediction drawn in, and his question answered in numbers.

use super::cases::{self, First};
use crate::model::chart::{Layer, Paint};
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::summary::Stats;
use crate::studies::curves::{figure, polyline, show};
use crate::theory::piston::Law;
use crate::theory::piston_equilibrium::degrees_of_freedom;
use std::f64::consts::TAU;
use std::fmt::Write;

const BLUE: (u8, u8, u8) = (0, 114, 178);
const GREEN: (u8, u8, u8) = (0, 158, 115);
pub(super) const PURPLE: (u8, u8, u8) = (204, 121, 167);
pub(super) const BLACK: (u8, u8, u8) = (0, 0, 0);
pub(super) const GREY: (u8, u8, u8) = (150, 150, 150);

/// A predicted piston path (t, x), its colour and its legend.
pub(super) type PredictedPath = (Vec<(f64, f64)>, (u8, u8, u8), &'static str);

const ANSWER: &str = include_str!("text/mackay.md");

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
pub fn mackay_case(all: &[cases::Run], figures: &mut Vec<Figure>) -> anyhow::Result<String> {
    let replicas = cases::runs(all, CASE);
    let Some(run) = replicas.first().copied() else {
        return Ok(String::new());
    };
    let first = First::<1>::of(run)?;
    let duration = run.0.descriptor.run.duration.unwrap_or(f64::NAN);
    let paths = [
        (Law::Adiabatic, BLACK, "adiabatic theory (γ = 3)"),
        (Law::Isothermal, GREY, "isothermal (γ = 1)"),
    ]
    .map(|(law, rgb, label)| (first.start.trajectory(law, duration, 0.02), rgb, label));
    let run_settings = &run.0.descriptor.run;
    let sample_every = run_settings.sample_every.unwrap_or(f64::NAN);
    let [left, right] = first.geometry.particles;
    let values = answer(
        &|name| cases::stat(&replicas, name),
        replicas.len(),
        (duration, sample_every),
        cases::cost(&replicas),
        (first.geometry.mass, degrees_of_freedom(1, left + right)),
    );
    let mut md = fill(ANSWER, &values);
    let horizons = [40.0_f64.min(duration), duration];
    for horizon in horizons {
        let caption = format!(
            "MacKay's case, first {horizon} time units: positions of all particles (time up; light gas blue, heavier gas green, piston purple) and the piston's path predicted by the adiabatic (black dashed) and isothermal (grey dashed) oscillators from the same start."
        );
        md += &show(figures, spacetime(&first, &paths, horizon), &caption);
    }
    for horizon in horizons {
        let name = format!("mackay_energy_{horizon}.svg");
        let title =
            format!("Kinetic energy of each gas and of the piston, first {horizon} time units");
        energies(&first, horizon, &title, &name, figures);
        let _ = writeln!(
            md,
            "![Kinetic energy of the light gas (blue), the heavier gas (green) and the piston (purple) over the first {horizon} time units; dashed: the piston's oscillator energy (kinetic + adiabatic potential) and its equilibrium level.]({name})\n"
        );
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
    let tau = stat("relaxation_time");
    let speed = stat("speed_ratio").mean;
    let harmonic = 100.0 * (small / ad - 1.0);
    let share = 100.0 * stat("initial_piston_share").mean;
    let measured_period = period(measured.mean);
    let period_error = measured.stderr * measured_period / measured.mean;
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
        (
            "swing",
            format!(
                "at this energy the small-oscillation frequency is {:.0}% {} the nonlinear one, so the \
                 oscillation is {}",
                harmonic.abs(),
                if harmonic < 0.0 { "below" } else { "above" },
                if harmonic.abs() > 5.0 {
                    "far from harmonic"
                } else {
                    "nearly harmonic"
                }
            ),
        ),
        ("ad", num(ad)),
        ("pad", num(period(ad))),
        ("inr", num(inertia)),
        ("pinr", num(period(inertia))),
        ("st", num(start)),
        ("pst", num(period(start))),
        ("sm", num(small)),
        ("psm", num(period(small))),
        ("iso", num(iso)),
        ("piso", num(period(iso))),
        ("n", measured.n.to_string()),
        ("meas", both(&measured)),
        ("pmeas", pm(measured_period, period_error)),
        ("r_ad", both(&ratios[0])),
        ("r_in", both(&ratios[1])),
        ("r_iso", both(&ratios[2])),
        ("r_st", pm(measured.mean / start, measured.stderr / start)),
        (
            "dev",
            format!(
                "{:.1}% {} than predicted ({})",
                longer.abs(),
                if longer < 0.0 { "shorter" } else { "longer" },
                if (measured.mean / start - 1.0).abs() <= 4.0 * measured.stderr / start {
                    "within four standard errors"
                } else {
                    "more than four standard errors off"
                }
            ),
        ),
        ("verdict", verdict(&ratios[0], &ratios[1], &ratios[2])),
        ("speed", num(speed)),
        ("slow", slow(speed, fits(&ratios[0]) || fits(&ratios[1]))),
        ("tau", both(&tau)),
        ("taun", tau.n.to_string()),
        ("cycles", format!("{:.1}", tau.mean * measured.mean / TAU)),
    ]
}

/// A measured ratio agrees with 1 within four standard errors.
fn fits(s: &Stats) -> bool {
    (s.mean - 1.0).abs() <= 4.0 * s.stderr
}

/// Whether the compression is slow (peak piston speed below 0.3 of the
/// gases' thermal speed) and whether the adiabatic frequency held.
fn slow(speed: f64, adiabatic: bool) -> String {
    let pace = if speed < 0.3 { "slow" } else { "not slow" };
    let held = match (speed < 0.3, adiabatic) {
        (true, true) | (false, false) => "and",
        _ => "yet",
    };
    let frequency = if adiabatic {
        "the adiabatic frequency holds"
    } else {
        "the frequency departs from the adiabatic one"
    };
    format!(": the compression is {pace} (below 0.3 counts as slow), {held} {frequency}")
}

/// Which theory the measurement agrees with, by the error bar (4 standard errors).
fn verdict(ad: &Stats, inertia: &Stats, iso: &Stats) -> String {
    let gap = |s: &Stats| format!("{:+.1}%", 100.0 * (s.mean - 1.0));
    match (fits(ad), fits(inertia), fits(iso)) {
        (true, _, false) => {
            "The adiabatic prediction holds within the error bar; the isothermal one does not."
                .into()
        }
        (false, true, false) => format!(
            "The measured frequency is {} off the plain adiabatic prediction but agrees with it once the gases' inertia is added; the isothermal prediction is {} off.",
            gap(ad),
            gap(iso)
        ),
        (_, _, true) => {
            "The error bar cannot tell the adiabatic prediction from the isothermal one.".into()
        }
        (false, false, false) => format!(
            "No prediction holds within the error bar: the measured frequency is {} off the adiabatic one ({} with the gases' inertia) and {} off the isothermal one, closer to {}.",
            gap(ad),
            gap(inertia),
            gap(iso),
            if (ad.mean - 1.0).abs() < (iso.mean - 1.0).abs() {
                "adiabatic"
            } else {
                "isothermal"
            }
        ),
    }
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
    title: &str,
    name: &str,
    figures: &mut Vec<Figure>,
) {
    let before = |(t, e): (&f64, &f64)| (*t <= horizon).then_some((*t, *e));
    let mut layers: Vec<Layer> = first
        .out
        .series
        .iter()
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
    let labels = (title.to_string(), "time t", "kinetic energy");
    figures.push(figure(name, labels, (false, false), layers));
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
}
