//! An allocator that asks Linux to back large blocks with 2 MiB pages.
//!
//! Beyond ~10^5 spheres the engine reads its state at random, a line here and
//! a line there, each likely on a 4 KiB page the TLB does not hold; in a
//! virtual machine the walk after such a miss reads two page tables. Where
//! the kernel gives 2 MiB pages only to memory that asks for them
//! (`transparent_hugepage=madvise`, as on this project's machines), the `study` binary
//! asks through this allocator: whole runs of 10^6 spheres were 7-11 %
//! faster on an Intel virtual machine (docs/performance.md). Smaller blocks
//! go to the system allocator, so systems that fit in the caches make no
//! system call. The advice changes no byte the program sees, only how the
//! kernel maps it.

use std::alloc::{GlobalAlloc, Layout, System};

/// The system allocator, but every block of [`LARGE`] bytes or more is
/// mapped on its own, starting on a 2 MiB boundary, and advised to be backed
/// by huge pages before it is first touched. Install it with
/// `#[global_allocator]`.
pub struct HugePages;

/// A huge page, and the least block mapped as huge pages.
pub const LARGE: usize = 2 << 20;

unsafe impl GlobalAlloc for HugePages {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if large(layout) {
            huge::map(layout.size())
        } else {
            unsafe { System.alloc(layout) }
        }
    }
    // A fresh mapping reads as zeros.
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if large(layout) {
            huge::map(layout.size())
        } else {
            unsafe { System.alloc_zeroed(layout) }
        }
    }
    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        if large(layout) {
            unsafe { huge::unmap(p, layout.size()) }
        } else {
            unsafe { System.dealloc(p, layout) }
        }
    }
    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: the caller guarantees that new_size makes a valid layout.
        let new = unsafe { Layout::from_size_align_unchecked(new_size, layout.align()) };
        if !large(layout) && !large(new) {
            return unsafe { System.realloc(p, layout, new_size) };
        }
        // Into or out of a mapping of its own (a large block grows rarely:
        // the engine reserves what it needs).
        let q = unsafe { self.alloc(new) };
        if !q.is_null() {
            unsafe {
                std::ptr::copy_nonoverlapping(p, q, layout.size().min(new_size));
                self.dealloc(p, layout);
            }
        }
        q
    }
}

fn large(layout: Layout) -> bool {
    cfg!(target_os = "linux") && layout.size() >= LARGE && layout.align() <= LARGE
}

#[cfg(target_os = "linux")]
mod huge {
    use super::LARGE;

    /// A fresh private mapping of `size` bytes starting on a huge-page
    /// boundary, advised for huge pages while untouched, so the kernel maps
    /// 2 MiB pages as it is first written. Where the kernel refuses the
    /// advice nothing is lost but speed, so its result is not checked.
    pub fn map(size: usize) -> *mut u8 {
        // Map a huge page more than asked for, then give back the ends.
        let Some(room) = size.checked_add(LARGE) else {
            return std::ptr::null_mut();
        };
        // SAFETY: an anonymous mapping at an address of the kernel's
        // choosing touches nothing the program already has.
        let p = unsafe {
            libc::mmap(
                std::ptr::null_mut(),
                room,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
                -1,
                0,
            )
        };
        if p == libc::MAP_FAILED {
            return std::ptr::null_mut();
        }
        // SAFETY: sysconf reads a value the C library keeps.
        let page = unsafe { libc::sysconf(libc::_SC_PAGESIZE) }.max(1) as usize;
        let (at, start) = (p as usize, (p as usize).next_multiple_of(LARGE));
        let end = (start + size).next_multiple_of(page);
        // SAFETY: both ends lie inside the mapping just made and are page
        // aligned; the block between them is what the caller gets.
        unsafe {
            unmap(at as *mut u8, start - at);
            unmap(end as *mut u8, at + room - end);
            libc::madvise(start as *mut libc::c_void, size, libc::MADV_HUGEPAGE);
        }
        start as *mut u8
    }

    /// # Safety
    /// `p` and `size` are a block `map` returned, or a page-aligned part of
    /// its mapping.
    pub unsafe fn unmap(p: *mut u8, size: usize) {
        if size > 0 {
            unsafe { libc::munmap(p.cast(), size) };
        }
    }
}

// Off Linux no block is large, and these are never called.
#[cfg(not(target_os = "linux"))]
mod huge {
    pub fn map(_: usize) -> *mut u8 {
        std::ptr::null_mut()
    }
    pub unsafe fn unmap(_: *mut u8, _: usize) {}
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Blocks of every size keep their contents through the allocator,
    /// across a growth and a shrink that move them.
    #[test]
    fn blocks_keep_their_contents() {
        for size in [1, 4096, LARGE - 1, LARGE, 3 * LARGE + 17] {
            let layout = Layout::from_size_align(size, 64).unwrap();
            unsafe {
                let p = HugePages.alloc_zeroed(layout);
                assert!(!p.is_null());
                assert!(std::slice::from_raw_parts(p, size).iter().all(|&b| b == 0));
                for k in 0..size {
                    *p.add(k) = k as u8;
                }
                let q = HugePages.realloc(p, layout, 2 * size);
                assert!(!q.is_null());
                assert!((0..size).all(|k| *q.add(k) == k as u8));
                let grown = Layout::from_size_align(2 * size, 64).unwrap();
                let r = HugePages.realloc(q, grown, size / 3 + 1);
                assert!(!r.is_null());
                assert!((0..size / 3 + 1).all(|k| *r.add(k) == k as u8));
                HugePages.dealloc(r, Layout::from_size_align(size / 3 + 1, 64).unwrap());
            }
        }
    }

    /// A large block starts on a huge page, and its mapping carries the
    /// advice (`hg` among its flags in /proc/self/smaps) wherever the kernel
    /// has transparent huge pages.
    #[cfg(target_os = "linux")]
    #[test]
    fn large_blocks_are_advised() {
        if !std::path::Path::new("/sys/kernel/mm/transparent_hugepage").exists() {
            return;
        }
        let layout = Layout::from_size_align(LARGE, 64).unwrap();
        let p = unsafe { HugePages.alloc(layout) };
        assert_eq!(p as usize % LARGE, 0);
        let middle = p as usize + LARGE / 2;
        let smaps = std::fs::read_to_string("/proc/self/smaps").unwrap();
        let mut inside = false;
        let mut flags = None;
        for line in smaps.lines() {
            if let Some((range, _)) = line.split_once(' ')
                && let Some((a, b)) = range.split_once('-')
                && let (Ok(a), Ok(b)) = (usize::from_str_radix(a, 16), usize::from_str_radix(b, 16))
            {
                inside = (a..b).contains(&middle);
            } else if inside && let Some(f) = line.strip_prefix("VmFlags:") {
                flags = Some(f.split_whitespace().any(|f| f == "hg"));
            }
        }
        unsafe { HugePages.dealloc(p, layout) };
        assert_eq!(
            flags,
            Some(true),
            "no mapping of the block advised for huge pages"
        );
    }
}
