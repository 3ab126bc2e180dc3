//! Statistical regression tests of the heat study (seeded; thresholds are
//! four standard errors of the ensemble, never tuned to one outcome).

use crate::study_common::{ensemble, stats};
use bonkers::stats::summary::Stats;
use bonkers::studies::heat::{Gas, Line, Profile};

/// Disks of diameter 1 between two thermal walls across x, periodic in y.
fn descriptor(
    (lx, ly): (f64, f64),
    count: usize,
    (start, low, high): (f64, f64, f64),
    (equilibrate, duration, sample): (f64, f64, f64),
    replicas: u32,
    extra: &str,
) -> String {
    format!(
        r#"
[study]
name = "heat-test"
replicas = {replicas}
seed = 17

[scene]
dimension = 2
box = [{lx:?}, {ly:?}]
boundary = ["walls", "periodic"]
velocities = {{ kind = "maxwell", temperature = {start:?} }}
thermal_walls = [
    {{ axis = 0, side = "low", temperature = {low:?} }},
    {{ axis = 0, side = "high", temperature = {high:?} }},
]
species = [{{ name = "disk", count = {count}, radius = 0.5 }}]

[run]
equilibrate = {equilibrate:?}
duration = {duration:?}
sample_every = {sample:?}

[observe]
scalars = ["wall_heat"]
histograms = ["energy_x"]

[analysis.heat]
{extra}
"#
    )
}

fn within(s: &Stats, theory: f64, what: &str) {
    assert!(
        s.n >= 8 && (s.mean - theory).abs() < 4.0 * s.stderr,
        "{what}: {} ± {} over {} runs against {theory}",
        s.mean,
        s.stderr,
        s.n
    );
}

/// A gas at kT = 2 between walls at 1 (packing 0.05) first loses energy at
/// the rate kinetic theory gives for a uniform Maxwellian: n_c sqrt(kT0/2pi m)
/// hits per unit wall area, each moving (d + 1)/2 (T_w - T0) on average.
/// Measured over the first 3% of the relaxation time, long enough for many
/// hits and short enough that the gas near the walls has barely changed.
#[test]
fn the_first_exchange_is_the_kinetic_rate() {
    let runs = ensemble(&descriptor(
        (40.0, 4000.0),
        10000,
        (2.0, 1.0, 1.0),
        (0.0, 3.0, 0.05),
        16,
        "initial_window = 0.03",
    ));
    within(
        &stats(&runs, "initial_rate_ratio"),
        1.0,
        "initial change over the kinetic rate's",
    );
}

/// The same gas, followed for about 15 relaxation times, settles at the
/// walls' temperature: with every wall at T_w the stationary state is the
/// canonical one at T_w.
#[test]
fn a_hot_gas_relaxes_to_its_walls() {
    let runs = ensemble(&descriptor(
        (40.0, 400.0),
        1000,
        (2.0, 1.0, 1.0),
        (0.0, 400.0, 0.5),
        12,
        "",
    ));
    within(&stats(&runs, "late_temperature"), 1.0, "settled kT");
    // The periodic axis has no walls: all the heat left through the thermal ones.
    for (_, o) in &runs {
        let out = o.scalar("heat_in.axis0.low").unwrap() + o.scalar("heat_in.axis0.high").unwrap();
        assert!(out < 0.0, "the hot gas heated its walls: {out}");
    }
}

/// Point particles never collide: each keeps its velocity until a wall
/// replaces it, and the collisionless renewal theory is exact. Their mean
/// temperature follows it at several times, and their relaxation time is
/// its time, within four standard errors.
#[test]
fn points_relax_as_the_collisionless_theory_says() {
    let text = descriptor(
        (40.0, 40.0),
        400,
        (2.0, 1.0, 1.0),
        (0.0, 200.0, 0.5),
        16,
        "",
    )
    .replace("radius = 0.5", "radius = 0.0");
    let runs = ensemble(&text);
    within(
        &stats(&runs, "relaxation_ratio_free"),
        1.0,
        "τ / τ collisionless",
    );
    let gas = Gas::of(&runs[0].0.descriptor).unwrap();
    // Per run, its excess over the theory from its own start, in units of
    // its starting excess, at a few samples.
    let samples = [10, 40, 100, 200];
    let off: Vec<Vec<f64>> = runs
        .iter()
        .map(|(_, o)| {
            let s = o.series("kinetic_energy").unwrap();
            let t0 = s.value[0] / 400.0;
            let free = gas.free(1.0, t0, 200.0).unwrap();
            samples
                .iter()
                .map(|&i| (s.value[i] / 400.0 - free.energy_at(s.t[i])) / (t0 - 1.0))
                .collect()
        })
        .collect();
    for (k, i) in samples.iter().enumerate() {
        let at: Vec<f64> = off.iter().map(|v| v[k]).collect();
        within(
            &Stats::of(&at),
            0.0,
            &format!("excess at sample {i} off the theory"),
        );
    }
}

/// Between a hot and a cold wall, after the steady state is reached, the
/// heat in at the hot wall equals the heat out at the cold one within error,
/// the temperature falls from hot to cold with a jump at each wall, and the
/// profile is straight in the middle (packing 0.2, Kn ~ 0.03).
///
/// Sized for the jumps, the smallest effects here (a few hundredths of kT):
/// 32 runs of 1500 time units gave 0.045 ± 0.007 (hot, sd per run 0.041)
/// and 0.043 ± 0.004 (cold), so 8 such runs expected z ~ 3 against the
/// 4-sigma test and passed by luck. Runs of 5000 scatter less (sd 0.015
/// hot, 0.012 cold); 16 of them give 0.032 ± 0.004 and 0.035 ± 0.003,
/// z ~ 8 and 12 (seed 18: 0.035 ± 0.004 and 0.031 ± 0.003, z ~ 9 and 10;
/// 18 s on one core).
#[test]
fn steady_conduction_balances_the_walls() {
    let runs = ensemble(&descriptor(
        (50.0, 30.0),
        382,
        (1.0, 1.25, 0.75),
        (300.0, 5000.0, 0.5),
        16,
        "",
    ));
    within(&stats(&runs, "flux_imbalance"), 0.0, "flux in − flux out");
    let flux = stats(&runs, "flux_in");
    assert!(
        flux.mean > 4.0 * flux.stderr,
        "heat flows from the hot wall"
    );
    let g = stats(&runs, "gradient");
    assert!(g.mean < -4.0 * g.stderr, "T falls toward the cold wall");
    for jump in ["jump_hot", "jump_cold"] {
        let j = stats(&runs, jump);
        eprintln!("{jump}: {} +- {} (sd {})", j.mean, j.stderr, j.std);
        assert!(j.mean > 4.0 * j.stderr, "{jump}: {} ± {}", j.mean, j.stderr);
    }
    // Away from the walls the profile is straight: over the fitted middle
    // half, the residuals of the line in its central third average the same
    // as in its outer thirds (a curved profile would lift one against the
    // other).
    let gas = Gas::of(&runs[0].0.descriptor).unwrap();
    let bend: Vec<f64> = runs
        .iter()
        .map(|(_, o)| {
            let h = |n: &str| o.histograms.iter().find(|h| h.observable == n).unwrap();
            let p = Profile::of(&gas, h("energy_x.count"), h("energy_x.energy"));
            let line = Line::fit(&p, 50.0, 0.5);
            let (mut inner, mut outer) = (Vec::new(), Vec::new());
            for (x, t) in p.x.iter().zip(&p.temperature) {
                let off = (x - 25.0).abs();
                if off <= 12.5 / 3.0 {
                    inner.push(t - line.at(*x));
                } else if off <= 12.5 {
                    outer.push(t - line.at(*x));
                }
            }
            let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
            mean(&inner) - mean(&outer)
        })
        .collect();
    within(&Stats::of(&bend), 0.0, "bend of the middle of the profile");
}

/// A moderately dilute gas (packing 0.1, mean free path 2.8, Kn = 0.03)
/// conducts as Enskog's theory says (1.19 times Chapman-Enskog's dilute
/// value there), within four standard errors.
#[test]
fn conductivity_at_packing_a_tenth_is_enskogs() {
    let runs = ensemble(&descriptor(
        (100.0, 30.0),
        382,
        (1.0, 1.25, 0.75),
        (1000.0, 2000.0, 0.5),
        12,
        "",
    ));
    within(
        &stats(&runs, "conductivity_ratio_enskog"),
        1.0,
        "κ / κ Enskog",
    );
}

/// Spheres at packing 0.2 (mean free path 0.58 before Enskog's correction,
/// Kn = 0.03) between a hot and a cold wall, periodic in y and z: heat in
/// equals heat out, and the conductivity in the middle is Enskog's for
/// spheres (Chapman and Cowling ch. 16; 2.5 times Chapman-Enskog's dilute
/// value there), within four standard errors.
#[test]
fn spheres_conduct_as_enskog_says() {
    let runs = ensemble(
        r#"
[study]
name = "heat-test-3d"
replicas = 8
seed = 19

[scene]
dimension = 3
box = [20.0, 6.0, 6.0]
boundary = ["walls", "periodic", "periodic"]
velocities = { kind = "maxwell", temperature = 1.0 }
thermal_walls = [
    { axis = 0, side = "low", temperature = 1.25 },
    { axis = 0, side = "high", temperature = 0.75 },
]
species = [{ name = "sphere", count = 275, radius = 0.5 }]

[run]
equilibrate = 200.0
duration = 1000.0
sample_every = 0.5

[observe]
scalars = ["wall_heat"]
histograms = ["energy_x"]

[analysis.heat]
"#,
    );
    within(&stats(&runs, "flux_imbalance"), 0.0, "flux in − flux out");
    let ratio = stats(&runs, "conductivity_ratio_enskog");
    within(&ratio, 1.0, "κ / κ Enskog (spheres)");
    println!("spheres: κ / κ Enskog = {} ± {}", ratio.mean, ratio.stderr);
}
