//! The piston as a wall between two gases of disks (2D), in pictures: its
//! path and the gases' energies over the early motion with the predicted
//! paths drawn in, and each prediction against the measured frequency and
//! relaxation time. Two `[[case]]`s of the `disk-piston` preset: a heavy wall
//! between gases that collide many times per swing (the adiabatic theory's
//! case), and MacKay's eleven particles as disks, whose gases hardly collide
//! in a swing.

use super::CAPTIONS;
use super::cases::{self, First};
use super::pictures::{BLACK, GREY, PURPLE, energies};
use crate::model::chart::Paint;
use crate::model::report::Figure;
use crate::stats::ensemble::Runs;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::named::named;
use crate::stats::point_runs::PointRuns;
use crate::stats::summary::Stats;
use crate::studies::curves::{figure, polyline, show};
use crate::theory::piston::Law;
use std::f64::consts::TAU;
use std::fmt::Write;

const ORANGE: (u8, u8, u8) = (230, 159, 0);

const INTRO: &str = include_str!("text/wall.md");
/// The labels of the table's rows, one a line.
const ROWS: &str = include_str!("text/wall_rows.md");

/// The `[[case]]`s of the `disk-piston` preset, by name, with their titles.
const CASES: [(&str, &str); 2] = [
    (
        "disk-collisional",
        "a heavy wall, gases that collide often per swing",
    ),
    (
        "disk-mackay",
        "MacKay's eleven particles as disks (the preset as it is)",
    ),
];

/// The frequency ratios the table shows, in its order.
const RATIOS: [&str; 5] = [
    "frequency_ratio",
    "frequency_ratio_inertia",
    "frequency_ratio_exchange",
    "frequency_ratio_collisionless",
    "frequency_ratio_isothermal",
];

/// Both cases from their runs: pictures, predictions against measurements,
/// costs, one column per case. Empty if the plan has neither.
pub fn wall_cases(all: &Runs, figures: &mut Vec<Figure>) -> anyhow::Result<String> {
    let (mut titles, mut columns, mut pictures) = (Vec::new(), Vec::new(), String::new());
    for (name, title) in CASES {
        let Some(case) = cases::case(all, name) else {
            continue;
        };
        columns.push(table_rows(name, &case)?);
        pictures += &case_pictures(name, title, &case, figures)?;
        titles.push(title);
    }
    let Some(first) = columns.first() else {
        return Ok(String::new());
    };
    let mut md = INTRO.to_string();
    let rule = "---|".repeat(titles.len());
    let _ = write!(md, "| | {} |\n|---|{rule}\n", titles.join(" | "));
    for (k, (what, _)) in first.iter().enumerate() {
        let values: Vec<&str> = columns.iter().map(|c| c[k].1.as_str()).collect();
        let _ = writeln!(md, "| {what} | {} |", values.join(" | "));
    }
    Ok(md + "\n" + &pictures)
}

/// One case's column of the table: (label, value) rows.
fn table_rows(name: &str, case: &PointRuns) -> anyhow::Result<Vec<(String, String)>> {
    let stat = |name: &str| case.stat(name);
    let both = |s: &Stats| pm(s.mean, s.stderr);
    let duration = case.spec.descriptor.run.duration.unwrap_or(f64::NAN);
    let piston = (case.scene().and_then(|s| s.piston))
        .ok_or_else(|| anyhow::anyhow!("case {name} has no piston"))?;
    let per_side = (piston.per_side).map_or("as the preset".into(), |n| n.to_string());
    let energy = num(piston.energy.unwrap_or(f64::NAN));
    let (omega, tau) = (stat("frequency"), stat("relaxation_time"));
    let tau_exchange = num(stat("relaxation_time_exchange").mean);
    let mut values = vec![
        format!("{}, {per_side}, {energy} kT", num(piston.mass)),
        num(stat("mass_over_gas").mean),
        num(stat("omega_tau").mean),
        format!("**{}** ({})", both(&omega), omega.n),
    ];
    values.extend(RATIOS.map(|name| both(&stat(name))));
    values.push(format!("{} ({}) / {tau_exchange}", both(&tau), tau.n));
    let (collisions, seconds) = (count(case.collisions()), case.cpu());
    values.push(format!("{}, {collisions}, {seconds:.2}", num(duration)));
    let n_runs = [("n_runs", case.outs.len().to_string())];
    Ok(ROWS.lines().map(|l| fill(l, &n_runs)).zip(values).collect())
}

/// The first replica's path and energies over five predicted periods, the
/// path beside those the laws predict from its start.
fn case_pictures(
    name: &str,
    title: &str,
    case: &PointRuns,
    figures: &mut Vec<Figure>,
) -> anyhow::Result<String> {
    let first = First::<2>::of(case)?;
    let duration = case.spec.descriptor.run.duration.unwrap_or(f64::NAN);
    let period = TAU / first.start.omega(Law::Adiabatic);
    let horizon = (5.0 * period).min(duration);
    let s = &first.samples;
    let before = |(t, x): (&f64, &f64)| (*t <= horizon).then_some((*t, *x));
    let simulated = s.t.iter().zip(&s.x).filter_map(before).collect();
    let label = Some("piston (simulated)".into());
    let mut layers = vec![polyline(simulated, Paint::solid(PURPLE), 3, false, label)];
    for (law, rgb, label) in [
        (Law::Adiabatic, BLACK, "adiabatic, γ = 2"),
        (Law::Collisionless, ORANGE, "collisionless, γ = 3"),
        (Law::Isothermal, GREY, "isothermal, γ = 1"),
    ] {
        let path = first.start.trajectory(law, horizon, period / 2000.0);
        layers.push(polyline(
            path,
            Paint::solid(rgb),
            2,
            true,
            Some(label.into()),
        ));
    }
    let heading = format!("2D, {title}: the piston's position");
    let labels = (heading, "time t", "piston position x [σ]");
    let file = name.replace('-', "_");
    let path = figure(&format!("{file}_path.svg"), labels, (false, false), layers);
    let (heading, file) = (
        format!("2D, {title}: kinetic energies"),
        format!("{file}_energy.svg"),
    );
    let energy = energies(&first, horizon, heading, &file);
    let caption = |name| fill(named(CAPTIONS, name), &[("title", title.to_string())]);
    let md = show(figures, path, &caption("wall_path"));
    Ok(md + &show(figures, energy, &caption("wall_energy")))
}
