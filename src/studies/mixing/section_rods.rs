//! The 1D half of the mixing section: per point the mixing time (censored
//! points flagged), its scaling with the mass spread and with N, the
//! ensemble mean of the energy concentration against time.

use super::section::Point;
use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::report::Figure;
use crate::stats::format::{count, num, pm};
use crate::stats::line::line;
use crate::studies::curves::mean_with_band;
use crate::theory::mixing::equilibrium_concentration;
use std::fmt::Write;

/// The scaling with the mass spread is fitted over spreads up to this
/// (small spreads: each collision moves a fraction ~ epsilon^2 of the energy
/// difference, so tau ~ epsilon^-2 is expected there, not at MacKay's 1 to 9).
pub const SMALL_SPREAD: f64 = 0.5;

fn label(p: &Point) -> String {
    let base = format!(
        "N = {}, ε = {}, M/m̄ = {}",
        num(p.first("particles")),
        num(p.first("mass_spread")),
        num(p.first("hot_mass_ratio"))
    );
    match &p.spec.case {
        Some(c) => format!("{base} (case {c})"),
        None => base,
    }
}

/// A fit of ln tau (collision clock) against ln x over the fully mixed
/// points, weighted by their error bars.
struct Fit {
    slope: f64,
    error: f64,
    intercept: f64,
    points: usize,
    /// Chi-square per degree of freedom: about 1 when the power law and the
    /// error bars hold together (NaN with two points).
    chi2: f64,
}

impl Fit {
    fn text(&self) -> String {
        format!(
            "{} over {} fully mixed points (χ²/dof = {})",
            pm(self.slope, self.error),
            self.points,
            num(self.chi2)
        )
    }
}

fn fit(points: &[&Point], x: impl Fn(&Point) -> f64) -> Fit {
    let mut xs = Vec::new();
    let mut ys = Vec::new();
    let mut ws = Vec::new();
    for p in points {
        let s = p.stat("mixing_collisions");
        if p.mixed() != p.outs.len() || s.n < 2 || s.stderr.is_nan() || s.stderr <= 0.0 {
            continue;
        }
        xs.push(x(p).ln());
        ys.push(s.mean.ln());
        ws.push((s.mean / s.stderr).powi(2));
    }
    let (slope, error, intercept) = line(&xs, &ys, Some(&ws));
    let dof = xs.len() as f64 - 2.0;
    let chi2 = if dof > 0.0 {
        let residual = |i: usize| ys[i] - intercept - slope * xs[i];
        (0..xs.len())
            .map(|i| ws[i] * residual(i).powi(2))
            .sum::<f64>()
            / dof
    } else {
        f64::NAN
    };
    Fit {
        slope,
        error,
        intercept,
        points: xs.len(),
        chi2,
    }
}

pub fn write(points: &[Point], md: &mut String, figures: &mut Vec<Figure>) {
    md.push_str(INTRO);
    let _ = writeln!(
        md,
        "| point | runs | mixed | τ (mixed runs) | τ [collisions per rod] | late Y / Y_eq | max \\|ΔY\\| | hot share / (n/N) | CPU s | collisions |\n\
         |---|---|---|---|---|---|---|---|---|---|"
    );
    let mut censored = Vec::new();
    for p in points {
        let tau = p.stat("mixing_time");
        let coll = p.stat("mixing_collisions");
        let (k, n) = (p.mixed(), p.outs.len());
        let duration = p.spec.descriptor.run.duration.unwrap_or(f64::NAN);
        let tau_text = if k == 0 {
            format!("> {} (none mixed)", num(duration))
        } else if k < n {
            censored.push(label(p));
            format!("{} (censored: a lower bound)", pm(tau.mean, tau.stderr))
        } else {
            pm(tau.mean, tau.stderr)
        };
        let late = p.stat("late_concentration_ratio");
        let hot = p.stat("hot_share_ratio");
        let change = p
            .outs
            .iter()
            .filter_map(|o| o.scalar("concentration_change"))
            .fold(0.0, f64::max);
        let _ = writeln!(
            md,
            "| {} | {n} | {k}/{n} | {tau_text} | {} | {} | {} | {} | {} | {} |",
            label(p),
            if k == n {
                pm(coll.mean, coll.stderr)
            } else {
                "—".into()
            },
            pm(late.mean, late.stderr),
            num(change),
            pm(hot.mean, hot.stderr),
            num(p.cpu()),
            count(p.collisions()),
        );
    }
    md.push('\n');
    if !censored.is_empty() {
        let _ = writeln!(
            md,
            "Some but not all runs mixed within their length at: {}. Their means are of the runs that \
             did, so they are lower bounds, and these points enter no fit.\n",
            censored.join("; ")
        );
    }
    widest(points, md);
    scaling(points, md, figures);
    curves(points, md, figures);
}

/// What the widest spread says about MacKay's question: how many
/// collisions per rod one rod's energy takes to be shared.
fn widest(points: &[Point], md: &mut String) {
    let sweep = points.iter().filter(|p| p.spec.case.is_none());
    let spread = sweep
        .clone()
        .map(|p| p.first("mass_spread"))
        .fold(0.0, f64::max);
    if spread <= 0.0 {
        return;
    }
    let at: Vec<String> = sweep
        .filter(|p| p.first("mass_spread") == spread && p.mixed() == p.outs.len())
        .map(|p| {
            let s = p.stat("mixing_collisions");
            format!(
                "{} at N = {}",
                pm(s.mean, s.stderr),
                num(p.first("particles"))
            )
        })
        .collect();
    if at.is_empty() {
        return;
    }
    let _ = writeln!(
        md,
        "With the masses spread widely (ε = {}: masses 1 to {}, the range MacKay asks for in the final part), one \
         rod's energy is shared within {} collisions per rod. A run of thousands of collisions per rod samples \
         equilibrium many times over: for such masses this kind of mixing is not slow. Mixing is slow only for \
         nearly equal masses, where τ grows as ε⁻² (below); MacKay's ten rods are two groups of nearly equal \
         masses, about 1 and about 4 (the bundled case `mackay-two-groups` in the table), and the exact \
         finite-N distribution, the other explanation of his dimple, is the equilibrium study's.\n",
        num(spread),
        num(1.0 + spread),
        at.join(", ")
    );
}

/// The fitted scaling with the spread (at each N) and with N (at each
/// spread), and the chart of tau against the spread.
fn scaling(points: &[Point], md: &mut String, figures: &mut Vec<Figure>) {
    let sweep: Vec<&Point> = points.iter().filter(|p| p.spec.case.is_none()).collect();
    let mut sizes: Vec<f64> = sweep.iter().map(|p| p.first("particles")).collect();
    sizes.sort_by(f64::total_cmp);
    sizes.dedup();
    let mut spreads: Vec<f64> = sweep
        .iter()
        .map(|p| p.first("mass_spread"))
        .filter(|e| *e > 0.0)
        .collect();
    spreads.sort_by(f64::total_cmp);
    spreads.dedup();
    let mut layers = Vec::new();
    let mut text = String::new();
    for (i, &n) in sizes.iter().enumerate() {
        let at: Vec<&Point> = sweep
            .iter()
            .copied()
            .filter(|p| p.first("particles") == n && p.first("mass_spread") > 0.0)
            .collect();
        let small: Vec<&Point> = at
            .iter()
            .copied()
            .filter(|p| p.first("mass_spread") <= SMALL_SPREAD)
            .collect();
        let f = fit(&small, |p| p.first("mass_spread"));
        let (a, b) = (f.intercept, f.slope);
        let _ = writeln!(
            text,
            "- N = {}, spreads ε ≤ {SMALL_SPREAD}: τ ∝ ε^b with b = {}",
            num(n),
            f.text()
        );
        let paint = colour(i);
        let mut bars = Vec::new();
        let mut centres = Vec::new();
        for p in &at {
            let s = p.stat("mixing_collisions");
            if p.mixed() == p.outs.len() && s.n > 0 {
                let e = p.first("mass_spread");
                bars.push((e, s.mean - s.stderr, s.mean, s.mean + s.stderr));
                centres.push((e, s.mean));
            }
        }
        layers.push(Layer::ErrorBars { bars, paint });
        layers.push(Layer::Markers {
            points: centres,
            paint,
            label: Some(format!("N = {}", num(n))),
        });
        if b.is_finite() {
            let xs: Vec<f64> = small.iter().map(|p| p.first("mass_spread")).collect();
            let (lo, hi) = (
                xs.iter().copied().fold(f64::INFINITY, f64::min),
                xs.iter().copied().fold(0.0, f64::max),
            );
            layers.push(Layer::Line {
                points: [lo, hi]
                    .iter()
                    .map(|&e| (e, (a + b * e.ln()).exp()))
                    .collect(),
                paint,
                width: 1,
                dashed: true,
                label: None,
            });
        }
    }
    for &e in &spreads {
        let at: Vec<&Point> = sweep
            .iter()
            .copied()
            .filter(|p| p.first("mass_spread") == e)
            .collect();
        if at.len() < 2 {
            continue;
        }
        let _ = writeln!(
            text,
            "- ε = {}: τ [collisions per rod] ∝ N^c with c = {}",
            num(e),
            fit(&at, |p| p.first("particles")).text()
        );
    }
    md.push_str("**Fitted scaling** (weighted least squares of ln τ on the collision clock; error: one standard error from the points' error bars; nearly elastic sharing predicts b = −2):\n\n");
    md.push_str(&text);
    md.push('\n');
    let file = "mixing_time_against_spread.svg".to_string();
    let _ = writeln!(
        md,
        "![Mixing time on the collision clock against the mass spread ε, per N (mean ± standard error over the runs, fully mixed points only; dashed: the fit over ε ≤ {SMALL_SPREAD}).]({file})\n"
    );
    figures.push(Figure {
        file,
        chart: ChartSpec {
            title: "1D mixing time against the mass spread".into(),
            x_label: "mass spread ε (masses uniform in [1, 1 + ε])".into(),
            y_label: "mixing time [collisions per rod]".into(),
            x_log: true,
            y_log: true,
            layers,
        },
    });
}

/// The ensemble mean of Y against time at the largest N, one curve per
/// spread (and per case), with the equilibrium value.
fn curves(points: &[Point], md: &mut String, figures: &mut Vec<Figure>) {
    let largest = points
        .iter()
        .filter(|p| p.spec.case.is_none())
        .map(|p| p.first("particles"))
        .fold(0.0, f64::max);
    let shown: Vec<&Point> = points
        .iter()
        .filter(|p| p.spec.case.is_none() && p.first("particles") == largest)
        .collect();
    let mut layers = Vec::new();
    for (i, p) in shown.iter().enumerate() {
        let (t, mean) = p.mean_curve("energy_concentration");
        let label = format!("ε = {}", num(p.first("mass_spread")));
        layers.extend(mean_with_band(&t, &mean, colour(i), label));
    }
    let Some(first) = shown.first() else {
        return;
    };
    let (t, _) = first.mean_curve("energy_concentration");
    let eq = equilibrium_concentration(largest as usize);
    layers.push(Layer::Line {
        points: vec![
            (t.first().copied().unwrap_or(0.0), eq),
            (t.last().copied().unwrap_or(1.0), eq),
        ],
        paint: colour(6),
        width: 1,
        dashed: true,
        label: Some("equilibrium 3/(N + 2)".into()),
    });
    let file = "mixing_concentration.svg".to_string();
    let _ = writeln!(
        md,
        "![Energy concentration Y = Σ(Kᵢ/K)² against time at N = {}, ensemble mean ± standard error per mass spread; dashed: its equilibrium mean 3/(N + 2). Equal masses (ε = 0) stay at Y = 1.]({file})\n",
        num(largest)
    );
    figures.push(Figure {
        file,
        chart: ChartSpec {
            title: format!(
                "Energy concentration after a hot start, N = {}",
                num(largest)
            ),
            x_label: "time t [σ √(m/kT)]".into(),
            y_label: "Σ(Kᵢ/K)²".into(),
            x_log: false,
            y_log: true,
            layers,
        },
    });
}

const INTRO: &str = "### Rods: how long until one particle's energy is everyone's?\n\n\
> is this dimple because N=10 is too small for the large-N equilibrium theory to apply? Or is it because \
the particular random masses chosen here give a system that has a slow mixing time, so the points \
generated were not actually a good representation of the equilibrium distribution? (MacKay, Bonkers)\n\n\
> it's important that the particles should all have different masses […] But initially when developing \
your program it might be wise to check what happens in the special case where they are equal. (MacKay)\n\n\
Rods between walls start with all the kinetic energy in one of them (the hot rod, mass M), the others \
at rest; gas masses are uniform in [1, 1 + ε]. Equal masses only swap velocities at each collision, so \
the set of speeds never changes and the energy stays in one rod's worth of velocity for ever: they never \
mix. A spread ε lets each collision share a little: for nearly equal masses a collision keeps a fraction \
of order ε of the velocity difference, and the energy spreads slowly. Where the whole ensemble mixed, \
the table gives the mixing time in time units and on the collision clock (collisions per rod); runs \
that did not mix are counted, never averaged in.\n\n";
