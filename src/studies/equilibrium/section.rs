//! The equilibrium part of the report: per point or case, its charts and
//! its rows of the tests, then what they say about MacKay's questions. The
//! prose is in the Markdown files beside this one.

use super::RESULTS;
use super::charts;
use super::dimple::{self, central_share, has_dimple, independent_samples};
use super::ensemble::Ensemble;
use super::measure::histogram;
use super::settling;
use super::tests_of::{MIN_EXPECTED, Particle, Tests, tests_of};
use crate::model::chart::ChartSpec;
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::stats::ensemble::Runs as AllRuns;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::named::named;
use crate::stats::point_runs::{PointRuns, by_point};
use crate::stats::replicas::Agreement;
use crate::stats::table::table_row;
use crate::studies::curves::show;
use std::fmt::Write;

/// |z| beyond this rejects a law (about 4 standard deviations).
const REJECT: f64 = 4.0;
/// Independent draws are simulated up to this many samples per run.
const MONTE_CARLO_SAMPLES: f64 = 2000.0;
const DIMPLE_TRIALS: usize = 1000;

const INTRO: &str = include_str!("intro.md");
const ROD_HEAD: &str = include_str!("rods.md");
const DIMPLE_HEAD: &str = include_str!("dimple.md");
const DIMPLE_PARTICLE: &str = include_str!("dimple_particle.md");
/// A dimple table row, and the conclusion's parts on the fewest and the
/// most samples per run.
const DIMPLE_ANSWER: &str = include_str!("dimple_answer.md");
const FLUID_HEAD: &str = include_str!("fluid.md");
const SETTLING_HEAD: &str = include_str!("settling.md");
const METHODS: &str = include_str!("methods.md");
const CAPTIONS: &str = include_str!("captions.md");
const TITLES: &str = include_str!("titles.md");
/// The sentences a finding is told in, one per outcome.
const FINDINGS: &str = include_str!("findings.md");

/// A placeholder and what fills it.
type Value = (&'static str, String);

/// A group of runs (a case, or a sweep point), each beside its ensemble.
struct Group<'a> {
    label: String,
    slug: String,
    runs: PointRuns<'a>,
    view: Vec<(&'a Ensemble, &'a RunOutput)>,
}

/// "200 disks, φ = 0.4, periodic" for a sweep point.
fn describe(e: &Ensemble) -> String {
    let kind = ["rods", "disks", "spheres"][e.dimension.clamp(1, 3) - 1];
    let (n, phi) = (e.balls.len(), num(e.packing()));
    format!("{n} {kind}, φ = {phi}, {}", boundary(e))
}

fn boundary(e: &Ensemble) -> &'static str {
    match (e.periodic[0], e.periodic.iter().all(|p| *p)) {
        (_, true) => "periodic",
        (false, false) => "walls along x",
        (true, false) => "walls",
    }
}

/// "z (p, bins)" of an agreement, or "–".
fn z_text(a: &Option<Agreement>) -> String {
    match a {
        Some(a) => format!("{} (p {}, {} bins)", num(a.z), num(a.p), a.bins),
        None => "–".into(),
    }
}

fn dash(x: f64) -> String {
    if x.is_nan() { "–".into() } else { num(x) }
}

fn opt(x: Option<f64>) -> String {
    x.map_or("–".into(), num)
}

fn verdict(a: &Option<Agreement>) -> &'static str {
    match a {
        Some(a) if a.z.abs() < REJECT => "holds",
        Some(_) => "rejected",
        None => "not tested",
    }
}

pub fn section(runs: &AllRuns) -> anyhow::Result<ReportSection> {
    let mut p = Parts::default();
    for point in by_point(runs) {
        let specs = runs
            .iter()
            .filter(|(s, _)| s.point_id == point.spec.point_id);
        let ensembles: Option<Vec<_>> = specs.map(|(s, _)| Ensemble::of_run(s)).collect();
        let Some(ensembles) = ensembles else { continue };
        let (e, case) = (&ensembles[0], &point.spec.case);
        let kind = if case.is_some() { "case" } else { "point" };
        let g = Group {
            label: case.clone().unwrap_or_else(|| describe(e)),
            slug: format!("{kind}{}", point.spec.point_id),
            view: ensembles.iter().zip(point.outs.iter().copied()).collect(),
            runs: point,
        };
        let t = tests_of(&g.view);
        let _ = writeln!(p.pictures, "#### {}\n", g.label);
        if e.dimension == 1 && !t.particles.is_empty() {
            p.rods(&g, &t);
        } else if e.dimension > 1 && !p.settling(&g) {
            p.fluid(&g, &t);
        }
    }
    Ok(ReportSection {
        title: "Equilibrium distributions".into(),
        markdown: p.markdown(),
        figures: p.figures,
        presents: RESULTS.iter().map(|r| r.to_string()).collect(),
    })
}

/// The section's tables, paragraphs and figures as the groups fill them.
#[derive(Default)]
struct Parts {
    rods: String,
    per_particle: String,
    dimple: String,
    dimples: Vec<Dimples>,
    fluid: String,
    settling: String,
    pictures: String,
    figures: Vec<Figure>,
}

impl Parts {
    fn markdown(&self) -> String {
        // A table under its head, if it has rows, and what follows it.
        let table = |head: &str, rows: &str, after: &str| match rows {
            "" => String::new(),
            _ => format!("{head}{rows}\n{after}"),
        };
        let mut md = fill(INTRO, &[("reject", num(REJECT))]);
        md += &table(ROD_HEAD, &self.rods, &self.per_particle);
        if !self.dimple.is_empty() || !self.dimples.is_empty() {
            md += "### The dimple in P(v₁)\n\n";
            md += &self.dimple;
            md += &fill(DIMPLE_HEAD, &[("trials", DIMPLE_TRIALS.to_string())]);
            for d in &self.dimples {
                md += &fill(named(DIMPLE_ANSWER, "row"), &d.values());
                md.push('\n');
            }
            md += &dimple_answer(&self.dimples).unwrap_or_default();
            md.push('\n');
        }
        md += &table(FLUID_HEAD, &self.fluid, "");
        md += &table(SETTLING_HEAD, &self.settling, "");
        md + "### Figures\n\n" + &self.pictures + METHODS
    }

    /// A group's figure, if its chart could be drawn, with its title and
    /// caption (`extra`: values for them beside the group's).
    fn figure(&mut self, g: &Group, name: &str, chart: Option<ChartSpec>, extra: &[Value]) {
        let Some(mut chart) = chart else { return };
        let (e, file) = (g.view[0].0, format!("equilibrium_{}_{name}.svg", g.slug));
        let mut values = vec![
            ("label", g.label.clone()),
            ("replicas", g.view.len().to_string()),
            ("dimension", e.dimension.to_string()),
            ("n", e.balls.len().to_string()),
            ("last", e.balls.len().saturating_sub(1).to_string()),
        ];
        values.extend_from_slice(extra);
        chart.title = fill(named(TITLES, name), &values);
        let caption = fill(named(CAPTIONS, name), &values);
        self.pictures += &show(&mut self.figures, Figure { file, chart }, &caption);
    }

    fn rods(&mut self, g: &Group, t: &Tests) {
        self.rod_rows(g, t);
        let view = &g.view[..];
        let whole = [("", charts::MEASURED)];
        let chart = charts::velocity(view, &|e| e.by_mass().first().copied(), &whole);
        self.figure(g, "light", chart, &[]);
        let chart = charts::velocity(view, &|e| e.by_mass().last().copied(), &whole);
        self.figure(g, "heavy", chart, &[]);
        self.figure(g, "std", charts::std_against_mass(view), &[]);
        self.figure(g, "positions", charts::positions(view), &[]);
        let ranked: Vec<usize> = view[0].0.by_rank().iter().map(|b| b.index).collect();
        let x = |rank: usize| format!("x.{}", ranked[rank]);
        let v = |rank: usize| format!("v.{}", ranked[rank]);
        let last = ranked.len() - 1;
        let sets = [
            (x(0), x(1), "x₁, x₂".into()),
            (x(last - 1), x(last), format!("x{last}, x{}", last + 1)),
        ];
        let axes = ("x of the left one [σ]", "x of the right one [σ]");
        self.figure(g, "scatter_x", charts::scatter(view, &sets, axes), &[]);
        let sets = [(v(0), v(1), "(v₁, v₂)".into())];
        self.figure(
            g,
            "scatter_v",
            charts::scatter(view, &sets, ("v₁", "v₂")),
            &[],
        );
        let sets = [(x(0), v(0), "(x₁, v₁)".into())];
        let chart = charts::scatter(view, &sets, ("x₁ [σ]", "v₁"));
        self.figure(g, "scatter_xv", chart, &[]);
        self.dimples(g, t);
        let first = t
            .particles
            .iter()
            .find(|p| p.rank == 0 && p.halves.is_some());
        let Some(p) = first else { return };
        let halves = [("_early", "first half"), ("_late", "second half")];
        self.figure(
            g,
            "dimple",
            charts::velocity(view, &|e| e.ball(p.index), &halves),
            &[],
        );
        self.dimple += &dimple_text(&g.label, p, view[0].0);
    }

    fn rod_rows(&mut self, g: &Group, t: &Tests) {
        let e = g.view[0].0;
        let zs = |f: fn(&Particle) -> Option<Agreement>| t.particles.iter().filter_map(f);
        let worst = |f| dash(zs(f).map(|a| a.z).fold(f64::NAN, f64::max));
        let least = |f| dash(zs(f).map(|a| a.z).fold(f64::NAN, f64::min));
        let (ratio, kurt) = (g.runs.stat("std_ratio"), g.runs.stat("kurtosis_lightest"));
        let means = [
            "lightest_mass",
            "heaviest_mass",
            "sqrt_mass_ratio",
            "std_ratio_exact",
        ];
        let [light, heavy, root, exact] = means.map(|n| num(g.runs.stat(n).mean));
        let row = [
            g.label.clone(),
            e.balls.len().to_string(),
            e.dof.to_string(),
            g.view.len().to_string(),
            format!("{light} – {heavy}"),
            pm(ratio.mean, ratio.stderr),
            root,
            exact,
            format!(
                "{} ({})",
                pm(kurt.mean, kurt.stderr),
                num(-6.0 / (e.dof + 2.0))
            ),
            worst(|p| p.exact),
            least(|p| p.gaussian),
            z_text(&t.positions),
            worst(|p| p.halves),
            format!(
                "{} s, {} collisions",
                num(g.runs.cpu()),
                count(g.runs.collisions())
            ),
        ];
        self.rods += &table_row(&row);
        let tested = |p: &Particle| p.exact.is_some() || p.gaussian.is_some() || p.halves.is_some();
        let tested = t.particles.iter().any(tested);
        let values = [
            ("label", g.label.clone()),
            ("min", MIN_EXPECTED.to_string()),
        ];
        let head = named(FINDINGS, if tested { "tested" } else { "untested" });
        let _ = writeln!(self.per_particle, "{}\n", fill(head, &values));
        if !tested {
            return;
        }
        self.per_particle += "| rank | mass | z exact | z Gaussian | z halves |\n";
        self.per_particle += "|---|---|---|---|---|\n";
        for p in &t.particles {
            let z = [p.exact, p.gaussian, p.halves]
                .map(|a| z_text(&a))
                .join(" | ");
            let _ = writeln!(
                self.per_particle,
                "| {} | {} | {z} |",
                p.rank + 1,
                num(p.mass)
            );
        }
        self.per_particle.push('\n');
    }

    /// How often particle 1's histogram shows a dimple over the replicas,
    /// and how often independent draws from the exact law would, as many.
    fn dimples(&mut self, g: &Group, t: &Tests) {
        let first = t.particles.iter().find(|p| p.rank == 0);
        let Some(p) = first else { return };
        let name = format!("velocity_x.{}", p.index);
        let hists: Vec<&[f64]> = (g.view.iter())
            .filter_map(|(_, o)| histogram(o, &name))
            .map(|h| h.count.as_slice())
            .collect();
        let Some(first) = hists.first() else { return };
        let samples = first.iter().sum::<f64>();
        let dof = g.view[0].0.dof;
        // The bins span ±min(reach, 6 std) (velocity_x_each), in reach units.
        let half = (6.0 / dof.sqrt()).min(1.0);
        let chance = |n: f64| {
            let simulated = n.is_finite() && (1.0..=MONTE_CARLO_SAMPLES).contains(&n);
            let trials = DIMPLE_TRIALS;
            simulated.then(|| dimple::chance(dof as usize, half, n.round() as usize, trials, 12))
        };
        let shares: Vec<f64> = hists.iter().map(|h| central_share(h)).collect();
        let independent = independent_samples(&shares);
        self.dimples.push(Dimples {
            label: g.label.clone(),
            particles: g.view[0].0.balls.len(),
            samples,
            seen: hists.iter().filter(|h| has_dimple(h)).count(),
            runs: hists.len(),
            independent,
            chance: chance(samples),
            chance_independent: chance(independent),
        });
    }

    /// A row of the equilibration table and the figures of the speeds' std
    /// and the total energy; false if the group has no speeds' std.
    fn settling(&mut self, g: &Group) -> bool {
        let (time, mean) = g.runs.mean_curve("speed_std");
        if mean.is_empty() {
            return false;
        }
        let (e, n) = (g.view[0].0, g.view.len() as f64);
        let kt = g.view.iter().map(|(e, _)| e.kt().sqrt()).sum::<f64>() / n;
        let reference = settling::maxwell_speed_std(e.dimension) * kt;
        let (level, tau) = settling::equilibration(&time, &mean);
        let duration = time.last().copied().unwrap_or(f64::NAN);
        let collisions = g.runs.collisions() as f64 / n * tau / duration / e.balls.len() as f64;
        let mut row = vec![g.label.clone(), e.balls.len().to_string(), num(e.packing())];
        row.push(g.view.len().to_string());
        row.extend([mean[0].mean, level, reference, tau, collisions].map(num));
        row.push(format!("{} s", num(g.runs.cpu())));
        self.settling += &table_row(&row);
        let reference = Some((reference, "Maxwell-Boltzmann: √((2 − π/2) kT/m) in 2D"));
        let chart = charts::settling(&time, &mean, "std of the speeds", reference);
        self.figure(g, "speed_std", Some(chart), &[]);
        let (time, energy) = g.runs.mean_curve("kinetic_energy");
        if let Some(start) = energy.first().map(|s| s.mean) {
            let drift = (energy.iter()).fold(0.0, |d, s| f64::max(d, (s.mean - start).abs()));
            let chart = charts::settling(&time, &energy, "total kinetic energy", None);
            self.figure(g, "energy", Some(chart), &[("drift", num(drift / start))]);
        }
        true
    }

    /// A row of the disks' table and their figures.
    fn fluid(&mut self, g: &Group, t: &Tests) {
        let e = g.view[0].0;
        let s = |n: &str| match g.runs.stat(n) {
            s if s.n == 0 => "–".into(),
            s => pm(s.mean, s.stderr),
        };
        let mut row = vec![
            g.label.clone(),
            e.balls.len().to_string(),
            num(e.packing()),
            boundary(e).into(),
            g.view.len().to_string(),
            num(e.kt()),
        ];
        row.extend([t.vx_exact, t.vx_gaussian, t.speed_exact, t.speed_mb].map(|a| z_text(&a)));
        row.extend(
            [
                "g_contact",
                "Z_contact",
                "Z_virial",
                "contact_theorem_ratio",
            ]
            .map(s),
        );
        row.push(format!("{} s", num(g.runs.cpu())));
        self.fluid += &table_row(&row);
        self.figure(g, "vx", charts::scaled_vx(&g.view), &[]);
        self.figure(g, "speed", charts::speed(&g.view), &[]);
        self.figure(g, "density", charts::density(&g.view), &[]);
        self.figure(g, "g", charts::radial(&g.view, 4.0), &[]);
    }
}

/// One line of the dimple table, kept for the conclusion.
#[derive(Default)]
struct Dimples {
    label: String,
    particles: usize,
    samples: f64,
    seen: usize,
    runs: usize,
    independent: f64,
    chance: Option<f64>,
    chance_independent: Option<f64>,
}

impl Dimples {
    /// What its table row and the conclusion's sentences are filled with.
    fn values(&self) -> [Value; 7] {
        [
            ("label", self.label.clone()),
            ("samples", num(self.samples)),
            ("seen", self.seen.to_string()),
            ("runs", self.runs.to_string()),
            ("chance", opt(self.chance)),
            ("independent", num(self.independent)),
            ("chance_independent", opt(self.chance_independent)),
        ]
    }
}

/// Particle 1's tests, and what its exact law looks like.
fn dimple_text(label: &str, p: &Particle, e: &Ensemble) -> String {
    let rejected = verdict(&p.gaussian) == "rejected";
    let limit = if rejected {
        "gaussian_rejected"
    } else {
        "gaussian_fits"
    };
    let mut values = vec![
        ("label", label.to_string()),
        ("mass", num(p.mass)),
        ("n", e.balls.len().to_string()),
        ("limit", named(FINDINGS, limit).into()),
        ("dof", num(e.dof)),
        ("power", num(0.5 * (e.dof - 3.0))),
        ("kurtosis", num(-6.0 / (e.dof + 2.0))),
        ("reject", num(REJECT)),
    ];
    let tests = [
        ("exact", p.exact),
        ("gaussian", p.gaussian),
        ("halves", p.halves),
    ];
    for ((name, a), z) in tests.into_iter().zip(["z_exact", "z_gaussian", "z_halves"]) {
        values.extend([
            (name, verdict(&a).into()),
            (z, a.map_or("–".into(), |a| num(a.z))),
        ]);
    }
    let finding = fill(named(FINDINGS, verdict(&p.exact)), &values);
    values.push(("finding", finding));
    fill(DIMPLE_PARTICLE, &values) + "\n"
}

/// What the dimple table says: the shortest runs against the longest of
/// as many particles (the first such, in table order), and whether the
/// shortest show dimples as often as that few independent samples would.
fn dimple_answer(all: &[Dimples]) -> Option<String> {
    let few = all.iter().min_by(|a, b| a.samples.total_cmp(&b.samples))?;
    let same = all.iter().filter(|d| d.particles == few.particles);
    let many = same.rev().max_by(|a, b| a.samples.total_cmp(&b.samples))?;
    if few.samples == many.samples {
        return None;
    }
    let verdict = few.chance_independent.map_or(String::new(), |p| {
        let expected = p * few.runs as f64;
        let off = few.seen as f64 - expected;
        let noise = off.abs() <= REJECT * (expected * (1.0 - p)).sqrt();
        let how = if off > 0.0 { "more" } else { "less" };
        let values = [("how", how.to_string()), ("reject", num(REJECT))];
        let name = if noise { "noise" } else { "beyond_noise" };
        fill(named(FINDINGS, name), &values)
    });
    let few = fill(named(DIMPLE_ANSWER, "few"), &few.values());
    let many = fill(named(DIMPLE_ANSWER, "many"), &many.values());
    Some(format!("\n{few} {many} {verdict}\n"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::fill::unfilled;
    use crate::stats::named::names;

    /// Every placeholder of every text is one the section fills.
    #[test]
    fn every_placeholder_is_filled() {
        let p = Particle {
            mass: 1.0,
            ..Default::default()
        };
        let e = Ensemble::default();
        let d = |samples| Dimples {
            samples,
            chance: Some(0.1),
            chance_independent: Some(0.2),
            ..Default::default()
        };
        let texts = [
            fill(INTRO, &[("reject", "4".into())]),
            fill(DIMPLE_HEAD, &[("trials", "1000".into())]),
            dimple_text("a", &p, &e),
            dimple_answer(&[d(400.0), d(20000.0)]).expect("two lengths"),
            fill(named(DIMPLE_ANSWER, "row"), &d(400.0).values()),
            ROD_HEAD.into(),
            FLUID_HEAD.into(),
            SETTLING_HEAD.into(),
            METHODS.into(),
        ];
        for text in &texts {
            assert!(unfilled(text).is_empty(), "{text}");
        }
        let figures = ["label", "replicas", "dimension", "n", "last", "drift"];
        let findings = ["label", "min", "n", "limit", "reject", "how"];
        for (texts, keys) in [(CAPTIONS, figures), (TITLES, figures), (FINDINGS, findings)] {
            let values = keys.map(|k| (k, "x".to_string()));
            for name in names(texts) {
                let text = fill(named(texts, name), &values);
                assert!(unfilled(&text).is_empty(), "{text}");
            }
        }
    }
}
