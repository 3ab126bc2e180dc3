//! The event queue: one scheduled event per particle, kept in a calendar
//! (G. Paul, J. Comput. Phys. 221, 615, 2007). Time is cut into buckets of
//! equal width. Events in the current bucket sit in a small indexed binary
//! heap; later events wait unsorted in one list per bucket, on a ring that
//! covers a few mean event times; the rare events beyond the ring wait in one
//! overflow list. Scheduling an event is O(1) unless it falls in the current
//! bucket, and the heap only ever holds the handful of events due next, so
//! the cost per event does not grow with N.
//!
//! Pops follow the total order (time, particle index) whatever the bucket
//! width: every event outside the heap lies in a later bucket than every
//! event in it, and a later bucket means a later time. So the width is only
//! a speed setting (retuned at each rebase) and runs reproduce bit for bit.

use super::prefetch::prefetch;

/// A record's `prev` says where its event is: `PARKED` (none), `IN_HEAP`
/// (at heap slot `next`), or in a list: first in list `prev & LIST` when
/// `HEAD` is set, after particle `prev & LIST` when not; `OVERFLOW` marks
/// the overflow list's events.
const PARKED: u32 = u32::MAX;
const IN_HEAP: u32 = u32::MAX - 1;
const OVERFLOW: u32 = 1 << 31;
const HEAD: u32 = 1 << 30;
const LIST: u32 = HEAD - 1;
/// No particle: the end of a list, or an empty one.
const NONE: u32 = u32::MAX;
/// Events per bucket the width aims at: enough to keep the lists cheap to
/// walk, few enough that the heap stays a few levels deep. Measured as fast
/// as 1, 2 or 4, with half the ring's bucket heads of 4 (2 bytes a particle).
const EVENTS_PER_BUCKET: f64 = 8.0;
/// The ring covers about this many mean times-to-event.
const HORIZON: f64 = 4.0;
/// Walk the next bucket ahead from this many particles on: measured, it
/// saves 6 % with 32,000 spheres (state 9 MB) and 11 % with 256,000, but
/// costs 2 % with 10^4 disks (2 MB), whose lists are still in cache.
const WALK_FROM: usize = 20_000;
/// The bucket of every event too far ahead to count its buckets.
const FAR_BUCKET: f64 = (1u64 << 62) as f64;

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

/// Particle i's event (its time, and `what` the queue's user keeps of it)
/// and its place in the calendar, in one record: handling and rescheduling
/// an event read and write one line of it, not several.
#[derive(Debug, Clone, Copy)]
struct Record<P> {
    time: f64,
    next: u32,
    prev: u32,
    what: P,
}
const _: () = assert!(std::mem::size_of::<Record<()>>() == 16);

#[derive(Debug, Clone)]
pub struct EventQueue<P = ()> {
    /// By particle: its event, and its place (doubly linked bucket lists,
    /// or a heap slot).
    record: Vec<Record<P>>,
    /// The current bucket's events.
    heap: Vec<Entry>,
    /// List heads: one per ring bucket, then the overflow list.
    heads: Vec<u32>,
    in_ring: usize,
    in_overflow: usize,
    /// Bucket b holds times in [base + b w, base + (b + 1) w).
    base: f64,
    inv_width: f64,
    /// The heap's bucket.
    current: u64,
    /// Ring length - 1 (the ring's length is a power of two).
    mask: usize,
    /// Whether to walk the next bucket's list ahead (see `walk_ahead`), and
    /// where the walk has got to (`NONE`: nowhere, and no walk).
    walks: bool,
    ahead: u32,
    /// Particles whose new event lies beyond the current bucket but is not
    /// yet filed in its list (only when `walks`): filing waits two
    /// reschedules, so that the scattered lines it touches load meanwhile
    /// (the list head and the old list's neighbours in the first, the
    /// head's record in the second). Their records already hold the new
    /// time; until then they stay where they were, or nowhere if they left
    /// the heap. `deferred[0]`: deferred since the last reschedule;
    /// `deferred[1]`: their heads' records asked for, filed at the next.
    deferred: [Vec<u32>; 2],
}

impl<P: Copy + Default> EventQueue<P> {
    pub fn new(n: usize) -> Self {
        Self::from_times(vec![f64::INFINITY; n])
    }

    /// A queue holding these event times (earliest first, ties by index).
    pub fn from_times(time: Vec<f64>) -> Self {
        let n = time.len();
        assert!(n <= LIST as usize, "too many particles for the queue");
        let mut q = EventQueue {
            record: time
                .into_iter()
                .map(|time| Record {
                    time,
                    next: NONE,
                    prev: PARKED,
                    what: P::default(),
                })
                .collect(),
            heap: Vec::new(),
            heads: Vec::new(),
            in_ring: 0,
            in_overflow: 0,
            base: 0.0,
            inv_width: 1.0,
            current: 0,
            mask: 0,
            walks: n >= WALK_FROM,
            ahead: NONE,
            deferred: Default::default(),
        };
        q.rebuild();
        q
    }

    /// Every particle's event time, by particle index.
    pub fn times(&self) -> impl ExactSizeIterator<Item = f64> + '_ {
        self.record.iter().map(|r| r.time)
    }

    /// What is kept of particle i's event beside its time.
    #[inline(always)]
    pub fn what(&self, i: usize) -> &P {
        &self.record[i].what
    }

    #[inline(always)]
    pub fn what_mut(&mut self, i: usize) -> &mut P {
        &mut self.record[i].what
    }

    /// What is kept of every particle's event, by particle index.
    pub fn whats(&self) -> impl ExactSizeIterator<Item = &P> + '_ {
        self.record.iter().map(|r| &r.what)
    }

    /// The particle with the earliest event, and its time.
    #[inline(always)]
    pub fn peek(&self) -> Option<(usize, f64)> {
        self.heap.first().map(|e| (e.particle as usize, e.time))
    }

    /// The particle whose event comes after the earliest, if it is in the
    /// current bucket too (a hint: the one to ask ahead for).
    #[inline(always)]
    pub fn peek_second(&self) -> Option<usize> {
        match self.heap.get(1..3) {
            Some([a, b]) => Some(if b.before(a) { b } else { a }),
            _ => self.heap.get(1),
        }
        .map(|e| e.particle as usize)
    }

    /// Replace particle i's event time.
    #[inline]
    pub fn set(&mut self, i: usize, t: f64) {
        self.walk_ahead();
        if self.walks {
            self.file_deferred();
        }
        let r = self.record[i];
        let b = self.bucket(t);
        if r.prev == IN_HEAP && b <= self.current && t.is_finite() {
            // Stays in the heap: move it up or down in place.
            let (old, k) = (r.time, r.next);
            self.record[i].time = t;
            self.heap[k as usize].time = t;
            if t < old {
                self.sift_up(k as usize)
            } else {
                self.sift_down(k as usize)
            }
            return;
        }
        // The bucket's list head is a scattered read: ask for it before
        // taking i out of where it was, so that the two overlap.
        if let Some(head) = self.heads.get(b as usize & self.mask) {
            prefetch(head);
        }
        if self.walks && b > self.current {
            self.defer(i, t, r);
        } else {
            self.remove(i);
            self.file(i, t, b);
        }
        if self.heap.is_empty() {
            self.file_every_deferred();
            self.refill();
        }
    }

    /// Put off filing i's event at t (beyond the current bucket) for two
    /// reschedules (see `deferred`), asking for the lines that taking it
    /// out of its old list will touch.
    #[inline(always)]
    fn defer(&mut self, i: usize, t: f64, r: Record<P>) {
        if r.prev == IN_HEAP {
            // The heap must never hold a time that is no longer i's.
            self.remove(i);
        } else if r.prev != PARKED {
            if r.prev & HEAD == 0 {
                prefetch(&self.record[(r.prev & LIST) as usize]);
            }
            if let Some(next) = self.record.get(r.next as usize) {
                prefetch(next);
            }
        }
        self.record[i].time = t;
        self.deferred[0].push(i as u32);
    }

    /// File every deferred event: the heap is about to move on to the next
    /// bucket, where some of them may belong.
    fn file_every_deferred(&mut self) {
        self.file_deferred();
        self.file_deferred();
    }

    /// One step of deferred filing: file the events deferred two
    /// reschedules ago (each record holds its time), and ask for the record
    /// of the list head each event deferred since will go in front of.
    #[inline(always)]
    fn file_deferred(&mut self) {
        let young = std::mem::take(&mut self.deferred[0]);
        let mut ready = std::mem::replace(&mut self.deferred[1], young);
        for &i in &ready {
            let i = i as usize;
            let t = self.record[i].time;
            self.remove(i);
            self.file(i, t, self.bucket(t));
        }
        ready.clear();
        self.deferred[0] = ready;
        for &i in &self.deferred[1] {
            let list = self.list_of(self.bucket(self.record[i as usize].time));
            if let Some(r) = self
                .heads
                .get(list)
                .and_then(|&h| self.record.get(h as usize))
            {
                prefetch(r);
            }
        }
    }

    /// The list an event in bucket b (beyond the current one) goes in: its
    /// bucket's on the ring, or the overflow list (as `file` decides).
    #[inline(always)]
    fn list_of(&self, b: u64) -> usize {
        if b - self.current.min(b) > self.mask as u64 {
            self.ring_len()
        } else {
            b as usize & self.mask
        }
    }

    /// Shift every time by `-dt` (a new time origin).
    pub fn rebase(&mut self, dt: f64) {
        for r in &mut self.record {
            r.time -= dt;
        }
        self.rebuild();
    }

    /// Choose the bucket width afresh for the events now queued.
    pub fn retune(&mut self) {
        self.rebuild();
    }

    #[inline(always)]
    fn bucket(&self, t: f64) -> u64 {
        // Far-future (and infinite) times land beyond the ring, at 2^62.
        // Clamped first, the conversion is one instruction; a saturating
        // `as u64` takes a dozen. Not `clamp`: it would keep a NaN, which
        // `max` takes to 0.
        #[allow(clippy::manual_clamp)]
        let b = ((t - self.base) * self.inv_width).max(0.0).min(FAR_BUCKET);
        // SAFETY: b is a number in [0, 2^62], which an i64 holds.
        unsafe { b.to_int_unchecked::<i64>() as u64 }
    }

    fn ring_len(&self) -> usize {
        self.mask + 1
    }

    /// Choose the bucket width from the events now queued, then file them all.
    fn rebuild(&mut self) {
        let mut ahead: Vec<f64> = self.times().filter(|t| t.is_finite()).collect();
        let live = ahead.len();
        let first = ahead.iter().copied().fold(f64::INFINITY, f64::min);
        // The rate at which events fall due near the front, from the time until
        // the earliest eighth of them (robust to a long tail of far events).
        let m = live / 8;
        let width = if m > 0 {
            let (_, t_m, _) = ahead.select_nth_unstable_by(m, f64::total_cmp);
            EVENTS_PER_BUCKET * (*t_m - first) / m as f64
        } else {
            0.0
        };
        let width = if width > 0.0 && width.is_finite() {
            width
        } else {
            1.0
        };
        let ring = ((HORIZON * live as f64 / EVENTS_PER_BUCKET) as usize)
            .clamp(16, 1 << 24)
            .next_power_of_two();
        self.base = if first.is_finite() { first } else { 0.0 };
        self.inv_width = 1.0 / width;
        self.current = 0;
        self.heads = vec![NONE; ring + 1];
        self.mask = ring - 1;
        // Anew, not cleared: before the first tuning every event fell in
        // one bucket, and the heap's room for all of them would stay.
        self.heap = Vec::new();
        // Filed below with the rest, by the times their records hold.
        self.deferred.iter_mut().for_each(Vec::clear);
        self.in_ring = 0;
        self.in_overflow = 0;
        for r in &mut self.record {
            r.prev = PARKED;
        }
        for i in 0..self.record.len() {
            self.insert(i, self.record[i].time);
        }
        if self.heap.is_empty() {
            self.refill();
        }
    }

    fn insert(&mut self, i: usize, t: f64) {
        self.file(i, t, self.bucket(t));
    }

    /// File particle i's event at time t, in bucket b.
    #[inline(always)]
    fn file(&mut self, i: usize, t: f64, b: u64) {
        self.record[i].time = t;
        if t == f64::INFINITY {
            self.record[i].prev = PARKED;
            return;
        }
        if b <= self.current {
            let k = self.heap.len();
            self.heap.push(Entry {
                time: t,
                particle: i as u32,
            });
            self.record[i].prev = IN_HEAP;
            self.sift_up(k);
        } else if b - self.current <= self.mask as u64 {
            self.in_ring += 1;
            self.link(i, b as usize & self.mask);
        } else {
            self.in_overflow += 1;
            self.link(i, self.ring_len());
        }
    }

    fn remove(&mut self, i: usize) {
        let r = self.record[i];
        match r.prev {
            PARKED => return,
            IN_HEAP => {
                let k = r.next as usize;
                let last = self.heap.pop().expect("a particle in the heap");
                if k < self.heap.len() {
                    self.place(k, last);
                    self.sift_up(k);
                    let k = self.record[last.particle as usize].next as usize;
                    self.sift_down(k);
                }
            }
            _ => {
                if r.prev & OVERFLOW != 0 {
                    self.in_overflow -= 1;
                } else {
                    self.in_ring -= 1;
                }
                let at = (r.prev & LIST) as usize;
                if r.prev & HEAD != 0 {
                    self.heads[at] = r.next;
                } else {
                    self.record[at].next = r.next;
                }
                if r.next != NONE {
                    // The next takes i's place: first in the same list, or
                    // after the same particle.
                    self.record[r.next as usize].prev = r.prev;
                }
            }
        }
        self.record[i].prev = PARKED;
    }

    fn link(&mut self, i: usize, list: usize) {
        let flag = if list == self.ring_len() { OVERFLOW } else { 0 };
        let h = self.heads[list];
        self.record[i].next = h;
        self.record[i].prev = HEAD | flag | list as u32;
        if h != NONE {
            self.record[h as usize].prev = i as u32 | flag;
        }
        self.heads[list] = i as u32;
    }

    /// Empty list `list`, filing each of its events afresh.
    fn refile(&mut self, list: usize) {
        let mut j = std::mem::replace(&mut self.heads[list], NONE);
        while j != NONE {
            let next = self.record[j as usize].next;
            if list == self.ring_len() {
                self.in_overflow -= 1;
            } else {
                self.in_ring -= 1;
            }
            self.insert(j as usize, self.record[j as usize].time);
            j = next;
        }
    }

    /// The heap ran dry: move on to the next bucket that holds events.
    fn refill(&mut self) {
        while self.heap.is_empty() && self.in_ring + self.in_overflow > 0 {
            if self.in_ring == 0 {
                // Only far-future events left: jump straight to the first.
                let first = self.take_overflow_min();
                self.current = first;
                self.file_overflow();
                continue;
            }
            self.current += 1;
            let slot = self.current as usize & self.mask;
            if slot == 0 {
                self.file_overflow();
            }
            self.refile(slot);
            if self.walks {
                self.ask_for(self.heads[(slot + 1) & self.mask]);
            }
        }
    }

    /// One step along the next bucket's list. Refiling a bucket follows its
    /// list from particle to particle, a chain of cache misses in a large
    /// system; walking it while the current bucket is served, one step per
    /// reschedule, lets those misses happen early. The walk only asks for
    /// lines: a particle that has left the list since just leads it astray.
    #[inline(always)]
    fn walk_ahead(&mut self) {
        if let Some(r) = self.record.get(self.ahead as usize) {
            self.ask_for(r.next);
        }
    }

    /// Ask for the lines refiling j will read.
    #[inline(always)]
    fn ask_for(&mut self, j: u32) {
        self.ahead = j;
        if let Some(r) = self.record.get(j as usize) {
            prefetch(r);
        }
    }

    fn take_overflow_min(&self) -> u64 {
        let mut j = self.heads[self.ring_len()];
        let mut first = u64::MAX;
        while j != NONE {
            let r = self.record[j as usize];
            first = first.min(self.bucket(r.time));
            j = r.next;
        }
        first
    }

    /// Move overflow events that now fall within the ring (or the current bucket).
    fn file_overflow(&mut self) {
        self.refile(self.ring_len());
    }

    #[inline(always)]
    fn place(&mut self, k: usize, e: Entry) {
        self.record[e.particle as usize].next = k as u32;
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

    fn drain(q: &mut EventQueue) -> Vec<(usize, f64)> {
        let mut order = Vec::new();
        while let Some((i, t)) = q.peek() {
            order.push((i, t));
            q.set(i, f64::INFINITY);
        }
        order
    }

    #[test]
    fn pops_in_time_then_index_order() {
        let mut q = EventQueue::new(5);
        for (i, t) in [3.0, 1.0, 2.0, 1.0, 0.5].into_iter().enumerate() {
            q.set(i, t);
        }
        let order: Vec<usize> = drain(&mut q).into_iter().map(|(i, _)| i).collect();
        assert_eq!(order, vec![4, 1, 3, 2, 0]);
    }

    #[test]
    fn rebuilt_queues_keep_times_and_order() {
        let times = vec![2.0, 0.25, 7.0, 0.25, 1.0];
        let mut q = EventQueue::<()>::from_times(times.clone());
        assert!(q.times().eq(times.iter().copied()));
        q.rebase(0.25);
        assert_eq!(q.peek(), Some((1, 0.0)));
        assert_eq!(q.times().nth(2), Some(6.75));
    }

    /// Against a sorted reference: random reschedules (earlier, later, far
    /// beyond the ring, parked, tied), interleaved with pops that reschedule
    /// the popped particle into the future, as the engine does; with and
    /// without the walk ahead (which large systems take).
    #[test]
    fn agrees_with_a_sorted_reference_under_random_rescheduling() {
        for walks in [false, true] {
            agrees_with_a_sorted_reference(walks);
        }
    }

    fn agrees_with_a_sorted_reference(walks: bool) {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let n = 300;
        let times: Vec<f64> = (0..n).map(|_| rng.random::<f64>()).collect();
        let mut q = EventQueue::<()>::from_times(times.clone());
        q.walks = walks;
        let mut reference = times;
        for step in 0..200_000 {
            let expect = (0..n)
                .filter(|&i| reference[i].is_finite())
                .min_by(|&a, &b| reference[a].total_cmp(&reference[b]).then(a.cmp(&b)))
                .map(|i| (i, reference[i]));
            assert_eq!(q.peek(), expect, "step {step}");
            let Some((i, now)) = expect else { break };
            let later = match rng.random_range(0..20) {
                0 => f64::INFINITY,
                1 => now + 1e3 * rng.random::<f64>(),
                2 => now,
                3 => (now * 8.0).round() / 8.0 + 0.125,
                _ => now + rng.random::<f64>(),
            };
            q.set(i, later);
            reference[i] = later;
            // Reschedule another particle somewhere from now on.
            let j = rng.random_range(0..n);
            let t = now + [0.0, 0.01, 0.5, 30.0][rng.random_range(0..4)] * rng.random::<f64>();
            q.set(j, t);
            reference[j] = t;
            if step % 5000 == 4999 {
                q.rebase(now);
                reference.iter_mut().for_each(|r| *r -= now);
            }
        }
        assert!(q.times().eq(reference.iter().copied()));
    }
}
