//! The expansion's part of the report: the relaxation time against p_max
//! and the Knudsen number beside the collisionless and diffusive
//! predictions; per gas the ensemble-mean left fraction; a table of every
//! point and case with the settled split and its z-scores and the cost;
//! the profiles and the measured diffusion coefficient of the cases.

use super::RESULTS;
use super::charts::{scaled, single, tau_against_knudsen, tau_against_p};
use super::group::{Group, groups};
use super::profiles;
use crate::model::report::{Figure, ReportSection};
use crate::stats::ensemble::Runs;
use crate::stats::format::{count, num, pm};
use crate::stats::line::line;
use crate::stats::summary::Stats;
use crate::theory::expansion_rods::Collisionless;
use std::fmt::Write;

/// Beyond this many collisionless relaxation times the curves are compared
/// no further: both are within noise of 1/2 there.
pub const COMPARED: f64 = 3.0;

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

/// Max |z| of a group's mean curve against a collisionless curve.
fn free_z(g: &Group, free: Option<Collisionless>) -> f64 {
    match free {
        Some(f) => largest_z(
            &g.t,
            &g.mean,
            &|t| f.left_fraction(t),
            g.particles(),
            COMPARED * f.relaxation_time(),
        ),
        None => f64::NAN,
    }
}

/// Power of p_max in the relaxation time of one gas: the weighted slope of
/// ln tau against ln p_max (weights from the runs' standard errors), its
/// standard error and z against -1.
fn exponent(gs: &[&Group]) -> (f64, f64) {
    let (mut x, mut y, mut w) = (Vec::new(), Vec::new(), Vec::new());
    for g in gs {
        let tau = g.stat("relaxation_time");
        if tau.mean > 0.0 && tau.stderr > 0.0 && g.p_max() > 0.0 {
            x.push(g.p_max().ln());
            y.push(tau.mean.ln());
            w.push((tau.mean / tau.stderr).powi(2));
        }
    }
    let (slope, se, _) = line(&x, &y, Some(&w));
    (slope, se)
}

fn z(mean: f64, theory: f64, se: f64) -> f64 {
    (mean - theory) / se
}

pub fn section(runs: &Runs) -> anyhow::Result<ReportSection> {
    let all = groups(runs);
    let sweep: Vec<&Group> = all.iter().filter(|g| g.case.is_none()).collect();
    let is = |g: &Group, prefix: &str| g.case.as_deref().is_some_and(|c| c.starts_with(prefix));
    let profile_cases: Vec<&Group> = all.iter().filter(|g| is(g, "profiles")).collect();
    let diffusion: Vec<&Group> = all
        .iter()
        .filter(|g| g.stat("diffusion_measured").n > 0)
        .collect();
    let expansion_cases: Vec<&Group> = all
        .iter()
        .filter(|g| g.case.is_some() && !is(g, "profiles") && g.stat("diffusion_measured").n == 0)
        .collect();

    // The sweep's gases (N, radius), each at its values of p_max.
    let mut gases: Vec<(String, Vec<&Group>)> = Vec::new();
    for g in &sweep {
        let label = format!("N = {}, radius {}", g.particles(), num(g.radius()));
        match gases.iter_mut().find(|(l, _)| *l == label) {
            Some((_, gs)) => gs.push(g),
            None => gases.push((label, vec![g])),
        }
    }

    let mut figures = Vec::new();
    let mut md = String::from(INTRO);

    // The diffusion coefficient measured in the case that records it.
    let mut measured_point = None;
    if let Some(g) = diffusion.first() {
        let measured = g.stat("diffusion_measured");
        let enskog = g.stat("diffusion_enskog").mean;
        let gas = g.gas.as_ref();
        let tau_d = gas.map_or(f64::NAN, |gas| {
            gas.diffusive(measured.mean).relaxation_time()
        });
        if let Some(gas) = gas {
            let scale = g.p_max() / (gas.kinds[0].1 * gas.length);
            measured_point = Some((gas.knudsen(), tau_d * scale));
        }
        let _ = writeln!(
            md,
            "**Diffusion coefficient** (case `{}`: {}, filling the box, y periodic): measured from the \
             mean-squared displacement along y, D = {} σ² per unit time over {} runs; Enskog's \
             (kinetic theory at the final density and kT = p_max²/3m) {}, ratio {}. The diffusive \
             relaxation time with the measured D is {} (Enskog's: {}); the measured one, at the same \
             gas in the left half (the sweep, same N, radius and p_max), is in the table.\n",
            g.case.as_deref().unwrap_or(""),
            g.label(),
            pm(measured.mean, measured.stderr),
            measured.n,
            num(enskog),
            num(measured.mean / enskog),
            num(tau_d),
            num(gas.map_or(f64::NAN, |gas| gas.diffusive(enskog).relaxation_time())),
        );
    }

    // Relaxation time against p_max and the Knudsen number.
    if sweep.iter().any(|g| g.p_max().is_finite()) {
        figures.push(Figure {
            file: "expansion_tau_p_max.svg".into(),
            chart: tau_against_p(&gases),
        });
        figures.push(Figure {
            file: "expansion_tau_knudsen.svg".into(),
            chart: tau_against_knudsen(&sweep, measured_point),
        });
        md.push_str(
            "![Relaxation time against p_max, one colour per gas, with the collisionless time \
             (dashed).](expansion_tau_p_max.svg)\n\n\
             ![τ p_max / (m L) against the Knudsen number: the collisionless prediction (dashed) \
             is a constant, the diffusive one grows as 1/Kn.](expansion_tau_knudsen.svg)\n\n",
        );
        md.push_str(
            "| gas | Kn = λ/L | points | τ ∝ p_max^a: a | z (a = −1) | τ p_max / (m L), measured at the smallest p_max | collisionless |\n\
             |---|---|---|---|---|---|---|\n",
        );
        for (label, gs) in &gases {
            let (a, se) = exponent(gs);
            let g = gs[0];
            let scale = g
                .gas
                .as_ref()
                .map_or(f64::NAN, |gas| g.p_max() / (gas.kinds[0].1 * gas.length));
            let _ = writeln!(
                md,
                "| {label} | {} | {} | {} | {} | {} | {} |",
                num(g.stat("knudsen").mean),
                gs.len(),
                pm(a, se),
                num(z(a, -1.0, se)),
                num(g.stat("relaxation_time").mean * scale),
                num(g.tau_free() * scale)
            );
        }
        md.push('\n');
    }

    // The left fraction of each gas (on the scaled time axis when it was
    // started with uniform momenta), then of each case.
    let mut singles: Vec<(String, &Group)> = Vec::new();
    for (i, (label, gs)) in gases.iter().enumerate() {
        if !gs[0].p_max().is_finite() {
            singles.extend(gs.iter().enumerate().map(|(j, g)| (format!("{i}_{j}"), *g)));
            continue;
        }
        let file = format!("expansion_left_fraction_{i}.svg");
        figures.push(Figure {
            file: file.clone(),
            chart: scaled(gs, label),
        });
        let _ = writeln!(
            md,
            "![{label}: ensemble mean of the left fraction at each p_max (band: ±1 standard error) \
             against t p_max / m, with the collisionless and diffusive predictions (dashed).]({file})\n"
        );
    }
    singles.extend(
        expansion_cases
            .iter()
            .map(|g| (g.case.clone().unwrap_or_default(), *g)),
    );
    for (name, g) in &singles {
        let file = format!("expansion_left_fraction_{name}.svg");
        figures.push(Figure {
            file: file.clone(),
            chart: single(g),
        });
        let _ = writeln!(
            md,
            "![{}: ensemble mean of the left fraction (band: ±1 standard error over {} runs) and \
             the collisionless prediction (dashed).]({file})\n",
            g.label(),
            g.outs.len()
        );
    }

    // Every point and case.
    md.push_str(
        "| gas | d | Kn = λ/L | runs | τ (runs reaching it) | τ of the mean curve | τ free | τ / τ free | \
         max \\|z\\| vs free, t ≤ 3 τ free | same vs free Maxwellian at the same kT | τ diffusive (Enskog D) | late mean (z vs ½) | \
         late variance × 4N (z vs S(0)) | S(0) | CPU s | collisions |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let (mut holds, mut fails) = (Vec::new(), Vec::new());
    for g in sweep.iter().chain(&expansion_cases) {
        let tau = g.stat("relaxation_time");
        let tau_free = g.tau_free();
        let zf = free_z(g, g.free());
        let zt = free_z(g, g.free_thermal());
        let kn = g.stat("knudsen").mean;
        let named = format!("{} (Kn = {})", g.label(), num(kn));
        if zf.is_finite() {
            if zf < 4.0 {
                holds.push(named);
            } else {
                fails.push(named);
            }
        }
        let late = g.stat("late_mean");
        let var = g.stat("late_variance_ratio");
        let s0 = g.stat("compressibility").mean;
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} ({}/{}) | {} | {} | {} | {} | {} | {} | {} ({}) | {} ({}) | {} | {} | {} |",
            g.label(),
            g.dimension(),
            num(kn),
            g.outs.len(),
            pm(tau.mean, tau.stderr),
            tau.n,
            g.outs.len(),
            num(g.tau_of_mean()),
            num(tau_free),
            num(tau.mean / tau_free),
            num(zf),
            num(zt),
            num(g.stat("relaxation_time_diffusive").mean),
            pm(late.mean, late.stderr),
            num(z(late.mean, 0.5, late.stderr)),
            pm(var.mean, var.stderr),
            num(z(var.mean, s0, var.stderr)),
            num(s0),
            num(g.cpu_seconds()),
            count(g.collisions()),
        );
    }
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

    // Profiles.
    for g in &profile_cases {
        let name = g.case.clone().unwrap_or_default();
        if let Some((fs, text)) = profiles::section(g, &name) {
            let _ = writeln!(md, "**Profiles during the expansion**, case `{name}`:\n");
            md.push_str(&text);
            figures.extend(fs);
        }
    }

    md.push_str(METHODS);
    Ok(ReportSection {
        title: "Expansion of the gas".into(),
        markdown: md,
        figures,
        presents: RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

const INTRO: &str = "> Build a simulation where all particles are randomly distributed but only on the left half of \
the box. The right half of the box is empty. Momenta of the particles can be randomly distributed. […] As a \
function of time, count the number of particles on each side of the box, and plot them on the same figure. How \
long does it take to reach equilibrium? Does it change, if you change the maximum initial momentum? (Imperial, \
\"Expansion of the gas\"; its particles start with \"random momenta in an interval [−p_max, p_max]\".)\n\n\
Particles start at random in the left half of a box with walls, the right half empty, each momentum component \
uniform in [−p_max, p_max] (the cases: Maxwellian). Were there no collisions, each particle would bounce between \
the walls for ever at its own speed, and the fraction on the left would follow exactly from the starting \
distribution (the collisionless prediction, dashed). **Yes, it changes: τ ∝ 1/p_max, at every density.** Hard \
particles have no energy scale: multiplying every velocity by λ gives the same trajectories run λ times faster, \
so every time, collisionless or not, scales as m/p_max; the sweep measures the power. What density changes is \
the shape: a gas whose mean free path exceeds the box (Knudsen number Kn = λ/L > 1) follows the collisionless \
curve; a dense one is a fluid, which pushes itself into the empty half as a rarefaction wave at the speed of \
sound, fills it sooner than free flight, overshoots and sloshes. Diffusion (each particle a random walker with \
the self-diffusion coefficient D) would be slower still by ~1/Kn and does not describe it: the gas's momentum is \
conserved, so density spreads by flow, not by diffusion (docs/expansion.md).\n\n";

const METHODS: &str = "\n### How each number is measured\n\n\
**Relaxation time** (`relaxation_time`): per run, the first time the excess f − ½ of the left fraction falls \
to 1/e of its value at the first sample (½), interpolated linearly between the samples around the crossing. \
A first passage rather than an exponential fit: the collisionless decay is not exponential, a fluid's \
undershoots ½ and sloshes, and the first passage measures both the same way; it needs no fit window and the \
theory gives it exactly. Its cost: the fraction fluctuates by about 1/(2√N) in each run, which can bring a \
crossing forward in small systems; `τ of the mean curve` is the same first passage of the ensemble mean, \
whose noise is smaller by √runs. `relaxation_time_free` is the first passage of the collisionless curve \
(exact), `relaxation_ratio` the measured over it. The power a of τ ∝ p_max^a is the slope of ln τ against \
ln p_max weighted by the runs' standard errors.\n\n\
**Collisionless curve** (`theory::expansion`): a particle of radius a moves its centre in [a, L − a]; \
unfolding the reflections, its image moves freely on a line, and it is on the left when the image modulo \
2(L − 2a) is within (L − 2a)/2 of a multiple of 2(L − 2a). Averaging over the start (uniform along x in \
[a, L/2 − a]) and v_x gives a sum over images in closed form: error functions for Maxwellian v_x, parabolas \
for uniform v_x (only images within reach of the fastest particle count), and, for Maxwellian v_x at late \
times, a sum of Fourier modes. The `max |z|` column is the largest deviation of the mean curve from it over \
the samples up to 3 τ free, in units of the standard error the collisionless gas itself predicts for a mean \
over the runs, √(f(1 − f)/(N runs)). The next column compares with free particles whose velocities are \
Maxwellian at the start's kT (m⟨v_x²⟩ = p_max²/3): it says whether the data tell the two starts apart (the \
uniform start's curve rings about ½, its modes decaying only as 1/t), and whether collisions too rare to \
change the flight have made the velocities Maxwellian (the curve would then tend to this one).\n\n\
**Diffusive curve** (`relaxation_time_diffusive`, `diffusion_enskog`): the diffusion equation in the same box \
with no flux through the walls, from the same start: the same modes, each damped by exp(−D k² t). D is \
Enskog's self-diffusion coefficient (dilute Chapman-Enskog value over the contact value of g; disks: Gass \
1971 with Henderson's g, spheres: Chapman & Cowling with Carnahan-Starling's) at the final density and kT = \
m⟨v_x²⟩; `diffusion_measured` is the slope of the mean-squared displacement along y over 2 in the case that \
records it.\n\n\
**Settled split** (`late_mean`, `late_variance_ratio`): over the last half of each run, the mean of the left \
fraction (theory ½ by symmetry) and its mean square deviation from ½ over the samples times 4N: 1 for \
independent particles (binomial). Hard particles exclude each other, so a denser gas fluctuates less: for half \
of a large closed box the ratio is the structure factor S(0) = kT ∂n/∂P (Tonks, Henderson, Carnahan-Starling \
at the packing fraction of the whole box; `compressibility`). The z columns are (mean − theory) / standard \
error over the runs (the summary's z). Both need the last half of the run to lie well after τ and the \
sloshing to have died out.\n\n\
**Profiles** (`temperature_x`): in 16 slabs along x at each sample, the number of particles and kT of their \
motion about the slab's mean velocity; the ensemble mean of the count, and kT pooled over the runs with \
weights n − 1. Dashed: the adiabat of the hard-particle fluid in local equilibrium from the start (packing \
fraction 2η̄) to each slab's density, kT/kT₀ = (n/n₀)^(2/d) exp((2/d)(F(η) − F(η₀))), F(η) = ∫(Z − 1)/η dη \
from the equation of state; the table adds the ideal gas's (n/n₀)^(2/d). The last column is the kinetic energy of the motion about the slabs' mean velocities \
over the total: below 1 when the gas flows (at t = 0 by about slabs/N, each slab's own centre-of-mass \
motion).\n";
