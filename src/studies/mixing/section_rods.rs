//! The 1D half of the mixing section: per point the mixing time (censored
//! points flagged), its scaling with the mass spread and with N, the
//! ensemble mean of the energy concentration against time.

use super::section::{Point, SENTENCES, all_mixed, distinct, label, mixed, tau_text};
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::named::named as sentence;
use crate::stats::power_law::{PowerLaw, log_point};
use crate::stats::table::table_row;
use crate::studies::curves::{bar, figure, mean_with_band, measured, polyline, show};
use crate::studies::parts::stat_pm;
use crate::theory::mixing::equilibrium_concentration;

const TEXT: &str = include_str!("rods.md");
pub(super) const WIDEST: &str = include_str!("widest.md");

/// The scaling with the mass spread is fitted over spreads up to this
/// (small spreads: each collision moves a fraction ~ epsilon^2 of the energy
/// difference, so tau ~ epsilon^-2 is expected there, not at MacKay's 1 to 9).
pub const SMALL_SPREAD: f64 = 0.5;

/// A run that holds this many mixing times samples equilibrium many times
/// over.
const MANY: f64 = 10.0;

/// What names a 1D point: its size, mass spread and hot rod's mass.
const LABEL: [(&str, &str); 3] = [
    ("N", "particles"),
    ("ε", "mass_spread"),
    ("M/m̄", "hot_mass_ratio"),
];

/// A power law of tau (collision clock) in x over the fully mixed points,
/// weighted by their error bars, and its text.
fn fit(points: &[&Point], x: impl Fn(&Point) -> f64) -> (PowerLaw, String) {
    let logs: Vec<_> = (points.iter().filter(|p| all_mixed(p)))
        .filter_map(|p| log_point(x(p), &p.stat("mixing_collisions")))
        .collect();
    let f = PowerLaw::fit(&logs, 2);
    let (b, chi2) = (pm(f.exponent, f.error), num(f.chi2_per_dof()));
    (
        f,
        format!("{b} over {} fully mixed points (χ²/dof = {chi2})", f.points),
    )
}

pub fn part(points: &[Point], figures: &mut Vec<Figure>) -> String {
    let mut rows = String::new();
    let mut censored = Vec::new();
    for p in points {
        let (k, n) = (mixed(p), p.outs.len());
        if k > 0 && k < n {
            censored.push(label(p, &LABEL));
        }
        let change = (p.outs.iter())
            .filter_map(|o| o.scalar("concentration_change"))
            .fold(0.0, f64::max);
        let per_rod = match k == n {
            true => stat_pm(p, "mixing_collisions"),
            false => "—".into(),
        };
        rows.push_str(&table_row(&[
            label(p, &LABEL),
            n.to_string(),
            format!("{k}/{n}"),
            tau_text(p),
            per_rod,
            stat_pm(p, "late_concentration_ratio"),
            num(change),
            stat_pm(p, "hot_share_ratio"),
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
    let spread = (sweep.clone().map(|p| p.first("mass_spread"))).fold(0.0, f64::max);
    let at: Vec<&Point> = sweep
        .filter(|p| p.first("mass_spread") == spread && all_mixed(p))
        .collect();
    if spread <= 0.0 || at.is_empty() {
        return String::new();
    }
    let times: Vec<String> = (at.iter())
        .map(|p| {
            format!(
                "{} at N = {}",
                stat_pm(p, "mixing_collisions"),
                num(p.first("particles"))
            )
        })
        .collect();
    // A run's length on the same clock: collisions per rod.
    let length = |p: &Point| {
        p.spec.descriptor.run.duration.unwrap_or(f64::NAN) * p.stat("collision_rate").mean
    };
    let held = (at.iter())
        .map(|p| length(p) / p.stat("mixing_collisions").mean)
        .fold(f64::INFINITY, f64::min);
    let shortest = at.iter().map(|p| length(p)).fold(f64::INFINITY, f64::min);
    let values = [
        ("length", num(shortest.round())),
        ("at_least", num(held.floor())),
        ("held", num(held)),
        ("many", MANY.to_string()),
    ];
    let verdict = sentence(SENTENCES, if held >= MANY { "many" } else { "few" });
    fill(
        WIDEST,
        &[
            ("spread", num(spread)),
            ("heaviest", num(1.0 + spread)),
            ("times", times.join(", ")),
            ("verdict", fill(verdict, &values)),
        ],
    )
}

/// The fitted scaling with the spread (at each N) and with N (at each
/// spread) as a list, and the chart of tau against the spread.
fn scaling(points: &[Point], figures: &mut Vec<Figure>) -> (String, String) {
    let sweep: Vec<&Point> = points.iter().filter(|p| p.spec.case.is_none()).collect();
    let spread = |p: &Point| p.first("mass_spread");
    let (mut layers, mut text) = (Vec::new(), String::new());
    for (i, &n) in distinct(sweep.iter().copied(), "particles")
        .iter()
        .enumerate()
    {
        let at: Vec<&Point> = (sweep.iter().copied())
            .filter(|p| p.first("particles") == n && spread(p) > 0.0)
            .collect();
        let small: Vec<&Point> = (at.iter().copied())
            .filter(|p| spread(p) <= SMALL_SPREAD)
            .collect();
        let (f, fitted) = fit(&small, spread);
        let elastic = match (f.exponent + 2.0) / f.error {
            z if z.abs() < 4.0 => format!("; agrees with −2, z = {z:+.1}"),
            z if z.is_finite() => format!("; differs from −2, z = {z:+.1}"),
            _ => String::new(),
        };
        let n = num(n);
        text.push_str(&format!(
            "- N = {n}, spreads ε ≤ {SMALL_SPREAD}: τ ∝ ε^b with b = {fitted}{elastic}\n"
        ));
        let mixed = (at.iter().filter(|p| all_mixed(p)))
            .map(|p| (spread(p), p.stat("mixing_collisions")))
            .filter(|(_, s)| s.n > 0)
            .map(|(x, s)| bar(x, &s));
        layers.extend(measured(mixed, colour(i), &format!("N = {n}")));
        if f.exponent.is_finite() {
            let xs = small.iter().map(|p| spread(p));
            let ends = [
                xs.clone().fold(f64::INFINITY, f64::min),
                xs.fold(0.0, f64::max),
            ];
            let line = ends.map(|e| (e, f.at(e))).to_vec();
            layers.push(polyline(line, colour(i), 1, true, None));
        }
    }
    for e in distinct(sweep.iter().copied(), "mass_spread") {
        let at: Vec<&Point> = sweep.iter().copied().filter(|p| spread(p) == e).collect();
        if e > 0.0 && at.len() >= 2 {
            let (_, fitted) = fit(&at, |p| p.first("particles"));
            let e = num(e);
            text.push_str(&format!(
                "- ε = {e}: τ [collisions per rod] ∝ N^c with c = {fitted}\n"
            ));
        }
    }
    let labels = (
        "1D mixing time against the mass spread".into(),
        "mass spread ε (masses uniform in [1, 1 + ε])",
        "mixing time [collisions per rod]",
    );
    let figure = figure(
        "mixing_time_against_spread.svg",
        labels,
        (true, true),
        layers,
    );
    let small = [("small", SMALL_SPREAD.to_string())];
    let caption = fill(sentence(SENTENCES, "spread"), &small);
    (text, show(figures, figure, &caption))
}

/// The ensemble mean of Y against time at the largest N, one curve per
/// spread, with the equilibrium value.
fn curves(points: &[Point], figures: &mut Vec<Figure>) -> String {
    let sweep = points.iter().filter(|p| p.spec.case.is_none());
    let largest = (sweep.clone().map(|p| p.first("particles"))).fold(0.0, f64::max);
    let shown: Vec<&Point> = sweep.filter(|p| p.first("particles") == largest).collect();
    let Some(first) = shown.first() else {
        return String::new();
    };
    let mut layers = Vec::new();
    for (i, p) in shown.iter().enumerate() {
        let (t, mean) = p.mean_curve("energy_concentration");
        let label = format!("ε = {}", num(p.first("mass_spread")));
        layers.extend(mean_with_band(&t, &mean, colour(i), label));
    }
    let (t, _) = first.mean_curve("energy_concentration");
    let eq = equilibrium_concentration(largest as usize);
    let ends = [
        t.first().copied().unwrap_or(0.0),
        t.last().copied().unwrap_or(1.0),
    ];
    let label = Some("equilibrium 3/(N + 2)".into());
    layers.push(polyline(
        ends.map(|t| (t, eq)).to_vec(),
        colour(6),
        1,
        true,
        label,
    ));
    let n = num(largest);
    let labels = (
        format!("Energy concentration after a hot start, N = {n}"),
        "time t [σ √(m/kT)]",
        "Σ(Kᵢ/K)²",
    );
    let figure = figure("mixing_concentration.svg", labels, (false, true), layers);
    let caption = fill(sentence(SENTENCES, "concentration"), &[("n", n)]);
    show(figures, figure, &caption)
}
