//! The 1D half of the mixing section: per point the mixing time (censored
//! points flagged), its scaling with the mass spread and with N, the
//! ensemble mean of the energy concentration against time.

use super::section::{Point, all_mixed, distinct, mixed, named, tau_text};
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::line::line;
use crate::stats::named::named as sentence;
use crate::stats::table::table_row;
use crate::studies::curves::{bar, figure, mean_with_band, measured, polyline, show};
use crate::theory::mixing::equilibrium_concentration;

const TEXT: &str = include_str!("rods.md");
pub(super) const WIDEST: &str = include_str!("widest.md");
/// The findings' sentences, one per outcome (the disks' too).
pub(super) const SENTENCES: &str = include_str!("sentences.md");

/// The scaling with the mass spread is fitted over spreads up to this
/// (small spreads: each collision moves a fraction ~ epsilon^2 of the energy
/// difference, so tau ~ epsilon^-2 is expected there, not at MacKay's 1 to 9).
pub const SMALL_SPREAD: f64 = 0.5;

/// A run that holds this many mixing times samples equilibrium many times
/// over.
const MANY: f64 = 10.0;

/// A point's name: its values of the results named, each after its symbol.
pub(super) fn label_of(p: &Point, values: &[(&str, &str)]) -> String {
    let values = values
        .iter()
        .map(|(symbol, r)| format!("{symbol} = {}", num(p.first(r))));
    named(p, values.collect::<Vec<_>>().join(", "))
}

fn label(p: &Point) -> String {
    label_of(
        p,
        &[
            ("N", "particles"),
            ("ε", "mass_spread"),
            ("M/m̄", "hot_mass_ratio"),
        ],
    )
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
    let (mut xs, mut ys, mut ws) = (Vec::new(), Vec::new(), Vec::new());
    for p in points {
        let s = p.stat("mixing_collisions");
        if !all_mixed(p) || s.n < 2 || s.stderr.is_nan() || s.stderr <= 0.0 {
            continue;
        }
        xs.push(x(p).ln());
        ys.push(s.mean.ln());
        ws.push((s.mean / s.stderr).powi(2));
    }
    let (slope, error, intercept) = line(&xs, &ys, Some(&ws));
    let residual = |i: usize| ys[i] - intercept - slope * xs[i];
    let chi2: f64 = (0..xs.len()).map(|i| ws[i] * residual(i).powi(2)).sum();
    let dof = xs.len() as f64 - 2.0;
    Fit {
        slope,
        error,
        intercept,
        points: xs.len(),
        chi2: if dof > 0.0 { chi2 / dof } else { f64::NAN },
    }
}

pub fn part(points: &[Point], figures: &mut Vec<Figure>) -> String {
    let mut rows = String::new();
    let mut censored = Vec::new();
    for p in points {
        let coll = p.stat("mixing_collisions");
        let (k, n) = (mixed(p), p.outs.len());
        if k > 0 && k < n {
            censored.push(label(p));
        }
        let late = p.stat("late_concentration_ratio");
        let hot = p.stat("hot_share_ratio");
        let change = p
            .outs
            .iter()
            .filter_map(|o| o.scalar("concentration_change"))
            .fold(0.0, f64::max);
        rows.push_str(&table_row(&[
            label(p),
            n.to_string(),
            format!("{k}/{n}"),
            tau_text(p),
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
        ]));
    }
    let censored = match censored.is_empty() {
        true => String::new(),
        false => {
            fill(
                sentence(SENTENCES, "censored"),
                &[("at", censored.join("; "))],
            ) + "\n\n"
        }
    };
    let (fits, mut shown) = scaling(points, figures);
    shown.push_str(&curves(points, figures));
    fill(
        TEXT,
        &[
            ("rows", rows),
            ("censored", censored),
            ("widest", widest(points)),
            ("fits", fits),
            ("figures", shown),
        ],
    )
}

/// What the widest spread says about MacKay's question: how many
/// collisions per rod one rod's energy takes to be shared, and how many
/// such times a run holds.
fn widest(points: &[Point]) -> String {
    let sweep = points.iter().filter(|p| p.spec.case.is_none());
    let spread = sweep
        .clone()
        .map(|p| p.first("mass_spread"))
        .fold(0.0, f64::max);
    let at: Vec<&Point> = sweep
        .filter(|p| p.first("mass_spread") == spread && all_mixed(p))
        .collect();
    if spread <= 0.0 || at.is_empty() {
        return String::new();
    }
    let times: Vec<String> = at
        .iter()
        .map(|p| {
            let s = p.stat("mixing_collisions");
            let n = num(p.first("particles"));
            format!("{} at N = {n}", pm(s.mean, s.stderr))
        })
        .collect();
    // A run's length on the same clock: collisions per rod.
    let length = |p: &Point| {
        p.spec.descriptor.run.duration.unwrap_or(f64::NAN) * p.stat("collision_rate").mean
    };
    let held = at
        .iter()
        .map(|p| length(p) / p.stat("mixing_collisions").mean)
        .fold(f64::INFINITY, f64::min);
    let shortest = at.iter().map(|p| length(p)).fold(f64::INFINITY, f64::min);
    let verdict = match held >= MANY {
        true => fill(
            sentence(SENTENCES, "many"),
            &[
                ("length", num(shortest.round())),
                ("held", num(held.floor())),
            ],
        ),
        false => fill(
            sentence(SENTENCES, "few"),
            &[("held", num(held)), ("many", MANY.to_string())],
        ),
    };
    fill(
        WIDEST,
        &[
            ("spread", num(spread)),
            ("heaviest", num(1.0 + spread)),
            ("times", times.join(", ")),
            ("verdict", verdict),
        ],
    )
}

/// The fitted scaling with the spread (at each N) and with N (at each
/// spread) as a list, and the chart of tau against the spread.
fn scaling(points: &[Point], figures: &mut Vec<Figure>) -> (String, String) {
    let sweep: Vec<&Point> = points.iter().filter(|p| p.spec.case.is_none()).collect();
    let spread = |p: &Point| p.first("mass_spread");
    let mut layers = Vec::new();
    let mut text = String::new();
    for (i, &n) in distinct(sweep.iter().copied(), "particles")
        .iter()
        .enumerate()
    {
        let at: Vec<&Point> = sweep
            .iter()
            .copied()
            .filter(|p| p.first("particles") == n && spread(p) > 0.0)
            .collect();
        let small: Vec<&Point> = at
            .iter()
            .copied()
            .filter(|p| spread(p) <= SMALL_SPREAD)
            .collect();
        let f = fit(&small, spread);
        let (a, b) = (f.intercept, f.slope);
        let elastic = match (b + 2.0) / f.error {
            z if z.abs() < 4.0 => format!("; agrees with −2, z = {z:+.1}"),
            z if z.is_finite() => format!("; differs from −2, z = {z:+.1}"),
            _ => String::new(),
        };
        text.push_str(&format!(
            "- N = {}, spreads ε ≤ {SMALL_SPREAD}: τ ∝ ε^b with b = {}{elastic}\n",
            num(n),
            f.text()
        ));
        let mixed = at
            .iter()
            .filter(|p| all_mixed(p))
            .map(|p| (spread(p), p.stat("mixing_collisions")))
            .filter(|(_, s)| s.n > 0)
            .map(|(x, s)| bar(x, &s));
        layers.extend(measured(mixed, colour(i), &format!("N = {}", num(n))));
        if b.is_finite() {
            let xs: Vec<f64> = small.iter().map(|p| spread(p)).collect();
            let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = xs.iter().copied().fold(0.0, f64::max);
            let ends = [lo, hi].map(|e| (e, (a + b * e.ln()).exp()));
            layers.push(polyline(ends.to_vec(), colour(i), 1, true, None));
        }
    }
    for e in distinct(sweep.iter().copied(), "mass_spread") {
        let at: Vec<&Point> = sweep.iter().copied().filter(|p| spread(p) == e).collect();
        if e <= 0.0 || at.len() < 2 {
            continue;
        }
        text.push_str(&format!(
            "- ε = {}: τ [collisions per rod] ∝ N^c with c = {}\n",
            num(e),
            fit(&at, |p| p.first("particles")).text()
        ));
    }
    let figure = figure(
        "mixing_time_against_spread.svg",
        (
            "1D mixing time against the mass spread".into(),
            "mass spread ε (masses uniform in [1, 1 + ε])",
            "mixing time [collisions per rod]",
        ),
        (true, true),
        layers,
    );
    let caption = format!(
        "Mixing time on the collision clock against the mass spread ε, per N (mean ± standard error over the runs, fully mixed points only; dashed: the fit over ε ≤ {SMALL_SPREAD})."
    );
    (text, show(figures, figure, &caption))
}

/// The ensemble mean of Y against time at the largest N, one curve per
/// spread, with the equilibrium value.
fn curves(points: &[Point], figures: &mut Vec<Figure>) -> String {
    let sweep = points.iter().filter(|p| p.spec.case.is_none());
    let largest = sweep
        .clone()
        .map(|p| p.first("particles"))
        .fold(0.0, f64::max);
    let shown: Vec<&Point> = sweep.filter(|p| p.first("particles") == largest).collect();
    let mut layers = Vec::new();
    for (i, p) in shown.iter().enumerate() {
        let (t, mean) = p.mean_curve("energy_concentration");
        let label = format!("ε = {}", num(p.first("mass_spread")));
        layers.extend(mean_with_band(&t, &mean, colour(i), label));
    }
    let Some(first) = shown.first() else {
        return String::new();
    };
    let (t, _) = first.mean_curve("energy_concentration");
    let eq = equilibrium_concentration(largest as usize);
    let ends = [
        t.first().copied().unwrap_or(0.0),
        t.last().copied().unwrap_or(1.0),
    ];
    let (level, label) = (ends.map(|t| (t, eq)), Some("equilibrium 3/(N + 2)".into()));
    layers.push(polyline(level.to_vec(), colour(6), 1, true, label));
    let n = num(largest);
    let figure = figure(
        "mixing_concentration.svg",
        (
            format!("Energy concentration after a hot start, N = {n}"),
            "time t [σ √(m/kT)]",
            "Σ(Kᵢ/K)²",
        ),
        (false, true),
        layers,
    );
    let caption = format!(
        "Energy concentration Y = Σ(Kᵢ/K)² against time at N = {n}, ensemble mean ± standard error per mass spread; dashed: its equilibrium mean 3/(N + 2). Equal masses (ε = 0) stay at Y = 1."
    );
    show(figures, figure, &caption)
}

#[cfg(test)]
mod tests {
    /// Every outcome the halves name has its sentence.
    #[test]
    fn every_sentence_is_there() {
        let names: Vec<&str> = crate::stats::named::names(super::SENTENCES).collect();
        assert_eq!(
            names,
            ["censored", "many", "few", "agree", "above", "below"]
        );
    }
}
