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

/// How long the pool's other threads stay awake after a step ends (so that
/// the next step, if it comes at once, finds them awake), and the longest a
/// helper waits for work while a step runs before it gives up its thread.
#[cfg(feature = "parallel")]
const HELPER_PATIENCE: std::time::Duration = std::time::Duration::from_millis(1);

#[cfg(feature = "parallel")]
mod awake {
    use std::cell::Cell;
    use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
    use std::sync::OnceLock;
    use std::time::Instant;

    /// Steps running with the pool kept awake, over all worlds.
    pub static STEPS: AtomicUsize = AtomicUsize::new(0);
    /// When the last of them ended (ns since [`epoch`]).
    pub static LAST_END: AtomicU64 = AtomicU64::new(0);

    thread_local! {
        /// This thread runs a step, or already helps: no helper here.
        pub static BUSY: Cell<bool> = const { Cell::new(false) };
    }

    pub fn epoch() -> Instant {
        static EPOCH: OnceLock<Instant> = OnceLock::new();
        *EPOCH.get_or_init(Instant::now)
    }

    pub fn now_ns() -> u64 {
        epoch().elapsed().as_nanos() as u64
    }

    /// A step running with the pool kept awake, on this thread; undone
    /// when dropped, also if the step panics.
    pub struct Stepping {
        was_busy: bool,
    }

    impl Stepping {
        pub fn start() -> Stepping {
            STEPS.fetch_add(1, Ordering::AcqRel);
            Stepping {
                was_busy: BUSY.with(|busy| busy.replace(true)),
            }
        }
    }

    impl Drop for Stepping {
        fn drop(&mut self) {
            BUSY.with(|busy| busy.set(self.was_busy));
            LAST_END.store(now_ns(), Ordering::Release);
            STEPS.fetch_sub(1, Ordering::AcqRel);
        }
    }

    /// Takes work from the pool (a stage's part), spinning in between
    /// rather than sleeping, until, with no step running, it has had no
    /// work or no step for [`super::HELPER_PATIENCE`]; or, while steps run,
    /// no work for four times that (a step busy on its own, or one this
    /// thread is itself part of).
    pub fn help() {
        if BUSY.with(|busy| busy.replace(true)) {
            return;
        }
        let patience = super::HELPER_PATIENCE.as_nanos() as u64;
        let mut last_work = now_ns();
        let mut idle = 0u32;
        loop {
            if rayon::yield_now() == Some(rayon::Yield::Executed) {
                idle = 0;
                last_work = now_ns();
                continue;
            }
            // Looking for work touches the other threads' queues: look
            // now and then, not flat out.
            for _ in 0..64 {
                std::hint::spin_loop();
            }
            idle += 1;
            if idle % 64 == 0 {
                let now = now_ns();
                let stepping = STEPS.load(Ordering::Acquire) > 0;
                let since_step = now.saturating_sub(LAST_END.load(Ordering::Acquire));
                let since_work = now.saturating_sub(last_work);
                if since_work > patience && (!stepping || since_work > 4 * patience)
                    || !stepping && since_step > patience
                {
                    break;
                }
            }
        }
        BUSY.with(|busy| busy.set(false));
    }
}

/// Runs `f` (a step) with the pool's other threads kept awake, when
/// `parallel`: between the step's parallel stages each waits for the next
/// by spinning instead of sleeping, and it goes on waiting for
/// `HELPER_PATIENCE` (1 ms) after the step. A pool thread that sleeps takes
/// 60–400 µs to wake on this machine (a 2-core VM): at 10⁵ discs, where a
/// step has half a dozen stages of about 100 µs, two threads were slower
/// than one. Which thread runs which part never changes a result
/// ([module docs](self)).
pub fn with_pool_awake<R: Send>(parallel: bool, f: impl FnOnce() -> R + Send) -> R {
    #[cfg(feature = "parallel")]
    {
        if parallel && rayon::current_num_threads() > 1 {
            let run = move || {
                let _stepping = awake::Stepping::start();
                // One helper per pool thread (each in its own queue, so
                // only that thread runs it); one that is already helping,
                // or runs this step, declines.
                rayon::spawn_broadcast(|_| awake::help());
                f()
            };
            // On a thread of the pool, which then does its share of each
            // stage itself instead of waiting for the others to.
            return if rayon::current_thread_index().is_some() {
                run()
            } else {
                rayon::scope(|_| run())
            };
        }
    }
    let _ = parallel;
    f()
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
/// `parallel` ([`on_each_part`]), else on this thread.
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
            let per_part = on_each_part(items, CHUNK, |_, part| {
                part.chunks_mut(CHUNK).map(&f).collect::<Vec<R>>()
            });
            out.extend(per_part.into_iter().flatten());
        },
        {
            out.extend(items.chunks_mut(CHUNK).map(f));
        }
    )
}

/// Calls `f` on each [`CHUNK`] of `items`; on rayon's pool if `parallel`
/// ([`on_each_part`]).
pub fn for_chunks_mut<T, F>(parallel: bool, items: &mut [T], f: F)
where
    T: Send,
    F: Fn(&mut [T]) + Sync + Send,
{
    pool_or_here!(
        parallel,
        {
            on_each_part(items, CHUNK, |_, part| part.chunks_mut(CHUNK).for_each(&f));
        },
        {
            items.chunks_mut(CHUNK).for_each(f);
        }
    )
}

/// The run of `count` chunk indices that thread `k` of `threads` takes:
/// contiguous, and the same at every stage and step.
#[cfg(feature = "parallel")]
pub(crate) fn run_of(k: usize, threads: usize, count: usize) -> std::ops::Range<usize> {
    count * k / threads..count * (k + 1) / threads
}

/// For each of `threads` threads, the items of `0..len` in its [run](run_of)
/// of chunks of `chunk` items: contiguous, in thread order, covering all.
#[cfg(feature = "parallel")]
pub(crate) fn spans_of(len: usize, chunk: usize, threads: usize) -> Vec<std::ops::Range<usize>> {
    let count = len.div_ceil(chunk);
    (0..threads)
        .map(|k| {
            let run = run_of(k, threads, count);
            (run.start * chunk).min(len)..(run.end * chunk).min(len)
        })
        .collect()
}

/// `items` cut into consecutive parts of the lengths of `spans` (contiguous
/// spans in order from 0, as [`spans_of`] gives).
#[cfg(feature = "parallel")]
pub(crate) fn split_by<'a, T>(
    mut items: &'a mut [T],
    spans: &[std::ops::Range<usize>],
) -> Vec<&'a mut [T]> {
    let mut parts = Vec::with_capacity(spans.len());
    for span in spans {
        let (part, rest) = std::mem::take(&mut items).split_at_mut(span.len());
        parts.push(part);
        items = rest;
    }
    parts
}

/// `f(run)` on every thread of the pool, each with its own run (`run_of`)
/// of the chunk indices `0..count`; the results in thread order.
///
/// Why not work stealing: on this machine (two cores of a VM) a core reads
/// what the other core last wrote at about the speed of one core alone
/// (a pass over 7 MB: 108 µs, the same halves each time 79 µs, one core
/// 107 µs). Giving each thread the same discs at every stage keeps them in
/// its own caches from stage to stage and step to step.
#[cfg(feature = "parallel")]
pub fn on_each_run<R, F>(count: usize, f: F) -> Vec<R>
where
    R: Send,
    F: Fn(std::ops::Range<usize>) -> R + Sync,
{
    rayon::broadcast(|ctx| f(run_of(ctx.index(), ctx.num_threads(), count)))
}

/// `f(first, part)` on every thread of the pool, each with its part of
/// `items`: whole chunks of `chunk` items, the same run (`run_of`) every
/// time, starting at chunk `first`. The results in thread order.
#[cfg(feature = "parallel")]
pub fn on_each_part<T, R, F>(items: &mut [T], chunk: usize, f: F) -> Vec<R>
where
    T: Send,
    R: Send,
    F: Fn(usize, &mut [T]) -> R + Sync,
{
    let threads = rayon::current_num_threads();
    let spans = spans_of(items.len(), chunk, threads);
    let firsts = spans.iter().map(|span| span.start / chunk);
    let parts: Vec<(usize, &mut [T])> = firsts.zip(split_by(items, &spans)).collect();
    on_each_thread(parts, |(first, part)| f(first, part))
}

/// `f(items[k])` on thread `k` of the pool, for every thread (`items` has
/// one per thread); the results in thread order. For stages whose part k
/// should be made where thread k will read it next (see [`on_each_run`]).
#[cfg(feature = "parallel")]
pub fn on_each_thread<T, R, F>(items: Vec<T>, f: F) -> Vec<R>
where
    T: Send,
    R: Send,
    F: Fn(T) -> R + Sync,
{
    use std::sync::Mutex;
    assert_eq!(
        items.len(),
        rayon::current_num_threads(),
        "one item per pool thread"
    );
    let items: Vec<Mutex<Option<T>>> = items.into_iter().map(|t| Mutex::new(Some(t))).collect();
    rayon::broadcast(|ctx| {
        // Each thread takes its own item, once.
        let taken = items[ctx.index()].lock().map(|mut item| item.take());
        match taken {
            Ok(Some(item)) => f(item),
            _ => unreachable!("each item is taken by its own thread, once"),
        }
    })
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

    fn pool(threads: usize) -> rayon::ThreadPool {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool")
    }

    #[test]
    fn each_thread_takes_the_same_run_every_time() {
        for threads in [2, 3, 5] {
            pool(threads).install(|| {
                // (thread that took it, times visited, index it was told)
                let mut items = vec![(usize::MAX, 0, 0); 7 * CHUNK + 5];
                for round in 0..4 {
                    let runs = on_each_part(&mut items, CHUNK, |first, part| {
                        let me = rayon::current_thread_index().expect("a pool thread");
                        for (k, item) in part.iter_mut().enumerate() {
                            if round == 0 {
                                item.0 = me;
                            }
                            assert_eq!(item.0, me, "the same thread every round");
                            item.1 += 1;
                            item.2 = first * CHUNK + k;
                        }
                        me
                    });
                    assert_eq!(runs, (0..threads).collect::<Vec<_>>(), "thread order");
                }
                let told: Vec<usize> = items.iter().map(|item| item.2).collect();
                assert_eq!(told, (0..items.len()).collect::<Vec<_>>());
                assert!(
                    items.iter().all(|item| item.1 == 4),
                    "each item once a round"
                );
                assert!(
                    items.windows(2).all(|w| w[0].0 <= w[1].0),
                    "contiguous runs"
                );
            });
        }
    }

    #[test]
    fn a_step_that_panics_leaves_its_thread_free_to_help_again() {
        pool(2).install(|| {
            let step = std::panic::AssertUnwindSafe(|| with_pool_awake(true, || panic!("a bug")));
            assert!(std::panic::catch_unwind(step).is_err());
            assert!(
                !awake::BUSY.with(|busy| busy.get()),
                "the thread is marked free again"
            );
            assert_eq!(with_pool_awake(true, || 7), 7, "and steps again");
        });
    }

    #[test]
    fn steps_with_the_pool_awake_finish_from_any_thread() {
        // Steps on a shared two-thread pool from four threads at once, from
        // inside and outside the pool, nested too: each returns its own
        // result (a helper that found itself on a busy thread gives it up).
        let shared = pool(2);
        std::thread::scope(|scope| {
            for t in 0..4u64 {
                let shared = &shared;
                scope.spawn(move || {
                    for k in 0..200u64 {
                        let step = || {
                            let mut items: Vec<u64> = (0..2 * CHUNK as u64).collect();
                            for_chunks_mut(true, &mut items, |c| {
                                c.iter_mut().for_each(|x| *x += t)
                            });
                            with_pool_awake(true, || items.iter().sum::<u64>() + k)
                        };
                        let got = if k % 2 == 0 {
                            shared.install(|| with_pool_awake(true, step))
                        } else {
                            with_pool_awake(true, step)
                        };
                        let n = 2 * CHUNK as u64;
                        assert_eq!(got, n * (n - 1) / 2 + n * t + k);
                    }
                });
            }
        });
    }
}
