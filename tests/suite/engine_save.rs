//! Save and continue: a run saved halfway, dropped, loaded and continued is
//! bit-identical to one never interrupted; broken files fail with clear errors.

use crate::common;

use bonkers::engine::{
    Axis, Chain, Counts, Disks, FORMAT_VERSION, NeighbourList, Observer, PairCollision, Particle,
    Persist, Rods, SaveError, SimBox, Simulation, Snapshot, Spheres, Stop, Wall, WallHit,
};

/// Everything the observer hooks see, as bits, in order.
#[derive(Debug, Default, PartialEq)]
struct Recorder(Vec<u64>);

impl<const D: usize> Observer<D> for Recorder {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        self.0.extend([1, e.time.to_bits(), e.i as u64, e.j as u64]);
    }
    fn wall_hit(&mut self, e: &WallHit<D>) {
        self.0
            .extend([2, e.time.to_bits(), e.energy_gain.to_bits()]);
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        let x_sum: f64 = (0..s.particles.len()).map(|i| s.position(i)[0]).sum();
        self.0.extend([
            3,
            s.time.to_bits(),
            s.kinetic_energy().to_bits(),
            x_sum.to_bits(),
        ]);
    }
}

fn bits<const D: usize>(ps: &[Particle<D>]) -> Vec<u64> {
    ps.iter()
        .flat_map(|p| {
            p.pos
                .iter()
                .chain(&p.vel)
                .chain([&p.t])
                .map(|x| x.to_bits())
        })
        .collect()
}

fn save<const D: usize, N: Persist<D>, O: Observer<D>>(sim: &Simulation<D, N, O>) -> Vec<u8> {
    let mut bytes = Vec::new();
    sim.save(&mut bytes).unwrap();
    bytes
}

/// Run A straight through `whole`; run B through `first`, save, drop, load,
/// then through `second`. Both end in the same state, bit for bit, having
/// shown their observers the same events. Returns B's counts at the save.
fn continues_bit_identically<const D: usize, N: Persist<D>>(
    (particles, sim_box): (Vec<Particle<D>>, SimBox<D>),
    sample_every: Option<f64>,
    whole: Stop,
    [first, second]: [Stop; 2],
) -> Counts {
    let build = || {
        let mut sim =
            Simulation::<D, N, Recorder>::new(particles.clone(), sim_box, Recorder::default(), 7)
                .unwrap();
        sim.sample_every(sample_every);
        sim
    };
    let mut a = build();
    a.run(whole);

    let mut b = build();
    b.run(first);
    let halfway = b.counts;
    let bytes = save(&b);
    let seen_before = b.into_observer().0;
    let mut b =
        Simulation::<D, N, Recorder>::load(&mut bytes.as_slice(), Recorder::default()).unwrap();
    assert_eq!(save(&b), bytes, "load then save gives back the same bytes");
    b.run(second);

    assert_eq!(bits(&a.particles().to_vec()), bits(&b.particles().to_vec()));
    assert_eq!(a.counts, b.counts);
    assert_eq!(a.time().to_bits(), b.time().to_bits());
    // The whole state, queue and random stream included, not just what shows.
    assert_eq!(save(&a), save(&b));
    let seen_after = b.into_observer().0;
    assert!(!seen_after.is_empty(), "the continued half did something");
    assert_eq!(a.into_observer().0, [seen_before, seen_after].concat());
    halfway
}

fn by_collisions(m: u64) -> (Stop, [Stop; 2]) {
    (Stop::Collisions(2 * m), [Stop::Collisions(m); 2])
}

fn by_time(t: f64) -> (Stop, [Stop; 2]) {
    (Stop::Time(t), [Stop::Time(t / 2.0), Stop::Time(t)])
}

/// Rods of two masses, spread along a line between hard walls.
fn rods(n: usize) -> (Vec<Particle<1>>, SimBox<1>) {
    let mut rng = common::rng(3);
    let particles = (0..n)
        .map(|i| {
            let mass = if i % 3 == 0 { 2.0 } else { 1.0 };
            Particle::new(
                [2.0 * i as f64 + 1.0],
                [common::gaussian(&mut rng)],
                mass,
                0.4,
            )
        })
        .collect();
    (particles, SimBox::hard([2.0 * n as f64]))
}

/// Disks on a square lattice, periodic in y, with a thermal wall at x = 0.
fn disks_with_thermal_wall() -> (Vec<Particle<2>>, SimBox<2>) {
    let (particles, mut sim_box) = common::lattice::<2>(10, 1.5, 5);
    sim_box.axes[0] = Axis::Walls {
        low: Wall::Thermal { temperature: 2.0 },
        high: Wall::Hard,
    };
    (particles, sim_box)
}

#[test]
fn rods_between_hard_walls_continue_bit_identically() {
    let (whole, halves) = by_collisions(20_000);
    let at_save = continues_bit_identically::<1, Chain>(rods(50), None, whole, halves);
    assert!(at_save.wall_hits > 0);
    let (whole, halves) = by_time(400.0);
    continues_bit_identically::<1, Chain>(rods(50), Some(0.7), whole, halves);
}

#[test]
fn periodic_disks_continue_bit_identically() {
    let (whole, halves) = by_collisions(20_000);
    let hex = || common::hexagonal(10, 10, 0.4, 11);
    let at_save = continues_bit_identically::<2, NeighbourList<2>>(hex(), None, whole, halves);
    assert!(at_save.renewals > 0);
    let (whole, halves) = by_time(50.0);
    continues_bit_identically::<2, NeighbourList<2>>(hex(), Some(0.3), whole, halves);
}

#[test]
fn disks_at_a_thermal_wall_continue_bit_identically() {
    // The thermal wall draws from the random stream: its state must carry over.
    let (whole, halves) = by_collisions(20_000);
    let at_save = continues_bit_identically::<2, NeighbourList<2>>(
        disks_with_thermal_wall(),
        Some(0.5),
        whole,
        halves,
    );
    assert!(at_save.wall_hits > 0);
}

/// Disks either side of a movable plane (the 2D piston), walls along x,
/// periodic along y.
fn disks_with_a_plane() -> (Vec<Particle<2>>, SimBox<2>) {
    let (mut particles, mut sim_box) = common::lattice::<2>(10, 1.6, 17);
    sim_box.axes[0] = Axis::HARD;
    // Lattice columns sit at x = 0.8, 2.4, ..., so x = 8 is 0.8 from the nearest.
    particles.push(Particle::plane(8.0, 0.1, 10.0, 0.2));
    (particles, sim_box)
}

#[test]
fn disks_with_a_plane_continue_bit_identically() {
    let (whole, halves) = by_collisions(20_000);
    continues_bit_identically::<2, NeighbourList<2, true>>(
        disks_with_a_plane(),
        Some(0.5),
        whole,
        halves,
    );
}

#[test]
fn periodic_spheres_continue_bit_identically() {
    let (whole, halves) = by_collisions(20_000);
    continues_bit_identically::<3, NeighbourList<3>>(
        common::fcc(3, 0.3, 13),
        Some(0.2),
        whole,
        halves,
    );
}

/// A small 1D run, saved after some collisions.
fn small_save() -> Vec<u8> {
    let (particles, sim_box) = rods(4);
    let mut sim = Rods::new(particles, sim_box, (), 1).unwrap();
    sim.run(Stop::Collisions(10));
    save(&sim)
}

fn load_rods(bytes: &[u8]) -> Result<Rods<()>, SaveError> {
    Rods::load(&mut &bytes[..], ())
}

#[test]
fn every_truncation_is_reported_as_truncated() {
    let bytes = small_save();
    assert!(load_rods(&bytes).is_ok());
    for len in 0..bytes.len() {
        match load_rods(&bytes[..len]) {
            Err(SaveError::Truncated { got, expected }) => {
                assert_eq!(got, len as u64);
                assert!(expected > got);
            }
            other => panic!("prefix of {len} bytes: {other:?}"),
        }
    }
    let message = load_rods(&bytes[..40]).err().unwrap().to_string();
    assert!(message.contains("ends after 40 bytes"), "{message}");
}

#[test]
fn every_flipped_byte_after_the_header_fails_the_checksum() {
    let bytes = small_save();
    // The header is magic, version, dimension, kind (20 bytes) and length (8).
    for k in 28..bytes.len() {
        let mut bad = bytes.clone();
        bad[k] ^= 0x10;
        assert!(
            matches!(load_rods(&bad), Err(SaveError::Checksum)),
            "byte {k} flipped"
        );
    }
}

#[test]
fn a_file_that_is_not_a_save_is_refused() {
    let mut bytes = small_save();
    bytes[0] = b'b';
    assert!(matches!(load_rods(&bytes), Err(SaveError::NotASave)));
    assert!(matches!(load_rods(b"PK\x03\x04"), Err(SaveError::NotASave)));
    let message = load_rods(b"{\"json\": true}").err().unwrap().to_string();
    assert!(message.contains("not a bonkers save file"), "{message}");
}

#[test]
fn another_format_version_is_refused_by_name() {
    let other = FORMAT_VERSION + 1;
    let mut bytes = small_save();
    bytes[8..12].copy_from_slice(&other.to_le_bytes());
    let err = load_rods(&bytes).err().unwrap();
    assert!(
        matches!(err, SaveError::Version { found } if found == other),
        "{err:?}"
    );
    let message = err.to_string();
    assert!(
        message.contains(&format!("version {other}"))
            && message.contains(&format!("reads version {FORMAT_VERSION}")),
        "{message}"
    );
}

#[test]
fn a_2d_run_does_not_load_as_3d() {
    let (particles, sim_box) = common::hexagonal(6, 6, 0.3, 2);
    let mut sim = Disks::new(particles, sim_box, (), 1).unwrap();
    sim.run(Stop::Collisions(100));
    let bytes = save(&sim);
    let err = Spheres::load(&mut bytes.as_slice(), ()).err().unwrap();
    assert!(
        matches!(
            err,
            SaveError::Dimension {
                found: 2,
                expected: 3
            }
        ),
        "{err:?}"
    );
    assert!(err.to_string().contains("2D run, loading as 3D"), "{err}");
    assert!(Disks::load(&mut bytes.as_slice(), ()).is_ok());
}

#[test]
fn load_stops_at_the_end_of_its_save() {
    // Two saves back to back in one stream load one after the other.
    let bytes = small_save();
    let stream = [bytes.clone(), bytes.clone()].concat();
    let mut r = stream.as_slice();
    for _ in 0..2 {
        let sim = Rods::load(&mut r, ()).unwrap();
        assert_eq!(save(&sim), bytes);
    }
    assert!(r.is_empty());
}
