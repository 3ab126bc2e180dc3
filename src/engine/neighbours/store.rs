//! Many short lists side by side: the neighbour lists, and the cell grid's
//! cells. Most lists are near the mean length and a few are much longer (the
//! longest of a million neighbour lists is nearly twice the mean), so room
//! for the longest in every list would take half as much memory again as
//! the entries. Instead each list has room in line for a little more than
//! the mean, and a list that outgrows it moves, whole, to a slot of a spill
//! store, where it stays until it is set anew or is short again; its slot's
//! number takes the place of its first entry in line. A list is always one
//! contiguous slice, wherever it lives. An entry is a word: a neighbour
//! list's a `u32`, a cell's a `u64` (a point and where it is in the cell).
//!
//! A list's length is a byte: a million lists' lengths fill a megabyte,
//! which the caches keep, so reading a list in a system far larger than the
//! caches waits on the list's own line and not on its length's too. A
//! spilled list's length is the first word of its slot.

use crate::engine::prefetch::{Read, prefetch_for};

/// A list's length byte when the list lives in the spill store.
const SPILLED: u8 = u8::MAX;
/// The most entries a list keeps in line: its length must fit below `SPILLED`.
const MOST_IN_LINE: usize = SPILLED as usize - 1;

/// Room in line for lists of this mean length: the mean and half the
/// standard deviation of counts that fall at random (Poisson), so that a
/// few lists in a hundred spill.
pub(super) fn room_for(mean: f64) -> usize {
    if mean.is_finite() {
        (mean + 0.5 * mean.sqrt())
            .ceil()
            .clamp(1.0, MOST_IN_LINE as f64) as usize
    } else {
        1
    }
}

/// What a store holds: a word, which can also hold a number (a spill
/// slot's, or a spilled list's length).
pub(super) trait Entry: Copy + Default {
    fn from_number(n: u32) -> Self;
    fn number(self) -> u32;
}

impl Entry for u32 {
    fn from_number(n: u32) -> Self {
        n
    }
    fn number(self) -> u32 {
        self
    }
}

impl Entry for u64 {
    fn from_number(n: u32) -> Self {
        n as u64
    }
    fn number(self) -> u32 {
        self as u32
    }
}

/// Where a list's entries are: from `at` in line or in the spill store, `n`
/// of them, in room for `room`.
#[derive(Clone, Copy)]
struct Place {
    spilled: bool,
    at: usize,
    n: usize,
    room: usize,
}

#[derive(Debug, Clone)]
pub(super) struct ListStore<T = u32> {
    /// List i in line is `inline[i * room..][..len]`.
    room: usize,
    /// Each list's length, or `SPILLED` if it lives in the spill store.
    len: Vec<u8>,
    inline: Vec<T>,
    /// Slot s is `spill[s * spill_room..]`: the list's length, then its
    /// entries; `free` holds the slots to reuse.
    spill_room: usize,
    spill: Vec<T>,
    free: Vec<u32>,
}

impl<T: Entry> ListStore<T> {
    /// `lists` empty lists, each with room for `room` entries in line.
    pub fn new(lists: usize, room: usize) -> Self {
        let room = room.clamp(1, MOST_IN_LINE);
        ListStore {
            room,
            len: vec![0; lists],
            inline: vec![T::default(); lists * room],
            spill_room: 1 + room + room.div_ceil(2),
            spill: Vec::new(),
            free: Vec::new(),
        }
    }

    /// Where list i's entries are.
    #[inline(always)]
    fn place(&self, i: usize) -> Place {
        let len = self.len[i];
        if len != SPILLED {
            return Place {
                spilled: false,
                at: i * self.room,
                n: len as usize,
                room: self.room,
            };
        }
        let slot = self.slot(i) as usize * self.spill_room;
        Place {
            spilled: true,
            at: slot + 1,
            n: self.spill[slot].number() as usize,
            room: self.spill_room - 1,
        }
    }

    /// The spill slot of list i, which lives in the spill store: its number
    /// takes the place of the list's first entry in line.
    #[inline(always)]
    fn slot(&self, i: usize) -> u32 {
        self.inline[i * self.room].number()
    }

    #[inline(always)]
    pub fn get(&self, i: usize) -> &[T] {
        let p = self.place(i);
        let store = if p.spilled { &self.spill } else { &self.inline };
        &store[p.at..p.at + p.n]
    }

    /// List i's whole room and how much of it the list fills.
    #[inline(always)]
    fn room_mut(&mut self, i: usize) -> (&mut [T], usize) {
        let p = self.place(i);
        let store = if p.spilled {
            &mut self.spill
        } else {
            &mut self.inline
        };
        (&mut store[p.at..p.at + p.room], p.n)
    }

    /// Make list i's length n (no more than its room).
    #[inline(always)]
    fn set_len(&mut self, i: usize, n: usize) {
        if self.len[i] == SPILLED {
            let slot = self.slot(i) as usize;
            self.spill[slot * self.spill_room] = T::from_number(n as u32);
        } else {
            self.len[i] = n as u8;
        }
    }

    /// List i's length and the two ends of its room in line (a hint: its
    /// place is computed, not read, so many can be asked for at once).
    #[inline(always)]
    pub fn prefetch(&self, i: usize, when: Read) {
        prefetch_for(&self.len[i], when);
        let room = self.inline.get(i * self.room..(i + 1) * self.room);
        if let Some((first, last)) = room.and_then(|r| r.first().zip(r.last())) {
            prefetch_for(first, when);
            prefetch_for(last, when);
        }
    }

    /// List i, with room for one more entry at its end.
    fn with_room_for_one(&mut self, i: usize) -> (&mut [T], usize) {
        let p = self.place(i);
        if p.n == p.room {
            self.make_room(i, p.spilled);
        }
        self.room_mut(i)
    }

    /// Put `e` at the end of list i.
    pub fn push(&mut self, i: usize, e: T) {
        let (list, n) = self.with_room_for_one(i);
        list[n] = e;
        self.set_len(i, n + 1);
    }

    /// Make entry `at` of list i `e`.
    pub fn replace(&mut self, i: usize, at: usize, e: T) {
        let (list, n) = self.room_mut(i);
        list[..n][at] = e;
    }

    /// Take entry `at` out of list i, moving its last entry into its place.
    pub fn swap_remove(&mut self, i: usize, at: usize) {
        let (list, n) = self.room_mut(i);
        list[at] = list[n - 1];
        self.set_len(i, n - 1);
        self.settle(i);
    }

    /// A spilled list that fits in line again, with one place to spare (so
    /// that a list at the edge does not go back and forth), comes back.
    fn settle(&mut self, i: usize) {
        let p = self.place(i);
        if p.spilled && p.n < self.room {
            self.free.push(self.slot(i));
            let at = i * self.room;
            self.inline[at..at + p.n].copy_from_slice(&self.spill[p.at..p.at + p.n]);
            self.len[i] = p.n as u8;
        }
    }

    /// Make list i `entries`.
    pub fn set(&mut self, i: usize, entries: &[T]) {
        if self.len[i] == SPILLED {
            self.free.push(self.slot(i));
        }
        self.len[i] = 0;
        if entries.len() > self.room {
            self.spill_out(i, entries.len());
        }
        let (list, _) = self.room_mut(i);
        list[..entries.len()].copy_from_slice(entries);
        self.set_len(i, entries.len());
    }

    /// Empty every list.
    pub fn clear(&mut self) {
        self.len.fill(0);
        self.spill.clear();
        self.free.clear();
    }

    /// List i (`spilled` or not) is full: give it more room.
    fn make_room(&mut self, i: usize, spilled: bool) {
        if spilled {
            self.widen_spill();
        } else {
            self.spill_out(i, self.len[i] as usize + 1);
        }
    }

    /// Half as much room again in every spill slot.
    fn widen_spill(&mut self) {
        let old = self.spill_room;
        let room = old + (old - 1).div_ceil(2);
        let slots = self.spill.len() / old;
        widen_rooms(&mut self.spill, slots, |_| old, (old, room));
        self.spill_room = room;
    }

    /// Move list i (in line) to a slot with room for `need` entries, or,
    /// when one list in sixteen would have spilled (the room in line was
    /// sized for a density the system no longer has), widen every room in
    /// line by a quarter instead.
    fn spill_out(&mut self, i: usize, need: usize) {
        let slots = self.spill.len() / self.spill_room;
        if 16 * (slots - self.free.len() + 1) > self.len.len() && self.room < MOST_IN_LINE {
            let room = (self.room + self.room.div_ceil(4)).min(MOST_IN_LINE);
            let (len, old) = (&self.len, self.room);
            widen_rooms(
                &mut self.inline,
                len.len(),
                |k| match len[k] {
                    SPILLED => 1,
                    l => l as usize,
                },
                (old, room),
            );
            self.room = room;
            if need <= room {
                return;
            }
        }
        while self.spill_room - 1 < need {
            self.widen_spill();
        }
        let slot = self.free.pop().unwrap_or_else(|| {
            self.spill
                .resize(self.spill.len() + self.spill_room, T::default());
            slots as u32
        });
        let (at, n) = (i * self.room, self.len[i] as usize);
        let to = slot as usize * self.spill_room;
        self.spill[to] = T::from_number(n as u32);
        self.spill[to + 1..to + 1 + n].copy_from_slice(&self.inline[at..at + n]);
        self.inline[at] = T::from_number(slot);
        self.len[i] = SPILLED;
    }
}

/// Sorted lists (the neighbour lists).
impl ListStore<u32> {
    /// Take the first entry `is` picks out of list i, if any, keeping the
    /// others in order.
    pub fn remove(&mut self, i: usize, is: impl Fn(u32) -> bool) {
        let (list, n) = self.room_mut(i);
        if let Some(at) = list[..n].iter().position(|&e| is(e)) {
            // One by one: lists are short, so this beats a call to memmove.
            for k in at..n - 1 {
                list[k] = list[k + 1];
            }
            self.set_len(i, n - 1);
            self.settle(i);
        }
    }

    /// Put `e` into list i, keeping it sorted.
    pub fn insert(&mut self, i: usize, e: u32) {
        // From the end, moving the larger entries up one: lists are short,
        // so this beats a search and a call to memmove.
        let (list, n) = self.with_room_for_one(i);
        let mut at = n;
        while at > 0 && list[at - 1] > e {
            list[at] = list[at - 1];
            at -= 1;
        }
        list[at] = e;
        self.set_len(i, n + 1);
    }
}

/// Give each of the `rooms` slots of `items` (slot k holds `used(k)` items,
/// in room for `old`) room for `new` items, in place: last slot first, each
/// moving up, so a large block grows without a second copy of it at the
/// peak, and to exactly that room (a resize alone would round the capacity
/// up to twice); new places hold the default entry.
fn widen_rooms<T: Entry>(
    items: &mut Vec<T>,
    rooms: usize,
    used: impl Fn(usize) -> usize,
    (old, new): (usize, usize),
) {
    let len = rooms * new;
    items.reserve_exact(len - items.len());
    items.resize(len, T::default());
    for k in (0..rooms).rev() {
        items.copy_within(k * old..k * old + used(k), k * new);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn reads_back<T: Entry + PartialEq + std::fmt::Debug>(
        store: &ListStore<T>,
        truth: &[Vec<T>],
        step: u32,
    ) {
        for (k, t) in truth.iter().enumerate() {
            assert_eq!(store.get(k), &t[..], "list {k} at step {step}");
        }
    }

    /// Random inserts, removals and settings against plain sorted vectors,
    /// with room in line for a few entries so that lists spill, come back,
    /// widen the spill slots and the rooms in line: every list reads back
    /// exactly.
    #[test]
    fn lists_read_back_exactly_in_line_or_spilled() {
        let mut rng = ChaCha8Rng::seed_from_u64(17);
        let lists = 256;
        let mut store = ListStore::new(lists, 3);
        let mut truth = vec![Vec::<u32>::new(); lists];
        let (mut spilled_seen, first) = (0, (store.room, store.spill_room));
        for step in 0..40_000u32 {
            let i = rng.random_range(0..lists);
            match rng.random_range(0..10) {
                0..=4 => {
                    let e = rng.random_range(0..200);
                    if !truth[i].contains(&e) {
                        store.insert(i, e);
                        let at = truth[i].partition_point(|&x| x < e);
                        truth[i].insert(at, e);
                    }
                }
                5..=7 => {
                    if let Some(&e) = truth[i].first() {
                        store.remove(i, |x| x == e);
                        truth[i].remove(0);
                    }
                }
                _ => {
                    // Mostly short, now and then much longer than the rest.
                    let n = if rng.random_range(0..40) == 0 { 40 } else { 6 };
                    let n = rng.random_range(0..n);
                    let mut new: Vec<u32> = (0..n).map(|_| rng.random_range(0..200)).collect();
                    new.sort();
                    new.dedup();
                    store.set(i, &new);
                    truth[i] = new;
                }
            }
            spilled_seen += (store.len[i] == SPILLED) as usize;
            if step % 997 == 0 {
                reads_back(&store, &truth, step);
            }
        }
        reads_back(&store, &truth, 40_000);
        assert!(spilled_seen > 1000, "lists spilled {spilled_seen} times");
        assert!(store.room > first.0, "the rooms in line widened");
        assert!(store.spill_room > first.1, "the spill slots widened");
        store.clear();
        assert!((0..lists).all(|k| store.get(k).is_empty()));
    }

    /// A list longer than a length byte can count lives in the spill store
    /// whatever room in line was asked for, and comes back in line once it
    /// is short enough.
    #[test]
    fn lists_longer_than_a_byte_counts_spill() {
        let mut store = ListStore::<u32>::new(3, 1000);
        assert_eq!(store.room, MOST_IN_LINE);
        let long: Vec<u32> = (0..600).map(|k| 2 * k).collect();
        store.set(1, &long);
        store.insert(1, 7);
        assert_eq!(store.len[1], SPILLED);
        let mut truth = long.clone();
        truth.insert(4, 7);
        for e in (0..1200).step_by(4) {
            store.remove(1, |x| x == e);
            truth.retain(|&x| x != e);
        }
        assert_eq!(store.get(1), &truth[..]);
        assert_eq!(
            store.len[1],
            SPILLED,
            "{} entries stay spilled",
            truth.len()
        );
        while truth.len() >= MOST_IN_LINE {
            let e = truth.pop().unwrap();
            store.remove(1, |x| x == e);
        }
        assert_eq!(store.len[1] as usize, truth.len(), "back in line");
        assert_eq!(store.get(1), &truth[..]);
        assert!(store.get(0).is_empty() && store.get(2).is_empty());
    }

    /// Points filed into cells and moved between them as the grid does
    /// (appended, taken out by moving the last into their place), against
    /// plain vectors doing the same: every cell reads back exactly, and the
    /// spilled cells that empty come back in line.
    #[test]
    fn cells_read_back_exactly_in_line_or_spilled() {
        let mut rng = ChaCha8Rng::seed_from_u64(29);
        let (cells, points) = (32, 120);
        let mut store = ListStore::<u64>::new(cells, 1);
        let mut truth = vec![Vec::<u64>::new(); cells];
        let mut home = vec![None::<usize>; points];
        let mut spilled_seen = 0;
        for step in 0..40_000u32 {
            let p = rng.random_range(0..points);
            // Crowd the first cells now and then, so that some spill.
            let c = rng.random_range(0..if step % 5000 < 500 { 3 } else { cells });
            if let Some(old) = home[p] {
                if old == c {
                    continue;
                }
                let at = truth[old]
                    .iter()
                    .position(|&e| e as u32 == p as u32)
                    .unwrap();
                store.swap_remove(old, at);
                truth[old].swap_remove(at);
            }
            // A cell's entry: the point, and above it where it is (here, when).
            let e = p as u64 | (step as u64) << 32;
            store.push(c, e);
            truth[c].push(e);
            home[p] = Some(c);
            spilled_seen += (store.len[c] == SPILLED) as usize;
            if step % 991 == 0 {
                reads_back(&store, &truth, step);
            }
        }
        reads_back(&store, &truth, 40_000);
        assert!(spilled_seen > 100, "cells spilled {spilled_seen} times");
        let in_use = store.spill.len() / store.spill_room - store.free.len();
        let spilled = store.len.iter().filter(|&&l| l == SPILLED).count();
        assert_eq!(in_use, spilled, "every slot not in use is free");
    }
}
