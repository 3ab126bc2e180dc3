//! The equilibrium part of the report: per point or case, its charts and
//! its rows of the tests, then what they say about MacKay's questions. The
//! prose is in the Markdown files beside this one.

use super::RESULTS;
use super::charts::{self, Runs};
use super::dimple::{self, central_share, has_dimple, independent_samples};
use super::ensemble::Ensemble;
use super::measure::histogram;
use super::settling;
use super::tests_of::{MIN_EXPECTED, Particle, Tests, tests_of};
use crate::model::chart::ChartSpec;
use crate::model::report::{Figure, ReportSection};
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::ensemble::Runs as AllRuns;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::named::named;
use crate::stats::replicas::Agreement;
use crate::stats::summary::{Stats, scalar};
use std::collections::BTreeMap;
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
const DIMPLE_ANSWER: &str = include_str!("dimple_answer.md");
const FLUID_HEAD: &str = include_str!("fluid.md");
const SETTLING_HEAD: &str = include_str!("settling.md");
const METHODS: &str = include_str!("methods.md");
const CAPTIONS: &str = include_str!("captions.md");
/// The sentences a finding is told in, one per outcome.
const FINDINGS: &str = include_str!("findings.md");

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
        let kind = if spec.case.is_some() { "case" } else { "point" };
        by.entry((spec.case.is_some(), spec.point_id))
            .or_insert_with(|| Group {
                point: spec.point_id,
                label: spec.case.clone().unwrap_or_else(|| describe(&e)),
                slug: format!("{kind}{}", spec.point_id),
                runs: Vec::new(),
            })
            .runs
            .push((e, out));
    }
    by.into_values().collect()
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

fn verdict(a: &Option<Agreement>) -> &'static str {
    match a {
        Some(a) if a.z.abs() < REJECT => "holds",
        Some(_) => "rejected",
        None => "not tested",
    }
}

fn stat(view: &Runs, name: &str) -> Stats {
    scalar(view.iter().map(|(_, o)| *o), name)
}

pub fn section(runs: &AllRuns) -> anyhow::Result<ReportSection> {
    let mut p = Parts::default();
    for g in groups(runs) {
        let view: Vec<(&Ensemble, &RunOutput)> = g.runs.iter().map(|(e, o)| (e, *o)).collect();
        let t = tests_of(&view);
        let e = view[0].0;
        let _ = writeln!(p.pictures, "#### {}\n", g.label);
        if e.dimension == 1 && !t.particles.is_empty() {
            p.rods(&g, &view, &t);
        } else if e.dimension > 1
            && let Some((time, mean)) = runs.mean(g.point, "speed_std")
        {
            p.settling(&g, &view, &time, &mean);
            if let Some((time, energy)) = runs.mean(g.point, "kinetic_energy") {
                let start = energy.first().map_or(f64::NAN, |s| s.mean);
                let drift = (energy.iter()).fold(0.0, |d, s| f64::max(d, (s.mean - start).abs()));
                let title = format!("{}: total energy", g.label);
                let chart = charts::settling(&title, &time, &energy, "total kinetic energy", None);
                p.figure_with(&g, "energy", Some(chart), ("drift", num(drift / start)));
            }
        } else if e.dimension > 1 {
            p.fluid(&g, &view, &t);
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
    dimple_rows: String,
    dimples: Vec<Dimples>,
    fluid: String,
    settling: String,
    pictures: String,
    figures: Vec<Figure>,
}

impl Parts {
    fn markdown(&self) -> String {
        let mut md = fill(INTRO, &[("reject", num(REJECT))]);
        if !self.rods.is_empty() {
            md += ROD_HEAD;
            md += &self.rods;
            md.push('\n');
            md += &self.per_particle;
        }
        if !self.dimple.is_empty() || !self.dimple_rows.is_empty() {
            md += "### The dimple in P(v₁)\n\n";
            md += &self.dimple;
            md += &fill(DIMPLE_HEAD, &[("trials", DIMPLE_TRIALS.to_string())]);
            md += &self.dimple_rows;
            md += &dimple_answer(&self.dimples);
            md.push('\n');
        }
        for (head, rows) in [(FLUID_HEAD, &self.fluid), (SETTLING_HEAD, &self.settling)] {
            if !rows.is_empty() {
                md += head;
                md += rows;
                md.push('\n');
            }
        }
        md += "### Figures\n\n";
        md += &self.pictures;
        md + METHODS
    }

    /// A group's figure, if its chart could be drawn, with its caption.
    fn figure(&mut self, g: &Group, name: &str, chart: Option<ChartSpec>) {
        self.figure_with(g, name, chart, ("", String::new()));
    }

    fn figure_with(
        &mut self,
        g: &Group,
        name: &str,
        chart: Option<ChartSpec>,
        extra: (&str, String),
    ) {
        let Some(chart) = chart else { return };
        let file = format!("equilibrium_{}_{name}.svg", g.slug);
        let values = [
            ("label", g.label.clone()),
            ("replicas", g.runs.len().to_string()),
            ("dimension", g.runs[0].0.dimension.to_string()),
            extra,
        ];
        let _ = writeln!(
            self.pictures,
            "![{}]({file})\n",
            fill(named(CAPTIONS, name), &values)
        );
        self.figures.push(Figure { file, chart });
    }

    fn rods(&mut self, g: &Group, view: &Runs, t: &Tests) {
        self.rod_rows(g, view, t);
        let title = |what: &str| format!("{}: {what}", g.label);
        let light = |r: usize| view[r].0.lightest().map(|b| (b.index, b.mass));
        let heavy = |r: usize| view[r].0.heaviest().map(|b| (b.index, b.mass));
        let whole = [("", charts::MEASURED)];
        let chart = charts::velocity(&title("lightest particle's vₓ"), view, &light, &whole);
        self.figure(g, "light", chart);
        let chart = charts::velocity(&title("heaviest particle's vₓ"), view, &heavy, &whole);
        self.figure(g, "heavy", chart);
        let chart = charts::std_against_mass(&title("velocity std against mass"), view);
        self.figure(g, "std", chart);
        let chart = charts::positions(&title("each rod's position"), view);
        self.figure(g, "positions", chart);
        let ranked = view[0].0.by_rank();
        let name = |kind: &str, rank: usize| format!("{kind}.{}", ranked[rank].index);
        let last = ranked.len() - 1;
        let sets = [
            (name("x", 0), name("x", 1), "x₁, x₂".into()),
            (
                name("x", last - 1),
                name("x", last),
                format!("x{last}, x{}", last + 1),
            ),
        ];
        let what = format!("positions of particles 1 and 2, {last} and {}", last + 1);
        let axes = ("x of the left one [σ]", "x of the right one [σ]");
        self.figure(
            g,
            "scatter_x",
            charts::scatter(&title(&what), view, &sets, axes),
        );
        let sets = [(name("v", 0), name("v", 1), "(v₁, v₂)".into())];
        let chart = charts::scatter(&title("v₁ against v₂"), view, &sets, ("v₁", "v₂"));
        self.figure(g, "scatter_v", chart);
        let sets = [(name("x", 0), name("v", 0), "(x₁, v₁)".into())];
        let chart = charts::scatter(&title("x₁ against v₁"), view, &sets, ("x₁ [σ]", "v₁"));
        self.figure(g, "scatter_xv", chart);
        self.dimples(&g.label, view, t);
        let Some(p) = (t.particles.iter()).find(|p| p.rank == 0 && p.halves.is_some()) else {
            return;
        };
        let first = |r: usize| view[r].0.ball(p.index).map(|b| (b.index, b.mass));
        let halves = [("_early", "first half"), ("_late", "second half")];
        let what = "P(v₁), first and second halves";
        let chart = charts::velocity(&title(what), view, &first, &halves);
        self.figure(g, "dimple", chart);
        self.dimple += &dimple_text(&g.label, p, view[0].0);
    }

    fn rod_rows(&mut self, g: &Group, view: &Runs, t: &Tests) {
        let e = view[0].0;
        let zs = |f: fn(&Particle) -> Option<Agreement>| t.particles.iter().filter_map(f);
        let worst = |f| zs(f).map(|a| a.z).fold(f64::NAN, f64::max);
        let least = |f| zs(f).map(|a| a.z).fold(f64::NAN, f64::min);
        let (ratio, kurt) = (stat(view, "std_ratio"), stat(view, "kurtosis_lightest"));
        let cost: f64 = view.iter().map(|(_, o)| o.cpu_seconds).sum();
        let collisions: u64 = view.iter().map(|(_, o)| o.collisions).sum();
        let _ = writeln!(
            self.rods,
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
            dash(worst(|p| p.exact)),
            dash(least(|p| p.gaussian)),
            z_text(&t.positions),
            dash(worst(|p| p.halves)),
            num(cost),
            count(collisions),
        );
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
            let _ = writeln!(
                self.per_particle,
                "| {} | {} | {} | {} | {} |",
                p.rank + 1,
                num(p.mass),
                z_text(&p.exact),
                z_text(&p.gaussian),
                z_text(&p.halves)
            );
        }
        self.per_particle.push('\n');
    }

    /// How often particle 1's histogram shows a dimple over the replicas,
    /// and how often independent draws from the exact law would, as many.
    fn dimples(&mut self, label: &str, view: &Runs, t: &Tests) {
        let Some(p) = t.particles.iter().find(|p| p.rank == 0) else {
            return;
        };
        let name = format!("velocity_x.{}", p.index);
        let hists: Vec<&[f64]> = (view.iter())
            .filter_map(|(_, o)| histogram(o, &name))
            .map(|h| h.count.as_slice())
            .collect();
        let Some(first) = hists.first() else { return };
        let samples = first.iter().sum::<f64>();
        let dof = view[0].0.dof;
        // The bins span ±min(reach, 6 std) (velocity_x_each), in reach units.
        let half = (6.0 / dof.sqrt()).min(1.0);
        let chance = |n: f64| {
            let simulated = n.is_finite() && (1.0..=MONTE_CARLO_SAMPLES).contains(&n);
            let trials = DIMPLE_TRIALS;
            simulated.then(|| dimple::chance(dof as usize, half, n.round() as usize, trials, 12))
        };
        let shares: Vec<f64> = hists.iter().map(|h| central_share(h)).collect();
        let independent = independent_samples(&shares);
        let d = Dimples {
            label: label.into(),
            particles: view[0].0.balls.len(),
            samples,
            seen: hists.iter().filter(|h| has_dimple(h)).count(),
            runs: hists.len(),
            independent,
            chance: chance(samples),
            chance_independent: chance(independent),
        };
        let _ = writeln!(
            self.dimple_rows,
            "| {label} | {} | {} of {} | {} | {} | {} |",
            num(samples),
            d.seen,
            d.runs,
            opt(d.chance),
            num(independent),
            opt(d.chance_independent)
        );
        self.dimples.push(d);
    }

    /// A row of the equilibration table and the figure of the speeds' std.
    fn settling(&mut self, g: &Group, view: &Runs, time: &[f64], mean: &[Stats]) {
        let e = view[0].0;
        let n = view.len() as f64;
        let kt = view.iter().map(|(e, _)| e.kt().sqrt()).sum::<f64>() / n;
        let reference = settling::maxwell_speed_std(e.dimension) * kt;
        let (level, tau) = settling::equilibration(time, mean);
        let duration = time.last().copied().unwrap_or(f64::NAN);
        let collisions = view.iter().map(|(_, o)| o.collisions as f64).sum::<f64>() / n;
        let cpu: f64 = view.iter().map(|(_, o)| o.cpu_seconds).sum();
        let _ = writeln!(
            self.settling,
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
        let reference = Some((reference, "Maxwell-Boltzmann: √((2 − π/2) kT/m) in 2D"));
        let title = format!("{}: std of the speeds", g.label);
        let chart = charts::settling(&title, time, mean, "std of the speeds", reference);
        self.figure(g, "speed_std", Some(chart));
    }

    /// A row of the disks' table and their figures.
    fn fluid(&mut self, g: &Group, view: &Runs, t: &Tests) {
        let e = view[0].0;
        let s = |n: &str| match stat(view, n) {
            s if s.n == 0 => "–".into(),
            s => pm(s.mean, s.stderr),
        };
        let cost: f64 = view.iter().map(|(_, o)| o.cpu_seconds).sum();
        let _ = writeln!(
            self.fluid,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} s |",
            g.label,
            e.balls.len(),
            num(e.packing()),
            boundary(e),
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
        let title = |what: &str| format!("{}: {what}", g.label);
        self.figure(g, "vx", charts::scaled_vx(&title("vₓ"), view));
        self.figure(g, "speed", charts::speed(&title("speeds"), view));
        let chart = charts::density(&title("density along x"), view);
        self.figure(g, "density", chart);
        self.figure(g, "g", charts::radial(&title("g(r)"), view, 4.0));
    }
}

fn opt(x: Option<f64>) -> String {
    x.map_or("–".into(), num)
}

/// One line of the dimple table, kept for the conclusion.
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

/// Particle 1's tests, and what its exact law looks like.
fn dimple_text(label: &str, p: &Particle, e: &Ensemble) -> String {
    let z = |a: &Option<Agreement>| a.map_or("–".into(), |a| num(a.z));
    let limit = match verdict(&p.gaussian) {
        "rejected" => "gaussian_rejected",
        _ => "gaussian_fits",
    };
    let values = [
        ("n", e.balls.len().to_string()),
        ("limit", named(FINDINGS, limit).into()),
        ("reject", num(REJECT)),
    ];
    let finding = fill(named(FINDINGS, verdict(&p.exact)), &values);
    let text = fill(
        DIMPLE_PARTICLE,
        &[
            ("label", label.to_string()),
            ("mass", num(p.mass)),
            ("exact", verdict(&p.exact).into()),
            ("z_exact", z(&p.exact)),
            ("gaussian", verdict(&p.gaussian).into()),
            ("z_gaussian", z(&p.gaussian)),
            ("halves", verdict(&p.halves).into()),
            ("z_halves", z(&p.halves)),
            ("dof", num(e.dof)),
            ("power", num(0.5 * (e.dof - 3.0))),
            ("kurtosis", num(-6.0 / (e.dof + 2.0))),
            ("finding", finding),
            ("reject", num(REJECT)),
        ],
    );
    text + "\n"
}

/// What the dimple table says: the shortest runs against the longest of
/// as many particles (the first such, in table order), and whether the
/// shortest show dimples as often as that few independent samples would.
fn dimple_answer(all: &[Dimples]) -> String {
    let Some(few) = all.iter().min_by(|a, b| a.samples.total_cmp(&b.samples)) else {
        return String::new();
    };
    let same = all.iter().filter(|d| d.particles == few.particles);
    let Some(many) = same.rev().max_by(|a, b| a.samples.total_cmp(&b.samples)) else {
        return String::new();
    };
    if few.samples == many.samples {
        return String::new();
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
    fill(
        DIMPLE_ANSWER,
        &[
            ("few_samples", num(few.samples)),
            ("few_label", few.label.clone()),
            ("few_seen", few.seen.to_string()),
            ("few_runs", few.runs.to_string()),
            ("few_independent", num(few.independent)),
            ("few_chance_independent", opt(few.chance_independent)),
            ("few_chance", opt(few.chance)),
            ("many_samples", num(many.samples)),
            ("many_label", many.label.clone()),
            ("many_independent", num(many.independent)),
            ("many_seen", many.seen.to_string()),
            ("many_runs", many.runs.to_string()),
            ("verdict", verdict),
        ],
    )
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
            index: 0,
            rank: 0,
            mass: 1.0,
            exact: None,
            gaussian: None,
            halves: None,
        };
        let e = Ensemble::default();
        let d = |samples| Dimples {
            label: "a".into(),
            particles: 10,
            samples,
            seen: 1,
            runs: 8,
            independent: 30.0,
            chance: Some(0.1),
            chance_independent: Some(0.2),
        };
        let texts = [
            fill(INTRO, &[("reject", "4".into())]),
            fill(DIMPLE_HEAD, &[("trials", "1000".into())]),
            dimple_text("a", &p, &e),
            dimple_answer(&[d(400.0), d(20000.0)]),
            ROD_HEAD.into(),
            FLUID_HEAD.into(),
            SETTLING_HEAD.into(),
            METHODS.into(),
        ];
        for text in &texts {
            assert!(unfilled(text).is_empty(), "{text}");
        }
        let values = ["label", "replicas", "dimension", "drift"].map(|k| (k, "x".to_string()));
        for name in names(CAPTIONS) {
            let text = fill(named(CAPTIONS, name), &values);
            assert!(unfilled(&text).is_empty(), "{text}");
        }
        let values = ["label", "min", "n", "limit", "reject", "how"].map(|k| (k, "x".to_string()));
        for name in names(FINDINGS) {
            let text = fill(named(FINDINGS, name), &values);
            assert!(unfilled(&text).is_empty(), "{text}");
        }
    }
}
