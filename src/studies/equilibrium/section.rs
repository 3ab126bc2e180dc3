//! The equilibrium part of the report: per point or case, its charts and
//! its rows of the tests, then what they say about MacKay's questions.

use super::RESULTS;
use super::charts::{self, Runs};
use super::dimple::{self, central_share, has_dimple, independent_samples};
use super::ensemble::Ensemble;
use super::settling;
use super::tests_of::{Tests, tests_of};
use crate::model::chart::ChartSpec;
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::ensemble::Runs as AllRuns;
use crate::stats::format::{num, pm};
use crate::stats::replicas::Agreement;
use crate::stats::summary::Stats;
use std::collections::BTreeMap;
use std::fmt::Write;

/// |z| beyond this rejects a law (about 4 standard deviations).
pub const REJECT: f64 = 4.0;

/// A group of runs: a case, or a sweep point.
struct Group<'a> {
    point: u64,
    label: String,
    slug: String,
    runs: Vec<(Ensemble, &'a RunOutput)>,
}

fn groups(runs: &[(RunSpec, RunOutput)]) -> Vec<Group<'_>> {
    let mut by: BTreeMap<(bool, u64), Group> = BTreeMap::new();
    for (spec, out) in runs {
        let Some(e) = Ensemble::of_run(spec) else {
            continue;
        };
        let key = (spec.case.is_some(), spec.point_id);
        by.entry(key)
            .or_insert_with(|| {
                let label = match &spec.case {
                    Some(c) => c.clone(),
                    None => describe(&e),
                };
                Group {
                    point: spec.point_id,
                    slug: format!(
                        "{}{}",
                        if spec.case.is_some() { "case" } else { "point" },
                        spec.point_id
                    ),
                    label,
                    runs: Vec::new(),
                }
            })
            .runs
            .push((e, out));
    }
    by.into_values().collect()
}

/// "200 disks, φ = 0.4, periodic" for a sweep point.
fn describe(e: &Ensemble) -> String {
    let kind = ["rods", "disks", "spheres"][e.dimension.clamp(1, 3) - 1];
    let boundary = match (e.periodic[0], e.periodic.iter().all(|p| *p)) {
        (_, true) => "periodic",
        (false, false) => "walls along x",
        (true, false) => "walls",
    };
    format!(
        "{} {kind}, φ = {}, {boundary}",
        e.balls.len(),
        num(e.packing())
    )
}

/// "z (per bin)" of an agreement, or "–".
pub fn z_text(a: &Option<Agreement>) -> String {
    match a {
        Some(a) => format!("{} (p {}, {} bins)", num(a.z), num(a.p), a.bins),
        None => "–".into(),
    }
}

fn dash(x: f64) -> String {
    if x.is_nan() { "–".into() } else { num(x) }
}

fn verdict(a: &Option<Agreement>) -> &'static str {
    match a {
        Some(a) if a.z.abs() < REJECT => "holds",
        Some(_) => "rejected",
        None => "not tested",
    }
}

pub fn section(runs: &AllRuns) -> anyhow::Result<ReportSection> {
    let mut md = String::from(INTRO);
    let mut figures = Vec::new();
    let mut rods_rows = String::new();
    let mut fluid_rows = String::new();
    let mut per_particle = String::new();
    let mut dimple = String::new();
    let mut dimple_rows = String::new();
    let mut dimple_all = Vec::new();
    let mut settling_rows = String::new();
    let mut pictures = String::new();
    for g in groups(runs) {
        let view: Vec<(&Ensemble, &RunOutput)> = g.runs.iter().map(|(e, o)| (e, *o)).collect();
        let t = tests_of(&view);
        let e = &g.runs[0].0;
        let _ = writeln!(pictures, "#### {}\n", g.label);
        let mut add = |name: &str, chart: Option<ChartSpec>, caption: String| {
            if let Some(chart) = chart {
                let file = format!("equilibrium_{}_{name}.svg", g.slug);
                let _ = writeln!(pictures, "![{caption}]({file})\n");
                figures.push(Figure { file, chart });
            }
        };
        if e.dimension == 1 && !t.particles.is_empty() {
            rods(&g, &view, &t, &mut rods_rows, &mut per_particle);
            let light = |r: usize| view[r].0.lightest().map(|b| (b.index, b.mass));
            let heavy = |r: usize| view[r].0.heaviest().map(|b| (b.index, b.mass));
            let whole = [("", "measured (mean ± standard error over replicas)")];
            add(
                "light",
                charts::velocity(
                    &format!("{}: lightest particle's vₓ", g.label),
                    &view,
                    &light,
                    &whole,
                ),
                format!(
                    "{}: the lightest particle's v_x in units of its std, pooled over {} replicas, beside the exact finite-N law and the Gaussian.",
                    g.label,
                    view.len()
                ),
            );
            add(
                "heavy",
                charts::velocity(
                    &format!("{}: heaviest particle's vₓ", g.label),
                    &view,
                    &heavy,
                    &whole,
                ),
                format!("{}: the heaviest particle's v_x, the same way.", g.label),
            );
            add(
                "std",
                charts::std_against_mass(&format!("{}: velocity std against mass", g.label), &view),
                format!(
                    "{}: each particle's velocity std against its mass (log-log): slope −½, the std ratio of two particles is √(mass ratio).",
                    g.label
                ),
            );
            add(
                "positions",
                charts::positions(&format!("{}: each rod's position", g.label), &view),
                format!(
                    "{}: each rod's position histogram (markers) beside its order-statistics law (lines).",
                    g.label
                ),
            );
            let ranked = e.by_rank();
            let name = |kind: &str, rank: usize| format!("{kind}.{}", ranked[rank].index);
            let last = ranked.len() - 1;
            add(
                "scatter_x",
                charts::scatter(
                    &format!(
                        "{}: positions of particles 1 and 2, {} and {}",
                        g.label,
                        last,
                        last + 1
                    ),
                    &view,
                    &[
                        (name("x", 0), name("x", 1), "x₁, x₂".into()),
                        (
                            name("x", last - 1),
                            name("x", last),
                            format!("x{}, x{}", last, last + 1),
                        ),
                    ],
                    ("x of the left one [σ]", "x of the right one [σ]"),
                ),
                format!(
                    "{}: MacKay's scatter plot of the positions of particles 1 and 2 and of the last two, one replica's samples.",
                    g.label
                ),
            );
            add(
                "scatter_v",
                charts::scatter(
                    &format!("{}: v₁ against v₂", g.label),
                    &view,
                    &[(name("v", 0), name("v", 1), "(v₁, v₂)".into())],
                    ("v₁", "v₂"),
                ),
                format!(
                    "{}: v₁ against v₂, one replica's samples: independent but for the shared energy.",
                    g.label
                ),
            );
            add(
                "scatter_xv",
                charts::scatter(
                    &format!("{}: x₁ against v₁", g.label),
                    &view,
                    &[(name("x", 0), name("v", 0), "(x₁, v₁)".into())],
                    ("x₁ [σ]", "v₁"),
                ),
                format!(
                    "{}: particle 1's position against its velocity, one replica's samples: independent.",
                    g.label
                ),
            );
            dimples(&g.label, &view, &t, &mut dimple_rows, &mut dimple_all);
            if let Some(p) = t
                .particles
                .iter()
                .find(|p| p.rank == 0 && p.halves.is_some())
            {
                let first = |r: usize| {
                    view[r]
                        .0
                        .balls
                        .iter()
                        .find(|b| b.index == p.index)
                        .map(|b| (b.index, b.mass))
                };
                let halves = [("_early", "first half"), ("_late", "second half")];
                add(
                    "dimple",
                    charts::velocity(
                        &format!("{}: P(v₁), first and second halves", g.label),
                        &view,
                        &first,
                        &halves,
                    ),
                    format!(
                        "{}: particle 1's v_x over the first and the second half of each run apart, beside the exact law and the Gaussian: a dimple that is mixing would differ between the halves.",
                        g.label
                    ),
                );
                dimple_text(&g.label, p, &view, &mut dimple);
            }
        }
        if e.dimension > 1
            && let Some((time, mean)) = runs.mean(g.point, "speed_std")
        {
            let kt = view.iter().map(|(e, _)| e.kt().sqrt()).sum::<f64>() / view.len() as f64;
            let reference = settling::maxwell_speed_std(e.dimension) * kt;
            let (level, tau) = settling::equilibration(&time, &mean);
            let duration = time.last().copied().unwrap_or(f64::NAN);
            let collisions =
                view.iter().map(|(_, o)| o.collisions as f64).sum::<f64>() / view.len() as f64;
            let cpu: f64 = view.iter().map(|(_, o)| o.cpu_seconds).sum();
            let _ = writeln!(
                settling_rows,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} s |",
                g.label,
                e.balls.len(),
                num(e.packing()),
                view.len(),
                num(mean[0].mean),
                num(level),
                num(reference),
                num(tau),
                num(collisions * tau / duration / e.balls.len() as f64),
                num(cpu),
            );
            add(
                "speed_std",
                Some(charts::settling(
                    &format!("{}: std of the speeds", g.label),
                    &time,
                    &mean,
                    "std of the speeds",
                    Some((reference, "Maxwell-Boltzmann: √((2 − π/2) kT/m) in 2D")),
                )),
                format!(
                    "{}: the standard deviation of the speeds against time from uniform momenta, mean over {} replicas, beside its Maxwell-Boltzmann value.",
                    g.label,
                    view.len()
                ),
            );
            if let Some((time, energy)) = runs.mean(g.point, "kinetic_energy") {
                add(
                    "energy",
                    Some(charts::settling(
                        &format!("{}: total energy", g.label),
                        &time,
                        &energy,
                        "total kinetic energy",
                        None,
                    )),
                    format!(
                        "{}: the total energy against time (conserved to round-off).",
                        g.label
                    ),
                );
            }
        } else if e.dimension > 1 {
            fluid(&g, &view, &t, &mut fluid_rows);
            add(
                "vx",
                charts::scaled_vx(&format!("{}: vₓ", g.label), &view),
                format!(
                    "{}: √m v_x of every particle in units of √(kT), beside the Gaussian.",
                    g.label
                ),
            );
            add(
                "speed",
                charts::speed(&format!("{}: speeds", g.label), &view),
                format!(
                    "{}: √m |v| in units of √(kT), beside the {}D Maxwell-Boltzmann law and the exact finite-N law.",
                    g.label, e.dimension
                ),
            );
            add(
                "density",
                charts::density(&format!("{}: density along x", g.label), &view),
                format!(
                    "{}: the density profile along x over the mean density.",
                    g.label
                ),
            );
            add(
                "g",
                charts::radial(&format!("{}: g(r)", g.label), &view, 4.0),
                format!("{}: the radial distribution function up to 4σ.", g.label),
            );
        }
    }
    if !rods_rows.is_empty() {
        md.push_str(ROD_HEAD);
        md.push_str(&rods_rows);
        md.push('\n');
        md.push_str(&per_particle);
    }
    if !dimple.is_empty() || !dimple_rows.is_empty() {
        md.push_str("### The dimple in P(v₁)\n\n");
        md.push_str(&dimple);
        md.push_str(DIMPLE_HEAD);
        md.push_str(&dimple_rows);
        md.push_str(&dimple_answer(&dimple_all));
        md.push('\n');
    }
    if !fluid_rows.is_empty() {
        md.push_str(FLUID_HEAD);
        md.push_str(&fluid_rows);
        md.push('\n');
    }
    if !settling_rows.is_empty() {
        md.push_str(SETTLING_HEAD);
        md.push_str(&settling_rows);
        md.push('\n');
    }
    md.push_str("### Figures\n\n");
    md.push_str(&pictures);
    md.push_str(METHODS);
    Ok(ReportSection {
        title: "Equilibrium distributions".into(),
        markdown: md,
        figures,
        presents: RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

fn stat(runs: &Runs, name: &str) -> Stats {
    Stats::of(
        &runs
            .iter()
            .filter_map(|(_, o)| o.scalar(name))
            .filter(|v| v.is_finite())
            .collect::<Vec<f64>>(),
    )
}

fn rods(g: &Group, view: &Runs, t: &Tests, rows: &mut String, per: &mut String) {
    let e = &g.runs[0].0;
    let worst = |f: &dyn Fn(&super::tests_of::Particle) -> Option<Agreement>| {
        t.particles
            .iter()
            .filter_map(f)
            .map(|a| a.z)
            .fold(f64::NAN, f64::max)
    };
    let least = |f: &dyn Fn(&super::tests_of::Particle) -> Option<Agreement>| {
        t.particles
            .iter()
            .filter_map(f)
            .map(|a| a.z)
            .fold(f64::NAN, f64::min)
    };
    let ratio = stat(view, "std_ratio");
    let kurt = stat(view, "kurtosis_lightest");
    let cost: f64 = view.iter().map(|(_, o)| o.cpu_seconds).sum();
    let collisions: u64 = view.iter().map(|(_, o)| o.collisions).sum();
    let _ = writeln!(
        rows,
        "| {} | {} | {} | {} | {} – {} | {} | {} | {} | {} ({}) | {} | {} | {} | {} | {} s, {} collisions |",
        g.label,
        e.balls.len(),
        e.dof,
        view.len(),
        num(stat(view, "lightest_mass").mean),
        num(stat(view, "heaviest_mass").mean),
        pm(ratio.mean, ratio.stderr),
        num(stat(view, "sqrt_mass_ratio").mean),
        num(stat(view, "std_ratio_exact").mean),
        pm(kurt.mean, kurt.stderr),
        num(-6.0 / (e.dof + 2.0)),
        dash(worst(&|p| p.exact)),
        dash(least(&|p| p.gaussian)),
        z_text(&t.positions),
        dash(worst(&|p| p.halves)),
        num(cost),
        crate::stats::format::count(collisions),
    );
    let _ = writeln!(
        per,
        "**{}**, each particle (left to right): z of its v_x histogram against the exact law, against the Gaussian, and of its early against its late half.\n\n\
         | rank | mass | z exact | z Gaussian | z halves |\n|---|---|---|---|---|",
        g.label
    );
    for p in &t.particles {
        let _ = writeln!(
            per,
            "| {} | {} | {} | {} | {} |",
            p.rank + 1,
            num(p.mass),
            z_text(&p.exact),
            z_text(&p.gaussian),
            z_text(&p.halves)
        );
    }
    per.push('\n');
}

/// How often particle 1's histogram shows a dimple over the replicas, and
/// how often independent draws from the exact law would, as many.
/// One line of the dimple table, kept for the conclusion.
struct Dimples {
    label: String,
    particles: usize,
    samples: f64,
    seen: usize,
    runs: usize,
    independent: f64,
    chance: String,
    chance_independent: String,
}

fn dimples(label: &str, view: &Runs, t: &Tests, rows: &mut String, all: &mut Vec<Dimples>) {
    let Some(p) = t.particles.iter().find(|p| p.rank == 0) else {
        return;
    };
    let hists: Vec<&crate::model::run_output::Histogram> = (view.iter())
        .filter_map(|(_, o)| {
            o.histograms
                .iter()
                .find(|h| h.observable == format!("velocity_x.{}", p.index))
        })
        .collect();
    let Some(first) = hists.first() else { return };
    let samples = first.count.iter().sum::<f64>();
    let seen = hists.iter().filter(|h| has_dimple(&h.count)).count();
    let dof = view[0].0.dof;
    // The bins span ±min(reach, 6 std) (velocity_x_each), in reach units.
    let half = (6.0 / dof.sqrt()).min(1.0);
    let chance = |n: f64| {
        if n.is_finite() && (1.0..=MONTE_CARLO_SAMPLES).contains(&n) {
            num(dimple::chance(
                dof as usize,
                half,
                n.round() as usize,
                DIMPLE_TRIALS,
                12,
            ))
        } else {
            "–".into()
        }
    };
    let shares: Vec<f64> = hists.iter().map(|h| central_share(&h.count)).collect();
    let independent = independent_samples(&shares);
    let _ = writeln!(
        rows,
        "| {label} | {} | {seen} of {} | {} | {} | {} |",
        num(samples),
        hists.len(),
        chance(samples),
        num(independent),
        chance(independent)
    );
    all.push(Dimples {
        label: label.into(),
        particles: view[0].0.balls.len(),
        samples,
        seen,
        runs: hists.len(),
        independent,
        chance: chance(samples),
        chance_independent: chance(independent),
    });
}

/// What the dimple table says: the shortest runs against the longest of
/// as many particles (the first such, in table order).
fn dimple_answer(all: &[Dimples]) -> String {
    let Some(few) = all.iter().min_by(|a, b| a.samples.total_cmp(&b.samples)) else {
        return String::new();
    };
    let same = all.iter().filter(|d| d.particles == few.particles);
    let Some(many) = same.fold(None, |best: Option<&Dimples>, d| match best {
        Some(b) if b.samples >= d.samples => Some(b),
        _ => Some(d),
    }) else {
        return String::new();
    };
    if few.samples == many.samples {
        return String::new();
    }
    format!(
        "\nSo: with {} samples per run ({}), {} of {} replicas show a dimple in P(v₁). Those runs are worth about {} \
         independent samples (consecutive samples are correlated: the rods mix slowly), for which the exact law \
         shows a dimple with chance {}; {} truly independent samples would show one with chance {}. With {} samples \
         per run ({}, worth about {} independent ones) {} of {} do. MacKay's dimple is neither the finite-N law nor \
         a failure to reach equilibrium: it is the noise of a histogram of few independent samples, made likelier \
         by slow mixing.\n",
        num(few.samples),
        few.label,
        few.seen,
        few.runs,
        num(few.independent),
        few.chance_independent,
        num(few.samples),
        few.chance,
        num(many.samples),
        many.label,
        num(many.independent),
        many.seen,
        many.runs,
    )
}

/// Independent draws are simulated up to this many samples per run.
const MONTE_CARLO_SAMPLES: f64 = 2000.0;
const DIMPLE_TRIALS: usize = 1000;

fn dimple_text(label: &str, p: &super::tests_of::Particle, view: &Runs, out: &mut String) {
    let e = view[0].0;
    let k = -6.0 / (e.dof + 2.0);
    let _ = writeln!(
        out,
        "{label}: particle 1 (mass {}) against the exact finite-N law: {} (z = {}); against the Gaussian: {} (z = {}); \
         its first against its second half: {} (z = {}). The exact law for f = {} free degrees of freedom is \
         (1 − (v − V)²/a²)^{} on |v − V| < a: flatter on top than the Gaussian of the same width (excess kurtosis {}) \
         and bounded, but with its maximum at v = V and no dimple: N = {} is not too small for equilibrium, \
         the finite-N law is just not the Gaussian. A dimple is a fluctuation of a histogram of too few independent \
         samples, and how few a run holds is set by how slowly it mixes: the table below counts dimples over the \
         replicas, measures how many independent samples each run is worth, and sets both beside the chance of a \
         dimple in as many independent draws from the exact law. Halves that disagree beyond {REJECT} standard \
         deviations would mean a run that had not reached equilibrium at all.\n",
        num(p.mass),
        verdict(&p.exact),
        p.exact.map_or("–".into(), |a| num(a.z)),
        verdict(&p.gaussian),
        p.gaussian.map_or("–".into(), |a| num(a.z)),
        verdict(&p.halves),
        p.halves.map_or("–".into(), |a| num(a.z)),
        e.dof,
        num(0.5 * (e.dof - 3.0)),
        num(k),
        e.balls.len(),
    );
}

fn fluid(g: &Group, view: &Runs, t: &Tests, rows: &mut String) {
    let e = &g.runs[0].0;
    let s = |n: &str| {
        let s = stat(view, n);
        if s.n == 0 {
            "–".into()
        } else {
            pm(s.mean, s.stderr)
        }
    };
    let cost: f64 = view.iter().map(|(_, o)| o.cpu_seconds).sum();
    let _ = writeln!(
        rows,
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} s |",
        g.label,
        e.balls.len(),
        num(e.packing()),
        if e.periodic.iter().all(|p| *p) {
            "periodic"
        } else {
            "walls along x"
        },
        view.len(),
        num(e.kt()),
        z_text(&t.vx_exact),
        z_text(&t.vx_gaussian),
        z_text(&t.speed_exact),
        z_text(&t.speed_mb),
        s("g_contact"),
        s("Z_contact"),
        s("Z_virial"),
        s("contact_theorem_ratio"),
        num(cost),
    );
}

const INTRO: &str = "> One of the predictions of statistical physics is that for a large system at equilibrium, the \
probability of any state is just exp(−βE)/Z […] First, each particle's velocity should have a Gaussian \
distribution. Second, all valid positions are equiprobable […] whatever the masses of the particles are. […] \
the standard deviations of v1 and v10 […] should be in the ratio 2:1, because the mass ratio is 1:4. This \
prediction is well borne out in the data, though the data show an intriguing dimple in P(v1) — is this dimple \
because N=10 is too small for the large-N equilibrium theory to apply? Or is it because the particular random \
masses chosen here give a system that has a slow mixing time […]? (MacKay, ten particles)\n\n\
> For a configuration after the equilibrium is reached, produce two histograms: one of the x component of the \
velocity for all particles; and another with of the speed of the particles. Overlay and compare these \
histograms with the theoretical distributions. […] Produce a density profile of the system along the x \
direction. […] Make a plot of the g(r) for one of your simulations. (Imperial)\n\n\
A run of elastic hard particles keeps its energy (and, in a periodic box, its momentum) exactly: it samples the \
microcanonical ensemble, not exp(−βE). For N particles that differs from the Gaussian: one velocity component of \
a uniform point on the energy shell of f free degrees of freedom has the law (1 − (v − V)²/a²)^((f−3)/2), \
a² = 2E′(1 − m/M)/m (1 − m/M → 1 without conserved momentum), whose variance is still kT/m with kT = 2E′/f \
but whose excess kurtosis is −6/(f + 2). Positions are independent of the velocities and uniform over the \
allowed configurations whatever the masses; rods keep their order, so the k-th from the left is the k-th order \
statistic of N uniform points in the free length (docs/equilibrium.md derives both). Each histogram below is \
tested against its exact law and its large-N limit, with the errors of each bin from the spread over the \
replicas: z is the distance of a chi-square-like sum from its null distribution (found by flipping the signs of \
whole replicas) in that distribution's standard deviations, so |z| < 4 means agreement.\n\n";

const ROD_HEAD: &str = "### Rods: velocities and positions\n\n\
| scene | N | f | runs | masses (lightest – heaviest) | std ratio light/heavy | √(mass ratio) | exact ratio | excess kurtosis of the lightest (exact) | largest z vs exact (any particle) | smallest z vs Gaussian | z positions vs order statistics | largest z early vs late | cost |\n\
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

const DIMPLE_HEAD: &str = "Counted: particle 1's histogram regrouped into 20 equal bins, and a dimple when the \
two central bins hold fewer counts than the pair beside them on each side. Beside the replicas, the chance that \
as many independent draws from the exact law show one (Monte Carlo, 1000 trials; consecutive samples of a run are \
correlated, so a run holds fewer independent samples than it has, and shows dimples more often).\n\n\
How many independent samples a run is worth follows from the replicas' spread of particle 1's share in the two \
central bins: the binomial variance p(1 − p)/n solved for n.\n\n\
| scene | samples per run | replicas with a dimple | chance for as many independent draws | independent samples per run | chance for that many |\n|---|---|---|---|---|---|\n";

const SETTLING_HEAD: &str = "### Equilibration (Imperial: \"plot the evolution of the standard deviation of the particle \
speeds as a function of time, and see if you have reached equilibrium\")\n\n\
Started with each momentum component uniform in [−p, p], the speeds relax to their equilibrium law. The \
equilibration time is the first time the ensemble mean of the speeds' std comes within 1/e of its start's \
distance from the settled level (the mean over the last half of the run); its cost is the collisions per \
particle until then.\n\n\
| scene | N | φ | runs | std of speeds at the start | settled | Maxwell-Boltzmann | equilibration time | collisions per particle to equilibrate | CPU |\n\
|---|---|---|---|---|---|---|---|---|---|\n";

const FLUID_HEAD: &str = "### Disks: velocities, speeds, structure and pressure\n\n\
| point | N | φ | boundary | runs | kT = 2E/f | z vₓ vs exact | z vₓ vs Gaussian | z speed vs exact | z speed vs Maxwell-Boltzmann | g(σ) | Z from g(σ): 1 + 2φ(N−1)/N g(σ) | Z from the virial | n(wall) kT / P (contact theorem: 1) | CPU |\n\
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

const METHODS: &str = "\n### How each number is measured\n\n\
**Histograms** accumulate as the run goes: `velocity_x_each` gives each particle its own 60 bins over its \
whole reach ±√(2E/m) (E the energy, conserved), `velocity_x_halves` the same over the first and second halves \
of the run apart (equal stretches from blocks of samples that merge pairwise, so memory stays bounded), \
`position_x_each` 50 bins over the box, `scaled_speed` and `scaled_velocity_x` √m|v| and √m vₓ of all \
particles, `density_x` all x in 200 bins, `pair_distance` the mean number of pairs per sample in bins of \
0.02σ.\n\n\
**Gaussian fit** (`std_lightest`, `std_heaviest`, `std_ratio`): the histogram's mean and standard deviation \
with Sheppard's correction for the bin width; `kurtosis_*` its excess kurtosis, likewise corrected (exact: \
−6/(f + 2), Gaussian: 0). `std_ratio_exact` is the exact laws' ratio, √(mass ratio) with walls.\n\n\
**Tests** (z columns): for each replica, the fraction of its samples in each bin less the probability its own \
exact law (or the limit law) gives the bin (masses are drawn per run, so each replica has its own law); bins \
where the law expects at least 20 counts per replica. S is the sum over the bins of (mean deviation over its \
standard error over the replicas)². If the law holds, replicas are independent and each replica's deviations are \
as likely as their negatives, so S recomputed with every replica's deviations times a random sign (1000 seeded \
patterns) is a draw from S's null distribution, with the correlations between bins kept: a slow collective mode \
(the light and heavy rods trading energy, the rods' positions breathing together) moves many bins of a run \
together, and a variance that took bins as independent would be several times too small. z is S's distance from \
the flipped mean in flipped standard deviations (p: the share of flips at least as large). Neither the time \
correlation of a run's samples nor that between bins needs a model. Early against late: the same with each \
replica's first-half fractions less its second-half fractions.\n\n\
**g(r)** (`g_contact`): pairs per sample over N(N − 1)/2 times the shell's area over the box's (the finite-N \
normalisation: each particle has N − 1 partners), nearest periodic image; its contact value is a quadratic \
fitted over the first 0.16σ beyond contact, at σ. The pressure of hard disks is Z = βP/n = 1 + 2φ g(σ) \
(spheres 1 + 4φ g(σ)); `Z_virial` is measured from the collisions, with the ideal part taken as 1 and the \
excess from the virial at kT = 2E/f, as in the pressure study. **Contact theorem** (`contact_theorem_ratio`): \
at a hard wall the pressure is kT times the density of centres at contact; the density profile is extrapolated \
to contact from its first eight bins beyond the half-empty one at each wall, and set over P/kT from the wall \
pressure.\n";
