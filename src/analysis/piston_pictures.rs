//! MacKay's pictures of his own eleven-particle case, and the table of where
//! the adiabatic theory holds.

use crate::engine::{Rods, Stop};
use crate::observe::{self, Context};
use crate::report::chart::{ChartSpec, Layer, Paint, render};
use crate::scene;
use crate::study::output::RunOutput;
use crate::study::plan_types::RunSpec;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::fmt::Write;
use std::path::Path;

const BLUE: (u8, u8, u8) = (31, 119, 180);
const GREEN: (u8, u8, u8) = (44, 160, 44);
const PURPLE: (u8, u8, u8) = (128, 0, 128);

fn colour(species: &str) -> (u8, u8, u8) {
    match species {
        "light" => BLUE,
        "heavy" => GREEN,
        _ => PURPLE,
    }
}

/// Simulate the `mackay-piston` preset for 200 time units and draw it.
pub fn mackay_case(
    seed: u64,
    out_dir: &Path,
    figures: &mut Vec<(String, String)>,
) -> anyhow::Result<String> {
    let spec = scene::presets::find("mackay-piston")
        .ok_or_else(|| anyhow::anyhow!("mackay-piston preset missing"))?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let built = scene::build::<1>(&spec, &mut rng).map_err(|e| anyhow::anyhow!(e))?;
    let names = [
        "positions".to_string(),
        "kinetic_energy_by_species".to_string(),
    ];
    let mut observers =
        observe::build::<1>(&names, &[], &[], built.piston).map_err(|e| anyhow::anyhow!(e))?;
    observers.recording = true;
    let started = std::time::Instant::now();
    let mut sim: Rods<_> = Rods::new(built.particles.clone(), built.sim_box, observers, 0)?;
    sim.sample_every(Some(0.05));
    sim.run(Stop::Time(200.0));
    let (collisions, energy) = (sim.counts.collisions, sim.kinetic_energy());
    let piston_share0 = built
        .piston
        .map_or(f64::NAN, |p| built.particles[p].kinetic_energy())
        / energy;
    let ctx = Context {
        species: &built.species,
        piston: built.piston,
        duration: 200.0,
        volume: built.sim_box.volume(),
        wall_area: 2.0,
        dimension: 1,
        degrees_of_freedom: built.particles.len() as f64,
    };
    let mut out = RunOutput::default();
    sim.into_observer().finish(&ctx, &mut out);
    let seconds = started.elapsed().as_secs_f64();

    for horizon in [40.0, 200.0] {
        // Space-time diagram: position across, time up (MacKay's layout).
        let layers = (0..built.particles.len())
            .filter_map(|i| {
                let s = out
                    .series
                    .iter()
                    .find(|s| s.observable == format!("x.{i}"))?;
                let species = &built.species[built.particles[i].species as usize];
                let points =
                    s.t.iter()
                        .zip(&s.value)
                        .filter(|(t, _)| **t <= horizon)
                        .map(|(t, x)| (*x, *t))
                        .collect();
                Some(Layer::Line {
                    points,
                    paint: Paint::solid(colour(species)),
                    width: if species == "piston" { 3 } else { 1 },
                    dashed: false,
                    label: None,
                })
            })
            .collect();
        let name = format!("mackay_spacetime_{horizon}.svg");
        let chart = ChartSpec {
            title: format!("MacKay's piston: positions, first {horizon} time units"),
            x_label: "position x [σ]".into(),
            y_label: "time t".into(),
            layers,
            ..Default::default()
        };
        crate::study::store::write_atomic(&out_dir.join(&name), render(&chart).as_bytes())?;
        figures.push((name, format!("Positions of all particles against time (up), first {horizon} time units: light gas blue, heavier gas green, piston purple.")));

        let layers = out
            .series
            .iter()
            .filter_map(|s| {
                let species = s.observable.strip_prefix("kinetic_energy.")?;
                let points =
                    s.t.iter()
                        .zip(&s.value)
                        .filter(|(t, _)| **t <= horizon)
                        .map(|(t, e)| (*t, *e))
                        .collect();
                Some(Layer::Line {
                    points,
                    paint: Paint::solid(colour(species)),
                    width: 2,
                    dashed: false,
                    label: Some(species.to_string()),
                })
            })
            .collect();
        let name = format!("mackay_energy_{horizon}.svg");
        let chart = ChartSpec {
            title: format!(
                "Kinetic energy of each gas and of the piston, first {horizon} time units"
            ),
            x_label: "time t".into(),
            y_label: "kinetic energy".into(),
            layers,
            ..Default::default()
        };
        crate::study::store::write_atomic(&out_dir.join(&name), render(&chart).as_bytes())?;
        figures.push((name, format!("Kinetic energy of the light gas, the heavier gas and the piston over the first {horizon} time units.")));
    }
    let mut md = String::new();
    let _ = write!(
        md,
        "MacKay's own case (`preset = \"mackay-piston\"`): five light rods (masses 0.9–1.1), five heavier (1.5–1.7), a \
         piston of mass 40, all starting with velocity 1. The piston starts with {:.0}% of the kinetic energy; at \
         equipartition it would hold 1/11 = 9%. Simulated here for 200 time units: {collisions} collisions, \
         {seconds:.3} s.\n\n",
        100.0 * piston_share0
    );
    Ok(md)
}

/// Per sweep point: measured / adiabatic frequency with its error, and the verdict.
pub fn regimes(runs: &[(RunSpec, RunOutput)]) -> String {
    let mut points: std::collections::BTreeMap<u64, Vec<&(RunSpec, RunOutput)>> =
        Default::default();
    for r in runs {
        points.entry(r.0.point_id).or_default().push(r);
    }
    let mut md = String::from(
        "\n**Where the adiabatic theory holds.** Per sweep point, the measured frequency over the nonlinear adiabatic \
         prediction (mean ± standard error over replicas), the isothermal ratio for contrast, and the cost:\n\n\
         | point | parameters | ω/ω_adiabatic | ω/ω_isothermal | verdict | collisions | seconds |\n|---|---|---|---|---|---|---|\n",
    );
    for (id, rs) in points {
        let stat = |name: &str| {
            let v: Vec<f64> = rs
                .iter()
                .filter_map(|r| r.1.scalar(name))
                .filter(|x| x.is_finite())
                .collect();
            let n = v.len() as f64;
            let mean = v.iter().sum::<f64>() / n;
            let se = if v.len() > 1 {
                (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0) / n).sqrt()
            } else {
                f64::NAN
            };
            (mean, se)
        };
        let (ad, ad_se) = stat("frequency_ratio");
        let (iso, iso_se) = stat("frequency_ratio_isothermal");
        // Holds: known to lie within 1% of the theory (with two standard
        // errors to spare); deviates: a significant gap below 5%; breaks
        // down: a significant gap above 5%; otherwise the error is too large.
        let gap = ad - 1.0;
        let verdict = if !ad.is_finite() {
            "no oscillation measured".to_string()
        } else if gap.abs() + 2.0 * ad_se < 0.01 {
            format!("adiabatic holds ({:+.2}%)", 100.0 * gap)
        } else if gap.abs() > 3.0 * ad_se && gap.abs() < 0.05 {
            format!("small deviation ({:+.1}%)", 100.0 * gap)
        } else if gap.abs() > 3.0 * ad_se {
            format!("breaks down ({:+.0}%)", 100.0 * gap)
        } else {
            "error too large to tell".to_string()
        };
        let params: Vec<String> = rs[0]
            .0
            .params
            .iter()
            .map(|(k, v)| format!("{}={}", k.rsplit('.').next().unwrap_or(k), v))
            .collect();
        let collisions: u64 = rs.iter().map(|r| r.1.collisions).sum();
        let seconds: f64 = rs.iter().map(|r| r.1.wall_seconds).sum();
        let _ = writeln!(
            md,
            "| {id} | {} | {ad:.4} ± {ad_se:.4} | {iso:.4} ± {iso_se:.4} | {verdict} | {collisions} | {seconds:.2} |",
            params.join(", ")
        );
    }
    md
}
