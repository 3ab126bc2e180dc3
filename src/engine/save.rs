//! Save a run and continue it later, bit for bit: the continued run is the
//! same as one never interrupted.
//!
//! Format (little-endian): a header — magic `BONKERS\0`, format version u32,
//! dimension u32, neighbourhood kind u32, total file length u64 — then the
//! state, then an FNV-1a 64 checksum of every byte before it. The length in
//! the header tells a truncated file from a corrupted one. The observer is
//! not saved: the caller hands one to `load`.

use std::io::{self, Read, Write};

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use super::bodies::Bodies;
use super::boundary::{Axis, SimBox, Wall};
use super::neighbours::{PLANE, Persist, image_shift};
use super::next::{Event, Next, Packed};
use super::observer::Observer;
use super::particle::{Particle, Shape};
use super::queue::EventQueue;
use super::simulation::{Counts, Simulation};

const MAGIC: &[u8; 8] = b"BONKERS\0";
/// The format this build writes and reads.
pub const FORMAT_VERSION: u32 = 2;
const HEADER: usize = 8 + 4 + 4 + 4 + 8;
const LENGTH_AT: usize = HEADER - 8;

#[derive(Debug, thiserror::Error)]
pub enum SaveError {
    #[error("not a bonkers save file (it does not start with the bytes BONKERS\\0)")]
    NotASave,
    #[error(
        "save format version {found} is not supported: this build reads version {FORMAT_VERSION}; \
         re-run with the bonkers that wrote it"
    )]
    Version { found: u32 },
    #[error("dimension mismatch: the file holds a {found}D run, loading as {expected}D")]
    Dimension { found: u32, expected: u32 },
    #[error("neighbourhood mismatch: the file holds a {found} run, loading as a {expected} run")]
    Neighbourhood {
        found: &'static str,
        expected: &'static str,
    },
    #[error("truncated save file: it ends after {got} bytes, expected at least {expected}")]
    Truncated { got: u64, expected: u64 },
    #[error("checksum mismatch: the save file is corrupted")]
    Checksum,
    #[error("malformed save file: {0}")]
    Malformed(String),
    #[error("I/O error on the save file: {0}")]
    Io(#[from] io::Error),
}

fn kind_name(kind: u32) -> &'static str {
    match kind {
        0 => "chain (1D)",
        2 => "neighbour list",
        3 => "neighbour list with a plane",
        _ => "unknown neighbourhood",
    }
}

fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

impl<const D: usize, N: Persist<D>, O: Observer<D>> Simulation<D, N, O> {
    /// Write the full state of the run.
    pub fn save(&self, w: &mut impl Write) -> io::Result<()> {
        let mut o = Out(Vec::new());
        o.0.extend(MAGIC);
        o.u32(FORMAT_VERSION);
        o.u32(D as u32);
        o.u32(N::KIND);
        o.u64(0); // total length, filled in below
        o.u64(self.particles.len() as u64);
        for p in &self.particles {
            p.pos.iter().chain(&p.vel).for_each(|&x| o.f64(x));
            [p.t, p.inv_mass, p.radius]
                .into_iter()
                .for_each(|x| o.f64(x));
            o.0.extend(p.species.to_le_bytes());
            o.u8(p.is_plane() as u8);
        }
        self.sim_box.size.iter().for_each(|&x| o.f64(x));
        for axis in &self.sim_box.axes {
            match *axis {
                Axis::Periodic => o.u8(0),
                Axis::Walls { low, high } => {
                    o.u8(1);
                    o.wall(low);
                    o.wall(high);
                }
            }
        }
        for event in self.queue.whats() {
            match event.next.unpack() {
                Next::Nothing => o.u8(0),
                Next::Pair { j, stamp, image } => {
                    o.u8(1);
                    o.u32(j);
                    o.u32(stamp);
                    o.u8(image);
                }
                Next::Wall { axis, high } => {
                    o.u8(2);
                    o.u8(axis);
                    o.u8(high as u8);
                }
                Next::Renew => o.u8(3),
            }
        }
        self.queue.whats().for_each(|e| o.u32(e.stamp));
        self.queue.times().for_each(|t| o.f64(t));
        o.f64(self.now);
        o.f64(self.origin);
        o.u64(self.rebase_every);
        o.u64(self.events_since_rebase);
        match self.sample_every {
            None => o.u8(0),
            Some(dt) => {
                o.u8(1);
                o.f64(dt);
            }
        }
        o.u64(self.samples_taken);
        o.f64(self.sample_start);
        // The stream position is enough to resume it: (seed, stream, word).
        o.0.extend(self.rng.get_seed());
        o.u64(self.rng.get_stream());
        o.0.extend(self.rng.get_word_pos().to_le_bytes());
        let c = &self.counts;
        for x in [
            c.events,
            c.collisions,
            c.wall_hits,
            c.renewals,
            c.stale,
            c.samples,
        ] {
            o.u64(x);
        }
        let state = self.neighbours.state();
        o.u64(state.len() as u64);
        state.iter().for_each(|&x| o.u32(x));
        let total = (o.0.len() + 8) as u64;
        o.0[LENGTH_AT..HEADER].copy_from_slice(&total.to_le_bytes());
        let sum = fnv1a(&o.0);
        o.u64(sum);
        w.write_all(&o.0)
    }

    /// Read a run written by `save`; it continues exactly where it stopped.
    /// Reads no further than the end of the save.
    pub fn load(r: &mut impl Read, observer: O) -> Result<Self, SaveError> {
        let bytes = read_checked::<D>(r, N::KIND)?;
        let mut i = In {
            bytes: &bytes[..bytes.len() - 8],
            at: HEADER,
        };
        let n = i.u64()? as usize;
        let mut particles = Vec::new();
        for _ in 0..n {
            let pos = i.vector::<D>()?;
            let vel = i.vector::<D>()?;
            let (t, inv_mass, radius) = (i.f64()?, i.f64()?, i.f64()?);
            let species = u16::from_le_bytes(i.array()?);
            let shape = match i.u8()? {
                0 => Shape::Ball,
                1 => Shape::Plane,
                tag => return Err(malformed(format!("unknown particle shape {tag}"))),
            };
            particles.push(Particle {
                pos,
                vel,
                t,
                inv_mass,
                radius,
                species,
                shape,
            });
        }
        let size = i.vector::<D>()?;
        let mut axes = [Axis::Periodic; D];
        for axis in &mut axes {
            *axis = match i.u8()? {
                0 => Axis::Periodic,
                1 => Axis::Walls {
                    low: i.wall()?,
                    high: i.wall()?,
                },
                tag => return Err(malformed(format!("unknown axis kind {tag}"))),
            };
        }
        let sim_box = SimBox { size, axes };
        let mut next = Vec::new();
        for _ in 0..n {
            next.push(match i.u8()? {
                0 => Next::Nothing,
                1 => Next::Pair {
                    j: i.u32()?,
                    stamp: i.u32()?,
                    image: i.u8()?,
                },
                2 => Next::Wall {
                    axis: i.u8()?,
                    high: i.u8()? != 0,
                },
                3 => Next::Renew,
                tag => return Err(malformed(format!("unknown event kind {tag}"))),
            });
        }
        // An event naming a particle or axis that does not exist would panic
        // mid-run; refuse it here.
        let images = 3u32.pow(D as u32);
        if next.iter().any(|e| match *e {
            Next::Pair { j, image, .. } => {
                j as usize >= n || (image as u32 >= images && !(N::PLANES && image == PLANE))
            }
            Next::Wall { axis, .. } => axis as usize >= D,
            Next::Nothing | Next::Renew => false,
        }) {
            return Err(malformed(
                "an event names a particle or axis that does not exist".into(),
            ));
        }
        let stamp = (0..n).map(|_| i.u32()).collect::<Result<Vec<_>, _>>()?;
        let times = (0..n).map(|_| i.f64()).collect::<Result<Vec<_>, _>>()?;
        let (now, origin) = (i.f64()?, i.f64()?);
        let (rebase_every, events_since_rebase) = (i.u64()?, i.u64()?);
        let sample_every = match i.u8()? {
            0 => None,
            _ => Some(i.f64()?),
        };
        let (samples_taken, sample_start) = (i.u64()?, i.f64()?);
        let mut rng = ChaCha8Rng::from_seed(i.array()?);
        rng.set_stream(i.u64()?);
        rng.set_word_pos(u128::from_le_bytes(i.array()?));
        let mut c = [0u64; 6];
        for x in &mut c {
            *x = i.u64()?;
        }
        let counts = Counts {
            events: c[0],
            collisions: c[1],
            wall_hits: c[2],
            renewals: c[3],
            stale: c[4],
            samples: c[5],
        };
        let words = i.u64()? as usize;
        let state = (0..words).map(|_| i.u32()).collect::<Result<Vec<_>, _>>()?;
        if i.at != i.bytes.len() {
            return Err(malformed(format!(
                "{} bytes left over after the state",
                i.bytes.len() - i.at
            )));
        }
        let neighbours = N::restore(&particles, &sim_box, &state).map_err(SaveError::Malformed)?;
        let mut bodies = Bodies::new(&particles);
        for (b, &t) in bodies.bodies_mut().iter_mut().zip(&times) {
            b.due = t;
        }
        let mut queue = EventQueue::from_times(times);
        for (k, (next, stamp)) in next.into_iter().zip(stamp).enumerate() {
            *queue.what_mut(k) = Event {
                next: Packed::pack(next),
                stamp,
            };
        }
        Ok(Simulation {
            shifts: (0..images)
                .map(|c| image_shift(c as u8, &sim_box.size))
                .collect(),
            particles: bodies,
            sim_box,
            neighbours,
            queue,
            unstamped: Vec::new(),
            now,
            origin,
            rebase_every,
            events_since_rebase,
            sample_every,
            samples_taken,
            sample_start,
            rng,
            batch: super::contacts::Batch::new(),
            prefetch_partners: super::simulation::worth_prefetching(n),
            counts,
            same_instant: 0,
            stall_after: super::halt::stall_bound(n),
            event_limit: u64::MAX,
            halt: None,
            observer,
        })
    }
}

/// Read the header and the rest of the save; check magic, version,
/// dimension, kind, length and checksum, in that order, so each failure is
/// named for what it is (a file from version 2 fails on its version, not on
/// a checksum it computes differently).
fn read_checked<const D: usize>(r: &mut impl Read, kind: u32) -> Result<Vec<u8>, SaveError> {
    let mut bytes = vec![0u8; HEADER];
    let got = fill(r, &mut bytes)?;
    let truncated = |got: usize, expected: usize| SaveError::Truncated {
        got: got as u64,
        expected: expected as u64,
    };
    let magic_len = got.min(MAGIC.len());
    if bytes[..magic_len] != MAGIC[..magic_len] {
        return Err(SaveError::NotASave);
    }
    let field = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
    if got < 12 {
        return Err(truncated(got, HEADER));
    }
    if field(8) != FORMAT_VERSION {
        return Err(SaveError::Version { found: field(8) });
    }
    if got < 16 {
        return Err(truncated(got, HEADER));
    }
    if field(12) != D as u32 {
        return Err(SaveError::Dimension {
            found: field(12),
            expected: D as u32,
        });
    }
    if got < 20 {
        return Err(truncated(got, HEADER));
    }
    if field(16) != kind {
        return Err(SaveError::Neighbourhood {
            found: kind_name(field(16)),
            expected: kind_name(kind),
        });
    }
    if got < HEADER {
        return Err(truncated(got, HEADER));
    }
    let total = u64::from_le_bytes(bytes[LENGTH_AT..HEADER].try_into().unwrap());
    if total < (HEADER + 8) as u64 {
        return Err(SaveError::Checksum);
    }
    // `take` bounds the read, so a corrupted length cannot allocate wildly.
    r.take(total - HEADER as u64).read_to_end(&mut bytes)?;
    if (bytes.len() as u64) < total {
        return Err(truncated(bytes.len(), total as usize));
    }
    let (body, sum) = bytes.split_at(bytes.len() - 8);
    if fnv1a(body) != u64::from_le_bytes(sum.try_into().unwrap()) {
        return Err(SaveError::Checksum);
    }
    Ok(bytes)
}

/// Read until `buf` is full or the input ends; how many bytes were read.
fn fill(r: &mut impl Read, buf: &mut [u8]) -> io::Result<usize> {
    let mut got = 0;
    while got < buf.len() {
        match r.read(&mut buf[got..]) {
            Ok(0) => break,
            Ok(k) => got += k,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(got)
}

fn malformed(msg: String) -> SaveError {
    SaveError::Malformed(msg)
}

struct Out(Vec<u8>);

impl Out {
    fn u8(&mut self, x: u8) {
        self.0.push(x);
    }
    fn u32(&mut self, x: u32) {
        self.0.extend(x.to_le_bytes());
    }
    fn u64(&mut self, x: u64) {
        self.0.extend(x.to_le_bytes());
    }
    fn f64(&mut self, x: f64) {
        self.u64(x.to_bits());
    }
    fn wall(&mut self, wall: Wall) {
        match wall {
            Wall::Hard => self.u8(0),
            Wall::Thermal { temperature } => {
                self.u8(1);
                self.f64(temperature);
            }
        }
    }
}

/// A cursor over a save whose length and checksum are already verified, so
/// running out of bytes here means the file is inconsistent, not truncated.
struct In<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl In<'_> {
    fn array<const K: usize>(&mut self) -> Result<[u8; K], SaveError> {
        let end = self.at + K;
        let b = self
            .bytes
            .get(self.at..end)
            .ok_or_else(|| malformed("the state ends early".into()))?;
        self.at = end;
        Ok(b.try_into().unwrap())
    }
    fn u8(&mut self) -> Result<u8, SaveError> {
        Ok(self.array::<1>()?[0])
    }
    fn u32(&mut self) -> Result<u32, SaveError> {
        Ok(u32::from_le_bytes(self.array()?))
    }
    fn u64(&mut self) -> Result<u64, SaveError> {
        Ok(u64::from_le_bytes(self.array()?))
    }
    fn f64(&mut self) -> Result<f64, SaveError> {
        Ok(f64::from_bits(self.u64()?))
    }
    fn vector<const D: usize>(&mut self) -> Result<[f64; D], SaveError> {
        let mut v = [0.0; D];
        for x in &mut v {
            *x = self.f64()?;
        }
        Ok(v)
    }
    fn wall(&mut self) -> Result<Wall, SaveError> {
        match self.u8()? {
            0 => Ok(Wall::Hard),
            1 => Ok(Wall::Thermal {
                temperature: self.f64()?,
            }),
            tag => Err(malformed(format!("unknown wall kind {tag}"))),
        }
    }
}
