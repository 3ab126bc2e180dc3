//! The expansion's part of the report: per sweep point, the ensemble mean
//! of the left fraction with its error band beside the collisionless
//! curve, and a table of the relaxation times, the settled split and its
//! fluctuations, and the cost.

use super::measure::{Gas, temperature};
use super::{RESULTS, relaxation_time};
use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::ensemble::Runs;
use crate::stats::format::{count, num, pm};
use crate::stats::summary::Stats;
use crate::studies::curves::mean_with_band;
use std::collections::BTreeMap;
use std::fmt::Write;

/// Beyond this many collisionless relaxation times the curves are compared
/// no further: both are within noise of 1/2 there.
pub const COMPARED: f64 = 3.0;

/// The charts show the first this many collisionless relaxation times (the
/// expansion and, in a fluid, its sloshing); the rest is noise about 1/2.
pub const SHOWN: f64 = 8.0;

/// Largest |mean - theory| over the collisionless prediction's own standard
/// error of a mean over `runs` runs of `n` particles, sqrt(f (1 - f) / (n
/// runs)) (free particles are independent, each on the left with
/// probability f), over the samples up to `until`. The error under the
/// hypothesis tested, not the runs' scatter: with a handful of runs that
/// scatter is itself uncertain, and its Student tails over hundreds of
/// samples would reject the theory by chance.
pub fn largest_z(
    t: &[f64],
    mean: &[Stats],
    theory: &dyn Fn(f64) -> f64,
    n: f64,
    until: f64,
) -> f64 {
    t.iter()
        .zip(mean)
        .filter(|(t, _)| **t > 0.0 && **t <= until)
        .map(|(t, s)| {
            let f = theory(*t);
            let se = (f * (1.0 - f) / (n * s.n as f64)).sqrt();
            if se > 0.0 {
                ((s.mean - f) / se).abs()
            } else {
                0.0
            }
        })
        .fold(0.0, f64::max)
}

pub fn section(runs: &Runs) -> anyhow::Result<ReportSection> {
    let mut by_point: BTreeMap<u64, Vec<&(RunSpec, RunOutput)>> = BTreeMap::new();
    for r in runs.iter().filter(|(s, _)| s.case.is_none()) {
        by_point.entry(r.0.point_id).or_default().push(r);
    }
    let mut figures = Vec::new();
    let mut rows = String::new();
    let mut pictures = String::new();
    let mut holds = Vec::new();
    let mut fails = Vec::new();
    for (id, rs) in &by_point {
        let spec = &rs[0].0;
        let outs: Vec<&RunOutput> = rs.iter().map(|r| &r.1).collect();
        let stat = |name: &str| {
            let v: Vec<f64> = outs
                .iter()
                .filter_map(|o| o.scalar(name))
                .filter(|v| v.is_finite())
                .collect();
            Stats::of(&v)
        };
        let gas = Gas::of_descriptor(&spec.descriptor);
        let free = gas
            .as_ref()
            .zip(temperature(&spec.descriptor))
            .map(|(g, kt)| g.free(kt));
        let (t, mean) = runs.mean(*id, "left_fraction").unwrap_or_default();
        let tau_free = free.as_ref().map_or(f64::NAN, |f| f.relaxation_time());
        let curve: Vec<f64> = mean.iter().map(|s| s.mean).collect();
        let tau_mean = relaxation_time(&t, &curve);
        let z = match &free {
            Some(f) => largest_z(
                &t,
                &mean,
                &|t| f.left_fraction(t),
                stat("particles").mean,
                COMPARED * tau_free,
            ),
            None => f64::NAN,
        };
        let radius = gas.as_ref().map_or(f64::NAN, |g| g.diameter / 2.0);
        let label = format!("N = {}, radius {}", stat("particles").mean, num(radius));
        let kn = stat("knudsen").mean;
        if z.is_finite() {
            if z < 4.0 {
                holds.push(format!("{label} (Kn = {})", num(kn)));
            } else {
                fails.push(format!("{label} (Kn = {})", num(kn)));
            }
        }
        let tau = stat("relaxation_time");
        let late = stat("late_mean");
        let var = stat("late_variance_ratio");
        let s0 = stat("compressibility").mean;
        let cpu: f64 = outs.iter().map(|o| o.cpu_seconds).sum();
        let collisions: u64 = outs.iter().map(|o| o.collisions).sum();
        let _ = writeln!(
            rows,
            "| {} | {} | {} | {} | {} | {} ({}/{}) | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            num(stat("particles").mean),
            num(radius),
            num(stat("number_density").mean),
            num(kn),
            outs.len(),
            pm(tau.mean, tau.stderr),
            tau.n,
            outs.len(),
            num(tau_mean),
            num(tau_free),
            num(tau.mean / tau_free),
            num(z),
            pm(late.mean, late.stderr),
            pm(var.mean, var.stderr),
            num(s0),
            num(cpu),
            count(collisions),
        );
        let file = format!("expansion_left_fraction_{id}.svg");
        // All of it when there is no collisionless time to scale by.
        let span = if tau_free.is_finite() {
            SHOWN * tau_free
        } else {
            f64::INFINITY
        };
        let shown = t.iter().take_while(|&&x| x <= span).count();
        figures.push(Figure {
            file: file.clone(),
            chart: chart(
                &label,
                &t[..shown],
                &mean[..shown],
                free.as_ref().map(|f| move |t| f.left_fraction(t)),
            ),
        });
        let _ = writeln!(
            pictures,
            "![{label}: ensemble mean of the left fraction (band: ±1 standard error over {} runs) and the collisionless prediction (dashed), up to t = {}.]({file})\n",
            outs.len(),
            num(t.get(shown.max(1) - 1).copied().unwrap_or(f64::NAN))
        );
    }
    let mut md = String::from(INTRO);
    md.push_str(&pictures);
    md.push_str(
        "| N | radius | n [σ⁻ᵈ] | Kn = λ/L | runs | τ (runs reaching it) | τ of the mean curve | τ free | τ / τ free | max \\|z\\| vs free (binomial error), t ≤ 3 τ free | late mean (½) | late variance × 4N | S(0) | CPU s | collisions |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    md.push_str(&rows);
    md.push('\n');
    let list = |v: &[String]| {
        if v.is_empty() {
            "none".to_string()
        } else {
            v.join("; ")
        }
    };
    let _ = writeln!(
        md,
        "The collisionless curve holds within 4 of its standard errors at every sample up to 3 τ free at: {}. \
         It does not at: {}.\n",
        list(&holds),
        list(&fails)
    );
    md.push_str(METHODS);
    Ok(ReportSection {
        title: "Expansion of the gas".into(),
        markdown: md,
        figures,
        presents: RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

fn chart(label: &str, t: &[f64], mean: &[Stats], free: Option<impl Fn(f64) -> f64>) -> ChartSpec {
    let measured = "measured (mean ± standard error)".to_string();
    let mut layers = mean_with_band(t, mean, colour(0), measured).to_vec();
    if let Some(f) = free {
        layers.push(Layer::Line {
            points: t.iter().map(|&t| (t, f(t))).collect(),
            paint: colour(1),
            width: 2,
            dashed: true,
            label: Some("collisionless".into()),
        });
    }
    ChartSpec {
        title: format!("Left fraction during the expansion, {label}"),
        x_label: "time t [σ √(m/kT)]".into(),
        y_label: "fraction of the particles in the left half".into(),
        x_log: false,
        y_log: false,
        layers,
    }
}

const INTRO: &str = "> Build a simulation where all particles are randomly distributed but only on the left half of \
the box. The right half of the box is empty. […] As a function of time, count the number of particles on each \
side of the box, and plot them on the same figure. How long does it take to reach equilibrium? Does it change, \
if you change the maximum initial momentum? (Imperial, \"Expansion of the gas\")\n\n\
Disks start at random in the left half of a box with walls, the right half empty, with Maxwellian velocities. \
Were there no collisions, each disk would bounce between the walls for ever at its own speed, and the \
fraction on the left would follow exactly from the starting distribution (dashed: the collisionless \
prediction). It relaxes toward ½ not exponentially but as the phases of the particles' bounces drift apart: \
its leading term decays as exp(−π²(kT/m)t²/2L²), and τ free ∝ L √(m/kT), so a higher starting speed, here a \
higher temperature, shortens it in proportion. Collisions make the \
gas a fluid: it pushes itself into the empty half as a rarefaction wave at the speed of sound, overshoots and \
sloshes back and forth between the walls (the box's slowest sound mode) while viscosity damps the sloshing. A \
fluid fills the empty half sooner than free flight does: the fast particles no longer run ahead alone, the \
pressure drives the bulk. The Knudsen number Kn = λ/L (λ of the dilute gas at the final density) says which \
regime a point is in.\n\n";

const METHODS: &str = "\n### How each number is measured\n\n\
**Relaxation time** (`relaxation_time`): per run, the first time the excess f − ½ of the left fraction falls \
to 1/e of its value at the first sample (½), interpolated linearly between the samples around the crossing. \
A first passage rather than an exponential fit: the collisionless decay is Gaussian in time, a fluid's \
undershoots ½ and sloshes, and the first passage measures both the same way; it needs no fit window and the \
theory gives it exactly. Its cost: the fraction fluctuates by about 1/(2√N) in each run, which can bring a \
crossing forward in small systems; `τ of the mean curve` is the same first passage of the ensemble mean, \
whose noise is smaller by √runs. `relaxation_time_free` is the first passage of the collisionless curve \
(exact), `relaxation_ratio` the measured over it.\n\n\
**Collisionless curve** (`theory::expansion`): a disk of radius a moves its centre in [a, L − a]; unfolding \
the reflections, its image moves freely on a line, and it is on the left when the image modulo 2(L − 2a) is \
within (L − 2a)/2 of a multiple of 2(L − 2a). Averaging over the start (uniform along x in [a, L/2 − a]) and \
the Maxwellian v_x gives a sum over images in closed form (error functions), used at early times, and a sum \
of Fourier modes, each damped by exp(−k²(kT/m)t²/2), used late; both are exact and agree to 10⁻¹⁰. The \
`max |z|` column is the largest deviation of the mean curve from it over the samples up to 3 τ free (after \
that both are within noise of ½), in units of the standard error the collisionless gas itself predicts for \
a mean over the runs, √(f(1 − f)/(N runs)): free particles are independent, each on the left with \
probability f. (The runs' own scatter, drawn as the band, is itself uncertain with few runs, and its \
Student tails over hundreds of samples would reject the theory by chance.)\n\n\
**Settled split** (`late_mean`, `late_variance_ratio`): over the last half of each run, the mean of the left \
fraction (theory ½ by symmetry) and its mean square deviation from ½ over the samples times 4N: 1 for \
independent particles (binomial). Hard disks exclude each other, so a denser gas fluctuates less: for half \
of a large closed box the ratio is the structure factor S(0) = kT ∂n/∂P, here from Henderson's equation of \
state of hard disks at the packing fraction of the whole box (`compressibility`, the summary's theory for \
`late_variance_ratio`). Both need the last half of the run to lie well after τ and the sloshing to have \
died out.\n";
