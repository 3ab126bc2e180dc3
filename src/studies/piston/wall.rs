//! The piston as a wall between two gases of disks (2D), in pictures: its
//! path and the gases' energies over the early motion with the predicted
//! paths drawn in, and each prediction against the measured frequency and
//! relaxation time. Two `[[case]]`s of the `disk-piston` preset: a heavy wall
//! between gases that collide many times per swing (the adiabatic theory's
//! case), and MacKay's eleven particles as disks, whose gases hardly collide
//! in a swing.

use super::cases::{self, First};
use super::pictures::{BLACK, GREY, PURPLE, PredictedPath, energies};
use crate::model::chart::{ChartSpec, Layer, Paint};
use crate::model::report::Figure;
use crate::stats::format::{count, num, pm};
use crate::theory::piston::Law;
use std::f64::consts::TAU;
use std::fmt::Write;

const ORANGE: (u8, u8, u8) = (230, 159, 0);

const INTRO: &str = include_str!("text/wall.md");

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

/// The frequency ratios the table shows, by label.
const RATIOS: [(&str, &str); 5] = [
    ("ω / adiabatic (γ = 2, nonlinear)", "frequency_ratio"),
    (
        "ω / adiabatic with the gases' inertia",
        "frequency_ratio_inertia",
    ),
    (
        "ω / exchange theory (inertia and lag)",
        "frequency_ratio_exchange",
    ),
    ("ω / collisionless (γ = 3)", "frequency_ratio_collisionless"),
    ("ω / isothermal", "frequency_ratio_isothermal"),
];

/// Both cases from their runs: pictures, predictions against measurements,
/// costs, one column per case. Empty if the plan has neither.
pub fn wall_cases(all: &[cases::Run], figures: &mut Vec<Figure>) -> anyhow::Result<String> {
    let mut titles = Vec::new();
    let mut columns = Vec::new();
    let mut pictures = String::new();
    for (name, title) in CASES {
        let runs = cases::runs(all, name);
        if runs.is_empty() {
            continue;
        }
        columns.push(table_rows(name, &runs)?);
        pictures.push_str(&case_pictures(name, title, runs[0], figures)?);
        titles.push(title);
    }
    let Some(first) = columns.first() else {
        return Ok(String::new());
    };
    let mut md = INTRO.to_string();
    let _ = write!(
        md,
        "| | {} |\n|---|{}\n",
        titles.join(" | "),
        "---|".repeat(titles.len())
    );
    for (k, (what, _)) in first.iter().enumerate() {
        let values: Vec<&str> = columns.iter().map(|c| c[k].1.as_str()).collect();
        let _ = writeln!(md, "| {what} | {} |", values.join(" | "));
    }
    md.push('\n');
    md.push_str(&pictures);
    Ok(md)
}

/// One case's column of the table: (label, value) rows.
fn table_rows(name: &str, runs: &[&cases::Run]) -> anyhow::Result<Vec<(String, String)>> {
    let stat = |name: &str| cases::stat(runs, name);
    let ratio = |name: &str| pm(stat(name).mean, stat(name).stderr);
    let (collisions, seconds) = cases::cost(runs);
    let n_runs = runs.len();
    let spec = &runs[0].0;
    let duration = spec.descriptor.run.duration.unwrap_or(f64::NAN);
    let piston = crate::scene::resolve(&spec.descriptor.scene)
        .ok()
        .and_then(|s| s.piston)
        .ok_or_else(|| anyhow::anyhow!("case {name} has no piston"))?;
    let per_side = piston
        .per_side
        .map_or("as the preset".into(), |n| n.to_string());
    let energy = num(piston.energy.unwrap_or(f64::NAN));
    let (omega, tau) = (stat("frequency"), stat("relaxation_time"));
    let tau_exchange = num(stat("relaxation_time_exchange").mean);
    let ratios = RATIOS.map(|(label, name)| (label.to_string(), ratio(name)));
    let mut rows = vec![
        (
            "piston mass M, disks a side, starting energy".into(),
            format!("{}, {per_side}, {energy} kT", num(piston.mass)),
        ),
        ("M/M_gas".into(), num(stat("mass_over_gas").mean)),
        (
            "ωτ_x (swing per x–y exchange time)".into(),
            num(stat("omega_tau").mean),
        ),
        (
            format!("**measured ω** (n of {n_runs})"),
            format!("**{}** ({})", pm(omega.mean, omega.stderr), omega.n),
        ),
        (
            format!("relaxation time τ measured (n of {n_runs}) / exchange theory"),
            format!("{} ({}) / {tau_exchange}", pm(tau.mean, tau.stderr), tau.n),
        ),
        (
            "cost: duration each, collisions, CPU s".into(),
            format!("{}, {}, {seconds:.2}", num(duration), count(collisions)),
        ),
    ];
    rows.splice(4..4, ratios);
    Ok(rows)
}

/// The first replica's path and energies over five predicted periods.
fn case_pictures(
    name: &str,
    title: &str,
    run: &cases::Run,
    figures: &mut Vec<Figure>,
) -> anyhow::Result<String> {
    let first = First::<2>::of(run)?;
    let duration = run.0.descriptor.run.duration.unwrap_or(f64::NAN);
    let period = TAU / first.start.omega(Law::Adiabatic);
    let horizon = (5.0 * period).min(duration);
    let step = period / 2000.0;
    let paths = [
        (Law::Adiabatic, BLACK, "adiabatic, γ = 2"),
        (Law::Collisionless, ORANGE, "collisionless, γ = 3"),
        (Law::Isothermal, GREY, "isothermal, γ = 1"),
    ]
    .map(|(law, rgb, label)| (first.start.trajectory(law, horizon, step), rgb, label));
    let file = name.replace('-', "_");
    let (path_name, energy_name) = (format!("{file}_path.svg"), format!("{file}_energy.svg"));
    path_figure(&first, &paths, horizon, title, &path_name, figures);
    let energy_title = format!("2D, {title}: kinetic energies");
    energies(&first, horizon, &energy_title, &energy_name, figures);
    Ok(format!(
        "![2D, {title}: the piston's position over its first five predicted periods (purple) and the paths the adiabatic (γ = 2, black), collisionless (γ = 3, orange) and isothermal (grey) oscillators predict from the same start.]({path_name})\n\n\
         ![2D, {title}: kinetic energy of the light gas (blue), the heavier gas (green) and the piston (purple); dashed: the piston's oscillator energy (kinetic + adiabatic potential) and its equilibrium level.]({energy_name})\n\n"
    ))
}

/// The piston's measured path with the predicted ones, up to `horizon`.
fn path_figure(
    first: &First<2>,
    paths: &[PredictedPath],
    horizon: f64,
    title: &str,
    name: &str,
    figures: &mut Vec<Figure>,
) {
    let s = &first.samples;
    let mut layers = vec![Layer::Line {
        points: (s.t.iter().zip(&s.x))
            .filter_map(|(t, x)| (*t <= horizon).then_some((*t, *x)))
            .collect(),
        paint: Paint::solid(PURPLE),
        width: 3,
        dashed: false,
        label: Some("piston (simulated)".into()),
    }];
    for (path, rgb, label) in paths {
        layers.push(Layer::Line {
            points: path.clone(),
            paint: Paint::solid(*rgb),
            width: 2,
            dashed: true,
            label: Some(label.to_string()),
        });
    }
    figures.push(Figure {
        file: name.to_string(),
        chart: ChartSpec {
            title: format!("2D, {title}: the piston's position"),
            x_label: "time t".into(),
            y_label: "piston position x [σ]".into(),
            layers,
            ..Default::default()
        },
    });
}
