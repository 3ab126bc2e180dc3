//! The heat study's part of the report: relaxation to the walls (temperature
//! against time beside the well-mixed model; times, initial rates and the
//! settled temperature per point) and conduction between a hot and a cold
//! wall (profiles, flux through each wall, jumps, conductivity beside
//! Chapman-Enskog and Enskog).

use super::{Experiment, Gas, Line, NAME, OPTIONS, Profile, RESULTS, model, passage};
use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::descriptor::Descriptor;
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::ensemble::Runs as AllRuns;
use crate::stats::format::{count, num, pm};
use crate::stats::summary::{Stats, z_score};
use crate::studies::curves::mean_with_band;
use crate::studies::options::value;
use crate::theory::heat::enskog_factor;
use std::collections::BTreeMap;
use std::fmt::Write;

/// The relaxation charts show this many well-mixed relaxation times.
const SHOWN: f64 = 5.0;

pub(super) type Runs<'a> = Vec<&'a (RunSpec, RunOutput)>;

pub(super) fn stat(rs: &Runs, name: &str) -> Stats {
    crate::stats::summary::scalar(rs.iter().map(|r| &r.1), name)
}

/// "mean ± se (z)" against `theory`.
pub(super) fn with_z(s: &Stats, theory: f64) -> String {
    match z_score(s, theory) {
        Some(z) => format!("{} (z = {:+.1})", pm(s.mean, s.stderr), z),
        None => pm(s.mean, s.stderr),
    }
}

pub(super) fn cost(rs: &Runs) -> (f64, u64) {
    (
        rs.iter().map(|r| r.1.cpu_seconds).sum(),
        rs.iter().map(|r| r.1.collisions).sum(),
    )
}

/// A point's name: its case, or its sweep values.
fn label(spec: &RunSpec, gas: &Gas) -> String {
    let what = format!("N = {}, φ = {}", num(gas.particles), num(gas.packing()));
    match &spec.case {
        Some(c) => format!("{c} ({what})"),
        None => what,
    }
}

pub fn section(d: &Descriptor, runs: &AllRuns) -> anyhow::Result<ReportSection> {
    // Sweep points and cases are numbered apart; in plan order.
    let mut groups: BTreeMap<u64, Runs> = BTreeMap::new();
    for r in runs.iter() {
        groups.entry(r.0.point_id).or_default().push(r);
    }
    let mut relaxing = Vec::new();
    let mut conducting = Vec::new();
    for rs in groups.into_values() {
        let Ok(gas) = Gas::of(&rs[0].0.descriptor) else {
            continue;
        };
        match gas.experiment() {
            Ok(Experiment::Relax { wall }) => relaxing.push((gas, wall, rs)),
            Ok(Experiment::Conduct {
                hot,
                cold,
                hot_high,
            }) => conducting.push((gas, (hot, cold, hot_high), rs)),
            Err(_) => {}
        }
    }
    let mut md = String::from(INTRO);
    let mut figures = Vec::new();
    if !relaxing.is_empty() {
        md.push_str(&relaxation(runs, &relaxing, &mut figures));
    }
    // Rods conduct anomalously: their own part.
    let (rods, balls): (Vec<_>, Vec<_>) = conducting.into_iter().partition(|p| p.0.dimension == 1);
    if !balls.is_empty() {
        md.push_str(&conduction(d, &balls, &mut figures));
    }
    if !rods.is_empty() {
        md.push_str(&super::chain::section(&rods, &mut figures));
    }
    md.push_str(METHODS);
    Ok(ReportSection {
        title: "Heat transfer across the boundary".into(),
        markdown: md,
        figures,
        presents: RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

/// Mean temperature curve over a point's runs, from their kinetic energy
/// means (T = 2K / (d N), the same for every run of the point).
fn mean_curve(gas: &Gas, all: &AllRuns, point: u64) -> (Vec<f64>, Vec<Stats>) {
    let Some((t, energy)) = all.mean(point, "kinetic_energy") else {
        return (Vec::new(), Vec::new());
    };
    let per_energy = 2.0 / (gas.dimension as f64 * gas.particles);
    (t, energy.iter().map(|s| s.scaled(per_energy)).collect())
}

fn relaxation(all: &AllRuns, points: &[(Gas, f64, Runs)], figures: &mut Vec<Figure>) -> String {
    let mut md = String::from(RELAX_INTRO);
    let mut rows = String::new();
    let mut pictures = String::new();
    let mut ratio_bars = Vec::new();
    for (k, (gas, wall, rs)) in points.iter().enumerate() {
        let name = label(&rs[0].0, gas);
        let (t, mean) = mean_curve(gas, all, rs[0].0.point_id);
        let start = mean.first().map_or(f64::NAN, |s| s.mean);
        let m = model(gas, *wall, start);
        let curve: Vec<f64> = mean.iter().map(|s| s.mean).collect();
        let tau_curve = passage(&t, &curve, *wall, (-1f64).exp());
        let tau = stat(rs, "relaxation_time");
        let ratio = stat(rs, "relaxation_ratio");
        let ratio_free = stat(rs, "relaxation_ratio_free");
        let half_d = gas.dimension as f64 / 2.0;
        let free = gas.free(*wall, start, t.last().copied().unwrap_or(0.0));
        let kn = gas.knudsen();
        if ratio.mean.is_finite() && kn.is_finite() {
            ratio_bars.push((
                kn,
                ratio.mean - ratio.stderr,
                ratio.mean,
                ratio.mean + ratio.stderr,
            ));
        }
        let (cpu, collisions) = cost(rs);
        let _ = writeln!(
            rows,
            "| {name} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            num(kn),
            rs.len(),
            pm(tau.mean, tau.stderr),
            num(tau_curve),
            num(m.relaxation_time()),
            pm(ratio.mean, ratio.stderr),
            num(free
                .as_ref()
                .map_or(f64::NAN, |f| f.relaxation_time(half_d * wall))),
            pm(ratio_free.mean, ratio_free.stderr),
            with_z(&stat(rs, "initial_rate_ratio"), 1.0),
            with_z(&stat(rs, "late_temperature"), *wall),
            num(cpu),
            count(collisions),
        );
        let shown = t
            .iter()
            .take_while(|&&x| x <= SHOWN * m.relaxation_time())
            .count()
            .max(2)
            .min(t.len());
        let file = format!("heat_relaxation_{k}.svg");
        let mut layers = mean_with_band(
            &t[..shown],
            &mean[..shown],
            colour(0),
            "measured (mean ± standard error)".into(),
        )
        .to_vec();
        layers.push(Layer::Line {
            points: t[..shown].iter().map(|&x| (x, m.temperature(x))).collect(),
            paint: colour(1),
            width: 2,
            dashed: true,
            label: Some("well-mixed model".into()),
        });
        if let Some(f) = &free {
            layers.push(Layer::Line {
                points: t[..shown]
                    .iter()
                    .map(|&x| (x, f.energy_at(x) / half_d))
                    .collect(),
                paint: colour(2),
                width: 2,
                dashed: true,
                label: Some("collisionless (exact for points)".into()),
            });
        }
        figures.push(Figure {
            file: file.clone(),
            chart: ChartSpec {
                title: format!(
                    "Temperature relaxing to walls at kT = {}, {name}",
                    num(*wall)
                ),
                x_label: "time t [σ √(m/kT)]".into(),
                y_label: "kinetic temperature 2K/(dN) [kT]".into(),
                x_log: false,
                y_log: false,
                layers,
            },
        });
        let _ = writeln!(
            pictures,
            "![{name}: ensemble mean of the temperature (band: ±1 standard error over {} runs) and the well-mixed model and the collisionless gas from the same start (dashed).]({file})\n",
            rs.len()
        );
    }
    md.push_str(&pictures);
    md.push_str(
        "| point | Kn = λ/L | runs | τ (runs) | τ of the mean curve | τ well-mixed | τ / τ well-mixed | τ collisionless | τ / τ collisionless | initial change / exact (1) | late T (T_w) | CPU s | collisions |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    md.push_str(&rows);
    md.push('\n');
    if !ratio_bars.is_empty() {
        let file = "heat_relaxation_ratio.svg".to_string();
        figures.push(Figure {
            file: file.clone(),
            chart: ChartSpec {
                title: "Relaxation time over the well-mixed model's, against Kn".into(),
                x_label: "Knudsen number λ/L".into(),
                y_label: "τ / τ well-mixed".into(),
                x_log: true,
                y_log: false,
                layers: vec![
                    Layer::ErrorBars {
                        bars: ratio_bars.clone(),
                        paint: colour(0),
                    },
                    Layer::Markers {
                        points: ratio_bars.iter().map(|b| (b.0, b.2)).collect(),
                        paint: colour(0),
                        label: Some("measured (mean ± standard error)".into()),
                    },
                    Layer::Line {
                        points: vec![
                            (
                                ratio_bars.iter().map(|b| b.0).fold(f64::INFINITY, f64::min),
                                1.0,
                            ),
                            (ratio_bars.iter().map(|b| b.0).fold(0.0, f64::max), 1.0),
                        ],
                        paint: colour(1),
                        width: 2,
                        dashed: true,
                        label: Some("well-mixed model".into()),
                    },
                ],
            },
        });
        let _ = writeln!(
            md,
            "![The measured relaxation time over the well-mixed model's against the Knudsen number (points with finite Kn).]({file})\n"
        );
    }
    md
}

fn conduction(
    d: &Descriptor,
    points: &[(Gas, (f64, f64, bool), Runs)],
    figures: &mut Vec<Figure>,
) -> String {
    let width = value(d, NAME, OPTIONS, "fit_width");
    let mut md = String::from(CONDUCT_INTRO);
    let mut rows = String::new();
    let mut jumps = String::new();
    let mut pictures = String::new();
    let mut bars = Vec::new();
    for (k, (gas, (hot, cold, _), rs)) in points.iter().enumerate() {
        let name = label(&rs[0].0, gas);
        let length = gas.size[0];
        let profiles: Vec<Profile> = rs
            .iter()
            .filter_map(|r| {
                let h = |n: &str| r.1.histograms.iter().find(|h| h.observable == n);
                Some(Profile::of(
                    gas,
                    h("energy_x.count")?,
                    h("energy_x.energy")?,
                ))
            })
            .collect();
        let Some(first) = profiles.first() else {
            continue;
        };
        let bins = first.x.len();
        let t_mean: Vec<Stats> = (0..bins)
            .map(|b| {
                Stats::of(
                    &profiles
                        .iter()
                        .map(|p| p.temperature[b])
                        .filter(|v| v.is_finite())
                        .collect::<Vec<_>>(),
                )
            })
            .collect();
        let n_mean: Vec<f64> = (0..bins)
            .map(|b| profiles.iter().map(|p| p.density[b]).sum::<f64>() / profiles.len() as f64)
            .collect();
        let pooled = Profile {
            x: first.x.clone(),
            temperature: t_mean.iter().map(|s| s.mean).collect(),
            density: n_mean.clone(),
            weight: (0..bins)
                .map(|b| profiles.iter().map(|p| p.weight[b]).sum())
                .collect(),
        };
        let line = Line::fit(&pooled, length, width);
        let kappa = stat(rs, "conductivity");
        let dilute = stat(rs, "conductivity_dilute").mean;
        let enskog = stat(rs, "conductivity_enskog").mean;
        let phi = stat(rs, "centre_packing");
        let kn = gas.knudsen_at(stat(rs, "centre_density").mean);
        let ratio_e = stat(rs, "conductivity_ratio_enskog");
        let ratio_0 = stat(rs, "conductivity_ratio_dilute");
        if ratio_0.mean.is_finite() {
            bars.push((
                phi.mean,
                ratio_0.mean - ratio_0.stderr,
                ratio_0.mean,
                ratio_0.mean + ratio_0.stderr,
            ));
        }
        let (cpu, collisions) = cost(rs);
        let _ = writeln!(
            rows,
            "| {name} | {} | {} / {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            std::iter::once(length)
                .chain(gas.size.iter().skip(1).copied())
                .map(num)
                .collect::<Vec<_>>()
                .join(" × "),
            num(*hot),
            num(*cold),
            rs.len(),
            pm(stat(rs, "flux_in").mean, stat(rs, "flux_in").stderr),
            pm(stat(rs, "flux_out").mean, stat(rs, "flux_out").stderr),
            with_z(&stat(rs, "flux_imbalance"), 0.0),
            pm(phi.mean, phi.stderr),
            num(kn),
            pm(kappa.mean, kappa.stderr),
            num(dilute),
            num(enskog),
            with_z(&ratio_e, 1.0),
            pm(ratio_0.mean, ratio_0.stderr),
            num(cpu),
        );
        let jh = stat(rs, "jump_hot");
        let jc = stat(rs, "jump_cold");
        let g = stat(rs, "gradient");
        let lambda = gas.knudsen_at(stat(rs, "centre_density").mean) * length;
        let _ = writeln!(
            jumps,
            "| {name} | {} | {} | {} | {} | {} | {} | {} |",
            pm(g.mean, g.stderr),
            pm(jh.mean, jh.stderr),
            pm(jc.mean, jc.stderr),
            num(jh.mean / g.mean.abs()),
            num(jc.mean / g.mean.abs()),
            num(lambda),
            count(collisions),
        );
        let file = format!("heat_profile_{k}.svg");
        let mut layers = mean_with_band(
            &first.x,
            &t_mean,
            colour(0),
            "temperature (mean ± standard error)".into(),
        )
        .to_vec();
        layers.push(Layer::Line {
            points: [gas.diameter / 2.0, length - gas.diameter / 2.0]
                .iter()
                .map(|&x| (x, line.at(x)))
                .collect(),
            paint: colour(1),
            width: 2,
            dashed: true,
            label: Some(format!(
                "straight line through the middle {}%",
                num(100.0 * width)
            )),
        });
        let (x_hot, x_cold) = if points[k].1.2 {
            (length, 0.0)
        } else {
            (0.0, length)
        };
        layers.push(Layer::Markers {
            points: vec![(x_hot, *hot), (x_cold, *cold)],
            paint: colour(3),
            label: Some("wall temperatures".into()),
        });
        // Density on the same axis, scaled to the temperature's range.
        let n_max = n_mean.iter().copied().fold(0.0, f64::max);
        if n_max > 0.0 {
            layers.push(Layer::Line {
                points: first
                    .x
                    .iter()
                    .zip(&n_mean)
                    .map(|(x, n)| (*x, n / n_max * hot))
                    .collect(),
                paint: colour(2),
                width: 1,
                dashed: false,
                label: Some(format!(
                    "density × {} (its maximum at kT_hot)",
                    num(hot / n_max)
                )),
            });
        }
        figures.push(Figure {
            file: file.clone(),
            chart: ChartSpec {
                title: format!(
                    "Steady profile between walls at kT = {} and {}, {name}",
                    num(*hot),
                    num(*cold)
                ),
                x_label: "x [σ]".into(),
                y_label: "kinetic temperature [kT]".into(),
                x_log: false,
                y_log: false,
                layers,
            },
        });
        let _ = writeln!(
            pictures,
            "![{name}: temperature across the box (band: ±1 standard error over {} runs), the straight line fitted through its middle, extended to the walls (dashed: the gap to each wall's marker is the temperature jump), and the density profile, scaled.]({file})\n",
            rs.len()
        );
    }
    md.push_str(&pictures);
    md.push_str(
        "| point | box | kT hot / cold | runs | flux in (hot wall) | flux out (cold wall) | in − out (0) | φ at the centre | Kn there | κ | κ Chapman-Enskog | κ Enskog | κ / κ Enskog (1) | κ / κ Chapman-Enskog | CPU s |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    md.push_str(&rows);
    md.push_str(
        "\n**Temperature jumps.** The straight line through the middle, extended to where the particles' centres touch each wall, \
         falls short of the hot wall's temperature and stays above the cold one's: the gas next to a wall is not at its temperature. \
         Over the gradient, each jump is a length (the extrapolation length ζ = ΔT / |dT/dx|), here beside the mean free path λ at the centre.\n\n\
         | point | dT/dx | jump at the hot wall | jump at the cold wall | ζ hot | ζ cold | λ at the centre | collisions |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    md.push_str(&jumps);
    md.push('\n');
    if !bars.is_empty() {
        let top = bars.iter().map(|b| b.0).fold(0.0, f64::max) * 1.1;
        let file = "heat_conductivity.svg".to_string();
        let dim = points[0].0.dimension;
        figures.push(Figure {
            file: file.clone(),
            chart: ChartSpec {
                title: "Thermal conductivity over the dilute (Chapman-Enskog) value".into(),
                x_label: "packing fraction at the centre φ".into(),
                y_label: "κ / κ Chapman-Enskog".into(),
                x_log: false,
                y_log: false,
                layers: vec![
                    Layer::Line {
                        points: (0..=50)
                            .map(|i| top * i as f64 / 50.0)
                            .map(|p| (p, enskog_factor(dim, p)))
                            .collect(),
                        paint: colour(1),
                        width: 2,
                        dashed: true,
                        label: Some("Enskog".into()),
                    },
                    Layer::ErrorBars {
                        bars: bars.clone(),
                        paint: colour(0),
                    },
                    Layer::Markers {
                        points: bars.iter().map(|b| (b.0, b.2)).collect(),
                        paint: colour(0),
                        label: Some("measured (mean ± standard error)".into()),
                    },
                ],
            },
        });
        let _ = writeln!(
            md,
            "![The measured conductivity over Chapman-Enskog's at the centre's temperature, against the packing fraction there, beside Enskog's dense-gas factor (dashed).]({file})\n"
        );
    }
    md
}

const INTRO: &str = "> At the moment the system we are simulating is isolated: there are no exchanges of mass or energy \
with the surroundings. We could however allow for the transfer of heat at the boundary, in which case collisions with \
the walls would no longer be elastic. What would happen if you had walls that were warmer/cooler than the gas? \
Implement the heat change with the box walls and look how the total energy of the gas changes with time. \
(Imperial, \"Heat transfer across the boundary\")\n\n\
A thermal wall sends every particle that hits it back with a velocity drawn afresh from the wall's flux-weighted \
Maxwellian: the particle forgets what it brought (full accommodation). [docs/heat.md](../../docs/heat.md) derives \
every formula used here.\n\n";

const RELAX_INTRO: &str = "### A gas relaxing to its walls\n\n\
Disks start with a Maxwellian at T0 between two thermal walls at T_w across x (periodic along y). A particle hitting \
a wall brings on average (d + 1)/2 kT (the flux favours the fast) and leaves with (d + 1)/2 kT_w; hits come at the rate \
n_c √(kT/2πm) per unit wall area, n_c the density at contact (βP, by the contact theorem). At the start the gas is a \
uniform Maxwellian at T0, so its first change is known exactly, at any density: `initial change / exact` sets the \
measured change of T over the first tenth of τ well-mixed beside it. A gas that stays uniform and Maxwellian \
(\"well mixed\") then follows dT/dt = c √T (T_w − T), solved in closed form (dashed). That needs two things at once: \
collisions frequent enough to keep the velocities Maxwellian near the walls, and heat carried across the box faster \
than the walls exchange it. The second fails in a dense gas: the centre lags behind the walls (heat diffuses in) and \
τ exceeds the model's. The first fails in a dilute gas: the walls reset the fast particles first (they hit more \
often) and nothing re-Maxwellises the rest, so the gas near the walls stays at T0 longer and the excess, carried \
mostly by the fast particles, falls faster than the model's at first; later the slow particles, which reach a wall \
last, make a long algebraic tail. Without collisions this is exact (the collisionless curve, dashed in its own colour: each particle \
keeps its velocity until a wall replaces it; docs/heat.md solves the renewal equation); point particles (radius 0) \
are that case. With every wall at T_w the gas settles at T_w exactly (the walls make it canonical at T_w), but a \
collisionless one gets there only as fast as its slowest particles reach a wall, so its late mean can still sit \
above T_w at the end of a run, as can that of a gas whose relaxation is not many times shorter than the run.\n\n";

const CONDUCT_INTRO: &str = "### Heat conduction between a hot and a cold wall\n\n\
The wall at low x is hot, the one at high x cold, the other axes periodic; after the steady state is reached (`run.equilibrate`), \
each run measures the heat each wall gives the gas (`wall_heat`) and the temperature and density across x \
(`energy_x`). In the steady state the flux in at the hot wall equals the flux out at the cold one (their \
difference is the change of the gas's energy over the run, over the time and area). The conductivity is the flux \
over the gradient of a straight line fitted through the middle of the profile, away from the walls' Knudsen layers, \
and is set beside the dilute gas's (Chapman-Enskog, first Sonine approximation: κ0 = (2k/σ)√(kT/πm) for disks, \
(75k/64σ²)√(kT/πm) for spheres) and Enskog's dense-gas value (disks, Gass 1971: κ/κ0 = 1/g + 3φ + (9/4 + 4/π)φ²g, \
g the contact value from Henderson's equation of state; spheres, Chapman and Cowling ch. 16: κ/κ0 = 1/g + (6/5)bn + \
(9/25)(1 + 32/(9π))(bn)²g, bn = 4φ, g from Carnahan-Starling's), both at the centre's temperature and density. The pressure is uniform, so the density is highest \
at the cold wall.\n\n";

const METHODS: &str = "### How each number is measured\n\n\
**Relaxation** (`relaxation_time`): per run, kT = 2K/(dN) from the `kinetic_energy` series; the first time \
(T − T_w)/(T0 − T_w) falls to 1/e, interpolated between samples. `relaxation_time_model` is the same time of the \
well-mixed model from the run's own T0, with c = ((d + 1)/d)(A/N) n_c √(1/2πm), A the thermal walls' area and \
n_c = N/V_free · Z(φ) (V_free: the volume the centres move in; Z from Henderson). `initial_rate_ratio`: the change of \
T from the first sample to the first sample after `initial_window` × τ well-mixed, over the model's change there: its \
first order is exact for the uniform Maxwellian start (what is left of the model is the curvature, a few per cent of \
a tenth of τ). `late_temperature`: the mean T over the last half of the run.\n\n\
**Conduction**: `flux_in` = heat from the hot wall / (time × wall area), `flux_out` = heat into the cold wall, likewise; \
`flux_imbalance` their difference. `energy_x` bins x into 100 slabs; per slab T = 2E/(d count), n = count / \
(samples × slab volume). A straight line through the slabs within `fit_width`/2 of the middle (weighted by \
particle-samples) gives `gradient` and `centre_temperature`; `centre_density` is the mean density over those slabs, \
`centre_packing` φ there. `conductivity` = flux / |gradient|; `conductivity_dilute` and `conductivity_enskog` at the \
centre's T and φ; `jump_hot` and `jump_cold`: the line extended to the contact positions (a radius from each wall) \
against the walls' temperatures. Error bars are standard errors over the runs.\n\n\
**Where the theory stops holding.** Chapman-Enskog needs the mean free path λ small against the box (Kn = λ/L ≪ 1) \
and against the distance over which T changes; within a few λ of a wall (the Knudsen layer) the gas is not in local \
equilibrium, hence the jumps and the fit through the middle only. It is the first Sonine approximation: the exact \
solution of the Boltzmann equation is a few per cent higher (for spheres, 2.5 %). Enskog's theory assumes \
uncorrelated collisions at contact density g; correlated (ring) collisions make it deviate at liquid densities \
(molecular dynamics of hard spheres: Alder, Gass and Wainwright 1970, J. Chem. Phys. 53, 3813; of hard disks, with a \
systematic difference from Enskog's conductivity: Risso and Cordero 1996, J. Stat. Phys. 82, 1453, N = 100 to 8000, \
who report the difference shrinking slowly as the density grows; their numbers are not reproduced here).\n";
