//! The piston analysis (MacKay's eleven particles): how fast the piston
//! oscillates, against adiabatic and isothermal theory; how long it takes to
//! give its excess energy to the gases; what share it keeps in the end.

use super::ReportSection;
use super::piston_estimators::{late_mean, late_share, oscillation, relaxation_time};
use super::piston_state::{Geometry, Samples};
use crate::observe::Context;
use crate::scene::Built;
use crate::study::descriptor_types::Descriptor;
use crate::study::output::RunOutput;
use crate::study::plan_types::RunSpec;
use crate::theory::piston::Law;
use crate::theory::piston_equilibrium::{degrees_of_freedom, oscillator_share};
use rand::SeedableRng;

pub use super::piston_state::SERIES;

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
    /// The descriptor's values; defaults (and the checks every value has
    /// passed) are in `crate::study::analyses`.
    pub fn of(d: &Descriptor) -> Options {
        let get = |key: &str| {
            let given = d.analysis.get("piston").and_then(|t| t.get(key));
            given
                .and_then(|v| v.as_float().or(v.as_integer().map(|i| i as f64)))
                .or_else(|| {
                    let piston = crate::study::analyses::find("piston")?;
                    Some(piston.options.iter().find(|o| o.name == key)?.default)
                })
                .unwrap_or(f64::NAN)
        };
        Options {
            periods: get("window_periods").max(1.0) as usize,
            band: get("band"),
            late: get("late_fraction"),
        }
    }
}

/// Scalars of one run (see the report section for what each means). The
/// theory starts from the first recorded sample, i.e. the state after any
/// `[run] equilibrate`, not the scene as built.
pub fn per_run<const D: usize>(
    d: &Descriptor,
    built: &Built<D>,
    _ctx: &Context,
    out: &mut RunOutput,
) -> Result<(), String> {
    let geometry = Geometry::of(built).ok_or("the piston analysis needs a scene with a piston")?;
    let samples = Samples::of(out)?;
    let scalars = measure(&geometry, &samples, &Options::of(d));
    out.scalars
        .extend(scalars.iter().map(|(k, v)| (k.to_string(), *v)));
    Ok(())
}

/// Everything measured in one run, by result name.
pub fn measure(g: &Geometry, s: &Samples, o: &Options) -> Vec<(&'static str, f64)> {
    let start = s.system(g, 0);
    let omega_ad = start.omega(Law::Adiabatic);
    let omega_inertia = start.with_gas_inertia().omega(Law::Adiabatic);
    let omega_iso = start.omega(Law::Isothermal);
    let measured = oscillation(&s.t, &s.x, o.periods, o.band);
    let frequency = measured.map_or(f64::NAN, |m| m.omega);
    let energy = s.oscillator_energy(g);
    let total = s.total[0];
    let (share_eq, _) = oscillator_share(g.dimension, g.particles[0], g.particles[1], DRAWS);
    let excess: Vec<f64> = energy.iter().map(|e| e - share_eq * total).collect();
    let gas_mass = g.gas_mass[0] + g.gas_mass[1];
    // Peak piston speed (all oscillator energy kinetic, at the balance) over
    // the gases' thermal speed along x, sqrt(<m v_x^2>/<m>).
    let thermal = (2.0 * (s.left[0] + s.right[0]) / (g.dimension as f64 * gas_mass)).sqrt();
    let peak = (2.0 * energy[0] / g.mass).sqrt();
    vec![
        ("frequency", frequency),
        (
            "frequency_periods",
            measured.map_or(0.0, |m| m.periods as f64),
        ),
        ("omega_adiabatic", omega_ad),
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
    ]
}

/// Equipartition: the piston's share of kinetic energy is one over the free
/// degrees of freedom, its oscillator energy the microcanonical mean; the
/// frequency ratios are 1 where their theory holds.
pub fn theory(d: &Descriptor, result: &str) -> Option<f64> {
    let scene = crate::scene::resolve(&d.scene).ok()?;
    match result {
        "frequency_ratio" | "frequency_ratio_inertia" => Some(1.0),
        "piston_share" | "oscillator_share" if scene.dimension.unwrap_or(1) == 1 => {
            // Counts per side do not depend on the random draws.
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0);
            let g = Geometry::of(&crate::scene::build::<1>(&scene, &mut rng).ok()?)?;
            Some(if result == "piston_share" {
                1.0 / degrees_of_freedom(1, g.particles[0] + g.particles[1]) as f64
            } else {
                oscillator_share(1, g.particles[0], g.particles[1], DRAWS).0
            })
        }
        _ => None,
    }
}

/// MacKay's pictures and answer for his own case, where the theory holds,
/// how the piston relaxes, and how each number was measured.
pub fn section(
    d: &Descriptor,
    runs: &[(RunSpec, RunOutput)],
    out_dir: &std::path::Path,
) -> anyhow::Result<ReportSection> {
    let mut md = super::piston_pictures::mackay_case(d, out_dir)?;
    md.push_str(&super::piston_regimes::regimes(runs, out_dir)?);
    md.push_str(METHODS);
    Ok(ReportSection {
        title: "Piston: oscillation and dissipation".into(),
        markdown: md,
        figures: Vec::new(),
    })
}

const METHODS: &str = "\n### How each number is measured\n\n\
**Theory** starts from each run's first sample (after any `[run] equilibrate`): the piston's position \
and kinetic energy and each gas's kinetic energy and free volume (its side's volume minus what its particles \
occupy: L − Nσ in 1D, Tonks). `omega_adiabatic` is the frequency of the full nonlinear oscillator in which each \
gas keeps P V^γ fixed, γ = (d+2)/d (3 in 1D), with the piston's actual energy (period by quadrature between the \
turning points); `omega_adiabatic_small` is its harmonic limit ω² = γP(1/X_L + 1/X_R)/M at the pressure \
balance; `omega_adiabatic_inertia` adds a third of the gases' mass to the piston's (a uniformly compressed gas \
moves with a velocity rising linearly from wall to piston: Rayleigh's correction for a spring's own mass); \
`omega_isothermal` is the nonlinear oscillator with γ = 1, for contrast.\n\n\
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
sphere, piston position from the gases' configurational weight V_L^N_L V_R^N_R). The relaxation time is when \
the excess E_osc − E_eq first falls to 1/e of its start, interpolated between samples. The decay is not one \
exponential (fast while the motion is far from adiabatic, ever slower as it becomes adiabatic, and near \
equilibrium E_osc wanders for long times), so an exponential fitted to the whole record would follow the late \
wandering; the first passage is the time to give away 63% of the excess whatever the shape. Runs too short to \
reach it report none; `excess_left` (the fraction of the starting excess left over the last 10% of the run) \
then gives the lower bound τ > T / −ln(excess_left), valid for a decay that does not speed up.\n\n\
**Long-time shares**: `piston_share` is the piston's mean share of the kinetic energy over the last half of \
the run (`late_fraction`), against equipartition 1/N_free with N_free = d N_gas + 1 (the piston moves along x \
only: 2N_side + 1 in 1D); `oscillator_share` likewise for E_osc. They test equipartition only where the piston \
has relaxed (τ well below half the run); elsewhere a large z measures how far from equilibrium it still is.\n";
