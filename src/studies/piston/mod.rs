//! The piston analysis (MacKay's eleven particles): how fast the piston
//! oscillates, against adiabatic and isothermal theory; how long it takes to
//! give its excess energy to the gases; what share it keeps in the end.

mod cases;
mod error;
mod estimators;
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
use crate::model::run_spec::RunSpec;
use crate::scene::{Built, OnBuilt, on_built};
use crate::stats::ensemble::Runs;
use crate::stats::oscillation::{Oscillation, oscillation};
use crate::theory::piston::{Law, PistonSystem};
use crate::theory::piston_equilibrium::{degrees_of_freedom, oscillator_share};
use estimators::{late_mean, late_share, relaxation_time};
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
        let rods = crate::scene::resolve(&d.scene).is_ok_and(|s| s.dimension() == Ok(1));
        RESULTS[..if rods { RESULTS.len() - 8 } else { RESULTS.len() }].to_vec()
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
    fn error_model(&self, d: &Descriptor) -> Option<super::ErrorModel> {
        error::error_model(d)
    }
    fn section(&self, _: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection> {
        section(runs)
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
    let mut results = vec![
        ("frequency", frequency),
        (
            "frequency_periods",
            measured.as_ref().map_or(0.0, |m| m.periods as f64),
        ),
        ("omega_adiabatic", omega_ad),
        ("omega_adiabatic_start", start.omega(Law::Adiabatic)),
        (
            "omega_adiabatic_small",
            start.small_oscillation_omega(Law::Adiabatic),
        ),
        ("omega_adiabatic_inertia", omega_inertia),
        ("omega_isothermal", omega_iso),
        ("frequency_ratio", frequency / omega_ad),
        ("frequency_ratio_inertia", frequency / omega_inertia),
        ("frequency_ratio_isothermal", frequency / omega_iso),
        ("initial_piston_share", s.piston[0] / total),
        (
            "relaxation_time",
            // Averaged over one measured period (none if there was none).
            relaxation_time(&s.t, &excess, std::f64::consts::TAU / frequency).unwrap_or(f64::NAN),
        ),
        ("excess_left", late_mean(&excess, 0.1) / excess[0]),
        ("oscillator_share", late_mean(&energy, o.late) / total),
        ("piston_share", late_share(&s.piston, &s.total, o.late)),
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
        (
            "relaxation_time_exchange",
            relaxing.decay_time(relaxing.frequency(start.omega(Law::Adiabatic))),
        ),
        ("excluded_fraction", excluded),
    ]
}

/// Equipartition: the piston's share of kinetic energy is one over the free
/// degrees of freedom, its oscillator energy the microcanonical mean; the
/// frequency ratios are 1 where their theory holds.
fn theory(d: &Descriptor, result: &str) -> Option<f64> {
    let scene = crate::scene::resolve(&d.scene).ok()?;
    match result {
        "frequency_ratio" | "frequency_ratio_inertia" | "frequency_ratio_exchange" => Some(1.0),
        "piston_share" | "oscillator_share" => {
            let (d, [left, right]) = gas_counts(&scene)?;
            Some(if result == "piston_share" {
                1.0 / degrees_of_freedom(d, left + right) as f64
            } else {
                oscillator_share(d, left, right, DRAWS).0
            })
        }
        _ => None,
    }
}

/// The dimension and the gas particles on each side of a scene's piston.
/// Counts per side do not depend on the random draws.
fn gas_counts(scene: &crate::model::scene::SceneSpec) -> Option<(usize, [usize; 2])> {
    struct Counts;
    impl OnBuilt for Counts {
        type Output = Option<[usize; 2]>;
        fn on<const D: usize>(self, built: &Built<D>) -> Self::Output {
            Some(Geometry::of(built)?.particles)
        }
    }
    let d = scene.dimension().ok()?;
    Some((d, on_built(scene, 0, Counts)??))
}

/// MacKay's pictures and answer and the 2D wall's (from the descriptor's
/// `[[case]]`s of those names, where it has them), where the theory holds
/// across the sweep, how the piston relaxes, and how each number was
/// measured.
fn section(runs: &[(RunSpec, RunOutput)]) -> anyhow::Result<ReportSection> {
    let mut figures = Vec::new();
    let figures = &mut figures;
    let mut md = pictures::mackay_case(runs, figures)?;
    md.push_str(&wall::wall_cases(runs, figures)?);
    md.push_str(&regimes::regimes(runs, figures)?);
    md.push_str(METHODS);
    Ok(ReportSection {
        title: "Piston: oscillation and dissipation".into(),
        markdown: md,
        figures: std::mem::take(figures),
        presents: RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

const METHODS: &str = "\n### How each number is measured\n\n\
**Theory** works per unit area of the piston's face. Each gas is an ideal gas in its free volume; divided by \
the face area its centres reach, that is a free length l, and the gas pushes the piston with \
F = (2/d)(K/l)·dl/da, K its kinetic energy and a its reach along x (wall to piston, less a radius at each end: \
the layer a disk's centre cannot enter). The free length is the reach less what the particles exclude each \
other from: in 1D exactly L − Σσ (Tonks); in 2D the free volume Q^(1/N) from the configurational integral \
to first order in pair overlaps in the box, l = a − c₀ + c₁/a, whose bulk term is the second virial \
coefficient πσ²/2 per pair and particle and whose edge term counts the exclusion the walls cut off. It \
leaves out terms of order (B₂ρ)², 0.2(B₂ρ)² in the pressure for disks: 0.04% at the sweep's densest \
(`excluded_fraction`, about B₂ρ, is 4% with 20 disks a side). A polytrope K l^(γ−1) = const gives the piston a potential: \
adiabatic γ = (d+2)/d (3 in 1D, 2 in 2D), isothermal γ = 1, collisionless γ = 3 (a gas whose particles \
never collide compresses only its x-motion). `omega_adiabatic` is the frequency of the full nonlinear \
adiabatic oscillator (period by quadrature between the turning points), asked at every turning point of the \
measured periods and averaged period by period: the piston loses energy as it swings, and a nonlinear \
oscillator's frequency follows its amplitude; at a turning point the piston and the gases as a whole are at \
rest, so the oscillator energy is all potential and the gases' kinetic energy all heat \
(`omega_adiabatic_start` is the prediction from the first sample alone, `omega_adiabatic_small` its harmonic \
limit ω² = γP(1/X_L + 1/X_R)/M). `omega_adiabatic_inertia` adds a third of the gases' mass to the piston's \
(a uniformly compressed gas moves with a velocity rising linearly from wall to piston: Rayleigh's correction \
for a spring's own mass, which holds for the gas's x-motion in any dimension; the flow's energy belongs to \
the oscillator, not to the gas's heat). `omega_isothermal` and, in 2D, `omega_collisionless` are those laws \
asked at the same oscillation moved along its adiabat to the balance, where neither gas is hot or cold from \
the swing. In 2D the gases are also relaxing media: a compression along x heats x first and collisions \
share it with y in τ_x = η/p (Chapman–Enskog viscosity of hard disks, Henderson's contact value; \
`exchange_time`, stiffness-weighted over the sides, and `omega_tau` = ω τ_x); with each gas's stiffness \
k(1 + ½ iωτ_x/(1 + iωτ_x)) the oscillator is stiffer and loses energy every swing: `omega_exchange` is the \
frequency with the gases' inertia and this lag, `relaxation_time_exchange` the time in which it loses energy \
by e (from the start, small-amplitude).\n\n\
**Frequency** (`frequency`): from the first `window_periods` (default 4) full periods of the piston's position. \
Turning points are found with a hysteresis band of 10% of the position's range (`band`), so jitter makes no \
extra turning points and counting stops once the oscillation has decayed into the band; between consecutive \
turning points the position crosses their midpoint, and same-direction crossings, interpolated where the motion \
is steepest, are one period apart (exactly so for an exponentially damped oscillation, and independent of a \
drifting centre). Zero crossings rather than a spectral peak: the early motion is nonlinear and decays, and a \
peak over four periods is resolved only to ±25%. `frequency_periods` says how many periods were used; a run \
with no full period above the band gives no frequency and is counted in n.\n\n\
**Relaxation** (`relaxation_time`): the piston's oscillator energy E_osc = K_piston + U(x) − U_min, U the \
adiabatic potential through each gas's current state, so energy already handed to the gases as heat does not \
count and the kinetic–potential swing of the oscillation cancels. At equilibrium E_osc averages \
`oscillator_share` × K, computed by sampling the microcanonical ensemble (velocities uniform on the energy \
sphere, piston position from the gases' configurational weight l_L^N_L l_R^N_R). The relaxation time is when \
the excess E_osc − E_eq first falls to 1/e of its start, interpolated between samples. The decay is not one \
exponential (fast while the motion is far from adiabatic, ever slower as it becomes adiabatic, and near \
equilibrium E_osc wanders for long times), so an exponential fitted to the whole record would follow the late \
wandering; the first passage is the time to give away 63% of the excess whatever the shape. Runs too short to \
reach it report none; `excess_left` (the fraction of the starting excess left over the last 10% of the run) \
then gives the lower bound τ > T / −ln(excess_left), valid for a decay that does not speed up.\n\n\
**Long-time shares**: `piston_share` is the piston's mean share of the kinetic energy over the last half of \
the run (`late_fraction`), against equipartition 1/N_free with N_free = d N_gas + 1 (the piston moves along x \
only: 2N_side + 1 in 1D, 2N_gas + 1 for a wall in 2D); `oscillator_share` likewise for E_osc. They test \
equipartition only where the piston has relaxed (τ well below half the run); elsewhere a large z measures how \
far from equilibrium it still is.\n";
