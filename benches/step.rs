//! Criterion benchmarks of `World::step` on the benchmark gas (equal discs
//! r = 0.5 m at 30 % area fraction, periodic, dt = 0.01 s), so regressions
//! show: the step of `impulse` / `grid` at several n, every broad phase, the
//! grid methods serial against parallel, and `exact`'s event loop with long
//! steps.
//!
//! `cargo bench --bench step` (about two minutes); `cargo bench --bench step
//! -- broad_phase` for one group. Times are per step; criterion also reports
//! discs per second (the throughput), whose inverse is the ns per
//! particle-step that `impulse bench` reports.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::{Method, Setting};
use impulse::presets::Gas;
use impulse::World;
use std::time::Duration;

/// The binary's allocator (large blocks on huge pages), so that these
/// timings are the sandbox's.
#[global_allocator]
static ALLOC: impulse::alloc_count::Counting = impulse::alloc_count::Counting;

const DT: f64 = 0.01;

/// The gas with a fixed method, broad phase and threading, warmed up.
fn gas(n: usize, method: Method, broad: BroadPhaseKind, parallel: bool) -> World {
    let mut world = Gas {
        count: n,
        ..Gas::default()
    }
    .build_fixed(method, broad);
    world.parallel = Setting::Fixed(parallel);
    for _ in 0..3 {
        world.step(DT);
    }
    world
}

/// A group of 10 samples after half a second of warm-up, measured for
/// `seconds`: enough to show a regression, short enough for a full run.
fn short_group<'a>(
    c: &'a mut Criterion,
    name: &str,
    seconds: u64,
) -> criterion::BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut group = c.benchmark_group(name);
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(seconds));
    group
}

/// `impulse` / `grid`, serial, as n grows.
fn step_against_n(c: &mut Criterion) {
    let mut group = short_group(c, "step_impulse_grid", 2);
    for n in [1_000, 10_000, 100_000] {
        let mut world = gas(n, Method::Impulse, BroadPhaseKind::Grid, false);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| world.step(DT))
        });
    }
    group.finish();
}

/// Every broad phase under `impulse` (brute force only where it is cheap).
fn broad_phases(c: &mut Criterion) {
    let mut group = short_group(c, "broad_phase", 1);
    for n in [1_000, 10_000] {
        group.throughput(Throughput::Elements(n as u64));
        for kind in BroadPhaseKind::ALL {
            if kind == BroadPhaseKind::Brute && n > 1_000 {
                continue;
            }
            let mut world = gas(n, Method::Impulse, kind, false);
            group.bench_function(BenchmarkId::new(kind.name(), n), |b| {
                b.iter(|| world.step(DT))
            });
        }
    }
    group.finish();
}

/// The grid methods at 10⁵ discs, serial and in parallel on two threads.
fn threads(c: &mut Criterion) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a thread pool");
    let mut group = short_group(c, "threads", 2);
    let n = 100_000;
    group.throughput(Throughput::Elements(n as u64));
    for method in [Method::Impulse, Method::Seed, Method::Verlet] {
        for parallel in [false, true] {
            let mut world = gas(n, method, BroadPhaseKind::Grid, parallel);
            let name = if parallel { "2_threads" } else { "serial" };
            group.bench_function(BenchmarkId::new(method.name(), name), |b| {
                pool.install(|| b.iter(|| world.step(DT)))
            });
        }
    }
    group.finish();
}

/// `exact`'s event loop beside the grid's step: the bench's "exact, long
/// steps" gas (2-second steps, about two collisions per disc each) at 10⁴
/// and 10⁵ discs, one thread. Criterion's throughput is discs per second;
/// `impulse bench` reports the same runs as collisions per second.
fn exact_event_loop(c: &mut Criterion) {
    let mut group = short_group(c, "exact_long_steps", 6);
    for n in [10_000, 100_000] {
        let mut world = Gas {
            count: n,
            ..Gas::default()
        }
        .build();
        world.method = Setting::Fixed(Method::Exact);
        world.parallel = Setting::Fixed(false);
        world.step(EXACT_DT);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| world.step(EXACT_DT))
        });
    }
    group.finish();
}

/// The step of `exact_event_loop` (s), as `impulse bench` takes it.
const EXACT_DT: f64 = 2.0;

criterion_group!(
    benches,
    step_against_n,
    broad_phases,
    threads,
    exact_event_loop
);
criterion_main!(benches);
