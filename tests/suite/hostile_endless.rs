//! Runs that never ended (issue 50, item 7): each reproduction is refused
//! by `study validate` with exit 2 at its key, within a time and memory
//! bound; and the engine itself halts, with the reason, where a scene it is
//! given directly could not move on (a stalled clock, a collision count
//! that never comes, nothing left to move).

use crate::bounded::study;
use bonkers::engine::{Halt, Particle, Rods, SimBox, Simulation, Stop};
use std::time::{Duration, Instant};

/// A 1D study with `scene`, `run` and `observe` left to each case.
fn descriptor(scene: &str, run: &str, observe: &str) -> String {
    format!(
        "[study]\nname = \"endless\"\nseed = 7\nreplicas = 1\n\n[scene]\n{scene}\n\n\
         [run]\n{run}\n\n[observe]\n{observe}\n"
    )
}

const FIVE_RODS: &str = "box = [20.0]\n[[scene.species]]\nname = \"rod\"\ncount = 5";
const SAMPLED: &str = "duration = 50\nsample_every = 1";

/// (what, descriptor, what the error must say: its key first).
fn cases() -> Vec<(&'static str, String, &'static [&'static str])> {
    vec![
        (
            "a thermal wall at kT = 1e40",
            descriptor(
                &format!(
                    "{FIVE_RODS}\n[[scene.thermal_walls]]\naxis = 0\nside = \"low\"\n\
                     temperature = 1e40"
                ),
                SAMPLED,
                "",
            ),
            &[
                "`scene.thermal_walls.0.temperature` = 1e40",
                "wall hits and neighbourhood renewals",
                "more than a run can finish",
            ],
        ),
        (
            "a movie far longer than its run",
            descriptor(
                FIVE_RODS,
                SAMPLED,
                "movie = { duration = 1e12, frames = 10 }",
            ),
            &[
                "`observe.movie.duration`: 1e12 is longer than the run it films, which lasts 50",
                "`duration = 50` at most",
            ],
        ),
        (
            "one rod stopped by a collision count",
            descriptor(
                "box = [20.0]\n[[scene.species]]\nname = \"rod\"\ncount = 1",
                "collisions = 100\nsample_every = 1",
                "",
            ),
            &[
                "`run.collisions`: no pair can ever collide",
                "stop the run by `duration`",
            ],
        ),
        (
            "a box whose volume no float holds",
            descriptor(
                "dimension = 2\nbox = [1e200, 1e200]\n[[scene.species]]\nname = \"disk\"\ncount = 1",
                "duration = 50",
                "",
            ),
            &["`scene.box`", "volume of more than 1e308"],
        ),
        (
            "a point rod in a box of 1e-12: wall hits are its events",
            descriptor(
                "box = [1e-12]\n[[scene.species]]\nname = \"rod\"\ncount = 1\nradius = 0.0",
                "duration = 50",
                "",
            ),
            &["CPU-hours", "pass --yes if you mean it"],
        ),
        (
            "an axis the neighbour grid cannot file",
            descriptor(
                "dimension = 2\nbox = [1e6, 1e-6]\n[[scene.species]]\nname = \"disk\"\n\
                 count = 10\nradius = 0.0",
                "duration = 50",
                "",
            ),
            &["`scene.box.0`: axis 0 is too long for 10 particles"],
        ),
        (
            "a rod caged between immovable rods in contact",
            descriptor(
                "box = [20.0]\n\
                 placement = { kind = \"explicit\", positions = [[1.0], [3.0], [2.0]] }\n\
                 velocities = { kind = \"explicit\", velocities = [[0.0], [0.0], [1.0]] }\n\
                 [[scene.species]]\nname = \"wall\"\ncount = 2\nradius = 0.5\nmass = inf\n\
                 [[scene.species]]\nname = \"rod\"\ncount = 1\nradius = 0.5",
                "duration = 50",
                "",
            ),
            &[
                "`scene.placement.positions.2`: the rod at 2 is shut in with no room to move",
                "leave a gap",
            ],
        ),
    ]
}

#[test]
fn runs_that_could_never_end_are_refused_at_validate() {
    let dir = tempfile::tempdir().unwrap();
    for (what, text, expect) in cases() {
        std::fs::write(dir.path().join("s.toml"), &text).unwrap();
        let clock = Instant::now();
        let (code, stderr) = study(&["validate", "s.toml"], dir.path(), Duration::from_secs(30));
        assert_eq!(code, 2, "{what}: exit {code}\n{stderr}");
        assert!(stderr.starts_with("error: s.toml:"), "{what}: {stderr}");
        for part in expect {
            assert!(
                stderr.contains(part),
                "{what}: expected {part:?} in\n{stderr}"
            );
        }
        // Refused from the descriptor alone: nothing is simulated.
        assert!(
            clock.elapsed() < Duration::from_secs(5),
            "{what}: {:?}",
            clock.elapsed()
        );
    }
}

/// The cage handed to the engine directly: every event comes at one
/// instant, and the run halts after the stall bound instead of looping.
#[test]
fn a_clock_that_stands_still_halts_the_run() {
    let rods = vec![
        Particle::new([1.0], [0.0], f64::INFINITY, 0.5),
        Particle::new([2.0], [1.0], 1.0, 0.5),
        Particle::new([3.0], [0.0], f64::INFINITY, 0.5),
    ];
    let mut sim: Rods<()> = Simulation::new(rods, SimBox::hard([20.0]), (), 1).unwrap();
    sim.run(Stop::Time(50.0));
    let Some(Halt::Stalled { time, events }) = sim.halted() else {
        panic!("not stalled: {:?}", sim.halted());
    };
    assert_eq!(time, 0.0);
    // The documented bound: 10^6 + 100 N events in a row at one instant.
    assert_eq!(events, 1_000_000 + 100 * 3);
    // Energy is kept to round-off through every bounce; a halted run stays put.
    assert_eq!(sim.particles()[1].vel[0].abs(), 1.0);
    let before = sim.counts.events;
    sim.run(Stop::Time(100.0));
    assert_eq!(sim.counts.events, before);
}

/// Simultaneous events that are physics, not a stall: a cradle of 2000
/// touching rods passes the impulse down the chain at one instant.
#[test]
fn a_long_cradle_is_not_a_stall() {
    let mut rods = vec![Particle::new([1.0], [1.0], 1.0, 0.5)];
    rods.extend((0..2000).map(|k| Particle::new([3.0 + k as f64], [0.0], 1.0, 0.5)));
    let mut sim: Rods<()> = Simulation::new(rods, SimBox::hard([2010.0]), (), 1).unwrap();
    sim.run(Stop::Time(5.0));
    assert_eq!(sim.halted(), None);
    assert_eq!(sim.particles()[2000].vel[0], 1.0);
}

/// A collision count that can never come: one rod between walls hits them
/// forever, and the event limit halts it; rods at rest have no event at all.
#[test]
fn a_collision_stop_that_never_comes_halts() {
    let one = vec![Particle::new([5.0], [1.0], 1.0, 0.5)];
    let mut sim: Rods<()> = Simulation::new(one, SimBox::hard([10.0]), (), 1).unwrap();
    sim.limit_events(1000);
    sim.run(Stop::Collisions(100));
    assert_eq!(
        sim.halted(),
        Some(Halt::Spent {
            limit: 1000,
            collisions: 0
        })
    );
    assert_eq!(sim.counts.events, 1000);

    let still = vec![
        Particle::new([2.0], [0.0], 1.0, 0.5),
        Particle::new([5.0], [0.0], 1.0, 0.5),
    ];
    let mut sim: Rods<()> = Simulation::new(still, SimBox::hard([10.0]), (), 1).unwrap();
    sim.run(Stop::Collisions(100));
    assert_eq!(sim.halted(), Some(Halt::Still { collisions: 0 }));
    assert!(sim.halted().unwrap().to_string().contains("nothing moves"));
}
