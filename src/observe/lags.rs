//! The fixed grid of lags, in samples, on which correlations against lag
//! accumulate as a run goes, and the ring of recent samples they need:
//! memory is one row per sample of the longest lag, whatever the run's length.

use super::state::{StateIn, StateOut};

/// Lags in samples: roughly geometric, two to an octave, up to 1024.
pub const LAGS: [usize; 21] = [
    1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 640, 768, 1024,
];

/// The last `LAGS.last() + 1` rows of `width` values each, with their times.
pub struct Ring {
    width: usize,
    rows: Vec<f64>,
    times: Vec<f64>,
    /// Samples pushed so far.
    pub pushed: usize,
}

impl Ring {
    const DEPTH: usize = LAGS[LAGS.len() - 1] + 1;

    pub fn new(width: usize) -> Ring {
        Ring {
            width,
            rows: Vec::new(),
            times: Vec::new(),
            pushed: 0,
        }
    }

    /// Append the newest row (the oldest beyond the longest lag is dropped).
    pub fn push(&mut self, time: f64, row: &[f64]) {
        debug_assert_eq!(row.len(), self.width);
        if self.rows.is_empty() {
            self.rows = vec![0.0; self.width * Self::DEPTH];
            self.times = vec![0.0; Self::DEPTH];
        }
        let slot = self.pushed % Self::DEPTH;
        self.rows[slot * self.width..(slot + 1) * self.width].copy_from_slice(row);
        self.times[slot] = time;
        self.pushed += 1;
    }

    /// Its whole state, for a checkpoint.
    pub fn save(&self, out: &mut StateOut) {
        out.number(self.width as f64);
        out.number(self.pushed as f64);
        out.list(&self.rows);
        out.list(&self.times);
    }

    pub fn restore(from: &mut StateIn) -> Result<Ring, String> {
        Ok(Ring {
            width: from.number()? as usize,
            pushed: from.number()? as usize,
            rows: from.list()?,
            times: from.list()?,
        })
    }

    /// The row `lag` samples before the newest, with its time, if kept.
    pub fn back(&self, lag: usize) -> Option<(f64, &[f64])> {
        if lag >= self.pushed || lag >= Self::DEPTH {
            return None;
        }
        let slot = (self.pushed - 1 - lag) % Self::DEPTH;
        Some((
            self.times[slot],
            &self.rows[slot * self.width..(slot + 1) * self.width],
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ring_gives_back_what_was_pushed_up_to_its_depth() {
        let mut ring = Ring::new(2);
        for n in 0..3000 {
            ring.push(n as f64, &[n as f64, -(n as f64)]);
        }
        assert_eq!(ring.back(0), Some((2999.0, &[2999.0, -2999.0][..])));
        assert_eq!(ring.back(1024), Some((1975.0, &[1975.0, -1975.0][..])));
        assert_eq!(ring.back(1025), None);
        let mut short = Ring::new(1);
        short.push(0.5, &[7.0]);
        assert_eq!(short.back(0), Some((0.5, &[7.0][..])));
        assert_eq!(short.back(1), None);
    }
}
