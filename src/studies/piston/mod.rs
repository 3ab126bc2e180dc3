//! The piston analysis (MacKay's eleven particles): how fast the piston
//! oscillates, against adiabatic and isothermal theory; how long it takes to
//! give its excess energy to the gases; what share it keeps in the end.

mod cases;
mod error;
mod pictures;
mod points;
mod regimes;
mod relaxation;
pub mod state;
mod wall;

use super::options::{StudyOption, value};
use super::{Finished, Start, Study};
use crate::model::descriptor::Descriptor;
use crate::model::need::Need;
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::scene::{Built, OnBuilt, on_built};
use crate::stats::decay::relaxation_time;
use crate::stats::ensemble::Runs;
use crate::stats::fill::fill;
use crate::stats::format::num;
use crate::stats::oscillation::{Oscillation, oscillation};
use crate::theory::piston::{Law, PistonSystem};
use crate::theory::piston_equilibrium::{degrees_of_freedom, oscillator_share};
use state::{Geometry, Samples};
use std::f64::consts::TAU;

pub use state::SERIES;

/// Monte Carlo draws for the equilibrium oscillator energy (0.6% precision).
pub const DRAWS: usize = 20_000;

/// Settings from `[analysis.piston]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Full periods the frequency is measured over (`window_periods`, default 4).
    pub periods: usize,
    /// Hysteresis band as a fraction of the position's range (`band`, 0.1).
    pub band: f64,
    /// Part of the run the late shares average over (`late_fraction`, 0.5).
    pub late: f64,
}

impl Options {
    /// The descriptor's values (checked against `OPTIONS` before anything ran).
    pub fn of(d: &Descriptor) -> Options {
        let get = |key: &str| value(d, "piston", OPTIONS, key);
        Options {
            periods: get("window_periods").max(1.0) as usize,
            band: get("band"),
            late: get("late_fraction"),
        }
    }
}

pub const OPTIONS: &[StudyOption] = &[
    StudyOption {
        name: "window_periods",
        above: 0.0,
        at_most: f64::INFINITY,
        default: 4.0,
        about: "full periods of the piston's motion, from the start, over which the frequency is measured",
    },
    StudyOption {
        name: "band",
        above: 0.0,
        at_most: 0.5,
        default: 0.1,
        about: "hysteresis band for turning points, as a fraction of the piston position's range",
    },
    StudyOption {
        name: "late_fraction",
        above: 0.0,
        at_most: 1.0,
        default: 0.5,
        about: "final fraction of the run over which the piston's energy share is averaged",
    },
];

/// The piston study as a plug-in.
pub struct Piston;

impl Study for Piston {
    fn name(&self) -> &'static str {
        "piston"
    }
    fn about(&self) -> &'static str {
        "piston oscillation frequency against adiabatic and isothermal theory, relaxation time, late energy share against equipartition"
    }
    fn options(&self) -> &'static [StudyOption] {
        OPTIONS
    }
    fn needs(&self) -> &'static [Need] {
        &[Need::Piston, Need::Sampling]
    }
    fn series(&self) -> &'static [&'static str] {
        SERIES
    }
    fn results(&self) -> &'static [&'static str] {
        RESULTS
    }
    fn writes(&self, d: &Descriptor) -> Vec<&'static str> {
        // Rods have no axis across x: none of the last eight.
        let rods = crate::scene::resolve(&d.scene).is_ok_and(|s| s.dimension() == Ok(1));
        RESULTS[..RESULTS.len() - if rods { 8 } else { 0 }].to_vec()
    }
    fn per_run(&self, run: &Finished, out: &mut RunOutput) -> Result<(), String> {
        let geometry = match run.start {
            Start::Rods(b) => Geometry::of(b),
            Start::Disks(b) => Geometry::of(b),
            Start::Spheres(b) => Geometry::of(b),
        }
        .ok_or("the piston analysis needs a scene with a piston")?;
        let samples = Samples::of(out)?;
        let scalars = measure(&geometry, &samples, &Options::of(run.descriptor));
        out.scalars
            .extend(scalars.iter().map(|(k, v)| (k.to_string(), *v)));
        Ok(())
    }
    fn theory(&self, d: &Descriptor, result: &str) -> Option<f64> {
        theory(d, result)
    }
    /// The piston alone as the inertia: MacKay's case shows it miss.
    fn contrast(&self, _: &Descriptor, result: &str) -> bool {
        result == "frequency_ratio"
    }
    fn error_model(&self, d: &Descriptor) -> Option<super::ErrorModel> {
        error::error_model(d)
    }
    fn section(&self, d: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection> {
        section(runs, &Options::of(d))
    }
}

/// Every result `measure` gives, in 1D and (the last eight) beside a wall in
/// 2D/3D: the report's piston section presents them all.
pub const RESULTS: &[&str] = &[
    "frequency",
    "frequency_periods",
    "omega_adiabatic",
    "omega_adiabatic_start",
    "omega_adiabatic_small",
    "omega_adiabatic_inertia",
    "omega_isothermal",
    "frequency_ratio",
    "frequency_ratio_inertia",
    "frequency_ratio_isothermal",
    "initial_piston_share",
    "relaxation_time",
    "excess_left",
    "oscillator_share",
    "piston_share",
    "mass_ratio",
    "mass_over_gas",
    "speed_ratio",
    "omega_collisionless",
    "frequency_ratio_collisionless",
    "exchange_time",
    "omega_tau",
    "omega_exchange",
    "frequency_ratio_exchange",
    "relaxation_time_exchange",
    "excluded_fraction",
];

/// Everything measured in one run, by result name (`RESULTS`).
pub fn measure(g: &Geometry, s: &Samples, o: &Options) -> Vec<(&'static str, f64)> {
    let start = s.system(g, 0);
    let measured = oscillation(&s.t, &s.x, o.periods, o.band);
    let frequency = measured.as_ref().map_or(f64::NAN, |m| m.omega);
    let window = window_states(g, s, measured.as_ref());
    let predict = |omega: &dyn Fn(&PistonSystem) -> f64| over_window(&window, omega);
    let omega_ad = predict(&|st| st.omega(Law::Adiabatic));
    let omega_inertia = predict(&|st| st.with_gas_inertia().omega(Law::Adiabatic));
    let omega_iso = predict(&|st| st.at_balance().omega(Law::Isothermal));
    let energy = s.oscillator_energy(g);
    let total = s.total[0];
    let (share_eq, _) = oscillator_share(g.dimension, g.particles[0], g.particles[1], DRAWS);
    let excess: Vec<f64> = energy.iter().map(|e| e - share_eq * total).collect();
    let gas_mass = g.gas_mass[0] + g.gas_mass[1];
    // Peak piston speed (all oscillator energy kinetic, at the balance) over
    // the gases' thermal speed along x, sqrt(<m v_x^2>/<m>).
    let thermal = (2.0 * (s.left[0] + s.right[0]) / (g.dimension as f64 * gas_mass)).sqrt();
    let peak = (2.0 * energy[0] / g.mass).sqrt();
    // Averaged over one measured period (none if there was none).
    let tau = relaxation_time(&s.t, &excess, TAU / frequency).unwrap_or(f64::NAN);
    let periods = measured.as_ref().map_or(0.0, |m| m.periods as f64);
    let small = start.small_oscillation_omega(Law::Adiabatic);
    let shares: Vec<f64> = s.piston.iter().zip(&s.total).map(|(p, k)| p / k).collect();
    let mut results = vec![
        ("frequency", frequency),
        ("frequency_periods", periods),
        ("omega_adiabatic", omega_ad),
        ("omega_adiabatic_start", start.omega(Law::Adiabatic)),
        ("omega_adiabatic_small", small),
        ("omega_adiabatic_inertia", omega_inertia),
        ("omega_isothermal", omega_iso),
        ("frequency_ratio", frequency / omega_ad),
        ("frequency_ratio_inertia", frequency / omega_inertia),
        ("frequency_ratio_isothermal", frequency / omega_iso),
        ("initial_piston_share", s.piston[0] / total),
        ("relaxation_time", tau),
        ("excess_left", late_mean(&excess, 0.1) / excess[0]),
        ("oscillator_share", late_mean(&energy, o.late) / total),
        ("piston_share", late_mean(&shares, o.late)),
        ("mass_ratio", g.mass),
        ("mass_over_gas", g.mass / gas_mass),
        ("speed_ratio", peak / thermal),
    ];
    if g.dimension > 1 {
        results.extend(across_x(g, &start, &window, frequency));
    }
    results
}

/// The states the frequency predictions start from: the turning points
/// within the measured periods (the first sample alone when no period was
/// measured). The piston gives its energy away as it swings, and a
/// nonlinear oscillator's frequency follows its amplitude, so the theory is
/// asked along the measured window. At a turning point the piston is at
/// rest and so are the gases as a whole: its energy is all potential, the
/// gases' kinetic energy all heat. (The other laws are asked at the same
/// oscillation moved to its balance, see `PistonSystem::at_balance`.)
fn window_states(g: &Geometry, s: &Samples, measured: Option<&Oscillation>) -> Vec<PistonSystem> {
    match measured {
        Some(m) => m.turning.iter().map(|&k| s.system(g, k)).collect(),
        None => vec![s.system(g, 0)],
    }
}

/// A predicted frequency over the window: one period over the mean of the
/// periods it predicts at the window's states (each period of the window
/// has two turning points), as the measured frequency counts periods over
/// their total time.
fn over_window(states: &[PistonSystem], omega: &dyn Fn(&PistonSystem) -> f64) -> f64 {
    let periods: f64 = states.iter().map(|st| TAU / omega(st)).sum();
    TAU * states.len() as f64 / periods
}

/// What only a gas with axes across x has: the collisionless prediction
/// (gamma = 3), and the gases as relaxing media (see
/// `theory::piston_exchange`): their exchange time at the start
/// (stiffness-weighted over the sides), omega tau, the frequency with the
/// gases' inertia and their lag, the relaxation time the lag predicts; and
/// how far from ideal the gases are (excluded over free length, ~ B2 rho).
fn across_x(
    g: &Geometry,
    start: &PistonSystem,
    window: &[PistonSystem],
    frequency: f64,
) -> Vec<(&'static str, f64)> {
    let relaxing = g.relaxing(start);
    let [(kl, tl), (kr, tr)] = relaxing.sides;
    let tau = (kl * tl + kr * tr) / (kl + kr);
    let omega_free = over_window(window, &|st| st.at_balance().omega(Law::Collisionless));
    let omega_exchange = over_window(window, &|st| {
        g.relaxing(st)
            .frequency(st.with_gas_inertia().omega(Law::Adiabatic))
    });
    let tau_exchange = relaxing.decay_time(relaxing.frequency(start.omega(Law::Adiabatic)));
    let excluded = [start.left, start.right]
        .iter()
        .map(|gas| gas.reach / gas.length() - 1.0)
        .fold(0.0, f64::max);
    vec![
        ("omega_collisionless", omega_free),
        ("frequency_ratio_collisionless", frequency / omega_free),
        ("exchange_time", tau),
        ("omega_tau", start.omega(Law::Adiabatic) * tau),
        ("omega_exchange", omega_exchange),
        ("frequency_ratio_exchange", frequency / omega_exchange),
        ("relaxation_time_exchange", tau_exchange),
        ("excluded_fraction", excluded),
    ]
}

/// Mean of the last `fraction` of a record (at least one sample; NaN for
/// none, as 0/0).
fn late_mean(values: &[f64], fraction: f64) -> f64 {
    let n = values.len();
    let from = (((1.0 - fraction.clamp(0.0, 1.0)) * n as f64) as usize).min(n.saturating_sub(1));
    values[from..].iter().sum::<f64>() / (n - from) as f64
}

/// Equipartition: the piston's share of kinetic energy is one over the free
/// degrees of freedom, its oscillator energy the microcanonical mean; the
/// frequency ratios are 1 where their theory holds.
fn theory(d: &Descriptor, result: &str) -> Option<f64> {
    match result {
        "frequency_ratio" | "frequency_ratio_inertia" | "frequency_ratio_exchange" => Some(1.0),
        "piston_share" => {
            gas_counts(d).map(|(d, [l, r])| 1.0 / degrees_of_freedom(d, l + r) as f64)
        }
        "oscillator_share" => gas_counts(d).map(|(d, [l, r])| oscillator_share(d, l, r, DRAWS).0),
        _ => None,
    }
}

/// The dimension and the gas particles on each side of a scene's piston,
/// as the runs count them (`Geometry::of`, on the scene built from seed 0:
/// counts per side do not depend on the draws). Not from the regions the
/// scene describes: a rod the lattice puts at the piston's own position is
/// counted on its left, which only the built scene shows.
fn gas_counts(d: &Descriptor) -> Option<(usize, [usize; 2])> {
    struct Counts;
    impl OnBuilt for Counts {
        type Output = Option<[usize; 2]>;
        fn on<const D: usize>(self, built: &Built<D>) -> Self::Output {
            Some(Geometry::of(built)?.particles)
        }
    }
    let scene = crate::scene::resolve(&d.scene).ok()?;
    let d = scene.dimension().ok()?;
    Some((d, on_built(&scene, 0, Counts)??))
}

/// MacKay's pictures and answer and the 2D wall's (from the descriptor's
/// `[[case]]`s of those names, where it has them), where the theory holds
/// across the sweep, how the piston relaxes, and how each number was
/// measured.
fn section(runs: &Runs, o: &Options) -> anyhow::Result<ReportSection> {
    let mut figures = Vec::new();
    let mut md = pictures::mackay_case(runs, &mut figures)?;
    md += &wall::wall_cases(runs, &mut figures)?;
    md += &regimes::regimes(runs, o, &mut figures);
    md = md + "\n" + &fill(METHODS, &methods_values(o));
    Ok(ReportSection {
        title: "Piston: oscillation and dissipation".into(),
        markdown: md,
        figures,
        presents: RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

const METHODS: &str = include_str!("text/methods.md");
/// The sweep's sentences and table heads, and the figures' captions, by name.
const SWEEP: &str = include_str!("text/sweep.md");
const CAPTIONS: &str = include_str!("text/captions.md");

/// The settings the methods text states.
fn methods_values(o: &Options) -> [(&'static str, String); 4] {
    [
        ("periods", o.periods.to_string()),
        ("band", num(100.0 * o.band)),
        ("peak", format!("{:.0}", 100.0 / o.periods as f64)),
        ("late", num(100.0 * o.late)),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn late_mean_takes_the_end() {
        assert_eq!(late_mean(&[1.0, 2.0, 3.0, 5.0], 0.5), 4.0);
        assert_eq!(late_mean(&[1.0, 2.0], 0.0), 2.0);
    }

    #[test]
    fn methods_placeholders_are_filled() {
        let o = Options {
            periods: 4,
            band: 0.1,
            late: 0.5,
        };
        let text = fill(METHODS, &methods_values(&o));
        assert!(crate::stats::fill::unfilled(&text).is_empty());
        assert!(text.contains("first 4 full periods") && text.contains("±25%"));
    }
}
