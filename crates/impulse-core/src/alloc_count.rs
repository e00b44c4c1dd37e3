//! The global allocator: it counts live heap bytes, for measuring what a
//! world really holds (`impulse bench`'s bytes per disc, `tests/memory.rs`),
//! and on Linux puts every block of 2 MiB or more on huge pages.
//!
//! The library does not install it; a binary does, with
//! `#[global_allocator] static ALLOC: impulse::alloc_count::Counting = impulse::alloc_count::Counting;`.
//! It forwards to the system allocator and keeps one relaxed atomic counter,
//! so it costs a few nanoseconds per allocation and nothing per step once a
//! step has stopped allocating.
//!
//! Huge pages: a step of a large scene reads its arrays all over (`exact`'s
//! discs and queue at 10⁵ discs, the grid's discs and pairs at 10⁶), and
//! with 4-KiB pages the processor's cache of address translations covers a
//! few MiB of them at most. A block of 2 MiB or more therefore starts on a
//! 2-MiB boundary and is advised for transparent huge pages (`madvise`)
//! before anything touches it: in the `madvise` mode most distributions
//! default to, a program gets huge pages only where it asks. The bytes counted are the bytes asked for,
//! as before; what the process holds can grow by the part of a block's huge
//! page it has not used yet (a vector's spare capacity, say): at 10⁶ discs
//! on the grid, 191 against 184 MB. Measured in docs/lab/NOTES.md (the tenth
//! look at issue 30).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

static LIVE: AtomicUsize = AtomicUsize::new(0);

/// The system allocator, counting the bytes it has handed out and not yet
/// been given back, with large blocks placed on huge pages (see the module).
#[derive(Clone, Copy, Debug, Default)]
pub struct Counting;

/// Blocks this large or larger start on a huge-page boundary and are
/// advised for huge pages.
#[cfg(target_os = "linux")]
const HUGE_PAGE: usize = 2 << 20;

/// Where the system allocator places a block asked for with `layout`: a
/// large one on a huge-page boundary (Linux), anything else as asked. The
/// same layout always gives the same answer, so a block is freed as it was
/// allocated.
fn placed(layout: Layout) -> Layout {
    #[cfg(target_os = "linux")]
    if layout.size() >= HUGE_PAGE && layout.align() < HUGE_PAGE {
        if let Ok(l) = Layout::from_size_align(layout.size(), HUGE_PAGE) {
            return l;
        }
    }
    layout
}

/// Asks for huge pages under a block just placed by [`placed`], before
/// anything touches it.
fn advise(p: *mut u8, layout: Layout) {
    #[cfg(target_os = "linux")]
    if layout.align() == HUGE_PAGE {
        // The block's pages (the last one partly past its end, in the same
        // mapping); a system without huge pages refuses, and nothing changes.
        let len = layout.size().next_multiple_of(4096);
        // SAFETY: the range starts at the block, page-aligned, and ends
        // inside its mapping; the advice changes no byte of memory.
        unsafe {
            libc::madvise(p.cast(), len, libc::MADV_HUGEPAGE);
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = (p, layout);
}

// SAFETY: every call forwards to `System` with the same layout or with a
// stricter alignment of the same size (`placed`, the same for the same
// layout, so a block is freed as it was allocated), and the counter is only
// bookkeeping.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let at = placed(layout);
        // SAFETY: the caller's contract is the system allocator's.
        let p = unsafe { System.alloc(at) };
        if !p.is_null() {
            advise(p, at);
            LIVE.fetch_add(layout.size(), Ordering::Relaxed);
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let at = placed(layout);
        if at == layout {
            // SAFETY: the caller's contract is the system allocator's.
            let p = unsafe { System.alloc_zeroed(layout) };
            if !p.is_null() {
                LIVE.fetch_add(layout.size(), Ordering::Relaxed);
            }
            return p;
        }
        // SAFETY: as in `alloc`.
        let p = unsafe { self.alloc(layout) };
        if !p.is_null() {
            // SAFETY: the block is `layout.size()` bytes, just allocated.
            unsafe { std::ptr::write_bytes(p, 0, layout.size()) };
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above; `placed` gives the layout it was allocated with.
        unsafe { System.dealloc(ptr, placed(layout)) };
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: the caller's contract: `new_size` with `layout`'s
        // alignment is a valid layout.
        let new_layout = unsafe { Layout::from_size_align_unchecked(new_size, layout.align()) };
        if placed(layout) == layout && placed(new_layout) == new_layout {
            // SAFETY: the caller's contract is the system allocator's.
            let p = unsafe { System.realloc(ptr, layout, new_size) };
            if !p.is_null() {
                LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
                LIVE.fetch_add(new_size, Ordering::Relaxed);
            }
            return p;
        }
        // A block placed on a huge page, or about to be: a new one, the
        // contents copied over.
        // SAFETY: as in `alloc`.
        let p = unsafe { self.alloc(new_layout) };
        if !p.is_null() {
            // SAFETY: both blocks are live and at least this long.
            unsafe {
                std::ptr::copy_nonoverlapping(ptr, p, layout.size().min(new_size));
                self.dealloc(ptr, layout);
            }
        }
        p
    }
}

/// Heap bytes live right now, if [`Counting`] is the global allocator
/// (0 otherwise).
pub fn live_bytes() -> usize {
    LIVE.load(Ordering::Relaxed)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MIB: usize = 1 << 20;

    #[test]
    fn small_blocks_are_placed_as_asked_and_large_ones_on_a_huge_page_boundary() {
        let small = Layout::from_size_align(MIB, 64).unwrap();
        assert_eq!(placed(small), small);
        let large = Layout::from_size_align(3 * MIB, 64).unwrap();
        let at = placed(large);
        assert_eq!(at.size(), large.size());
        if cfg!(target_os = "linux") {
            assert_eq!(at.align(), 2 * MIB);
        } else {
            assert_eq!(at, large);
        }
    }

    /// Bytes that differ from one place to the next.
    fn pattern(k: usize) -> u8 {
        (k.wrapping_mul(2_654_435_761) >> 13) as u8
    }

    #[test]
    fn a_block_keeps_its_contents_growing_past_the_threshold_and_shrinking_back() {
        let a = Counting;
        let layout = |size| Layout::from_size_align(size, 8).unwrap();
        // SAFETY: every block is used within its size and freed once, with
        // the layout it has at that moment.
        unsafe {
            let p = a.alloc(layout(MIB));
            assert!(!p.is_null());
            for k in 0..MIB {
                *p.add(k) = pattern(k);
            }
            let q = a.realloc(p, layout(MIB), 3 * MIB);
            assert!(!q.is_null());
            if cfg!(target_os = "linux") {
                assert_eq!(
                    q as usize % (2 * MIB),
                    0,
                    "a large block starts on a boundary"
                );
            }
            assert!((0..MIB).all(|k| *q.add(k) == pattern(k)));
            for k in MIB..3 * MIB {
                *q.add(k) = pattern(k);
            }
            let r = a.realloc(q, layout(3 * MIB), MIB / 2);
            assert!(!r.is_null());
            assert!((0..MIB / 2).all(|k| *r.add(k) == pattern(k)));
            a.dealloc(r, layout(MIB / 2));

            let z = a.alloc_zeroed(layout(3 * MIB));
            assert!(!z.is_null());
            assert!((0..3 * MIB).all(|k| *z.add(k) == 0));
            a.dealloc(z, layout(3 * MIB));
        }
    }

    /// On Linux with transparent huge pages (which this machine and CI
    /// have), the mapping under a large block carries the advice: `hg` in
    /// its flags in `/proc/self/smaps`.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_large_block_is_advised_for_huge_pages() {
        let a = Counting;
        let layout = Layout::from_size_align(5 * MIB, 64).unwrap();
        // SAFETY: allocated, looked up and freed with the same layout.
        let p = unsafe { a.alloc(layout) };
        assert!(!p.is_null());
        let inside = p as usize + 3 * MIB;
        let smaps = std::fs::read_to_string("/proc/self/smaps").unwrap();
        let mut flags = None;
        let mut holds = false;
        for line in smaps.lines() {
            if let Some((range, _)) = line.split_once(' ') {
                if let Some((lo, hi)) = range.split_once('-') {
                    if let (Ok(lo), Ok(hi)) =
                        (usize::from_str_radix(lo, 16), usize::from_str_radix(hi, 16))
                    {
                        holds = (lo..hi).contains(&inside);
                        continue;
                    }
                }
            }
            if holds && line.starts_with("VmFlags:") {
                flags = Some(line.to_string());
            }
        }
        // SAFETY: as above.
        unsafe { a.dealloc(p, layout) };
        let flags = flags.expect("the block's mapping is listed");
        let huge_pages = std::path::Path::new("/sys/kernel/mm/transparent_hugepage").exists();
        assert_eq!(
            flags.split_whitespace().any(|f| f == "hg"),
            huge_pages,
            "{flags}"
        );
    }
}
