//! The piston as a wall between two gases of disks (2D), in pictures: its
//! path and the gases' energies over the early motion with the predicted
//! paths drawn in, and each prediction against the measured frequency and
//! relaxation time. Two `[[case]]`s of the `disk-piston` preset: a heavy wall
//! between gases that collide many times per swing (the adiabatic theory's
//! case), and MacKay's eleven particles as disks, whose gases hardly collide
//! in a swing (where it breaks down).

use super::cases;
use crate::model::chart::{ChartSpec, Layer, Paint};
use crate::model::report::Figure;
use crate::stats::format::{count, num, pm};
use crate::studies::piston::pictures::{BLACK, GREY, Oscillator, PURPLE, PredictedPath, energies};
use crate::studies::piston::state::{Geometry, Samples};
use crate::theory::piston::Law;
use crate::theory::piston_equilibrium::oscillator_share;
use std::f64::consts::TAU;
use std::fmt::Write;

const ORANGE: (u8, u8, u8) = (230, 159, 0);

/// One case of the `disk-piston` preset: the `[[case]]` of this name.
struct Case {
    name: &'static str,
    title: &'static str,
}

const CASES: [Case; 2] = [
    Case {
        name: "disk-collisional",
        title: "a heavy wall, gases that collide often per swing",
    },
    Case {
        name: "disk-mackay",
        title: "MacKay's eleven particles as disks (the preset as it is)",
    },
];

/// Both cases from their runs: pictures, predictions against measurements,
/// costs. Empty if the plan has neither.
pub fn wall_cases(all: &[cases::Run], figures: &mut Vec<Figure>) -> anyhow::Result<String> {
    let present: Vec<(&Case, Vec<&cases::Run>)> = CASES
        .iter()
        .map(|c| (c, cases::runs(all, c.name)))
        .filter(|(_, runs)| !runs.is_empty())
        .collect();
    if present.is_empty() {
        return Ok(String::new());
    }
    let mut md = String::from(
        "### The piston as a wall between disks (2D)\n\n\
         The `disk-piston` preset puts MacKay's two gases into 2D: light disks (masses 0.9–1.1) left and \
         heavier ones (1.5–1.7) right of a wall that slides along x in a 40 × 40 box with hard walls, disks of \
         diameter 1. The wall spans the box, so each gas is pushed along x only. If it shares the compression \
         with its y-motion (collisions between disks), it follows the 2D adiabat, γ = 2; if its disks never \
         collide, each keeps its x-action as a rod between two walls does, and the x-motion alone is \
         compressed, γ = 3 (a frequency sqrt(3/2) = 1.22 times the adiabatic). Each case is a `[[case]]` of \
         the descriptor (the gas drawn afresh per replica), run for a few of its predicted relaxation times \
         and sampled 200 times per predicted period; predictions along each replica's measured periods (as in \
         the sweep; see How each number is measured):\n\n",
    );
    let mut rows: Vec<[String; 2]> = Vec::new();
    let mut pictures = String::new();
    for (case, runs) in &present {
        let (case_rows, case_md) = one_case(case, runs, figures)?;
        if rows.is_empty() {
            rows = case_rows
                .iter()
                .map(|r| [r.0.clone(), r.1.clone()])
                .collect();
        } else {
            for (row, r) in rows.iter_mut().zip(case_rows) {
                row[1].push_str(" | ");
                row[1].push_str(&r.1);
            }
        }
        pictures.push_str(&case_md);
    }
    let titles: Vec<&str> = present.iter().map(|(c, _)| c.title).collect();
    let _ = write!(
        md,
        "| | {} |\n|---|{}\n",
        titles.join(" | "),
        "---|".repeat(titles.len())
    );
    for [what, values] in &rows {
        let _ = writeln!(md, "| {what} | {values} |");
    }
    md.push('\n');
    md.push_str(&pictures);
    Ok(md)
}

/// One case: its table rows (label, value) and its pictures.
fn one_case(
    case: &Case,
    runs: &[&cases::Run],
    figures: &mut Vec<Figure>,
) -> anyhow::Result<(Vec<(String, String)>, String)> {
    let stat = |name: &str| cases::stat(runs, name);
    let (collisions, seconds) = cases::cost(runs);
    let n_runs = runs.len();
    let (spec0, out0) = runs[0];
    let duration = spec0.descriptor.run.duration.unwrap_or(f64::NAN);
    let piston = crate::scene::resolve(&spec0.descriptor.scene)
        .ok()
        .and_then(|s| s.piston)
        .ok_or_else(|| anyhow::anyhow!("case {} has no piston", case.name))?;

    // Pictures of replica 0.
    let scene0 = cases::start::<2>(spec0)?;
    let g0 = Geometry::of(&scene0).ok_or_else(|| anyhow::anyhow!("no piston"))?;
    let samples = Samples::of(out0).map_err(|e| anyhow::anyhow!(e))?;
    let p0 = scene0.piston.unwrap_or(0);
    let start0 = g0.system(
        samples.x[0],
        samples.piston[0],
        samples.left[0],
        samples.right[0],
        scene0.particles[p0].vel[0],
    );
    let period = TAU / start0.omega(Law::Adiabatic);
    let horizon = (5.0 * period).min(duration);
    let step = period / 2000.0;
    let paths = [
        (Law::Adiabatic, BLACK, "adiabatic, γ = 2"),
        (Law::Collisionless, ORANGE, "collisionless, γ = 3"),
        (Law::Isothermal, GREY, "isothermal, γ = 1"),
    ]
    .map(|(law, rgb, label)| (start0.trajectory(law, horizon, step), rgb, label));
    let path_name = format!("{}_path.svg", case.name.replace('-', "_"));
    path_figure(&samples, &paths, horizon, case.title, &path_name, figures)?;
    let energy_name = format!("{}_energy.svg", case.name.replace('-', "_"));
    let share = oscillator_share(
        2,
        g0.particles[0],
        g0.particles[1],
        crate::studies::piston::DRAWS,
    )
    .0;
    let energy = samples.oscillator_energy(&g0);
    let oscillator = Oscillator {
        t: &samples.t,
        energy: &energy,
        equilibrium: share * samples.total[0],
    };
    energies(
        out0,
        &oscillator,
        horizon,
        &format!("2D, {}: kinetic energies", case.title),
        &energy_name,
        figures,
    )?;
    let mut md = String::new();
    let _ = writeln!(
        md,
        "![2D, {title}: the piston's position over its first five predicted periods (purple) and the paths the adiabatic (γ = 2, black), collisionless (γ = 3, orange) and isothermal (grey) oscillators predict from the same start.]({path_name})\n",
        title = case.title
    );
    let _ = writeln!(
        md,
        "![2D, {title}: kinetic energy of the light gas (blue), the heavier gas (green) and the piston (purple); dashed: the piston's oscillator energy (kinetic + adiabatic potential) and its equilibrium level.]({energy_name})\n",
        title = case.title
    );

    let ratio = |name: &str| {
        let s = stat(name);
        pm(s.mean, s.stderr)
    };
    let measured = stat("frequency");
    let tau_measured = stat("relaxation_time");
    let rows = vec![
        (
            "piston mass M, disks a side, starting energy".into(),
            format!(
                "{}, {}, {} kT",
                num(piston.mass),
                piston
                    .per_side
                    .map_or("as the preset".into(), |n| n.to_string()),
                num(piston.energy.unwrap_or(f64::NAN))
            ),
        ),
        ("M/M_gas".into(), num(stat("mass_over_gas").mean)),
        (
            "ωτ_x (swing per x–y exchange time)".into(),
            num(stat("omega_tau").mean),
        ),
        (
            format!("**measured ω** (n of {n_runs})"),
            format!(
                "**{}** ({})",
                pm(measured.mean, measured.stderr),
                measured.n
            ),
        ),
        (
            "ω / adiabatic (γ = 2, nonlinear)".into(),
            ratio("frequency_ratio"),
        ),
        (
            "ω / adiabatic with the gases' inertia".into(),
            ratio("frequency_ratio_inertia"),
        ),
        (
            "ω / exchange theory (inertia and lag)".into(),
            ratio("frequency_ratio_exchange"),
        ),
        (
            "ω / collisionless (γ = 3)".into(),
            ratio("frequency_ratio_collisionless"),
        ),
        ("ω / isothermal".into(), ratio("frequency_ratio_isothermal")),
        (
            format!("relaxation time τ measured (n of {n_runs}) / exchange theory"),
            format!(
                "{} ({}) / {}",
                pm(tau_measured.mean, tau_measured.stderr),
                tau_measured.n,
                num(stat("relaxation_time_exchange").mean)
            ),
        ),
        (
            "cost: duration each, collisions, CPU s".into(),
            format!("{}, {}, {seconds:.2}", num(duration), count(collisions)),
        ),
    ];
    Ok((rows, md))
}

/// The piston's measured path with the predicted ones, up to `horizon`.
fn path_figure(
    samples: &Samples,
    paths: &[PredictedPath],
    horizon: f64,
    title: &str,
    name: &str,
    figures: &mut Vec<Figure>,
) -> anyhow::Result<()> {
    let mut layers = vec![Layer::Line {
        points: samples
            .t
            .iter()
            .zip(&samples.x)
            .filter(|(t, _)| **t <= horizon)
            .map(|(t, x)| (*t, *x))
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
    let chart = ChartSpec {
        title: format!("2D, {title}: the piston's position"),
        x_label: "time t".into(),
        y_label: "piston position x [σ]".into(),
        layers,
        ..Default::default()
    };
    figures.push(Figure {
        file: name.to_string(),
        chart,
    });
    Ok(())
}
