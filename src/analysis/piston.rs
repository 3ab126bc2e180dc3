//! The piston analysis (MacKay's eleven particles): how fast the piston
//! oscillates, against adiabatic and isothermal theory; how long it takes to
//! give its excess energy to the gases; what share it keeps in the end.

use super::ReportSection;
use crate::engine::Particle;
use crate::observe::Context;
use crate::scene::Built;
use crate::study::descriptor_types::Descriptor;
use crate::study::output::{RunOutput, Series};
use crate::study::plan_types::RunSpec;
use crate::theory::piston::{Gas, Law, PistonSystem};
use std::f64::consts::{E, TAU};

pub const SERIES: &[&str] = &[
    "piston_position",
    "kinetic_energy_by_species",
    "kinetic_energy",
];

fn option(d: &Descriptor, key: &str, default: f64) -> f64 {
    d.analysis
        .get("piston")
        .and_then(|t| t.get(key))
        .and_then(|v| v.as_float().or(v.as_integer().map(|i| i as f64)))
        .unwrap_or(default)
}

/// The theory's view of a 1D scene at its start.
pub fn system<const D: usize>(built: &Built<D>) -> Option<PistonSystem> {
    let p = built.piston?;
    let ps: &[Particle<D>] = &built.particles;
    let piston = ps[p];
    let gas = |range: &[Particle<D>]| -> (f64, f64) {
        (
            range.iter().map(Particle::kinetic_energy).sum(),
            range.iter().map(|q| 2.0 * q.radius).sum(),
        )
    };
    let (el, occupied_l) = gas(&ps[..p]);
    let (er, occupied_r) = gas(&ps[p + 1..]);
    let x = piston.pos[0];
    Some(PistonSystem {
        dimension: D,
        mass: piston.mass(),
        x0: x,
        v0: piston.vel[0],
        left: Gas {
            energy: el,
            free_length: x - piston.radius - occupied_l,
        },
        right: Gas {
            energy: er,
            free_length: built.sim_box.size[0] - x - piston.radius - occupied_r,
        },
    })
}

/// Scalars of one run (see the report section for what each means).
pub fn per_run<const D: usize>(
    d: &Descriptor,
    built: &Built<D>,
    ctx: &Context,
    out: &mut RunOutput,
) -> Result<(), String> {
    let sys = system(built).ok_or("the piston analysis needs a scene with a piston")?;
    let omega_ad = sys.omega(Law::Adiabatic);
    let omega_iso = sys.omega(Law::Isothermal);
    let find = |name: &str| out.series.iter().find(|s| s.observable == name).cloned();
    let x =
        find("piston_position").ok_or("piston_position was not sampled: set [run] sample_every")?;
    let ep = find("kinetic_energy.piston").ok_or("piston energy was not sampled")?;
    let total = find("kinetic_energy").ok_or("kinetic energy was not sampled")?;
    let period = TAU / omega_ad;
    let frequency = zero_crossing_omega(
        &x,
        x.t.first().copied().unwrap_or(0.0) + option(d, "window_periods", 4.0) * period,
    );
    let n_free = ctx.degrees_of_freedom;
    let energy = total.value.first().copied().unwrap_or(f64::NAN);
    let late = option(d, "late_fraction", 0.5);
    let scalars = [
        ("frequency", frequency),
        ("omega_adiabatic", omega_ad),
        (
            "omega_adiabatic_small",
            sys.small_oscillation_omega(Law::Adiabatic),
        ),
        ("omega_isothermal", omega_iso),
        ("frequency_ratio", frequency / omega_ad),
        ("frequency_ratio_isothermal", frequency / omega_iso),
        (
            "initial_piston_share",
            ep.value.first().copied().unwrap_or(f64::NAN) / energy,
        ),
        (
            "relaxation_time",
            relaxation_time(&ep, energy / n_free, period),
        ),
        ("piston_share", late_share(&ep, &total, late)),
        ("mass_ratio", sys.mass),
    ];
    out.scalars
        .extend(scalars.iter().map(|(k, v)| (k.to_string(), *v)));
    Ok(())
}

/// Angular frequency from upward crossings of the mean position in [t0, end]:
/// a local measure that needs only a few cycles and follows the early,
/// large-amplitude motion (a spectral peak over so few cycles would be
/// resolved only to about 2 pi / window, i.e. +-25% for four periods).
pub fn zero_crossing_omega(x: &Series, end: f64) -> f64 {
    let n = x.t.iter().take_while(|&&t| t <= end).count();
    if n < 3 {
        return f64::NAN;
    }
    let level = x.value[..n].iter().sum::<f64>() / n as f64;
    let mut ups = Vec::new();
    for k in 1..n {
        let (a, b) = (x.value[k - 1] - level, x.value[k] - level);
        if a < 0.0 && b >= 0.0 {
            ups.push(x.t[k - 1] + (x.t[k] - x.t[k - 1]) * (-a) / (b - a));
        }
    }
    if ups.len() < 2 {
        return f64::NAN;
    }
    TAU * (ups.len() - 1) as f64 / (ups[ups.len() - 1] - ups[0])
}

/// Time for the piston's excess energy over equipartition, averaged over one
/// period, to fall to 1/e of its start; NaN if the run ends first.
pub fn relaxation_time(ep: &Series, equipartition: f64, period: f64) -> f64 {
    let excess0 = ep.value.first().copied().unwrap_or(f64::NAN) - equipartition;
    if excess0.is_nan() || excess0 <= 0.0 || ep.t.len() < 2 {
        return f64::NAN;
    }
    let t0 = ep.t[0];
    let mut start = 0;
    while start < ep.t.len() {
        let end = ep.t[start..]
            .iter()
            .position(|&t| t >= ep.t[start] + period)
            .map_or(ep.t.len(), |k| start + k);
        if end == ep.t.len() {
            break;
        }
        let mean = ep.value[start..end].iter().sum::<f64>() / (end - start) as f64;
        if mean - equipartition <= excess0 / E {
            return 0.5 * (ep.t[start] + ep.t[end]) - t0;
        }
        start = end;
    }
    f64::NAN
}

/// Time-averaged share of the kinetic energy held by the piston over the last
/// `fraction` of the run.
pub fn late_share(ep: &Series, total: &Series, fraction: f64) -> f64 {
    let n = ep.value.len();
    let from = ((1.0 - fraction.clamp(0.0, 1.0)) * n as f64) as usize;
    let shares: Vec<f64> = (from..n).map(|k| ep.value[k] / total.value[k]).collect();
    if shares.is_empty() {
        f64::NAN
    } else {
        shares.iter().sum::<f64>() / shares.len() as f64
    }
}

/// Equipartition: the piston's share of kinetic energy is one over the free
/// degrees of freedom; the frequency ratio is 1 where the adiabatic theory holds.
pub fn theory(d: &Descriptor, result: &str) -> Option<f64> {
    let scene = crate::scene::resolve(&d.scene).ok()?;
    let piston = scene.piston.as_ref()?;
    match result {
        "piston_share" => {
            let gas: usize = scene
                .species
                .iter()
                .map(|s| piston.per_side.unwrap_or(s.count))
                .sum();
            let dim = scene.dimension.unwrap_or(1);
            Some(1.0 / (dim * (gas + 1)) as f64)
        }
        "frequency_ratio" => Some(1.0),
        _ => None,
    }
}

/// MacKay's pictures for his own case, and how to read the piston results.
pub fn section(
    d: &Descriptor,
    runs: &[(RunSpec, RunOutput)],
    out_dir: &std::path::Path,
) -> anyhow::Result<ReportSection> {
    let mut figures = Vec::new();
    let mackay = super::piston_pictures::mackay_case(d.study.seed, out_dir, &mut figures)?;
    let mut md = String::new();
    md.push_str(&mackay);
    md.push_str(&super::piston_pictures::regimes(runs));
    md.push_str(
        "\n**How the frequency is measured.** From upward crossings of the piston's mean position over the first \
         few adiabatic periods (`window_periods`, default 4): the oscillation decays and, started far from \
         balance, is strongly nonlinear, so a local period is what can be compared with theory; a spectral peak \
         over so few cycles is resolved only to about 2π/window (±25% for four periods).\n\n\
         **Theory.** `omega_adiabatic` is the period of the full nonlinear oscillator in which each gas keeps \
         E X^(2/d) fixed (γ = (d+2)/d = 3 in 1D) and the piston starts with its actual position and velocity; \
         `omega_adiabatic_small` is the harmonic limit ω² = γP(1/X_L + 1/X_R)/M at pressure balance; \
         `omega_isothermal` is the same nonlinear oscillator with γ = 1, for contrast. All are computed per run \
         from its own initial state.\n\n\
         **Dissipation.** `relaxation_time` is when the piston's energy, averaged over one period, has lost 1/e of \
         its excess over equipartition; `piston_share` is its time-averaged share of the kinetic energy over the \
         last half of the run, against equipartition 1/N_free. A heavy piston moves slowly, so each gas particle \
         hits it with nearly the same speed from both sides: it loses energy only through the small \
         velocity-dependent imbalance of those hits (a friction of order the gas density times its thermal \
         speed), so the relaxation time grows in proportion to M. Equipartition is reached only in runs much longer than \
         the relaxation time: where `relaxation_time` is long or missing (the run ended first), a large z for \
         `piston_share` measures how far from equilibrium the piston still is, not a failure of equipartition.\n",
    );
    Ok(ReportSection {
        title: "Piston: oscillation and dissipation".into(),
        markdown: md,
        figures,
    })
}
