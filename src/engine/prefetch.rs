//! A hint to start loading memory that will be read soon.
//!
//! Beyond a few 10^4 particles the state outgrows the caches, and an event
//! reads records scattered through it (partners, their lists, grid cells).
//! Each miss costs ~100 ns; asking for all of them before the first is used
//! lets them overlap instead of following one another. A prefetch is only a
//! hint: it never faults, changes nothing the program can see, and so cannot
//! change a trajectory. It takes a reference, so it only ever names live data.
//!
//! A line from memory takes ~170 ns, and while it comes it holds one of
//! the core's L1 miss buffers (about twenty: `cargo bench --bench memory`
//! gains nothing beyond 24 lines in flight). What the event loop asks for
//! an event ahead, or a stage before it is read, goes into L2 only
//! ([`Read::Later`]): it has time to arrive, and the buffers stay free for
//! the lines the core is waiting on now. Asked for again just before it is
//! read, it comes on to L1 from L2 in a few ns. With 10^6 spheres that made
//! a collision ~9 % cheaper than asking for everything into L1 (see
//! docs/performance.md).

/// When a hinted line will be read, which decides the cache it is brought to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Read {
    /// Within the stage being run: into L1.
    Soon,
    /// A stage or an event from now: into L2.
    Later,
}

/// Ask for the cache lines holding the first and the last byte of `value`
/// (all of it for a value up to a line and a bit, which may straddle two
/// lines). A value no larger than its alignment (an index, a time) lies in
/// one line, and one hint is enough. A 64-byte body (aligned to 8 bytes)
/// gets two that name the same line, since bodies start on one: a check at
/// run time for that was no faster.
#[inline(always)]
pub fn prefetch<T>(value: &T) {
    prefetch_for(value, Read::Soon);
}

/// [`prefetch`], for a value that will be read `when`.
#[inline(always)]
pub fn prefetch_for<T>(value: &T, when: Read) {
    let start = value as *const T as *const i8;
    line(start, when);
    let size = std::mem::size_of::<T>();
    if size > std::mem::align_of::<T>().min(64) {
        line(start.wrapping_add(size - 1), when);
    }
}

/// Where a slice's records lie, to ask for record k while the slice is
/// borrowed elsewhere (a hint reads nothing, so it needs no borrow). A
/// record gets a hint for its first and its last byte, as `prefetch` gives
/// one larger than its alignment (a body).
#[derive(Debug, Clone, Copy)]
pub struct Lines {
    start: usize,
    size: usize,
    len: usize,
}

impl Lines {
    pub fn of<T>(records: &[T]) -> Self {
        Lines {
            start: records.as_ptr() as usize,
            size: std::mem::size_of::<T>(),
            len: records.len(),
        }
    }

    #[inline(always)]
    pub fn ask(&self, k: usize, when: Read) {
        if k < self.len && self.size > 0 {
            let start = self.start + k * self.size;
            line(start as *const i8, when);
            line((start + self.size - 1) as *const i8, when);
        }
    }
}

#[inline(always)]
fn line(address: *const i8, when: Read) {
    #[cfg(target_arch = "x86_64")]
    {
        use core::arch::x86_64::{_MM_HINT_T0, _MM_HINT_T1, _mm_prefetch};
        // SAFETY: a prefetch never dereferences in the language's sense: it
        // cannot fault, whatever the address (here always inside `value`).
        match when {
            Read::Soon => unsafe { _mm_prefetch::<_MM_HINT_T0>(address) },
            Read::Later => unsafe { _mm_prefetch::<_MM_HINT_T1>(address) },
        }
    }
    // Elsewhere no hint is given, which changes nothing but the speed.
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (address, when);
}
