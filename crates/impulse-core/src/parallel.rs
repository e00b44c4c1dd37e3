//! Running the order-free stages of a step on several threads (rayon), with
//! results that do not depend on how many threads there are.
//!
//! A discrete step is mostly work that is independent per disc or per pair:
//! the skin list's "has anything moved too far?" check, the grid's gathering,
//! sorting and sweeping of cells, the narrow phase, integration and the
//! boundaries. Those run on rayon's pool when [`crate::auto`] says the scene
//! is large enough ([`crate::auto::PARALLEL_MIN_DISCS`]). Resolution is
//! Gauss–Seidel, sequential by nature; from
//! [`crate::resolution::BANDED_MIN_CONTACTS`] contacts per step it goes band by
//! band, and bands that share no disc run side by side
//! ([`crate::resolution::Banded`]). Below that (the benchmark gas has about
//! 2,300 contacts per step at 10⁶ discs, 1–2 % of the step) it stays in
//! ascending pair order on one thread, and so do the resting-contact sweeps.
//!
//! The rule that keeps a run bit-for-bit the same on 1, 2 or 64 threads, and
//! the same as the serial code: **work is cut where the data says, never
//! where the thread count says**. Discs come in chunks of [`CHUNK`], pairs in
//! chunks of [`PAIR_CHUNK`], the grid in bands of [`BAND_ROWS`] rows, contacts
//! in bands of the world's height; each
//! chunk's result is kept apart and the results are joined in chunk order;
//! a floating-point sum is summed per chunk and the chunk sums are added in
//! chunk order, by the serial code as well. Rayon only decides which thread
//! runs which chunk, which changes nothing. `tests/parallel.rs` holds a
//! 20,000-disc gas to that on one and two threads for every grid method.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// `$par` (on rayon's pool) when `$cond` holds and the crate is built with
/// its `parallel` feature; `$serial` otherwise. Both give the same result:
/// the parallel stages are written so that they do, bit for bit.
macro_rules! pool_or_here {
    ($cond:expr, $par:block, $serial:block) => {{
        #[cfg(feature = "parallel")]
        {
            if $cond $par else $serial
        }
        #[cfg(not(feature = "parallel"))]
        {
            let _ = $cond;
            $serial
        }
    }};
}
pub(crate) use pool_or_here;

/// `a` and `b`, side by side on rayon's pool with the `parallel` feature,
/// one after the other without it.
pub fn join<A, B, RA, RB>(a: A, b: B) -> (RA, RB)
where
    A: FnOnce() -> RA + Send,
    B: FnOnce() -> RB + Send,
    RA: Send,
    RB: Send,
{
    #[cfg(feature = "parallel")]
    {
        rayon::join(a, b)
    }
    #[cfg(not(feature = "parallel"))]
    {
        (a(), b())
    }
}

/// Discs per chunk of the per-disc stages (integration, boundaries, the skin
/// check). Large enough that a chunk costs far more than handing it to a
/// thread (a few µs against about 1 µs), small enough that 10⁴ discs still
/// make three chunks.
pub const CHUNK: usize = 4096;

/// Candidate pairs per chunk of the narrow phase.
pub const PAIR_CHUNK: usize = 8192;

/// Grid rows per band of the grid's column sort and sweep.
pub const BAND_ROWS: usize = 16;

/// Calls `f` on each [`CHUNK`] of `items` (the last one may be shorter) and
/// puts the results into `out`, in chunk order; on rayon's pool if
/// `parallel`, else on this thread. `out` keeps its allocation.
pub fn map_chunks_mut<T, R, F>(parallel: bool, items: &mut [T], f: F, out: &mut Vec<R>)
where
    T: Send,
    R: Send,
    F: Fn(&mut [T]) -> R + Sync + Send,
{
    out.clear();
    pool_or_here!(
        parallel,
        {
            items.par_chunks_mut(CHUNK).map(f).collect_into_vec(out);
        },
        {
            out.extend(items.chunks_mut(CHUNK).map(f));
        }
    )
}

/// Calls `f` on each [`CHUNK`] of `items`; on rayon's pool if `parallel`.
pub fn for_chunks_mut<T, F>(parallel: bool, items: &mut [T], f: F)
where
    T: Send,
    F: Fn(&mut [T]) + Sync + Send,
{
    pool_or_here!(
        parallel,
        {
            items.par_chunks_mut(CHUNK).for_each(f);
        },
        {
            items.chunks_mut(CHUNK).for_each(f);
        }
    )
}

/// Asks the memory for the cache line holding `value`; nothing else (for
/// the loops over more discs than the caches hold).
#[inline(always)]
pub fn prefetch<T>(value: &T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch is only a hint: it reads nothing into the program
    // and never faults, and SSE is part of every x86-64 processor.
    unsafe {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        _mm_prefetch::<_MM_HINT_T0>((value as *const T).cast());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = value;
}

/// The number of threads a parallel stage would use here: rayon's current
/// pool (inside `ThreadPool::install`, that pool; otherwise the global one,
/// sized by `RAYON_NUM_THREADS` or the number of cores).
pub fn threads() -> usize {
    #[cfg(feature = "parallel")]
    {
        rayon::current_num_threads()
    }
    #[cfg(not(feature = "parallel"))]
    {
        1
    }
}

#[cfg(all(test, feature = "parallel"))]
mod tests {
    use super::*;

    #[test]
    fn chunks_come_back_in_order_whatever_the_pool() {
        let pool = |k| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(k)
                .build()
                .expect("a thread pool")
        };
        let mut items: Vec<u64> = (0..3 * CHUNK as u64 + 17).collect();
        let sums = |parallel: bool, items: &mut Vec<u64>| {
            let mut out = Vec::new();
            map_chunks_mut(parallel, items, |c| c.iter().sum::<u64>(), &mut out);
            out
        };
        let serial = sums(false, &mut items);
        assert_eq!(serial.len(), 4);
        assert_eq!(serial.iter().sum::<u64>(), items.iter().sum::<u64>());
        for k in [1, 2, 3] {
            assert_eq!(pool(k).install(|| sums(true, &mut items)), serial);
        }
        for_chunks_mut(true, &mut items, |c| c.iter_mut().for_each(|x| *x *= 2));
        assert_eq!(items[3 * CHUNK + 16], 2 * (3 * CHUNK as u64 + 16));
    }
}
