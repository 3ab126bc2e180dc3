//! Statistical tests of the piston as a wall between two gases of disks
//! (the `disk-piston` preset). Seeded; thresholds are four standard errors
//! of the ensemble, each with a check that the ensemble can tell the
//! predictions apart.

use crate::piston_common::{
    assert_equipartition, assert_not_one, assert_one, ensemble, geometry, measure_with, result,
    scalar, stats,
};
use bonkers::stats::summary::Stats;
use bonkers::theory::piston_equilibrium::degrees_of_freedom;

/// The preset with its piston and, optionally, other disks.
fn descriptor(
    piston: &str,
    species: &str,
    duration: f64,
    sample_every: f64,
    replicas: u32,
) -> String {
    format!(
        r#"
[study]
name = "disk-piston-test"
replicas = {replicas}
seed = 23

[scene]
preset = "disk-piston"
{species}
piston = {piston}

[run]
duration = {duration:?}
sample_every = {sample_every:?}

[analysis.piston]
"#
    )
}

/// A heavy wall (M/M_gas ~ 2000) between gases of 20 disks a side, which
/// share a compression between x and y many times per swing (omega tau_x
/// ~ 0.03): the frequency is the 2D adiabatic one (gamma = 2; nonlinear,
/// at the amplitude of each measured period), neither the isothermal
/// (gamma = 1) nor the collisionless (gamma = 3) one. The disks (diameter
/// 1, 2% packing) take room: the prediction that gives back the layer a
/// radius thick along the walls and the piston, or only the area the disks
/// exclude each other from (4% of the free length), is rejected; each
/// gas's free length is the reach less both.
#[test]
fn heavy_wall_oscillates_at_the_two_dimensional_adiabatic_frequency() {
    let text = descriptor(
        "{ mass = 100000.0, position = 0.5, radius = 0.0, energy = 40.0, per_side = 20 }",
        "",
        12_000.0,
        4.0,
        10,
    );
    let runs = ensemble(&text);
    // The report's piston section presents every result the analysis gives.
    let (spec, out) = &runs[0];
    let names: Vec<&str> = measure_with(spec, out, &geometry::<2>(spec))
        .iter()
        .map(|r| r.0)
        .collect();
    assert_eq!(names, bonkers::studies::piston::RESULTS);
    let adiabatic = stats(&runs, scalar("frequency_ratio"));
    assert_eq!(adiabatic.n, 10, "every run measured a frequency");
    assert_one(&adiabatic, "omega/omega_adiabatic");
    // Power: gamma = 1 and gamma = 3 lie far outside the error bar.
    for other in ["omega_isothermal", "omega_collisionless"] {
        let gap = stats(&runs, |o| {
            Some(o.scalar("omega_adiabatic")? / o.scalar(other)?)
        });
        assert!(
            4.0 * adiabatic.stderr < (gap.mean - 1.0).abs(),
            "the error bar {} cannot tell gamma = 2 from {other} ({})",
            adiabatic.stderr,
            gap.mean
        );
        let ratio = other.replace("omega_", "frequency_ratio_");
        assert_not_one(&stats(&runs, scalar(&ratio)), &ratio);
    }
    // The same runs, measured against gases that lose less room.
    let without = |keep_layer: bool| {
        let ratios: Vec<f64> = runs
            .iter()
            .map(|(spec, out)| {
                let mut g = geometry::<2>(spec);
                for room in &mut g.rooms {
                    (room.excluded, room.edge) = (0.0, 0.0);
                    if !keep_layer {
                        room.radius = 0.0;
                    }
                }
                result(&measure_with(spec, out, &g), "frequency_ratio")
            })
            .collect();
        Stats::of(&ratios)
    };
    let (ideal_box, point) = (without(true), without(false));
    eprintln!(
        "omega/omega_adiabatic = {} +- {}; without the excluded area {} +- {}; point disks {} +- {}",
        adiabatic.mean,
        adiabatic.stderr,
        ideal_box.mean,
        ideal_box.stderr,
        point.mean,
        point.stderr
    );
    assert_not_one(
        &ideal_box,
        "ignoring the area disks exclude each other from",
    );
    assert_not_one(&point, "ignoring the disks' size");
}

/// The gas's own inertia: a gas compressed uniformly moves along x with a
/// speed rising linearly from the wall to the piston, so a third of its
/// mass moves with the piston, in 2D as in 1D (and that flow's energy is
/// the oscillator's, not the gas's heat). At M/M_gas ~ 10 that lowers the
/// frequency by ~1.5%: the measured frequency agrees with the adiabatic one
/// with M + M_gas/3 as the inertia and not with M alone. Many small disks
/// (80 a side, diameter 0.25, in a 40 x 10 box: 2% packing) collide often
/// enough per swing (omega tau_x ~ 0.09) to keep gamma = 2; a piston energy
/// of 100 kT lifts the oscillation well above the gases' thermal noise.
#[test]
fn two_dimensional_gas_adds_a_third_of_its_mass() {
    let species = r#"box = [40.0, 10.0]
species = [
  { name = "light", count = 5, mass = [0.9, 1.1], radius = 0.125, region = { from = [0.0, 0.0], to = [0.5, 1.0] } },
  { name = "heavy", count = 5, mass = [1.5, 1.7], radius = 0.125, region = { from = [0.5, 0.0], to = [1.0, 1.0] } },
]"#;
    let text = descriptor(
        "{ mass = 2000.0, position = 0.5, radius = 0.0, energy = 100.0, per_side = 80 }",
        species,
        1800.0,
        1.0,
        12,
    );
    let runs = ensemble(&text);
    let inertia = stats(&runs, scalar("frequency_ratio_inertia"));
    let plain = stats(&runs, scalar("frequency_ratio"));
    let shift = stats(&runs, |o| {
        Some(1.0 - o.scalar("omega_adiabatic_inertia")? / o.scalar("omega_adiabatic")?)
    });
    eprintln!(
        "omega/omega_(M+M_gas/3) = {} +- {}; omega/omega_M = {} +- {}; predicted shift {}",
        inertia.mean, inertia.stderr, plain.mean, plain.stderr, shift.mean
    );
    assert_eq!(inertia.n, 12, "every run measured a frequency");
    assert!(
        4.0 * inertia.stderr < shift.mean,
        "the error bar {} cannot resolve the inertia shift {}",
        inertia.stderr,
        shift.mean
    );
    assert_one(&inertia, "omega/omega_adiabatic with M + M_gas/3");
    assert_not_one(&plain, "omega/omega_adiabatic with M alone");
}

/// A light wall (M = 30) between five disks a side gives up its excess
/// within ~100 time units; averaged over the last half of a long run its
/// share of the kinetic energy is 1/N_free = 1/(2 N_gas + 1) = 1/21 (the
/// wall moves along x only), and its oscillator energy the microcanonical
/// mean of the 2D gases.
#[test]
fn long_time_wall_share_is_equipartition() {
    let text = descriptor(
        "{ mass = 30.0, position = 0.5, radius = 0.0, energy = 10.0, per_side = 5 }",
        "",
        20_000.0,
        0.5,
        16,
    );
    let runs = ensemble(&text);
    assert_eq!(runs.len(), 16);
    let expected = 1.0 / degrees_of_freedom(2, 10) as f64;
    assert!((expected - 1.0 / 21.0).abs() < 1e-15);
    assert_equipartition(&runs, 2, 5, expected);
}
