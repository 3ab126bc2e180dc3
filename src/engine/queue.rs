//! The event queue: one scheduled event per particle, kept in an indexed
//! binary min-heap so a particle's event can be replaced in O(log N) without
//! leaving stale entries behind. Ties break on the particle index, so the
//! order of events is a total order and runs reproduce bit for bit. Each heap
//! slot holds its time beside the particle index, so a sift compares without
//! a second, scattered memory access.

#[derive(Debug, Clone, Copy)]
struct Entry {
    time: f64,
    particle: u32,
}

impl Entry {
    #[inline(always)]
    fn before(&self, other: &Entry) -> bool {
        self.time < other.time || (self.time == other.time && self.particle < other.particle)
    }
}

#[derive(Debug, Clone)]
pub struct EventQueue {
    heap: Vec<Entry>,
    /// slot[i] = heap slot of particle i.
    slot: Vec<u32>,
}

impl EventQueue {
    pub fn new(n: usize) -> Self {
        Self::from_times(vec![f64::INFINITY; n])
    }

    /// A queue holding these event times. The heap layout may differ from the
    /// queue the times came from, but not the pop order: (time, index) is a
    /// total order, so the earliest entry is the same whatever the layout.
    pub fn from_times(time: Vec<f64>) -> Self {
        let n = time.len();
        let mut q = EventQueue {
            heap: time
                .iter()
                .enumerate()
                .map(|(i, &t)| Entry {
                    time: t,
                    particle: i as u32,
                })
                .collect(),
            slot: (0..n as u32).collect(),
        };
        q.heapify();
        q
    }

    /// Every particle's event time, by particle index.
    pub fn times(&self) -> Vec<f64> {
        (0..self.slot.len()).map(|i| self.time_of(i)).collect()
    }

    /// The particle with the earliest event, and its time.
    #[inline(always)]
    pub fn peek(&self) -> Option<(usize, f64)> {
        self.heap.first().map(|e| (e.particle as usize, e.time))
    }

    pub fn time_of(&self, i: usize) -> f64 {
        self.heap[self.slot[i] as usize].time
    }

    /// Replace particle i's event time.
    #[inline]
    pub fn set(&mut self, i: usize, t: f64) {
        let k = self.slot[i] as usize;
        let old = self.heap[k].time;
        self.heap[k].time = t;
        if t < old {
            self.sift_up(k)
        } else {
            self.sift_down(k)
        }
    }

    /// Shift every time by `-dt` (a new time origin), keeping the heap valid.
    pub fn rebase(&mut self, dt: f64) {
        for e in &mut self.heap {
            e.time -= dt;
        }
        self.heapify();
    }

    fn heapify(&mut self) {
        for k in (0..self.heap.len() / 2).rev() {
            self.sift_down(k);
        }
        for (k, e) in self.heap.iter().enumerate() {
            self.slot[e.particle as usize] = k as u32;
        }
    }

    #[inline(always)]
    fn place(&mut self, k: usize, e: Entry) {
        self.slot[e.particle as usize] = k as u32;
        self.heap[k] = e;
    }

    fn sift_up(&mut self, mut k: usize) {
        let e = self.heap[k];
        while k > 0 {
            let parent = (k - 1) / 2;
            let p = self.heap[parent];
            if !e.before(&p) {
                break;
            }
            self.place(k, p);
            k = parent;
        }
        self.place(k, e);
    }

    fn sift_down(&mut self, mut k: usize) {
        let n = self.heap.len();
        let e = self.heap[k];
        loop {
            let left = 2 * k + 1;
            if left >= n {
                break;
            }
            let right = left + 1;
            let child = if right < n && self.heap[right].before(&self.heap[left]) {
                right
            } else {
                left
            };
            let c = self.heap[child];
            if !c.before(&e) {
                break;
            }
            self.place(k, c);
            k = child;
        }
        self.place(k, e);
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

    #[test]
    fn rebuilt_queues_keep_times_and_order() {
        let times = vec![2.0, 0.25, 7.0, 0.25, 1.0];
        let mut q = EventQueue::from_times(times.clone());
        assert_eq!(q.times(), times);
        q.rebase(0.25);
        assert_eq!(q.peek(), Some((1, 0.0)));
        assert_eq!(q.time_of(2), 6.75);
    }
}
