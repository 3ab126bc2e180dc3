//! What a fixed step gets wrong, counted as it happens: how deep pairs
//! overlap when a step end finds them, how long a pair stays overlapping
//! (one that stays longer than it would take to pass clean through its
//! partner at their relative speed is stuck: the seeds' sticking bug), and
//! how many collisions hit a pair that was already overlapping a step
//! before (repeat collisions, which an exact method never makes).

/// One overlapping pair: how many step ends in a row it has overlapped, and
/// whether that episode was already counted as stuck.
#[derive(Debug, Clone, Copy, Default)]
struct Episode {
    steps: u32,
    stuck: bool,
}

/// Pairs overlapping at one step end, sorted, with their episodes.
#[derive(Debug, Clone, Default)]
pub struct Tally {
    previous: Vec<((u32, u32), Episode)>,
    current: Vec<((u32, u32), Episode)>,
    /// Overlaps seen (a pair counts once per step end it overlaps at).
    pub overlaps: u64,
    pub depth_sum: f64,
    /// Deepest overlap seen, as a fraction of the contact distance.
    pub depth_max: f64,
    /// Longest run of consecutive step ends one pair spent overlapping.
    pub longest: u32,
    pub repeat_collisions: u64,
    /// Overlap episodes that outlasted a pass through (stuck pairs).
    pub stuck: u64,
    pub steps: u64,
}

impl Tally {
    /// A pair (i < j) overlaps at this step end by `depth` (fraction of its
    /// contact distance); `pass` is the time it would take to move through
    /// its partner (two contact distances over their relative speed).
    /// Returns whether it already overlapped a step ago.
    pub fn overlap(&mut self, i: usize, j: usize, depth: f64, pass: f64, dt: f64) -> bool {
        let key = (i as u32, j as u32);
        let before = self
            .previous
            .binary_search_by(|(k, _)| k.cmp(&key))
            .map_or(Episode::default(), |at| self.previous[at].1);
        let mut episode = Episode {
            steps: before.steps + 1,
            stuck: before.stuck,
        };
        // A bounce that works separates a pair within two step ends,
        // however long the step.
        if !episode.stuck && episode.steps > 2 && f64::from(episode.steps) * dt > pass {
            episode.stuck = true;
            self.stuck += 1;
        }
        self.current.push((key, episode));
        self.longest = self.longest.max(episode.steps);
        self.overlaps += 1;
        self.depth_sum += depth;
        self.depth_max = self.depth_max.max(depth);
        before.steps > 0
    }

    /// The step is over: its overlaps become the previous ones.
    pub fn end_step(&mut self) {
        self.steps += 1;
        // Pairs are found cell by cell, not in index order.
        self.current.sort_unstable_by_key(|(k, _)| *k);
        std::mem::swap(&mut self.previous, &mut self.current);
        self.current.clear();
    }

    /// The scalars a run reports (names as in `runs.parquet`).
    pub fn scalars(&self, dt: f64) -> Vec<(&'static str, f64)> {
        let mean = if self.overlaps > 0 {
            self.depth_sum / self.overlaps as f64
        } else {
            0.0
        };
        vec![
            ("steps", self.steps as f64),
            ("dt", dt),
            ("overlap_depth_max", self.depth_max),
            ("overlap_depth_mean", mean),
            ("overlap_steps_max", f64::from(self.longest)),
            ("repeat_collisions", self.repeat_collisions as f64),
            ("stuck_pairs", self.stuck as f64),
        ]
    }
}
