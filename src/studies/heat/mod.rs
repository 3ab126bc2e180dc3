//! The heat-transfer analysis (Imperial "Heat transfer across the
//! boundary"): walls that are heat baths. A gas started hotter or colder
//! than walls at one temperature relaxes to it (against the exact initial
//! exchange rate and a well-mixed model); a gas between a hot and a cold
//! wall conducts heat, and its conductivity is set beside Chapman-Enskog and
//! Enskog. docs/heat.md derives the theory.

mod chain;
mod conduct;
mod gas;
mod relax;
mod section;
mod section_conduct;
mod section_relax;

use super::options::value;
use super::{Finished, Study, StudyOption};
use crate::model::descriptor::Descriptor;
use crate::model::need::Need;
use crate::model::problem::{Check, bad};
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::model::scene::SceneSpec;
use crate::stats::ensemble::Runs;
use crate::stats::late::late_mean;
use crate::studies::parts::scalars;
use crate::theory::heat::{conductivity_dilute, enskog_factor};
pub use conduct::{Line, Profile, centre_density};
pub use gas::{Experiment, Gas};
pub use relax::{initial_ratio, model, passage, temperatures};

pub const NAME: &str = "heat";

/// The series every run records for it.
pub const SERIES: &[&str] = &["kinetic_energy"];

pub const OPTIONS: &[StudyOption] = &[
    StudyOption {
        name: "initial_window",
        above: 0.0,
        at_most: 1.0,
        default: 0.1,
        about: "relaxation: the first stretch, as a fraction of the well-mixed relaxation time, over which the change of T is set beside the exact initial exchange rate",
    },
    StudyOption {
        name: "fit_width",
        above: 0.0,
        at_most: 1.0,
        default: 0.5,
        about: "conduction: the middle part of the box, as a fraction of its length, through whose temperature profile a straight line gives the gradient",
    },
];

/// Every result `per_run` adds: three for every run, then eight for
/// relaxation runs and fifteen for conduction runs (`writes` splits them
/// there); the report's heat section presents them.
pub const RESULTS: &[&str] = &[
    "particles",
    "packing_fraction",
    "knudsen",
    "start_temperature",
    "relaxation_time",
    "relaxation_time_model",
    "relaxation_ratio",
    "relaxation_time_free",
    "relaxation_ratio_free",
    "initial_rate_ratio",
    "late_temperature",
    "flux_in",
    "flux_out",
    "flux_imbalance",
    "gradient",
    "centre_temperature",
    "centre_density",
    "centre_packing",
    "conductivity",
    "conductivity_effective",
    "conductivity_dilute",
    "conductivity_enskog",
    "conductivity_ratio_dilute",
    "conductivity_ratio_enskog",
    "jump_hot",
    "jump_cold",
];

/// The heat study as a plug-in.
pub struct Heat;

impl Study for Heat {
    fn name(&self) -> &'static str {
        NAME
    }
    fn about(&self) -> &'static str {
        "thermal walls: a gas relaxing to walls at one temperature (time against the exact initial exchange rate and a well-mixed model), and a hot and a cold wall (flux balance, profiles, temperature jumps, conductivity against Chapman-Enskog and Enskog)"
    }
    fn options(&self) -> &'static [StudyOption] {
        OPTIONS
    }
    fn needs(&self) -> &'static [Need] {
        &[Need::Sampling, Need::Walls, Need::ThermalWalls]
    }
    fn check(&self, d: &Descriptor, _: &SceneSpec, key: &str) -> Check {
        let experiment = Gas::of(d).and_then(|gas| gas.experiment());
        let o = &d.observe;
        match experiment {
            Err(message) => bad(key, message, None),
            // What `conduction` reads off the walls and the profile.
            Ok(Experiment::Conduct { .. }) if !o.scalars.iter().any(|n| n == "wall_heat") => bad(
                key,
                "a hot and a cold wall: conduction needs the heat each wall gives",
                Some("add `scalars = [\"wall_heat\"]` to [observe]"),
            ),
            Ok(Experiment::Conduct { .. }) if !o.histograms.iter().any(|n| n == "energy_x") => bad(
                key,
                "a hot and a cold wall: conduction needs the temperature profile",
                Some("add `histograms = [\"energy_x\"]` to [observe]"),
            ),
            Ok(_) => Ok(()),
        }
    }
    fn series(&self) -> &'static [&'static str] {
        SERIES
    }
    fn results(&self) -> &'static [&'static str] {
        RESULTS
    }
    fn writes(&self, d: &Descriptor) -> Vec<&'static str> {
        let (common, rest) = RESULTS.split_at(3);
        let (relaxation, conduction) = rest.split_at(8);
        let own = match Gas::of(d).and_then(|gas| gas.experiment()) {
            Ok(Experiment::Relax { .. }) => relaxation,
            Ok(Experiment::Conduct { .. }) => conduction,
            Err(_) => &[],
        };
        [common, own].concat()
    }
    fn per_run(&self, run: &Finished, out: &mut RunOutput) -> Result<(), String> {
        let d = run.descriptor;
        let gas = Gas::of(d)?;
        let mut put = |k: &str, v: f64| out.scalars.push((k.to_string(), v));
        put("particles", gas.particles);
        put("packing_fraction", gas.packing());
        put("knudsen", gas.knudsen());
        match gas.experiment()? {
            Experiment::Relax { wall } => relaxation(d, &gas, wall, out),
            Experiment::Conduct {
                hot,
                cold,
                hot_high,
            } => conduction(d, &gas, (hot, cold, hot_high), run.context.duration, out),
        }
    }
    fn theory(&self, d: &Descriptor, result: &str) -> Option<f64> {
        let gas = Gas::of(d).ok()?;
        match (gas.experiment().ok()?, result) {
            (Experiment::Relax { .. }, "initial_rate_ratio") => Some(1.0),
            (Experiment::Relax { wall }, "late_temperature") => Some(wall),
            // The well-mixed model: it holds only between the dilute and the
            // dense ends (the report shows where).
            // Point particles never collide: the collisionless theory is exact.
            (Experiment::Relax { wall }, "relaxation_time") => {
                let start = gas.start?;
                if gas.diameter == 0.0 {
                    let until = 20.0 * model(&gas, wall, start).linear_time();
                    Some(
                        gas.free(wall, start, until)?
                            .relaxation_time(gas.dimension as f64 / 2.0 * wall),
                    )
                } else {
                    Some(model(&gas, wall, start).relaxation_time())
                }
            }
            (Experiment::Conduct { .. }, "flux_imbalance") => Some(0.0),
            (Experiment::Conduct { .. }, "conductivity_ratio_enskog") => Some(1.0),
            _ => None,
        }
    }
    /// The well-mixed model, which the dilute and dense ends are meant to
    /// miss (for point particles the theory is the exact collisionless one).
    fn contrast(&self, d: &Descriptor, result: &str) -> bool {
        result == "relaxation_time" && Gas::of(d).is_ok_and(|g| g.diameter > 0.0)
    }
    fn section(&self, d: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection> {
        section::section(d, runs)
    }
}

fn relaxation(d: &Descriptor, gas: &Gas, wall: f64, out: &mut RunOutput) -> Result<(), String> {
    let series = out
        .series("kinetic_energy")
        .ok_or("the heat analysis needs the kinetic_energy series")?;
    let t = series.t.clone();
    let temp = temperatures(gas, &series.value);
    let start = *temp.first().ok_or("the kinetic_energy series is empty")?;
    let m = model(gas, wall, start);
    let tau_model = m.relaxation_time();
    let window = value(d, NAME, OPTIONS, "initial_window") * tau_model;
    let tau = passage(&t, &temp, wall, (-1f64).exp());
    let until = t.last().copied().unwrap_or(0.0).max(tau_model);
    let tau_free = gas.free(wall, start, until).map_or(f64::NAN, |f| {
        f.relaxation_time(gas.dimension as f64 / 2.0 * wall)
    });
    out.scalars.extend(scalars([
        ("start_temperature", start),
        ("relaxation_time", tau),
        ("relaxation_time_model", tau_model),
        ("relaxation_ratio", tau / tau_model),
        ("relaxation_time_free", tau_free),
        ("relaxation_ratio_free", tau / tau_free),
        ("initial_rate_ratio", initial_ratio(&t, &temp, &m, window)),
        ("late_temperature", late_mean(&t, &temp)),
    ]));
    Ok(())
}

fn conduction(
    d: &Descriptor,
    gas: &Gas,
    (hot, cold, hot_high): (f64, f64, bool),
    duration: f64,
    out: &mut RunOutput,
) -> Result<(), String> {
    let heat = |side: &str| {
        out.scalar(&format!("heat_in.axis0.{side}"))
            .ok_or("the heat analysis of a hot and a cold wall needs `scalars = [\"wall_heat\"]` in [observe]")
    };
    let (low, high) = (heat("low")?, heat("high")?);
    let (q_hot, q_cold) = if hot_high { (high, low) } else { (low, high) };
    let area = gas.wall_area(0);
    let flux_in = q_hot / (duration * area);
    let flux_out = -q_cold / (duration * area);
    let flux = (flux_in + flux_out) / 2.0;
    let profile = Profile::of_run(gas, out).ok_or(
        "the heat analysis of a hot and a cold wall needs `histograms = [\"energy_x\"]` in [observe]",
    )?;
    let length = gas.size[0];
    let width = value(d, NAME, OPTIONS, "fit_width");
    let line = Line::fit(&profile, length, width);
    // Heat flows toward the cold wall: along +x when the hot one is low.
    let along = if hot_high { -flux } else { flux };
    let kappa = -along / line.slope;
    let n = centre_density(&profile, length, width);
    let phi = n * gas.particle_volume();
    let dilute = conductivity_dilute(gas.dimension, gas.diameter, gas.mass, line.centre);
    let enskog = dilute * enskog_factor(gas.dimension, phi);
    // Centres touch the walls a radius from them.
    let (x_hot, x_cold) = {
        let (a, b) = (gas.diameter / 2.0, length - gas.diameter / 2.0);
        if hot_high { (b, a) } else { (a, b) }
    };
    out.scalars.extend(scalars([
        ("flux_in", flux_in),
        ("flux_out", flux_out),
        ("flux_imbalance", flux_in - flux_out),
        ("gradient", line.slope),
        ("centre_temperature", line.centre),
        ("centre_density", n),
        ("centre_packing", phi),
        ("conductivity", kappa),
        // The whole chain's: the walls' temperature difference over
        // their distance, jumps included (what 1D studies of anomalous
        // conduction report against N).
        ("conductivity_effective", flux * length / (hot - cold)),
        ("conductivity_dilute", dilute),
        ("conductivity_enskog", enskog),
        ("conductivity_ratio_dilute", kappa / dilute),
        ("conductivity_ratio_enskog", kappa / enskog),
        ("jump_hot", hot - line.at(x_hot)),
        ("jump_cold", line.at(x_cold) - cold),
    ]));
    Ok(())
}
