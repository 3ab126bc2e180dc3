//! Counts accumulated over a run in blocks of equally many samples, so that
//! its first and second halves can be told apart without knowing its length
//! in advance: when the blocks reach `MOST`, neighbours merge and each block
//! holds twice the samples. Memory stays at most `MOST` blocks.

use super::state::{StateIn, StateOut};

/// Blocks kept before neighbours merge.
const MOST: usize = 16;

pub struct Blocks {
    size: usize,
    /// Samples in each full block.
    per_block: u64,
    full: Vec<Vec<f64>>,
    current: Vec<f64>,
    in_current: u64,
}

impl Blocks {
    /// Blocks of `size` counts each.
    pub fn new(size: usize) -> Blocks {
        Blocks {
            size,
            per_block: 1,
            full: Vec::new(),
            current: vec![0.0; size],
            in_current: 0,
        }
    }

    /// Its whole state, for a checkpoint.
    pub fn save(&self, out: &mut StateOut) {
        out.number(self.size as f64);
        out.number(self.per_block as f64);
        out.number(self.in_current as f64);
        out.list(&self.current);
        out.number(self.full.len() as f64);
        for block in &self.full {
            out.list(block);
        }
    }

    pub fn restore(from: &mut StateIn) -> Result<Blocks, String> {
        let size = from.number()? as usize;
        let per_block = from.number()? as u64;
        let in_current = from.number()? as u64;
        let current = from.list()?;
        let full = (0..from.number()? as usize)
            .map(|_| from.list())
            .collect::<Result<Vec<_>, _>>()?;
        if current.len() != size || full.iter().any(|b| b.len() != size) {
            return Err("the observers' state holds blocks of another size".into());
        }
        Ok(Blocks {
            size,
            per_block,
            full,
            current,
            in_current,
        })
    }

    /// The counts the sample being read adds to.
    pub fn counts(&mut self) -> &mut [f64] {
        &mut self.current
    }

    /// Close the sample just read.
    pub fn end_sample(&mut self) {
        self.in_current += 1;
        if self.in_current < self.per_block {
            return;
        }
        let block = std::mem::replace(&mut self.current, vec![0.0; self.size]);
        self.full.push(block);
        self.in_current = 0;
        if self.full.len() == MOST {
            let pairs = std::mem::take(&mut self.full);
            for pair in pairs.chunks(2) {
                self.full.push(sum(pair.iter()));
            }
            self.per_block *= 2;
        }
    }

    /// All counts of the run.
    pub fn total(&self) -> Vec<f64> {
        let mut all = sum(self.full.iter());
        all.iter_mut().zip(&self.current).for_each(|(a, c)| *a += c);
        all
    }

    /// The counts of the first and of the second of two equally long
    /// stretches that open the run, and the samples in each: the full
    /// blocks split in two (an odd last block and the unfinished one are
    /// left out: less than a fifth of a long run).
    pub fn halves(&self) -> (Vec<f64>, Vec<f64>, u64) {
        let h = self.full.len() / 2;
        (
            sum(self.full[..h].iter()),
            sum(self.full[h..2 * h].iter()),
            h as u64 * self.per_block,
        )
    }
}

fn sum<'a>(blocks: impl Iterator<Item = &'a Vec<f64>>) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::new();
    for b in blocks {
        if out.is_empty() {
            out = vec![0.0; b.len()];
        }
        out.iter_mut().zip(b).for_each(|(a, c)| *a += c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sample k adds k to its one count: the halves are sums of consecutive
    /// runs of k.
    #[test]
    fn halves_are_consecutive_and_equal() {
        for samples in [0u64, 1, 7, 16, 17, 100, 1000] {
            let mut b = Blocks::new(1);
            for k in 0..samples {
                b.counts()[0] += k as f64;
                b.end_sample();
            }
            let total: f64 = (0..samples).map(|k| k as f64).sum();
            assert_eq!(b.total().first().copied().unwrap_or(0.0), total);
            let (early, late, n) = b.halves();
            let early_expect: f64 = (0..n).map(|k| k as f64).sum();
            let late_expect: f64 = (n..2 * n).map(|k| k as f64).sum();
            assert_eq!(early.first().copied().unwrap_or(0.0), early_expect);
            assert_eq!(late.first().copied().unwrap_or(0.0), late_expect);
            if samples >= 16 {
                assert!(2 * n * 5 >= samples * 4, "{samples}: {n}");
            }
        }
    }
}
