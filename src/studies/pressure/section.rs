//! The report section: Z against packing fraction with the equations of
//! state, per dimension a table of the points (error bars and where they
//! come from, how each start was made and equilibrated, the phase, z-scores),
//! wall against virial pressure, the 1/N extrapolation, pressure against
//! time and the dense disks' pressure.

use super::charts::{self, NAMES};
use super::equations::{self, Equation};
use super::finite_size::{self, Fit};
use super::phases;
use super::points::{self, Point};
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::format::{num, pm};
use crate::stats::summary::z_score;
use std::fmt::Write;

/// A point's |drift| (second half against first, in error units) above
/// which it is flagged as still relaxing.
const DRIFT: f64 = 4.0;

pub fn section(runs: &[(RunSpec, RunOutput)]) -> anyhow::Result<ReportSection> {
    let all = points::points(runs);
    let fits = finite_size::fits(&all);
    let mut md = String::from(INTRO);
    let mut figures = Vec::new();
    let mut figure = |md: &mut String, file: &str, chart, caption: &str| {
        figures.push(Figure {
            file: file.into(),
            chart,
        });
        let _ = writeln!(md, "![{caption}]({file})\n");
    };
    if !all.is_empty() {
        figure(
            &mut md,
            "pressure_z.svg",
            charts::z_chart(&all),
            "Compressibility factor Z = βP/ρ against packing fraction η (rods between walls, disks and spheres in periodic boxes; mean ± error bar per point, see the tables); lines: each dimension's equations of state, the first solid, the others dashed; black dashed: the ideal gas, Z = 1",
        );
        if let Some(chart) = charts::deviation_chart(&all) {
            figure(
                &mut md,
                "pressure_deviation.svg",
                chart,
                "Z over each dimension's reference equation (Tonks, Kolafa-Rottner, Hansen-Goos), minus 1, at the points where it holds; dashed: the other equations against the same reference. The points are at finite N: see the 1/N extrapolation",
            );
        }
        let examples = time_examples(&all);
        if !examples.is_empty() {
            figure(
                &mut md,
                "pressure_time.svg",
                charts::time_chart(&examples),
                "Pressure against time, the Imperial project's plot: the pressure over each sampling interval of one run, over its mean. It fluctuates about a constant: the runs are in equilibrium, and the spread shrinks as the interval or the system grows",
            );
        }
    }
    if !fits.is_empty() {
        figure(
            &mut md,
            "pressure_finite_size.svg",
            charts::finite_size_chart(&fits),
            "Z against 1/N at fixed packing fraction (periodic boxes), over the reference equation, with the weighted straight-line fit and its value at 1/N = 0 (N → ∞)",
        );
    }
    let dense = dense_disks(&all);
    if dense.len() >= 3 {
        figure(
            &mut md,
            "pressure_dense_disks.svg",
            charts::dense_disks_chart(&dense),
            "The pressure βPσ² = Zρ of the disks near the liquid-hexatic transition (mean ± error bar; dashed: joining the means; solid: Kolafa and Rottner's fluid equation, for N → ∞, up to where the fluid ends). Where the pressure falls as η grows is the finite box's loop (see the table below)",
        );
    }
    md.push_str(&headline(&all));
    md.push_str(FINITE_N);
    for d in 1..=3 {
        let pts: Vec<&Point> = all
            .iter()
            .filter(|p| p.dimension == d && (d == 1 || !p.walls))
            .collect();
        if !pts.is_empty() {
            md.push_str(&table(d, &pts));
        }
    }
    md.push_str(&walls_table(&all));
    md.push_str(&finite_size_table(&fits));
    if dense.len() >= 3 {
        md.push_str(&loop_text(&dense));
    }
    md.push_str(METHODS);
    Ok(ReportSection {
        title: "Pressure against density: the equation of state".into(),
        markdown: md,
        figures,
        presents: super::RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

/// Up to four runs for the pressure-against-time figure: a rod point, the
/// walled disks (wall pressure), a disk and a sphere point.
fn time_examples(all: &[Point]) -> Vec<(&Point, &str)> {
    let pick = |f: &dyn Fn(&Point) -> bool| all.iter().filter(|p| f(p)).last();
    [
        (pick(&|p| p.dimension == 1), "rods, walls"),
        (pick(&|p| p.dimension == 2 && p.walls), "disks, walls"),
        (
            pick(&|p| p.dimension == 2 && !p.walls && p.particles < 1000),
            "disks, virial",
        ),
        (
            pick(&|p| p.dimension == 3 && phases::is_fluid(3, p.eta)),
            "spheres, virial",
        ),
    ]
    .into_iter()
    .filter_map(|(p, label)| Some((p?, label)))
    .collect()
}

/// The periodic disks of the largest N with at least 1000 disks, from
/// eta = 0.68 on, by packing fraction.
fn dense_disks(all: &[Point]) -> Vec<&Point> {
    let dense = |p: &&Point| p.dimension == 2 && !p.walls && p.eta >= 0.68 && p.particles >= 1000;
    let Some(n) = all.iter().filter(dense).map(|p| p.particles).max() else {
        return Vec::new();
    };
    let mut pts: Vec<&Point> = all
        .iter()
        .filter(dense)
        .filter(|p| p.particles == n)
        .collect();
    pts.sort_by(|a, b| a.eta.total_cmp(&b.eta));
    pts
}

/// How precise the fluid points are and what they cost.
fn headline(all: &[Point]) -> String {
    let fluid: Vec<&Point> = all
        .iter()
        .filter(|p| {
            (p.dimension == 1 || !p.walls)
                && phases::is_fluid(p.dimension, p.eta)
                && p.eta <= equations::of(p.dimension)[0].holds_below
        })
        .collect();
    if fluid.is_empty() {
        return String::new();
    }
    let rel: Vec<f64> = fluid.iter().map(|p| p.error().0 / p.z.mean).collect();
    let best = rel.iter().copied().fold(f64::INFINITY, f64::min);
    let worst = rel.iter().copied().fold(0.0, f64::max);
    let at_1e4 = rel.iter().filter(|r| **r <= 1.05e-4).count();
    let cpu: f64 = fluid.iter().map(|p| p.cpu_seconds).sum();
    let total: f64 = all.iter().map(|p| p.cpu_seconds).sum();
    format!(
        "**Precision.** At the {} fluid points where a reference equation holds, the relative standard error of Z is {} to {}; {} of them reach 1e-4. They cost {} CPU seconds of the study's {}.\n",
        fluid.len(),
        num(best),
        num(worst),
        at_1e4,
        num(cpu),
        num(total)
    )
}

/// One dimension's points: Z against each of its equations.
fn table(d: usize, pts: &[&Point]) -> String {
    let eqs = equations::of(d);
    let mut md = format!(
        "\n### {}\n\n| η | N | start | phase | Z | error from | rel. error | runs' own error (block; ×2 ratio) | discarded | MSER cut | max \\|drift\\| |",
        NAMES[d - 1]
    );
    for e in eqs {
        let _ = write!(md, " {} (z) |", e.name);
    }
    md.push_str(" CPU s | note |\n|");
    md.push_str(&"---|".repeat(11 + eqs.len() + 2));
    md.push('\n');
    for p in pts {
        let (err, from) = p.error();
        let start = if p.start == "compressed" {
            format!(
                "compressed ({} coll./particle)",
                num(p.prepare_per_particle)
            )
        } else {
            p.start.to_string()
        };
        let _ = write!(
            md,
            "| {} | {} | {start} | {} | {} | {from} ({}) | {} | {} | {} | {} | {} |",
            num(p.eta),
            p.particles,
            phases::label(d, p.eta),
            pm(p.z.mean, err),
            p.z.n,
            num(err / p.z.mean),
            block(p),
            discarded(p),
            num(p.cut),
            num(p.drift),
        );
        for e in eqs {
            let theory = (e.z)(p.eta);
            let z = z_score(&p.z_stats(), theory).map_or("–".into(), |z| format!("{z:+.1}"));
            let _ = write!(md, " {} ({z}) |", num(theory));
        }
        let _ = writeln!(md, " {} | {} |", num(p.cpu_seconds), note(eqs, p));
    }
    md
}

/// "±s (t; r)": the block-average error, block length and doubling ratio;
/// for rods the wall-hit model's error instead.
fn block(p: &Point) -> String {
    if p.run_basis == "wall hits" && p.run_stderr.is_finite() {
        return format!(
            "±{} (wall hits; blocks ±{}, not valid here)",
            num(p.run_stderr),
            num(p.block_stderr)
        );
    }
    if !p.block_stderr.is_finite() {
        return "–".into();
    }
    let ratio = if p.block_doubling.is_finite() {
        num(p.block_doubling)
    } else {
        "no plateau".into()
    };
    format!("±{} ({}; {ratio})", num(p.block_stderr), num(p.block_time))
}

/// Time discarded before recording, and about how many collisions per
/// particle that was (at the measured rate).
fn discarded(p: &Point) -> String {
    if p.equilibrate == 0.0 {
        return "0".into();
    }
    format!(
        "{} (~{} coll./particle)",
        num(p.equilibrate),
        num(p.equilibrate * p.collision_rate)
    )
}

/// The phase, equations beyond their range, and any sign of a run not in
/// equilibrium.
fn note(eqs: &[Equation], p: &Point) -> String {
    let mut notes = Vec::new();
    if !phases::is_fluid(p.dimension, p.eta) {
        notes.push(format!(
            "not the stable fluid ({}): no fluid equation applies",
            phases::label(p.dimension, p.eta)
        ));
    }
    let beyond: Vec<&str> = eqs
        .iter()
        .filter(|e| p.eta > e.holds_below)
        .map(|e| e.name)
        .collect();
    if !beyond.is_empty() {
        notes.push(format!("beyond the range of {}", beyond.join(", ")));
    }
    if p.drift > DRIFT {
        notes.push(format!(
            "drifting: a run's halves differ by {} error bars",
            num(p.drift)
        ));
    }
    let (_, from) = p.error();
    if from != "replicas" {
        notes.push(format!(
            "the {} replicas scatter less than their runs' own error ({}): that error used",
            p.z.n,
            num(p.z.stderr)
        ));
    }
    notes.join("; ")
}

fn walls_table(all: &[Point]) -> String {
    let both: Vec<&Point> = all
        .iter()
        .filter(|p| p.wall_minus_virial.is_some())
        .collect();
    if both.is_empty() {
        return String::new();
    }
    let mut md = String::from(
        "\n### Wall and virial pressure side by side\n\n\
         In a box with walls both estimates apply: the momentum the walls receive, and the collision virial with \
         the walls' own virial counted (a wall pushes a particle at its centre, a radius from the wall, so \
         2K + W = P_wall (dV − σA/2), A the walls' area). They are two measurements of the same pressure; \
         the difference is taken run by run. (The Z of a walled box is not the bulk fluid's: the walls add a \
         surface term of order σ/L.)\n\n\
         | dimension | η | N | Z from the walls | Z from the virial | walls − virial | z |\n|---|---|---|---|---|---|---|\n",
    );
    for p in both {
        let diff = p.wall_minus_virial.as_ref().expect("filtered");
        let (w, v) = (p.z_wall.as_ref(), p.z_virial.as_ref());
        let z = z_score(diff, 0.0).map_or("–".into(), |z| format!("{z:+.1}"));
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {z} |",
            p.dimension,
            num(p.eta),
            p.particles,
            w.map_or("–".into(), |s| pm(s.mean, s.stderr)),
            v.map_or("–".into(), |s| pm(s.mean, s.stderr)),
            pm(diff.mean, diff.stderr),
        );
    }
    md
}

fn finite_size_table(fits: &[Fit]) -> String {
    if fits.is_empty() {
        return String::new();
    }
    let mut md = String::from(
        "\n### Finite size: Z against 1/N\n\n\
         Each row fits Z(N) = Z∞ + b/N to the points of one packing fraction, weighted by their error bars, \
         and compares Z∞ with the reference equation (and the others). At low density b → −B₂ρ (−2η for disks, \
         −4η for spheres): each particle of a periodic box sees N − 1 others, so the pair term of Z is (N − 1)/N \
         of the infinite system's. The line is the leading term: where the smallest box already shows the next \
         one (the line's χ² beyond its 99 % point) it is left out and the line refitted, as the χ² column says.\n\n\
         | dimension | η | points (N: Z) | Z∞ | b | χ² (dof) | equations (z of Z∞) |\n|---|---|---|---|---|---|---|\n",
    );
    for f in fits {
        let data: Vec<String> = f
            .data
            .iter()
            .map(|&(n, z, e)| format!("{n}: {}", pm(z, e)))
            .collect();
        let eqs: Vec<String> = equations::of(f.dimension)
            .iter()
            .map(|e| {
                let t = (e.z)(f.eta);
                format!(
                    "{} {} ({:+.1})",
                    e.name,
                    num(t),
                    (f.z_inf - t) / f.z_inf_err
                )
            })
            .collect();
        let mut chi2 = if f.dof > 0 {
            format!("{} ({})", num(f.chi2), f.dof)
        } else {
            "– (0)".into()
        };
        for (n, c, dof) in &f.left_out {
            let _ = write!(
                chi2,
                "; N = {n} left out (the line through it: χ² {} for {dof}, beyond its 99 % point)",
                num(*c)
            );
        }
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {chi2} | {} |",
            f.dimension,
            num(f.eta),
            data.join("; "),
            pm(f.z_inf, f.z_inf_err),
            pm(f.slope, f.slope_err),
            eqs.join("; ")
        );
    }
    md
}

/// Whether the dense disks' pressure falls anywhere as the density grows
/// (the finite-size loop of the liquid-hexatic coexistence), and by how
/// much: the loop's height is the largest fall of βPσ² from a point to a
/// denser one, with the two points' errors combined.
fn loop_text(pts: &[&Point]) -> String {
    let rho = |eta: f64| 4.0 * eta / std::f64::consts::PI;
    let p = |q: &Point| (q.z.mean * rho(q.eta), q.error().0 * rho(q.eta));
    let mut best: Option<(usize, usize, f64, f64)> = None;
    for i in 0..pts.len() {
        for j in i + 1..pts.len() {
            let ((pi, ei), (pj, ej)) = (p(pts[i]), p(pts[j]));
            let drop = pi - pj;
            let err = ei.hypot(ej);
            if drop > 0.0 && best.is_none_or(|b| drop > b.2) {
                best = Some((i, j, drop, err));
            }
        }
    }
    let n = pts[0].particles;
    let mut md = format!(
        "\n### The disks' loop near η = 0.70-0.72\n\n\
         With {n} disks in a periodic box the fluid and the hexatic phase cannot coexist as in a large system: \
         the interface between them costs free energy that a small box cannot dilute, and the pressure \
         against density has a loop (a stretch where it falls as the density grows) in the coexistence range \
         0.700-0.716 (Bernard and Krauth 2011); it shrinks as N grows and vanishes for an infinite system \
         (Engel et al. 2013). Each point below started from a compression to its density, discarded the \
         time in `discarded`, and was then tested for drift (second half of each run against the first, in \
         block errors) after the MSER cut.\n\n\
         | η | phase | βPσ² | error from | discarded | MSER cut | max \\|drift\\| | CPU s |\n|---|---|---|---|---|---|---|---|\n"
    );
    for q in pts {
        let (v, e) = p(q);
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} ({}) | {} | {} | {} | {} |",
            num(q.eta),
            phases::label(2, q.eta),
            pm(v, e),
            q.error().1,
            q.z.n,
            num(q.equilibrate),
            num(q.cut),
            num(q.drift),
            num(q.cpu_seconds)
        );
    }
    md.push('\n');
    match best {
        Some((i, j, drop, err)) => {
            let _ = write!(
                md,
                "**Loop height.** βPσ² falls from {} at η = {} to {} at η = {}: the loop is {} high, {} standard \
                 errors above the noise (the largest fall between any two of the {} points, so a pure-noise curve \
                 would show a fall of a standard error or two).",
                pm(p(pts[i]).0, p(pts[i]).1),
                num(pts[i].eta),
                pm(p(pts[j]).0, p(pts[j]).1),
                num(pts[j].eta),
                pm(drop, err),
                num(drop / err),
                pts.len()
            );
        }
        None => md.push_str("Here βPσ² rises at every step: no loop is resolved."),
    }
    let errors: Vec<f64> = pts.iter().map(|q| p(q).1).collect();
    let _ = writeln!(
        md,
        " The error bars of βPσ² are {} to {}.",
        num(errors.iter().copied().fold(f64::INFINITY, f64::min)),
        num(errors.iter().copied().fold(0.0, f64::max))
    );
    md
}

const FINITE_N: &str = "\nThe disks' and spheres' points are periodic boxes of fixed N, and the \
equations describe N → ∞: a point at finite N sits below its equation by about −b/N, with b → −B₂ρ at low density \
(−2η for disks, −4η for spheres; each particle sees N − 1 others) and b ≈ −0.76 (disks) and −1.1 (spheres) at \
η = 0.3. At N = 256 that is several times the error bar of a precise point, so the z-scores in these tables \
measure the finite size as much as the equations; the 1/N extrapolation below is the test of the equations.\n";

const INTRO: &str = "\nThe Imperial project asks: \"Can you modify the boundary code so that you can record the pressure \
being exerted on the box during each time step and hence produce a plot of pressure vs. time? Does your simulation \
agree with the ideal gas equations? You can plot the pressure for changing system density. You may be able to \
observe a phase transition.\" Dilute, every gas here is ideal (Z = 1); as the packing fraction grows the \
particles' own size raises the pressure well above the ideal gas's, by a factor 5 for rods at η = 0.8, and \
each dimension has an equation of state that says by how much. Past the fluid's stability the equations \
stop: disks go through the liquid-hexatic transition near η = 0.70-0.72, spheres freeze at 0.494; those points \
are labelled by phase below, not hidden.\n\n";

const METHODS: &str = "\n### How pressure is measured\n\n\
Reduced units: σ = 1 (particle diameter), m = 1, and kT is each run's own kinetic temperature, kT = 2K/f with K \
the kinetic energy (constant: the collisions and walls are elastic) and f the free degrees of freedom. \
**Rods** are between hard walls: the pressure is the momentum the walls receive per unit time and Z = P L/(N kT) \
with f = N. For N rods between walls the exact result is P (L − Nσ) = N kT at every N, so Tonks' Z = 1/(1 − η), \
with η = Nσ/L and L the box length, is exact for the simulated system, not only in the limit. **Disks and \
spheres** are in periodic boxes: the pressure is the collision virial, P V = 2K/d + W/d with W = Σ r_ij·Δp_i per \
unit time over the pair collisions. \
**Ensemble.** The runs keep the energy and (in periodic boxes) the total momentum fixed, at zero. For hard \
bodies this changes nothing in the configurations: the potential energy is zero wherever it is defined, so \
fixing the energy fixes only the momenta, and the positions are distributed as in the canonical ensemble at the \
same N and V. With kT = 2K/(d(N − 1)) the mean squared relative velocity of a pair is exactly the canonical \
2d kT/m, so the collision virial has its canonical value too. The one difference is the ideal part, 2K/d = \
(N − 1) kT where the canonical has N kT: Z = 1 + W/(d N kT) corrects it (uncorrected, Z would be 1/N low). What \
is left is the canonical finite-size effect of a periodic box whose N is fixed, of order 1/N (the full study \
measured −0.76/N for disks and −1.1/N for spheres at η = 0.3): the study measures Z at several N and \
extrapolates. This, not the equations or the statistics, is why the spheres at η = 0.3 and N = 256 sit about \
0.1 % below Hansen-Goos. \
**Starts and equilibration.** Rods start from the exact equilibrium distribution (uniform gaps) and nothing is \
discarded. Dilute disks and spheres start from random insertion; dense ones (disks from η = 0.5, spheres from \
0.3) from Lubachevsky-Stillinger compression, never random insertion. Each run then discards the time in \
`discarded` (with about how many collisions per particle that was) and records the pressure over every sampling \
interval. The MSER rule (White 1997, batches of 5 intervals) then cuts whatever is left of a transient: the cut \
that minimises the variance of the remaining mean (`MSER cut`, mean time over the replicas; a few intervals is \
noise). Equilibrium is then judged by the drift: the mean of the second half of the kept series minus the first, \
in units of its block error bar; it is about N(0, 1) when the run is stationary, and a point whose largest \
|drift| over its replicas exceeds 4 is flagged. \
**Error bars.** Z of a run is the mean over its kept intervals. Each run also has its own error: the \
block-average error of its series (Flyvbjerg and Petersen 1989: the kept series is cut into blocks of 1, 2, 4, \
... intervals and the first block length whose doubling no longer raises the estimate beyond its own \
statistical error is used; the column gives the block length in time and the ratio of the estimate at twice \
that length, about 1 on a plateau, `no plateau` when the series was too short to show one and the block \
error is a lower bound). For rods the block error does not apply: equal rods swap velocities, so each speed \
hits the walls periodically and the mean converges as 1/T, not 1/√T; their own error is the exact wall-hit \
phase noise, σ_Z = (L/T)√(m/12K) per run. The point's error bar is the standard error over its independent \
replicas (each its own start and velocities) when there are at least 16; with fewer it is the larger of that \
and the runs' own error combined, because a standard error from n replicas is itself uncertain by \
1/√(2(n − 1)) (41 % for 4), and 4 replicas that happen to agree closely give z-scores of 5 or more about 1 % of \
the time. `error from` says which was used, and with how many replicas. \
**Theory**: rods, Tonks 1936 (exact). Disks, Kolafa and Rottner 2006 (Mol. Phys. 104, 3435), \
Z = Σ Cₙ xⁿ with x = η/(1 − η), fitted to simulations of the fluid extrapolated to infinite N up to η = 0.707 \
(the last 0.008 of which may keep finite-size effects) with the known virial coefficients built in: its \
expansion gives B3-B5 exactly and B6-B10 within Clisby and McCoy's Monte Carlo errors, and it is the \
reference to η = 0.68, as far as this project's own extrapolations check it (docs/pressure.md); the virial series with \
the coefficients up to B10 of Clisby and McCoy 2006 (J. Stat. Phys. 122, 15; B3 and B4 exact) plus the terms \
left out continued geometrically (5e-5 of Z at η = 0.3, 7e-4 at 0.4, 0.2 % high at 0.6); and Henderson 1975, \
Z = (1 + η²/8)/(1 − η)², 2.5e-4 above the series at 0.3. Spheres, Hansen-Goos 2016 (J. Chem. Phys. 144, 164506), \
Z = 8 ln(1 − η)/η + p(η)/(1 − η)³ with a degree-7 polynomial p built on the virial coefficients and fitted to \
the fluid's simulations: its expansion gives B2-B4 exactly and B5-B10 within 0.4 %; Carnahan-Starling-Kolafa \
(Boublík and Nezbeda 1986), Z = (1 + η + η² − ⅔(η³ + η⁴))/(1 − η)³, within 1e-4 of it up to 0.4; the spheres' \
virial series to B10 with its tail; and Carnahan-Starling, (1 + η + η² − η³)/(1 − η)³, which is 0.25 % low at \
0.3. The `note` column flags points beyond where an equation \
is expected to be within ~1e-3 of the fluid's Z, and points where the fluid is not the stable phase: disks \
above 0.700 (fluid-hexatic coexistence to 0.716, hexatic to 0.720, solid above; Bernard and Krauth 2011), \
spheres above freezing at 0.494 (coexistence to 0.545, crystal above).\n";
