//! MacKay's own eleven-particle case (the `[[case]]` named "mackay"): his
//! pictures (space-time diagram, the energy of each gas and of the piston
//! over the first 40 time units and the whole run) with the adiabatic
//! prediction drawn in, and his question answered in numbers.

use super::cases;
use crate::model::chart::{ChartSpec, Layer, Paint};
use crate::model::report::Figure;
use crate::model::run_output::RunOutput;
use crate::scene::Built;
use crate::stats::format::{count, num, pm};
use crate::stats::summary::Stats;
use crate::studies::piston::DRAWS;
use crate::studies::piston::state::{Geometry, Samples};
use crate::theory::piston::Law;
use crate::theory::piston_equilibrium::oscillator_share;
use std::fmt::Write;

const BLUE: (u8, u8, u8) = (0, 114, 178);
const GREEN: (u8, u8, u8) = (0, 158, 115);
pub(super) const PURPLE: (u8, u8, u8) = (204, 121, 167);
pub(super) const BLACK: (u8, u8, u8) = (0, 0, 0);
pub(super) const GREY: (u8, u8, u8) = (150, 150, 150);

/// A predicted piston path (t, x), its colour and its legend.
pub(super) type PredictedPath = (Vec<(f64, f64)>, (u8, u8, u8), &'static str);

pub(super) fn colour(species: &str) -> (u8, u8, u8) {
    match species {
        "light" => BLUE,
        "heavy" => GREEN,
        _ => PURPLE,
    }
}

/// The `[[case]]` that runs MacKay's own eleven particles.
pub const CASE: &str = "mackay";
/// MacKay's case from its runs: his pictures, and his question answered.
/// Empty if the plan has no such case.
pub fn mackay_case(all: &[cases::Run], figures: &mut Vec<Figure>) -> anyhow::Result<String> {
    let replicas = cases::runs(all, CASE);
    let Some((spec, out)) = replicas.first().copied() else {
        return Ok(String::new());
    };
    let stat = |name: &str| cases::stat(&replicas, name);
    let built = cases::start::<1>(spec)?;
    let first = First { built, out };
    let run = &spec.descriptor.run;
    let duration = run.duration.unwrap_or(f64::NAN);
    let sample_every = run.sample_every.unwrap_or(f64::NAN);
    let n_runs = replicas.len();
    let geometry = Geometry::of(&first.built).ok_or_else(|| anyhow::anyhow!("no piston"))?;
    let samples = Samples::of(first.out).map_err(|e| anyhow::anyhow!(e))?;
    let p = first.built.piston.unwrap_or(0);
    let start = geometry.system(
        samples.x[0],
        samples.piston[0],
        samples.left[0],
        samples.right[0],
        first.built.particles[p].vel[0],
    );
    let paths = [
        (Law::Adiabatic, BLACK, "adiabatic theory (γ = 3)"),
        (Law::Isothermal, GREY, "isothermal (γ = 1)"),
    ]
    .map(|(law, rgb, label)| (start.trajectory(law, duration, 0.02), rgb, label));
    let mut md = String::new();
    let horizons = [40.0_f64.min(duration), duration];
    for horizon in horizons {
        let name = spacetime(&first, &paths, horizon, figures)?;
        let _ = writeln!(
            md,
            "![MacKay's case, first {horizon} time units: positions of all particles (time up; light gas blue, heavier gas green, piston purple) and the piston's path predicted by the adiabatic (black dashed) and isothermal (grey dashed) oscillators from the same start.]({name})\n"
        );
    }
    let total = samples.total[0];
    let (share_eq, _) = oscillator_share(1, geometry.particles[0], geometry.particles[1], DRAWS);
    let energy = samples.oscillator_energy(&geometry);
    for horizon in horizons {
        let name = format!("mackay_energy_{horizon}.svg");
        let oscillator = Oscillator {
            t: &samples.t,
            energy: &energy,
            equilibrium: share_eq * total,
        };
        energies(
            first.out,
            &oscillator,
            horizon,
            &format!("Kinetic energy of each gas and of the piston, first {horizon} time units"),
            &name,
            figures,
        )?;
        let _ = writeln!(
            md,
            "![Kinetic energy of the light gas (blue), the heavier gas (green) and the piston (purple) over the first {horizon} time units; dashed: the piston's oscillator energy (kinetic + adiabatic potential) and its equilibrium level.]({name})\n"
        );
    }

    let (cost_collisions, cost_seconds) = cases::cost(&replicas);
    let measured = stat("frequency");
    let period = |w: f64| std::f64::consts::TAU / w;
    let theory = |name: &str| stat(name).mean;
    let (ad, inertia, small, iso) = (
        theory("omega_adiabatic"),
        theory("omega_adiabatic_inertia"),
        theory("omega_adiabatic_small"),
        theory("omega_isothermal"),
    );
    let ratio = stat("frequency_ratio");
    let ratio_inertia = stat("frequency_ratio_inertia");
    let ratio_iso = stat("frequency_ratio_isothermal");
    let tau = stat("relaxation_time");
    let speed = stat("speed_ratio");
    let mut text = String::new();
    let _ = write!(
        text,
        "### MacKay's case: at what frequency?\n\n\
         MacKay's eleven particles (`preset = \"mackay-piston\"`): five light rods (masses 0.9–1.1) left, five \
         heavier (1.5–1.7) right, a piston of mass 40 between them, all starting with velocity 1, so the piston \
         holds {share:.0}% of the kinetic energy (equipartition: 1/11 = 9%). {n_runs} replicas (the masses are \
         drawn from his ranges), {duration} time units each, sampled every {sample_every}: {coll} collisions, \
         {secs:.2} CPU s in all.\n\n\
         If each gas is compressed adiabatically (P X^3 fixed in 1D), the piston moves in the potential of the \
         two gases, and with this much energy its swing is large, so the oscillation is far from harmonic:\n\n\
         | prediction | ω | period |\n|---|---|---|\n\
         | adiabatic, nonlinear, at the amplitude of each measured period | {ad} | {pad} |\n\
         | adiabatic, nonlinear, gases' inertia added (M + M_gas/3) | {inr} | {pinr} |\n\
         | adiabatic, small oscillations, ω² = γP(1/X_L + 1/X_R)/M | {sm} | {psm} |\n\
         | isothermal (γ = 1), nonlinear | {iso} | {piso} |\n\
         | **measured** (first periods, mean ± standard error, n = {n} of {n_runs}) | **{meas}** | **{pmeas}** |\n\n\
         Measured over adiabatic: {r_ad}; over adiabatic with the gases' inertia: {r_in}; over isothermal: \
         {r_iso}. {verdict} The piston's peak speed is {speed} times the gases' thermal speed: {slow}.\n\n\
         **How does it lose its excess energy?** Each collision exchanges momentum between the piston and a gas \
         particle. While the piston moves into a gas, the particles it meets bounce off faster than they came \
         and those behind it slower; when the gas follows its adiabat this is reversible: the energy comes \
         back when the piston returns. What is lost is the part that is not: particles arriving at \
         different phases, and collisions within each gas that share the energy out. Here the piston gives \
         away 63% of its excess oscillator energy in τ = {tau} time units (n = {taun} of {n_runs}), about \
         {cycles:.1} periods; the sweep below shows how that time grows with M.\n\n",
        share = 100.0 * stat("initial_piston_share").mean,
        coll = count(cost_collisions),
        secs = cost_seconds,
        ad = num(ad),
        pad = num(period(ad)),
        inr = num(inertia),
        pinr = num(period(inertia)),
        sm = num(small),
        psm = num(period(small)),
        iso = num(iso),
        piso = num(period(iso)),
        n = measured.n,
        meas = pm(measured.mean, measured.stderr),
        pmeas = pm(
            period(measured.mean),
            measured.stderr * period(measured.mean) / measured.mean
        ),
        r_ad = pm(ratio.mean, ratio.stderr),
        r_in = pm(ratio_inertia.mean, ratio_inertia.stderr),
        r_iso = pm(ratio_iso.mean, ratio_iso.stderr),
        verdict = verdict(&ratio, &ratio_inertia, &ratio_iso),
        speed = num(speed.mean),
        slow = if speed.mean < 0.3 {
            "the compression is slow, as the adiabatic picture assumes"
        } else {
            "the compression is not slow, so the gases lag behind their adiabats"
        },
        tau = pm(tau.mean, tau.stderr),
        taun = tau.n,
        cycles = tau.mean * measured.mean / std::f64::consts::TAU,
    );
    text.push_str(&md);
    Ok(text)
}

/// Which theory the measurement agrees with, by the error bar (4 standard errors).
fn verdict(ad: &Stats, inertia: &Stats, iso: &Stats) -> String {
    let fits = |s: &Stats| (s.mean - 1.0).abs() <= 4.0 * s.stderr;
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
            "No prediction holds within the error bar: the measured frequency is {} off the adiabatic one ({} with the gases' inertia) and {} off the isothermal one, much closer to adiabatic.",
            gap(ad),
            gap(inertia),
            gap(iso)
        ),
    }
}

/// The first replica: its start and what it recorded.
struct First<'a> {
    built: Built<1>,
    out: &'a RunOutput,
}

/// MacKay's space-time diagram with the predicted piston paths; returns the file name.
fn spacetime(
    first: &First,
    paths: &[PredictedPath],
    horizon: f64,
    figures: &mut Vec<Figure>,
) -> anyhow::Result<String> {
    let built = &first.built;
    let mut layers: Vec<Layer> = (0..built.particles.len())
        .filter_map(|i| {
            let s = first.out.series(&format!("x.{i}"))?;
            let species = &built.species[built.particles[i].species as usize];
            let points =
                s.t.iter()
                    .zip(&s.value)
                    .filter(|(t, _)| **t <= horizon)
                    .map(|(t, x)| (*x, *t))
                    .collect();
            Some(Layer::Line {
                points,
                paint: Paint::solid(colour(species)),
                width: if species == "piston" { 3 } else { 1 },
                dashed: false,
                label: None,
            })
        })
        .collect();
    for (path, rgb, label) in paths {
        layers.push(Layer::Line {
            points: path
                .iter()
                .filter(|(t, _)| *t <= horizon)
                .map(|(t, x)| (*x, *t))
                .collect(),
            paint: Paint::solid(*rgb),
            width: 2,
            dashed: true,
            label: Some(label.to_string()),
        });
    }
    let name = format!("mackay_spacetime_{horizon}.svg");
    let chart = ChartSpec {
        title: format!("MacKay's piston: positions, first {horizon} time units"),
        x_label: "position x [σ]".into(),
        y_label: "time t".into(),
        layers,
        ..Default::default()
    };
    figures.push(Figure {
        file: name.to_string(),
        chart,
    });
    Ok(name)
}

/// The piston's oscillator energy over time and the level it relaxes to.
pub(super) struct Oscillator<'a> {
    pub t: &'a [f64],
    pub energy: &'a [f64],
    pub equilibrium: f64,
}

/// Kinetic energy of each gas and the piston, with the oscillator energy
/// and its equilibrium level, up to `horizon`; written as `name`.
pub(super) fn energies(
    out: &RunOutput,
    osc: &Oscillator,
    horizon: f64,
    title: &str,
    name: &str,
    figures: &mut Vec<Figure>,
) -> anyhow::Result<()> {
    let (t, oscillator, equilibrium) = (osc.t, osc.energy, osc.equilibrium);
    let within = |t: f64| t <= horizon;
    let mut layers: Vec<Layer> = out
        .series
        .iter()
        .filter_map(|s| {
            let species = s.observable.strip_prefix("kinetic_energy.")?;
            Some(Layer::Line {
                points: s
                    .t
                    .iter()
                    .zip(&s.value)
                    .filter(|(t, _)| within(**t))
                    .map(|(t, e)| (*t, *e))
                    .collect(),
                paint: Paint::solid(colour(species)),
                width: 2,
                dashed: false,
                label: Some(species.to_string()),
            })
        })
        .collect();
    layers.push(Layer::Line {
        points: t
            .iter()
            .zip(oscillator)
            .filter(|(t, _)| within(**t))
            .map(|(t, e)| (*t, *e))
            .collect(),
        paint: Paint::solid(PURPLE).faded(0.6),
        width: 1,
        dashed: true,
        label: Some("piston oscillator energy".into()),
    });
    layers.push(Layer::Line {
        points: vec![(0.0, equilibrium), (horizon, equilibrium)],
        paint: Paint::solid(GREY),
        width: 1,
        dashed: true,
        label: Some("its equilibrium mean".into()),
    });
    let chart = ChartSpec {
        title: title.to_string(),
        x_label: "time t".into(),
        y_label: "kinetic energy".into(),
        layers,
        ..Default::default()
    };
    figures.push(Figure {
        file: name.to_string(),
        chart,
    });
    Ok(())
}
