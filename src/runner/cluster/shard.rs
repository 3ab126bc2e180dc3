//! `--shard K/N`: one of N slices of a plan, for job arrays. Every run is in
//! exactly one shard, whatever N: the slices are dealt longest first, each
//! run to the shard with the least estimated work so far (ties to the lower
//! shard), so shards take about equally long even when sweep points differ
//! in cost. The deal is a function of the plan alone, so every array task
//! computes the same one without talking to the others.

use crate::model::run_spec::RunSpec;
use crate::runner::plan::estimate;
use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::fmt;
use std::str::FromStr;

/// Shard `index` (1-based, as Slurm array task ids are) of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

impl Shard {
    /// "K-of-N": how file names tell shards apart.
    pub fn tag(&self) -> String {
        format!("{}-of-{}", self.index, self.count)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = String;

    fn from_str(s: &str) -> Result<Shard, String> {
        let bad = || format!("`{s}` is not a shard: write K/N with 1 <= K <= N, e.g. 2/8");
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let index: u32 = k.trim().parse().map_err(|_| bad())?;
        let count: u32 = n.trim().parse().map_err(|_| bad())?;
        if count == 0 || index == 0 || index > count {
            return Err(bad());
        }
        Ok(Shard { index, count })
    }
}

/// Estimated CPU seconds of each run of the plan, by position. A run whose
/// scene the estimate cannot resolve counts as the mean of the others (1 s
/// if none resolves), so it is still dealt somewhere.
pub fn estimated_seconds(specs: &[RunSpec]) -> Vec<f64> {
    let mut seconds: Vec<Option<f64>> = Vec::with_capacity(specs.len());
    for (i, spec) in specs.iter().enumerate() {
        // Replicas of a point share its descriptor: one estimate per point.
        let same_point = i > 0 && specs[i - 1].point_id == spec.point_id;
        let s = if same_point {
            seconds[i - 1]
        } else {
            estimate::run_cost(&spec.descriptor).map(|c| c.seconds())
        };
        seconds.push(s.filter(|s| s.is_finite() && *s >= 0.0));
    }
    let known: Vec<f64> = seconds.iter().flatten().copied().collect();
    let fallback = if known.is_empty() {
        1.0
    } else {
        known.iter().sum::<f64>() / known.len() as f64
    };
    seconds.into_iter().map(|s| s.unwrap_or(fallback)).collect()
}

/// The shard (1-based) of each run of the plan, by position, for `count`
/// shards, dealt by `seconds` (see the module comment). Memory follows the
/// plan, not `count`: an untouched shard is never picked before a lower
/// untouched one, so R runs reach only shards 1 to R, and only those are
/// kept (the deal is the one all `count` shards would give).
pub fn deal(seconds: &[f64], count: u32) -> Vec<u32> {
    let mut order: Vec<usize> = (0..seconds.len()).collect();
    order.sort_by(|&a, &b| seconds[b].total_cmp(&seconds[a]).then(a.cmp(&b)));
    let reachable = u32::try_from(seconds.len()).unwrap_or(u32::MAX);
    // Loads are finite and >= 0, where the order of f64 bits is that of
    // the numbers: an exact, integer key.
    let mut loads: BinaryHeap<Reverse<(u64, u32)>> = (1..=count.min(reachable).max(1))
        .map(|k| Reverse((0, k)))
        .collect();
    let mut shard = vec![0; seconds.len()];
    for i in order {
        let Some(Reverse((load, k))) = loads.pop() else {
            break;
        };
        shard[i] = k;
        let load = f64::from_bits(load) + seconds[i];
        loads.push(Reverse((load.to_bits(), k)));
    }
    shard
}

/// Estimated CPU seconds of each shard (index 0 is shard 1).
pub fn loads(seconds: &[f64], shards: &[u32], count: u32) -> Vec<f64> {
    let mut loads = vec![0.0; count as usize];
    for (s, &k) in seconds.iter().zip(shards) {
        loads[k as usize - 1] += s;
    }
    loads
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_parse_and_refuse_nonsense() {
        assert_eq!("2/8".parse(), Ok(Shard { index: 2, count: 8 }));
        for bad in ["0/3", "4/3", "1/0", "3", "a/b", "1/3/4", ""] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
    }

    #[test]
    fn every_run_is_in_exactly_one_shard_and_loads_are_balanced() {
        let seconds: Vec<f64> = (0..50).map(|i| 1.0 + (i % 7) as f64).collect();
        for n in [1, 2, 3, 7, 50, 80] {
            let shards = deal(&seconds, n);
            assert!(shards.iter().all(|&k| (1..=n).contains(&k)));
            let loads = loads(&seconds, &shards, n);
            let total: f64 = seconds.iter().sum();
            assert_eq!(loads.iter().sum::<f64>(), total);
            // Longest first: no shard exceeds the mean by more than one run.
            let mean = total / n as f64;
            assert!(loads.iter().all(|&l| l <= mean + 7.0), "{n}: {loads:?}");
        }
        assert_eq!(deal(&seconds, 3), deal(&seconds, 3));
    }

    /// More shards than runs: the deal keeps only the shards runs can
    /// reach, and is the one a heap of every shard gives (zero-cost runs,
    /// which leave a shard's load at 0, included).
    #[test]
    fn many_shards_deal_as_all_of_them_would_in_memory_of_the_plan() {
        let all = |seconds: &[f64], count: u32| {
            let mut order: Vec<usize> = (0..seconds.len()).collect();
            order.sort_by(|&a, &b| seconds[b].total_cmp(&seconds[a]).then(a.cmp(&b)));
            let mut loads: BinaryHeap<Reverse<(u64, u32)>> =
                (1..=count).map(|k| Reverse((0, k))).collect();
            let mut shard = vec![0; seconds.len()];
            for i in order {
                let Reverse((load, k)) = loads.pop().unwrap();
                shard[i] = k;
                loads.push(Reverse(((f64::from_bits(load) + seconds[i]).to_bits(), k)));
            }
            shard
        };
        let seconds = [3.0, 0.0, 1.0, 0.0, 2.0, 1.0, 0.0];
        for count in [1, 2, 6, 7, 8, 40] {
            assert_eq!(deal(&seconds, count), all(&seconds, count), "{count}");
        }
        let dealt = deal(&seconds, u32::MAX);
        assert!(dealt.iter().all(|&k| (1..=7).contains(&k)), "{dealt:?}");
        assert!(deal(&[], u32::MAX).is_empty());
    }
}
