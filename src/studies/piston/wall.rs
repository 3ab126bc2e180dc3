//! The piston as a wall between two gases of disks (2D), in pictures: its
//! path and the gases' energies over the early motion with the predicted
//! paths drawn in, and each prediction against the measured frequency and
//! relaxation time. Two cases of the `disk-piston` preset: a heavy wall
//! between gases that collide many times per swing (the adiabatic theory's
//! case), and MacKay's eleven particles as disks, whose gases hardly collide
//! in a swing (where it breaks down).

use crate::descriptor::load::parse;
use crate::model::chart::{ChartSpec, Layer, Paint};
use crate::model::descriptor::Descriptor;
use crate::model::report::Figure;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::runner::seeds::{fnv1a, run_seed};
use crate::stats::format::{count, num, pm};
use crate::stats::summary::Stats;
use crate::studies::piston::Options;
use crate::studies::piston::pictures::{BLACK, GREY, Oscillator, PURPLE, PredictedPath, energies};
use crate::studies::piston::state::{Geometry, Samples};
use crate::theory::piston::Law;
use crate::theory::piston_equilibrium::oscillator_share;
use rand::SeedableRng;
use std::f64::consts::TAU;
use std::fmt::Write;

const ORANGE: (u8, u8, u8) = (230, 120, 20);
const REPLICAS: u32 = 16;

/// One case: the preset with these piston settings.
struct Case {
    tag: &'static str,
    title: &'static str,
    mass: f64,
    per_side: usize,
    energy: f64,
}

const CASES: [Case; 2] = [
    Case {
        tag: "collisional",
        title: "a heavy wall, gases that collide often per swing",
        mass: 3162.0,
        per_side: 20,
        energy: 10.0,
    },
    Case {
        tag: "mackay",
        title: "MacKay's eleven particles as disks (the preset as it is)",
        mass: 40.0,
        per_side: 5,
        energy: 10.0,
    },
];

/// The case's descriptor: the preset with its piston, run for `duration`.
fn descriptor(
    case: &Case,
    o: &Options,
    duration: f64,
    sample_every: f64,
) -> anyhow::Result<Descriptor> {
    let text = format!(
        "[study]\nname = \"disk-piston-{tag}\"\nreplicas = {REPLICAS}\nseed = 1\n\n\
         [scene]\npreset = \"disk-piston\"\n\
         piston = {{ mass = {mass:?}, position = 0.5, radius = 0.0, energy = {energy:?}, per_side = {n} }}\n\n\
         [run]\nduration = {duration:?}\nsample_every = {sample_every:?}\n\n\
         [analysis.piston]\nwindow_periods = {periods}\nband = {band:?}\nlate_fraction = {late:?}\n",
        tag = case.tag,
        mass = case.mass,
        energy = case.energy,
        n = case.per_side,
        periods = o.periods,
        band = o.band,
        late = o.late,
    );
    parse(case.tag, &text)
        .map(|l| l.descriptor)
        .map_err(|e| anyhow::anyhow!("{e}"))
}

/// The scene of a run as built (its geometry and the piston's first velocity).
fn built(spec: &RunSpec) -> anyhow::Result<crate::scene::Built<2>> {
    let scene = crate::scene::resolve(&spec.descriptor.scene).map_err(|e| anyhow::anyhow!(e))?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(spec.seed);
    crate::scene::build::<2>(&scene, &mut rng).map_err(|e| anyhow::anyhow!(e))
}

/// Both cases: pictures, predictions against measurements, costs.
pub fn wall_cases(d: &Descriptor, figures: &mut Vec<Figure>) -> anyhow::Result<String> {
    let o = Options::of(d);
    let mut md = String::from(
        "### The piston as a wall between disks (2D)\n\n\
         The `disk-piston` preset puts MacKay's two gases into 2D: light disks (masses 0.9–1.1) left and \
         heavier ones (1.5–1.7) right of a wall that slides along x in a 40 × 40 box with hard walls, disks of \
         diameter 1. The wall spans the box, so each gas is pushed along x only. If it shares the compression \
         with its y-motion (collisions between disks), it follows the 2D adiabat, γ = 2; if its disks never \
         collide, each keeps its x-action as a rod between two walls does, and the x-motion alone is \
         compressed, γ = 3 (a frequency sqrt(3/2) = 1.22 times the adiabatic). Two cases, each \
         16 replicas (the gas drawn afresh), predictions along each replica's measured periods (as in the sweep; see How each number is measured):\n\n",
    );
    let mut rows: Vec<[String; 2]> = Vec::new();
    let mut pictures = String::new();
    for (index, case) in CASES.iter().enumerate() {
        let (case_rows, case_md) = one_case(d, &o, index, case, figures)?;
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
    let _ = write!(
        md,
        "| | {} | {} |\n|---|---|---|\n",
        CASES[0].title, CASES[1].title
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
    d: &Descriptor,
    o: &Options,
    index: usize,
    case: &Case,
    figures: &mut Vec<Figure>,
) -> anyhow::Result<(Vec<(String, String)>, String)> {
    let base = d.study.seed ^ fnv1a(b"disk-piston");
    let seed = |r: u32| run_seed(base, index as u64, r);
    // Run long enough for the first periods and the relaxation the
    // exchange theory predicts, from replica 0's start.
    let probe = descriptor(case, o, 1.0, 1.0)?;
    let first = RunSpec {
        run_id: 0,
        point_id: index as u64,
        replica: 0,
        seed: seed(0),
        params: Vec::new(),
        descriptor: probe,
    };
    let scene = built(&first)?;
    let geometry = Geometry::of(&scene).ok_or_else(|| anyhow::anyhow!("no piston"))?;
    let p = scene.piston.unwrap_or(0);
    let gas = |side: usize| -> f64 {
        scene
            .particles
            .iter()
            .enumerate()
            .filter(|(i, q)| *i != p && usize::from(q.pos[0] > scene.particles[p].pos[0]) == side)
            .map(|(_, q)| q.kinetic_energy())
            .sum()
    };
    let start = geometry.system(
        scene.particles[p].pos[0],
        scene.particles[p].kinetic_energy(),
        gas(0),
        gas(1),
        1.0,
    );
    let period = TAU / start.omega(Law::Adiabatic);
    let tau = geometry
        .relaxing(&start)
        .decay_time(start.omega(Law::Adiabatic));
    let horizon = 5.0 * period;
    let duration = (3.0 * tau).clamp(2.0 * horizon, 50.0 * period);
    let descriptor = descriptor(case, o, duration, period / 200.0)?;
    let started = std::time::Instant::now();
    let runs: Vec<(RunSpec, RunOutput)> = (0..REPLICAS)
        .map(|r| {
            let spec = RunSpec {
                run_id: u64::from(r),
                point_id: index as u64,
                replica: r,
                seed: seed(r),
                params: Vec::new(),
                descriptor: descriptor.clone(),
            };
            let out = crate::runner::simulate::run(&spec)?;
            Ok((spec, out))
        })
        .collect::<anyhow::Result<_>>()?;
    let seconds = started.elapsed().as_secs_f64();
    let collisions: u64 = runs.iter().map(|r| r.1.collisions).sum();
    let stat = |name: &str| {
        let v: Vec<f64> = runs
            .iter()
            .filter_map(|r| r.1.scalar(name))
            .filter(|v| v.is_finite())
            .collect();
        Stats::of(&v)
    };

    // Pictures of replica 0.
    let (spec0, out0) = &runs[0];
    let scene0 = built(spec0)?;
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
    let step = period / 2000.0;
    let paths = [
        (Law::Adiabatic, BLACK, "adiabatic, γ = 2"),
        (Law::Collisionless, ORANGE, "collisionless, γ = 3"),
        (Law::Isothermal, GREY, "isothermal, γ = 1"),
    ]
    .map(|(law, rgb, label)| (start0.trajectory(law, horizon, step), rgb, label));
    let path_name = format!("disk_piston_{}_path.svg", case.tag);
    path_figure(&samples, &paths, horizon, case.title, &path_name, figures)?;
    let energy_name = format!("disk_piston_{}_energy.svg", case.tag);
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
                num(case.mass),
                case.per_side,
                num(case.energy)
            ),
        ),
        ("M/M_gas".into(), num(stat("mass_over_gas").mean)),
        (
            "ωτ_x (swing per x–y exchange time)".into(),
            num(stat("omega_tau").mean),
        ),
        (
            "**measured ω** (n of 16)".into(),
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
            "relaxation time τ measured (n of 16) / exchange theory".into(),
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
