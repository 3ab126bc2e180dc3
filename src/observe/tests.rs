//! The catalogue against what its observables do: every entry builds in 1D,
//! 2D and 3D and writes exactly the names its entry says, to the table its
//! kind says, with the right values on a hand-made run.

use super::catalogue::{self, CATALOGUE, matches};
use super::{Context, Kind, build};
use crate::engine::{Axis, Observer, PairCollision, Particle, SimBox, Snapshot, Wall, WallHit};
use crate::model::run_output::RunOutput;

const SPECIES: [&str; 3] = ["light", "piston", "heavy"];
const L: f64 = 4.0;

/// Three particles of three species in a box of side L, the middle one the
/// piston; axis 0 has a thermal wall at its low end.
fn scene<const D: usize>() -> (Vec<Particle<D>>, SimBox<D>) {
    let at = |x: f64| std::array::from_fn(|k| if k == 0 { x } else { 1.0 });
    let velocity = |a: f64| std::array::from_fn(|k| a / (k + 1) as f64);
    let particles = vec![
        Particle::new(at(1.0), velocity(1.0), 1.0, 0.5).with_species(0),
        Particle::new(at(2.0), velocity(0.5), 10.0, 0.5).with_species(1),
        Particle::new(at(3.0), velocity(-1.0), 2.0, 0.5).with_species(2),
    ];
    let mut sim_box = SimBox::hard([L; D]);
    sim_box.axes[0] = Axis::Walls {
        low: Wall::Thermal { temperature: 1.0 },
        high: Wall::Hard,
    };
    (particles, sim_box)
}

fn along0<const D: usize>(a: f64) -> [f64; D] {
    std::array::from_fn(|k| if k == 0 { a } else { 0.0 })
}

/// Two samples (t = 0 and 1) with a thermal wall hit and a pair collision
/// between them, observed by the named observables.
fn observe<const D: usize>(kind: Kind, names: &[&str]) -> Result<RunOutput, String> {
    let (particles, sim_box) = scene::<D>();
    let names: Vec<String> = names.iter().map(|s| s.to_string()).collect();
    let none = Vec::new();
    let pick = |k: Kind| if k == kind { &names } else { &none };
    let mut set = build::<D>(
        pick(Kind::Series),
        pick(Kind::Scalars),
        pick(Kind::Histograms),
        Some(1),
    )?;
    set.recording = true;
    let bodies = crate::engine::Bodies::new(&particles);
    let snapshot = |time| Snapshot {
        time,
        now: 0.0,
        particles: &bodies,
        sim_box: &sim_box,
    };
    set.sample(&snapshot(0.0));
    set.wall_hit(&WallHit {
        time: 0.5,
        i: 0,
        axis: 0,
        high: false,
        impulse: along0(2.0),
        energy_gain: 0.25,
    });
    set.pair_collision(&PairCollision {
        time: 0.6,
        i: 0,
        j: 2,
        impulse_i: along0(-1.0),
        separation: along0(1.0),
    });
    set.sample(&snapshot(1.0));
    let species = SPECIES.map(String::from);
    let ctx = Context {
        species: &species,
        piston: Some(1),
        duration: 1.0,
        volume: L.powi(D as i32),
        wall_area: 2.0 * L.powi(D as i32 - 1) * D as f64,
        dimension: D,
        degrees_of_freedom: (3 * D) as f64,
    };
    let mut out = RunOutput::default();
    set.finish(&ctx, &mut out);
    Ok(out)
}

/// What a run wrote, with the table each name went to.
fn written(out: &RunOutput) -> Vec<(Kind, String)> {
    let series = out
        .series
        .iter()
        .map(|s| (Kind::Series, s.observable.clone()));
    let scalars = out.scalars.iter().map(|(n, _)| (Kind::Scalars, n.clone()));
    let histograms = out
        .histograms
        .iter()
        .map(|h| (Kind::Histograms, h.observable.clone()));
    series.chain(scalars).chain(histograms).collect()
}

fn every_entry_writes_what_it_says<const D: usize>() {
    for e in CATALOGUE {
        let out = observe::<D>(e.kind, &[e.name]).unwrap();
        let names = written(&out);
        assert!(!names.is_empty(), "{D}D: `{}` wrote nothing", e.name);
        for (kind, name) in names {
            assert_eq!(kind, e.kind, "{D}D: `{}` wrote `{name}`", e.name);
            assert!(
                matches(e.writes, &name).is_some(),
                "{D}D: `{}` wrote `{name}`, not `{}`",
                e.name,
                e.writes
            );
        }
    }
}

#[test]
fn every_entry_builds_and_writes_its_names_in_1d_2d_3d() {
    every_entry_writes_what_it_says::<1>();
    every_entry_writes_what_it_says::<2>();
    every_entry_writes_what_it_says::<3>();
}

fn values_on_the_hand_made_run<const D: usize>() {
    let (particles, _) = scene::<D>();
    let kinetic: f64 = particles.iter().map(Particle::kinetic_energy).sum();
    let series = |name: &str| observe::<D>(Kind::Series, &[name]).unwrap().series;

    let k = series("kinetic_energy");
    assert_eq!(
        (k[0].t.clone(), k[0].value.clone()),
        (vec![0.0, 1.0], vec![kinetic; 2])
    );
    let by_species: Vec<String> = series("kinetic_energy_by_species")
        .into_iter()
        .map(|s| s.observable)
        .collect();
    assert_eq!(by_species, SPECIES.map(|s| format!("kinetic_energy.{s}")));
    let x = series("positions");
    let xs: Vec<(&str, f64)> = x
        .iter()
        .map(|s| (s.observable.as_str(), s.value[1]))
        .collect();
    assert_eq!(xs, [("x.0", 1.0), ("x.1", 2.0), ("x.2", 3.0)]);
    assert_eq!(series("piston_position")[0].value, [2.0, 2.0]);
    // Left of the piston: the light particle; right: the heavy one.
    let sides = series("gas_energy_by_side");
    assert_eq!(sides[0].observable, "gas_energy.left");
    assert_eq!(sides[0].value[0], particles[0].kinetic_energy());
    assert_eq!(sides[1].value[0], particles[2].kinetic_energy());
    assert_eq!(series("left_fraction")[0].value, [1.0 / 3.0; 2]);

    let scalars = observe::<D>(Kind::Scalars, &["wall_pressure", "wall_heat"]).unwrap();
    let area = 2.0 * L.powi(D as i32 - 1) * D as f64;
    assert_eq!(scalars.scalar("wall_pressure"), Some(2.0 / area));
    assert_eq!(scalars.scalar("heat_in.axis0.low"), Some(0.25));
    assert_eq!(scalars.scalar("heat_in.axis0.high"), Some(0.0));
    assert_eq!(scalars.scalars.len(), 1 + 2 * D);

    let histogram = &observe::<D>(Kind::Histograms, &["scaled_velocity_x"])
        .unwrap()
        .histograms[0];
    // Every particle at both samples, in bins of width 0.2 over [-6, 6).
    assert_eq!(histogram.count.iter().sum::<f64>(), 6.0);
    assert_eq!((histogram.lo[0], histogram.hi[59]), (-6.0, 6.0));

    // Slabs of L/100: particles at x = 1, 2, 3 in slabs 25, 50, 75, twice.
    let profile = observe::<D>(Kind::Histograms, &["energy_x"]).unwrap();
    let (count, energy) = (&profile.histograms[0], &profile.histograms[1]);
    assert_eq!(count.observable, "energy_x.count");
    assert_eq!((count.lo[0], count.hi[99]), (0.0, L));
    assert_eq!(
        [count.count[25], count.count[50], count.count[75]],
        [2.0; 3]
    );
    assert_eq!(count.count.iter().sum::<f64>(), 6.0);
    let (particles, _) = scene::<D>();
    assert_eq!(energy.count[75], 2.0 * particles[2].kinetic_energy());
}

#[test]
fn observables_measure_what_they_say_in_1d_2d_3d() {
    values_on_the_hand_made_run::<1>();
    values_on_the_hand_made_run::<2>();
    values_on_the_hand_made_run::<3>();
}

#[test]
fn a_histogram_name_builds_that_histogram_and_an_unknown_one_is_an_error() {
    let out = observe::<2>(Kind::Histograms, &["scaled_velocity_x"]).unwrap();
    let names: Vec<&str> = out
        .histograms
        .iter()
        .map(|h| h.observable.as_str())
        .collect();
    assert_eq!(names, ["scaled_velocity_x"]);
    let err = observe::<2>(Kind::Histograms, &["speed"]).unwrap_err();
    assert_eq!(
        err,
        "unknown histograms observable `speed`; known: scaled_velocity_x, velocity_x_each, \
         velocity_x_halves, position_x_each, scaled_speed, density_x, energy_x, pair_distance"
    );
    // A name of another kind is not a histogram either.
    assert!(observe::<2>(Kind::Histograms, &["kinetic_energy"]).is_err());
}

/// The tables rely on this order: observers of their own first (in the
/// order named), then the shared sampling pass (series, then averages).
#[test]
fn results_come_in_a_fixed_order() {
    let (particles, sim_box) = scene::<1>();
    let own = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let mut set = build::<1>(
        &own(&["kinetic_energy", "gas_energy_by_side", "piston_position"]),
        &own(&["temperature", "wall_pressure"]),
        &[],
        Some(1),
    )
    .unwrap();
    set.recording = true;
    let bodies = crate::engine::Bodies::new(&particles);
    set.sample(&Snapshot {
        time: 0.0,
        now: 0.0,
        particles: &bodies,
        sim_box: &sim_box,
    });
    let species = SPECIES.map(String::from);
    let ctx = Context {
        species: &species,
        piston: Some(1),
        duration: 1.0,
        volume: L,
        wall_area: 2.0,
        dimension: 1,
        degrees_of_freedom: 3.0,
    };
    let mut out = RunOutput::default();
    set.finish(&ctx, &mut out);
    let series: Vec<&str> = out.series.iter().map(|s| s.observable.as_str()).collect();
    assert_eq!(
        series,
        [
            "gas_energy.left",
            "gas_energy.right",
            "kinetic_energy",
            "piston_position"
        ]
    );
    let scalars: Vec<&str> = out.scalars.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(scalars, ["wall_pressure", "temperature"]);
}

/// An example of the names `pattern` stands for: each part its first word,
/// or "a".
fn example(pattern: &str) -> String {
    let mut out = String::new();
    let mut rest = pattern;
    while let Some((literal, tail)) = rest.split_once('<') {
        let (hole, tail) = tail.split_once('>').unwrap();
        out += literal;
        out += if hole.contains('|') {
            hole.split('|').next().unwrap()
        } else {
            "a"
        };
        rest = tail;
    }
    out + rest
}

fn holes(pattern: &str) -> Vec<&str> {
    pattern
        .split('<')
        .skip(1)
        .map(|s| s.split_once('>').unwrap().0)
        .collect()
}

#[test]
fn entries_are_unique_and_well_formed() {
    for (i, e) in CATALOGUE.iter().enumerate() {
        let twice = CATALOGUE[..i]
            .iter()
            .any(|o| (o.kind, o.name) == (e.kind, e.name));
        assert!(!twice, "{} `{}` is listed twice", e.kind.key(), e.name);
        assert!(!e.doc.is_empty() && !e.doc.contains('\n'), "{}", e.name);
        assert!(!e.unit.is_empty() && !e.label.is_empty(), "{}", e.name);
        // The label's parts are filled from the names written.
        for hole in holes(e.label) {
            assert!(holes(e.writes).contains(&hole), "{}: <{hole}>", e.name);
        }
        assert!(
            matches(e.writes, &example(e.writes)).is_some(),
            "{}",
            e.name
        );
        // No two observables of a kind write the same name.
        for o in CATALOGUE
            .iter()
            .filter(|o| o.kind == e.kind && o.name != e.name)
        {
            assert!(
                matches(o.writes, &example(e.writes)).is_none(),
                "`{}` and `{}` both write `{}`",
                o.name,
                e.name,
                example(e.writes)
            );
        }
        // A name under two kinds is one quantity: one unit, one label.
        for o in CATALOGUE.iter().filter(|o| o.name == e.name) {
            assert_eq!((o.unit, o.label), (e.unit, e.label), "{}", e.name);
        }
    }
}

#[test]
fn patterns_match_the_names_they_stand_for() {
    let p = "heat_in.axis<k>.<low|high>";
    assert_eq!(
        matches(p, "heat_in.axis2.high"),
        Some(vec![("k", "2"), ("low|high", "high")])
    );
    assert_eq!(matches(p, "heat_in.axis2.middle"), None);
    assert_eq!(matches(p, "heat_in.axis.low"), None);
    assert_eq!(matches("x.<index>", "x.1.2"), None);
    assert_eq!(matches("kinetic_energy", "kinetic_energy"), Some(vec![]));
    assert_eq!(matches("kinetic_energy.<species>", "kinetic_energy"), None);
    assert_eq!(
        catalogue::label("gas_energy.right"),
        Some((
            "kinetic energy of the gas right of the piston".to_string(),
            "kT"
        ))
    );
    assert_eq!(catalogue::label("scene.piston.mass"), None);
}

/// The hand-made run's events, `t0` later: a sample, a thermal wall hit, a
/// pair collision, a sample.
fn feed<const D: usize>(set: &mut super::ObserverSet<D>, t0: f64) {
    let (particles, sim_box) = scene::<D>();
    let bodies = crate::engine::Bodies::new(&particles);
    let snapshot = |time| Snapshot {
        time,
        now: 0.0,
        particles: &bodies,
        sim_box: &sim_box,
    };
    set.sample(&snapshot(t0));
    set.wall_hit(&WallHit {
        time: t0 + 0.5,
        i: 0,
        axis: 0,
        high: false,
        impulse: along0(2.0),
        energy_gain: 0.25,
    });
    set.pair_collision(&PairCollision {
        time: t0 + 0.6,
        i: 0,
        j: 2,
        impulse_i: along0(-1.0),
        separation: along0(1.0),
    });
    set.sample(&snapshot(t0 + 1.0));
}

fn bits(state: &[f64]) -> Vec<u64> {
    state.iter().map(|x| x.to_bits()).collect()
}

/// Checkpoints: every observable saves what it accumulated, and a fresh set
/// restored from that goes on exactly as the original (same output, bit for
/// bit); a state of other observers is refused.
fn restored_sets_go_on_as_the_original<const D: usize>() {
    let species = SPECIES.map(String::from);
    let ctx = Context {
        species: &species,
        piston: Some(1),
        duration: 2.0,
        volume: L.powi(D as i32),
        wall_area: 2.0 * L.powi(D as i32 - 1) * D as f64,
        dimension: D,
        degrees_of_freedom: (3 * D) as f64,
    };
    for e in CATALOGUE {
        let make = || {
            let names = vec![e.name.to_string()];
            let none = Vec::new();
            let pick = |k: Kind| if k == e.kind { &names } else { &none };
            build::<D>(
                pick(Kind::Series),
                pick(Kind::Scalars),
                pick(Kind::Histograms),
                Some(1),
            )
            .unwrap()
        };
        let mut original = make();
        original.recording = true;
        feed(&mut original, 0.0);
        let state = original
            .save_state()
            .unwrap_or_else(|| panic!("{D}D: `{}` cannot be checkpointed", e.name));
        let mut restored = make();
        restored.restore_state(&state).unwrap();
        assert!(restored.recording);
        let again = restored.save_state().unwrap();
        assert_eq!(bits(&again), bits(&state), "{D}D: `{}`", e.name);
        feed(&mut original, 1.0);
        feed(&mut restored, 1.0);
        let [mut a, mut b] = [RunOutput::default(), RunOutput::default()];
        original.finish(&ctx, &mut a);
        restored.finish(&ctx, &mut b);
        assert_eq!(format!("{a:?}"), format!("{b:?}"), "{D}D: `{}`", e.name);
    }
    let mut sampled = build::<D>(&["kinetic_energy".into()], &[], &[], Some(1)).unwrap();
    sampled.recording = true;
    feed(&mut sampled, 0.0);
    let state = sampled.save_state().unwrap();
    let mut other = build::<D>(&[], &["wall_pressure".into()], &[], Some(1)).unwrap();
    assert!(other.restore_state(&state).is_err());
    assert!(other.restore_state(&state[..1]).is_err());
}

#[test]
fn observers_restore_from_a_checkpoint_in_1d_2d_3d() {
    restored_sets_go_on_as_the_original::<1>();
    restored_sets_go_on_as_the_original::<2>();
    restored_sets_go_on_as_the_original::<3>();
}
