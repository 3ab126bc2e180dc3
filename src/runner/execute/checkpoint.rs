//! Checkpoints of long runs: every few minutes of wall time a run saves its
//! full state into `OUT/runs/run-<seed>.ckpt` (the engine's save format, the
//! observers' accumulated state, and where the run is: equilibrating or
//! measuring, since when), so a run killed by a time limit, a failed node or
//! Ctrl-C continues from there, bit for bit, when the study is run again.
//! The file is written atomically and removed once the run's record is
//! saved; one written by another descriptor or bonkers version (its
//! fingerprint differs) or one that does not read back is ignored.
//!
//! The runner tells the simulator where a run's checkpoint goes through a
//! per-thread slot (`scoped`), set only while it simulates that run on that
//! thread, so the simulator's signature (`Fn(&RunSpec)`) stays what tests and
//! other front ends use.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Every this often by default (`--checkpoint-every`).
pub const DEFAULT_EVERY: Duration = Duration::from_secs(300);

/// Where and how often the run on this thread checkpoints.
#[derive(Debug, Clone, PartialEq)]
pub struct Place {
    pub path: PathBuf,
    pub every: Duration,
    /// The run's fingerprint (`run::fingerprint`): a checkpoint is only
    /// continued by the run that wrote it.
    pub fingerprint: String,
    /// Set by the simulator when it continued from a checkpoint.
    pub continued: bool,
}

thread_local! {
    static PLACE: RefCell<Option<Place>> = const { RefCell::new(None) };
}

/// Run `f` with `place` as this thread's checkpoint place; returns what `f`
/// returned and whether the run continued from a checkpoint.
pub fn scoped<R>(place: Option<Place>, f: impl FnOnce() -> R) -> (R, bool) {
    PLACE.with(|p| *p.borrow_mut() = place);
    let result = f();
    let continued = PLACE.with(|p| p.borrow_mut().take().is_some_and(|p| p.continued));
    (result, continued)
}

/// This thread's checkpoint place, if the runner set one.
pub fn current() -> Option<Place> {
    PLACE.with(|p| p.borrow().clone())
}

/// Note that the run on this thread continued from its checkpoint.
pub fn mark_continued() {
    PLACE.with(|p| {
        if let Some(place) = p.borrow_mut().as_mut() {
            place.continued = true;
        }
    });
}

/// `OUT/runs/run-<seed>.ckpt`.
pub fn file(runs_dir: &Path, seed: u64) -> PathBuf {
    runs_dir.join(format!("run-{seed}.ckpt"))
}

/// Where a run was when it saved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Phase {
    Equilibrating,
    /// Measuring since simulation time `start`, when the kinetic energy was
    /// `energy0`; a run of a fixed number of collisions ends when the engine
    /// has counted `end_collisions`.
    Measuring {
        start: f64,
        energy0: f64,
        end_collisions: u64,
    },
}

/// A run's saved state.
#[derive(Debug, Clone, PartialEq)]
pub struct Saved {
    pub phase: Phase,
    /// Wall and CPU seconds the run had spent before it saved.
    pub wall_seconds: f64,
    pub cpu_seconds: f64,
    /// `ObserverSet::save_state`.
    pub observers: Vec<f64>,
    /// `Simulation::save`.
    pub engine: Vec<u8>,
}

const MAGIC: &[u8; 8] = b"BONKCKPT";
const VERSION: u32 = 1;

impl Saved {
    /// Header, fingerprint, phase, times, observers, engine, checksum.
    pub fn encode(&self, fingerprint: &str) -> Vec<u8> {
        let mut o = Vec::new();
        o.extend(MAGIC);
        o.extend(VERSION.to_le_bytes());
        bytes(&mut o, fingerprint.as_bytes());
        let (tag, start, energy0, end) = match self.phase {
            Phase::Equilibrating => (0u8, 0.0, 0.0, 0),
            Phase::Measuring {
                start,
                energy0,
                end_collisions,
            } => (1, start, energy0, end_collisions),
        };
        o.push(tag);
        for x in [start, energy0, self.wall_seconds, self.cpu_seconds] {
            o.extend(x.to_bits().to_le_bytes());
        }
        o.extend(end.to_le_bytes());
        o.extend((self.observers.len() as u64).to_le_bytes());
        for x in &self.observers {
            o.extend(x.to_bits().to_le_bytes());
        }
        bytes(&mut o, &self.engine);
        let sum = crate::runner::plan::seeds::fnv1a(&o);
        o.extend(sum.to_le_bytes());
        o
    }

    /// Read back what `encode` wrote for the run with `fingerprint`; why not.
    pub fn decode(data: &[u8], fingerprint: &str) -> Result<Saved, String> {
        let (body, sum) = data
            .split_last_chunk::<8>()
            .ok_or("the checkpoint is empty")?;
        if crate::runner::plan::seeds::fnv1a(body) != u64::from_le_bytes(*sum) {
            return Err("the checkpoint is damaged (checksum)".into());
        }
        let mut r = Reader { data: body, at: 0 };
        if r.take(8)? != MAGIC || r.u32()? != VERSION {
            return Err("not a checkpoint of this bonkers version".into());
        }
        if r.bytes()? != fingerprint.as_bytes() {
            return Err("made by another descriptor or bonkers version".into());
        }
        let tag = r.take(1)?[0];
        let [start, energy0, wall_seconds, cpu_seconds] = [r.f64()?, r.f64()?, r.f64()?, r.f64()?];
        let end_collisions = r.u64()?;
        let phase = match tag {
            0 => Phase::Equilibrating,
            1 => Phase::Measuring {
                start,
                energy0,
                end_collisions,
            },
            t => return Err(format!("unknown phase {t}")),
        };
        let n = r.u64()? as usize;
        let observers = (0..n).map(|_| r.f64()).collect::<Result<_, _>>()?;
        let engine = r.bytes()?.to_vec();
        if r.at != body.len() {
            return Err("the checkpoint has trailing bytes".into());
        }
        Ok(Saved {
            phase,
            wall_seconds,
            cpu_seconds,
            observers,
            engine,
        })
    }
}

fn bytes(o: &mut Vec<u8>, b: &[u8]) {
    o.extend((b.len() as u64).to_le_bytes());
    o.extend(b);
}

struct Reader<'a> {
    data: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Result<&'a [u8], String> {
        let end = self
            .at
            .checked_add(n)
            .filter(|&e| e <= self.data.len())
            .ok_or("the checkpoint ends early")?;
        let s = &self.data[self.at..end];
        self.at = end;
        Ok(s)
    }
    fn u32(&mut self) -> Result<u32, String> {
        Ok(u32::from_le_bytes(
            self.take(4)?.try_into().unwrap_or_default(),
        ))
    }
    fn u64(&mut self) -> Result<u64, String> {
        Ok(u64::from_le_bytes(
            self.take(8)?.try_into().unwrap_or_default(),
        ))
    }
    fn f64(&mut self) -> Result<f64, String> {
        self.u64().map(f64::from_bits)
    }
    fn bytes(&mut self) -> Result<&'a [u8], String> {
        let n = self.u64()? as usize;
        self.take(n)
    }
}

/// The checkpoint at `place`, if there is one this run can continue: a
/// regular file (a link is not followed, a device or pipe not read).
pub fn read(place: &Place) -> Option<Saved> {
    let limit = crate::runner::store::outdir::CHECKPOINT_LIMIT;
    let data = crate::runner::store::outdir::read_own(&place.path, limit).ok()?;
    Saved::decode(&data, &place.fingerprint).ok()
}

/// Save `saved` at `place`, atomically.
pub fn write(place: &Place, saved: &Saved) -> anyhow::Result<()> {
    crate::files::write_atomic(&place.path, &saved.encode(&place.fingerprint))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_checkpoint_reads_back_and_refuses_others() {
        let saved = Saved {
            phase: Phase::Measuring {
                start: 10.5,
                energy0: f64::MIN_POSITIVE,
                end_collisions: 7,
            },
            wall_seconds: 1.25,
            cpu_seconds: f64::NAN,
            observers: vec![1.0, -0.0, f64::INFINITY],
            engine: vec![1, 2, 3],
        };
        let data = saved.encode("abc");
        let back = Saved::decode(&data, "abc").unwrap();
        assert_eq!(back.phase, saved.phase);
        assert_eq!(back.engine, saved.engine);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&back.observers), bits(&saved.observers));
        assert!(back.cpu_seconds.is_nan());
        assert!(Saved::decode(&data, "abd").unwrap_err().contains("another"));
        let mut bad = data.clone();
        bad[20] ^= 1;
        assert!(Saved::decode(&bad, "abc").unwrap_err().contains("damaged"));
        assert!(Saved::decode(&data[..data.len() - 3], "abc").is_err());
    }
}
