//! Where the neighbour lists' entries live. Most lists are near the mean
//! length and a few are much longer (the longest of a million lists is
//! nearly twice the mean), so room for the longest in every list would take
//! half as much memory again as the entries. Instead each list has room in
//! line for a little more than the mean, and a list that outgrows it moves,
//! whole, to a slot of a spill store, where it stays until it is set anew;
//! its slot's number takes the place of its first entry in line. A list is
//! always one contiguous slice, wherever it lives.

use super::widen_rooms;
use crate::engine::prefetch::prefetch;

/// Marks a list's length when the list lives in the spill store.
const SPILLED: u32 = 1 << 31;

#[derive(Debug, Clone)]
pub(super) struct ListStore {
    /// List i in line is `inline[i * room..][..len]`.
    room: usize,
    /// Each list's length, with `SPILLED` set if it lives in the spill store.
    len: Vec<u32>,
    inline: Vec<u32>,
    /// Slot s is `spill[s * spill_room..]`; `free` holds the slots to reuse.
    spill_room: usize,
    spill: Vec<u32>,
    free: Vec<u32>,
}

impl ListStore {
    /// `lists` empty lists, each with room for `room` entries in line.
    pub fn new(lists: usize, room: usize) -> Self {
        let room = room.max(1);
        ListStore {
            room,
            len: vec![0; lists],
            inline: vec![0; lists * room],
            spill_room: room + room / 2,
            spill: Vec::new(),
            free: Vec::new(),
        }
    }

    #[inline(always)]
    fn where_is(&self, i: usize) -> (bool, usize) {
        let len = self.len[i];
        (len & SPILLED != 0, (len & !SPILLED) as usize)
    }

    /// Where list i's room starts (in line or in the spill store) and how
    /// long the room is.
    #[inline(always)]
    fn room_of(&self, i: usize, spilled: bool) -> (usize, usize) {
        if spilled {
            let slot = self.inline[i * self.room] as usize;
            (slot * self.spill_room, self.spill_room)
        } else {
            (i * self.room, self.room)
        }
    }

    #[inline(always)]
    pub fn get(&self, i: usize) -> &[u32] {
        let (spilled, n) = self.where_is(i);
        let (at, _) = self.room_of(i, spilled);
        if spilled {
            &self.spill[at..at + n]
        } else {
            &self.inline[at..at + n]
        }
    }

    /// List i's whole room and how much of it the list fills.
    fn room_mut(&mut self, i: usize) -> (&mut [u32], usize) {
        let (spilled, n) = self.where_is(i);
        let (at, room) = self.room_of(i, spilled);
        let store = if spilled {
            &mut self.spill
        } else {
            &mut self.inline
        };
        (&mut store[at..at + room], n)
    }

    /// List i's length and where it starts in line (a hint).
    #[inline(always)]
    pub fn prefetch(&self, i: usize) {
        prefetch(&self.len[i]);
        if let Some(first) = self.inline.get(i * self.room) {
            prefetch(first);
        }
    }

    /// Put `e` into list i, keeping it sorted.
    pub fn insert(&mut self, i: usize, e: u32) {
        let (spilled, n) = self.where_is(i);
        if n == self.room_of(i, spilled).1 {
            self.make_room(i, spilled);
        }
        // From the end, moving the larger entries up one: lists are short,
        // so this beats a search and a call to memmove.
        let (list, mut at) = self.room_mut(i);
        while at > 0 && list[at - 1] > e {
            list[at] = list[at - 1];
            at -= 1;
        }
        list[at] = e;
        self.len[i] += 1;
    }

    /// Take the first entry `is` picks out of list i, if any.
    pub fn remove(&mut self, i: usize, is: impl Fn(u32) -> bool) {
        let (list, n) = self.room_mut(i);
        if let Some(at) = list[..n].iter().position(|&e| is(e)) {
            list.copy_within(at + 1..n, at);
            self.len[i] -= 1;
        }
    }

    /// Make list i `entries`.
    pub fn set(&mut self, i: usize, entries: &[u32]) {
        let (spilled, _) = self.where_is(i);
        if spilled {
            self.free.push(self.inline[i * self.room]);
        }
        self.len[i] = 0;
        if entries.len() > self.room {
            self.spill_out(i, entries.len());
        }
        let (list, _) = self.room_mut(i);
        list[..entries.len()].copy_from_slice(entries);
        self.len[i] |= entries.len() as u32;
    }

    /// Empty every list.
    pub fn clear(&mut self) {
        self.len.fill(0);
        self.spill.clear();
        self.free.clear();
    }

    /// List i (`spilled` or not) is full: give it more room.
    fn make_room(&mut self, i: usize, spilled: bool) {
        let (_, n) = self.where_is(i);
        if spilled {
            let (old, room) = (self.spill_room, self.spill_room + self.spill_room / 2);
            let slots = self.spill.len() / old;
            widen_rooms(&mut self.spill, slots, |_| old, (old, room), 0);
            self.spill_room = room;
            return;
        }
        let at = i * self.room;
        let moving = self.inline[at..at + n].to_vec();
        self.spill_out(i, n + 1);
        let (list, _) = self.room_mut(i);
        list[..n].copy_from_slice(&moving);
        self.len[i] |= n as u32;
    }

    /// Give list i (empty, in line) a slot with room for `need` entries, or,
    /// when one list in sixteen would have spilled (the room in line was
    /// sized for a density the system no longer has), widen every room in
    /// line by a quarter instead.
    fn spill_out(&mut self, i: usize, need: usize) {
        let slots = self.spill.len() / self.spill_room;
        if 16 * (slots - self.free.len() + 1) > self.len.len() {
            let room = self.room + self.room.div_ceil(4);
            let (len, old) = (&self.len, self.room);
            widen_rooms(
                &mut self.inline,
                len.len(),
                |k| match len[k] {
                    l if l & SPILLED != 0 => 1,
                    l => l as usize,
                },
                (old, room),
                0,
            );
            self.room = room;
            if need <= room {
                return;
            }
        }
        while self.spill_room < need {
            self.make_room(i, true);
        }
        let slot = self.free.pop().unwrap_or_else(|| {
            self.spill.resize(self.spill.len() + self.spill_room, 0);
            slots as u32
        });
        self.inline[i * self.room] = slot;
        self.len[i] = SPILLED;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

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
        for step in 0..40_000 {
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
            spilled_seen += (store.len[i] & SPILLED != 0) as usize;
            if step % 997 == 0 {
                for (k, t) in truth.iter().enumerate() {
                    assert_eq!(store.get(k), &t[..], "list {k} at step {step}");
                }
            }
        }
        for (k, t) in truth.iter().enumerate() {
            assert_eq!(store.get(k), &t[..], "list {k}");
        }
        assert!(spilled_seen > 1000, "lists spilled {spilled_seen} times");
        assert!(store.room > first.0, "the rooms in line widened");
        assert!(store.spill_room > first.1, "the spill slots widened");
        store.clear();
        assert!((0..lists).all(|k| store.get(k).is_empty()));
    }
}
