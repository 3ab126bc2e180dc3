//! The event queue: one scheduled event per particle, kept in an indexed
//! binary min-heap so a particle's event can be replaced in O(log N) without
//! leaving stale entries behind. Ties break on the particle index, so the
//! order of events is a total order and runs reproduce bit for bit.

#[derive(Debug, Clone)]
pub struct EventQueue {
    /// heap[k] = particle at heap slot k.
    heap: Vec<u32>,
    /// slot[i] = heap slot of particle i.
    slot: Vec<u32>,
    /// time[i] = time of particle i's scheduled event.
    time: Vec<f64>,
}

impl EventQueue {
    pub fn new(n: usize) -> Self {
        EventQueue {
            heap: (0..n as u32).collect(),
            slot: (0..n as u32).collect(),
            time: vec![f64::INFINITY; n],
        }
    }

    /// A queue holding these event times. The heap layout may differ from the
    /// queue the times came from, but not the pop order: (time, index) is a
    /// total order, so the earliest entry is the same whatever the layout.
    pub fn from_times(time: Vec<f64>) -> Self {
        let n = time.len();
        let mut q = EventQueue {
            heap: (0..n as u32).collect(),
            slot: (0..n as u32).collect(),
            time,
        };
        for k in (0..n / 2).rev() {
            q.sift_down(k);
        }
        q
    }

    /// Every particle's event time, by particle index.
    pub fn times(&self) -> &[f64] {
        &self.time
    }

    /// The particle with the earliest event, and its time.
    #[inline(always)]
    pub fn peek(&self) -> Option<(usize, f64)> {
        self.heap
            .first()
            .map(|&i| (i as usize, self.time[i as usize]))
    }

    pub fn time_of(&self, i: usize) -> f64 {
        self.time[i]
    }

    /// Replace particle i's event time.
    #[inline]
    pub fn set(&mut self, i: usize, t: f64) {
        let old = self.time[i];
        self.time[i] = t;
        let k = self.slot[i] as usize;
        if t < old {
            self.sift_up(k)
        } else {
            self.sift_down(k)
        }
    }

    /// Shift every time by `-dt` (a new time origin), keeping the heap valid.
    pub fn rebase(&mut self, dt: f64) {
        for t in &mut self.time {
            *t -= dt;
        }
        for k in (0..self.heap.len() / 2).rev() {
            self.sift_down(k);
        }
    }

    #[inline(always)]
    fn less(&self, a: u32, b: u32) -> bool {
        let (ta, tb) = (self.time[a as usize], self.time[b as usize]);
        ta < tb || (ta == tb && a < b)
    }

    #[inline(always)]
    fn place(&mut self, k: usize, i: u32) {
        self.heap[k] = i;
        self.slot[i as usize] = k as u32;
    }

    fn sift_up(&mut self, mut k: usize) {
        let i = self.heap[k];
        while k > 0 {
            let parent = (k - 1) / 2;
            let p = self.heap[parent];
            if !self.less(i, p) {
                break;
            }
            self.place(k, p);
            k = parent;
        }
        self.place(k, i);
    }

    fn sift_down(&mut self, mut k: usize) {
        let n = self.heap.len();
        let i = self.heap[k];
        loop {
            let left = 2 * k + 1;
            if left >= n {
                break;
            }
            let right = left + 1;
            let child = if right < n && self.less(self.heap[right], self.heap[left]) {
                right
            } else {
                left
            };
            let c = self.heap[child];
            if !self.less(c, i) {
                break;
            }
            self.place(k, c);
            k = child;
        }
        self.place(k, i);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pops_in_time_then_index_order() {
        let mut q = EventQueue::new(5);
        for (i, t) in [3.0, 1.0, 2.0, 1.0, 0.5].into_iter().enumerate() {
            q.set(i, t);
        }
        let mut order = Vec::new();
        while let Some((i, t)) = q.peek() {
            if t.is_infinite() {
                break;
            }
            order.push(i);
            q.set(i, f64::INFINITY);
        }
        assert_eq!(order, vec![4, 1, 3, 2, 0]);
    }
}
