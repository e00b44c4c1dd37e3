//! `impulse bench`: what a step costs per disc, for every broad phase and
//! method, as the number of discs grows.
//!
//! The scene is a gas of equal discs (radius 0.5 m, rms speed 1 m/s) at 30 %
//! area fraction in a periodic square, stepped at dt = 0.01 s (a disc moves
//! 2 % of its radius per step). Each configuration is timed in batches of
//! about 0.2 s after a warm-up; the figure is the median batch, in ns per
//! particle-step (wall-clock of one step divided by n). Configurations whose
//! estimated run time would exceed the budget (brute force at large n) are
//! skipped and said so.
//!
//! Every configuration runs on a pool of one thread (so `auto` keeps it
//! serial); the grid methods run again on `--threads` threads (default 2),
//! where `auto` runs them in parallel from
//! [`impulse::auto::PARALLEL_MIN_DISCS`] discs, and their speed-up over one
//! thread is timed against a one-thread twin, batch by batch alternately
//! (the machine's load drifts between the rows). Bytes per disc are the heap
//! bytes the world holds after its warm-up steps (discs and every buffer of
//! the pipeline), counted by the binary's global allocator
//! ([`impulse::alloc_count`]). Tables after it (`crossovers.rs`) measure the
//! crossovers behind `auto`'s rules, among them serial against parallel on
//! the same pool, and resolution on one thread against several in a crowded
//! gas.

mod crossovers;

use super::chart::{method_colour, write_chart, Chart, Series};
use crate::progress;
use crossovers::{crossovers, crowded_resolution, resting_piles, thread_crossover};
use impulse::alloc_count::live_bytes;
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::{Method, Setting};
use impulse::presets::Gas;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `impulse bench`.
#[derive(Clone, Debug, clap::Args)]
pub struct BenchArgs {
    /// Up to 10,000 discs and shorter timings (about a minute).
    #[arg(long)]
    pub quick: bool,
    /// Folder for bench.csv, bench.png and bench.svg.
    #[arg(long, default_value = "lab-out")]
    pub out: PathBuf,
    /// Threads of the parallel runs of the grid methods (the others and the
    /// grid's serial runs use one).
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u16).range(1..=256))]
    pub threads: u16,
}

/// Time step of the benchmark gas (s).
pub const DT: f64 = 0.01;

/// One measured configuration.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    /// Collision method.
    pub method: Method,
    /// Broad phase (`exact` keeps its own cells and ignores it).
    pub broad_phase: String,
    /// Threads in the pool it ran on.
    pub threads: usize,
    /// Whether `auto` ran the step in parallel.
    pub parallel: bool,
    /// Discs.
    pub n: usize,
    /// Median ns per particle-step.
    pub ns_per_particle_step: f64,
    /// Heap bytes the world holds per disc after warming up.
    pub bytes_per_particle: f64,
    /// Pair collisions per wall-clock second.
    pub collisions_per_second: f64,
    /// Steps timed.
    pub steps: u64,
    /// On more than one thread: the median over paired batches of the same
    /// configuration's time on one thread over its time on these threads,
    /// the two timed alternately, batch by batch ([`measure_against_one_thread`]).
    pub speed_up: Option<f64>,
}

/// The configurations: every broad phase under `impulse`, and every other
/// method on the grid, on one thread; the grid methods again on `threads`.
fn configurations(threads: usize) -> Vec<(Method, BroadPhaseKind, usize)> {
    let mut list: Vec<_> = BroadPhaseKind::ALL
        .iter()
        .map(|&b| (Method::Impulse, b, 1))
        .collect();
    list.extend(
        [Method::Seed, Method::Verlet, Method::Exact].map(|m| (m, BroadPhaseKind::Grid, 1)),
    );
    if threads > 1 {
        list.extend(
            [Method::Impulse, Method::Seed, Method::Verlet]
                .map(|m| (m, BroadPhaseKind::Grid, threads)),
        );
    }
    list
}

/// A rayon pool of `threads` threads.
fn pool(threads: usize) -> anyhow::Result<rayon::ThreadPool> {
    Ok(rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()?)
}

/// Runs the benchmark, prints the table and writes CSV and chart.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    // The folder first: a bad --out is refused before minutes of measuring.
    super::create_out_dir(&args.out)?;
    let sizes: &[usize] = if args.quick {
        &[100, 1_000, 10_000]
    } else {
        &[100, 1_000, 10_000, 100_000, 1_000_000]
    };
    let (batch_seconds, budget_seconds) = if args.quick { (0.05, 5.0) } else { (0.2, 40.0) };
    let threads = usize::from(args.threads);
    let configs = configurations(threads);
    let pools = [pool(1)?, pool(threads)?];
    let bar = progress::bar((configs.len() * sizes.len()) as u64, "bench");
    let mut rows = Vec::new();
    let mut skipped = Vec::new();
    for &(method, broad, k) in &configs {
        let mut last: Option<(usize, f64)> = None;
        for &n in sizes {
            bar.inc(1);
            if let Some((prev_n, prev_ns)) = last {
                // Brute force costs O(n) per disc, the others O(1).
                let growth = if broad == BroadPhaseKind::Brute && method != Method::Exact {
                    1.0
                } else {
                    0.0
                };
                let step_seconds =
                    prev_ns * 1e-9 * n as f64 * (n as f64 / prev_n as f64).powf(growth);
                if step_seconds * 12.0 > budget_seconds {
                    skipped.push(format!(
                        "{} / {} ({k} thread(s)) at n = {n}: about {step_seconds:.1} s per step",
                        method,
                        broad.name()
                    ));
                    continue;
                }
            }
            bar.set_message(format!("{method} / {} ×{k} n = {n}", broad.name()));
            let row = if k > 1 {
                let pools = (&pools[0], &pools[1]);
                measure_against_one_thread(method, broad, n, batch_seconds, pools)
            } else {
                pools[0].install(|| measure(method, broad, n, batch_seconds))
            };
            last = Some((n, row.ns_per_particle_step));
            rows.push(row);
        }
    }
    bar.finish_and_clear();
    let mut crossovers = crossovers(batch_seconds);
    crossovers += &resting_piles(args.quick);
    if threads > 1 {
        let sizes: &[usize] = if args.quick {
            &[1_000, 10_000]
        } else {
            &[1_000, 2_000, 5_000, 10_000, 20_000, 50_000]
        };
        crossovers += &pools[1].install(|| thread_crossover(sizes, batch_seconds));
        let sizes: &[usize] = if args.quick {
            &[100_000]
        } else {
            &[100_000, 400_000, 1_000_000]
        };
        crossovers += &crowded_resolution(sizes, &pools[0], &pools[1]);
    }
    // (discs, collisions to run): the full run takes 10⁷ collisions at 10⁴
    // discs, where the energy target is set.
    let throughput_runs: &[(usize, usize)] = if args.quick {
        &[(10_000, 100_000)]
    } else {
        &[(10_000, 10_000_000), (100_000, 1_000_000)]
    };
    let throughput: Vec<Throughput> = throughput_runs
        .iter()
        .map(|&(n, collisions)| exact_throughput(n, collisions))
        .collect();
    let mut table = table(&rows, &skipped);
    let _ = writeln!(table, "\n| exact, long steps (dt = {EXACT_DT} s) | n | collisions | collisions per wall-clock second (median step) | events per collision | relative energy change |");
    let _ = writeln!(table, "|---|---:|---:|---:|---:|---:|");
    for t in &throughput {
        let _ = writeln!(
            table,
            "| exact{} | {} | {:.1e} | {:.3e} | {:.2} | {:.1e} |",
            match t.cut_short {
                0 => String::new(),
                k => format!(" ({k} steps cut short: stalled)"),
            },
            t.n,
            t.collisions as f64,
            t.collisions_per_second,
            t.events_per_collision,
            t.energy_change
        );
    }
    table.push_str(&crossovers);
    print!("{table}");
    write_csv(&args.out.join("bench.csv"), &rows)?;
    crate::files::write_atomically(&args.out.join("bench.md"), table.as_bytes())?;
    let (png, svg) = write_bench_chart(&rows, &args.out)?;
    println!(
        "wrote {}, {}, {}",
        args.out.join("bench.csv").display(),
        png.display(),
        svg.display()
    );
    Ok(())
}

/// Median ns per particle-step of `world` over a few batches.
pub(super) fn time_world(world: &mut impulse::World, batch_seconds: f64) -> f64 {
    let n = world.particles.len().max(1) as f64;
    let warm = Instant::now();
    world.step(DT);
    let batch =
        ((batch_seconds / warm.elapsed().as_secs_f64().max(1e-7)).round() as u64).clamp(1, 100_000);
    let mut samples: Vec<f64> = (0..5)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..batch {
                world.step(DT);
            }
            t.elapsed().as_secs_f64() * 1e9 / (batch as f64 * n)
        })
        .collect();
    median(&mut samples)
}

/// Step for the exact method's throughput, long enough that the per-step
/// set-up is amortised over many collisions (s).
pub const EXACT_DT: f64 = 2.0;

/// Collisions per wall-clock second of the exact method.
#[derive(Clone, Debug, Serialize)]
pub struct Throughput {
    /// Discs.
    pub n: usize,
    /// Pair collisions timed.
    pub collisions: usize,
    /// Pair collisions per wall-clock second (median over the steps).
    pub collisions_per_second: f64,
    /// Events processed per pair collision.
    pub events_per_collision: f64,
    /// |KE after − KE before| / KE before over the timed steps.
    pub energy_change: f64,
    /// Steps the event cap cut short (the rate is then of a stalled run).
    pub cut_short: usize,
}

/// Measures `exact` on the gas with long steps, for at least `collisions`
/// pair collisions (and at least three steps).
pub fn exact_throughput(n: usize, collisions: usize) -> Throughput {
    let mut world = Gas {
        count: n,
        ..Gas::default()
    }
    .build();
    world.method = Setting::Fixed(Method::Exact);
    world.step(EXACT_DT);
    let ke0 = world.metrics().kinetic_energy;
    let target = collisions;
    let bar = progress::bar(target as u64, &format!("exact, {n} discs"));
    let (mut rates, mut events, mut collisions, mut cut_short) = (Vec::new(), 0usize, 0usize, 0);
    // A gas that stopped colliding would never reach the target: give up
    // after a step without collisions.
    while rates.len() < 3 || (collisions < target && rates.last() != Some(&0.0)) {
        let t = Instant::now();
        let stats = world.step(EXACT_DT);
        rates.push(stats.pair_collisions as f64 / t.elapsed().as_secs_f64());
        events += stats.events;
        collisions += stats.pair_collisions;
        cut_short += usize::from(stats.truncated);
        bar.set_position(collisions.min(target) as u64);
    }
    bar.finish_and_clear();
    Throughput {
        n,
        collisions,
        collisions_per_second: median(&mut rates),
        events_per_collision: events as f64 / collisions.max(1) as f64,
        energy_change: (world.metrics().kinetic_energy - ke0).abs() / ke0,
        cut_short,
    }
}

/// Times one configuration on the current rayon pool (`auto` decides
/// whether to run in parallel).
pub fn measure(method: Method, broad: BroadPhaseKind, n: usize, batch_seconds: f64) -> Row {
    let (mut world, bytes, batch) = warmed(method, broad, n, batch_seconds);
    let mut batches = Batches::default();
    for _ in 0..5 {
        let before = world.total_pair_collisions;
        let t = Instant::now();
        for _ in 0..batch {
            world.step(DT);
        }
        batches.add(
            t.elapsed().as_secs_f64(),
            batch,
            n,
            world.total_pair_collisions - before,
        );
    }
    batches.row(
        method,
        broad,
        &world,
        bytes,
        rayon::current_num_threads(),
        None,
    )
}

/// [`measure`] on `threads`, and the speed-up over one thread measured
/// against a twin world on `one` (a pool of one thread), the two stepped
/// alternately batch by batch (which goes first alternating too): the
/// machine's load drifts over minutes, and a ratio of runs minutes apart
/// carries that drift. Timed batches as in [`measure`]; the speed-up is the
/// median of the batches' ratios.
pub fn measure_against_one_thread(
    method: Method,
    broad: BroadPhaseKind,
    n: usize,
    batch_seconds: f64,
    (one, threads): (&rayon::ThreadPool, &rayon::ThreadPool),
) -> Row {
    let (mut world, bytes, batch) = threads.install(|| warmed(method, broad, n, batch_seconds));
    let (mut twin, _, _) = one.install(|| warmed(method, broad, n, batch_seconds));
    let time = |pool: &rayon::ThreadPool, world: &mut impulse::World| {
        pool.install(|| {
            let t = Instant::now();
            for _ in 0..batch {
                world.step(DT);
            }
            t.elapsed().as_secs_f64()
        })
    };
    let (mut batches, mut ratios) = (Batches::default(), Vec::new());
    for round in 0..5 {
        let before = world.total_pair_collisions;
        let (secs, serial) = if round % 2 == 0 {
            let secs = time(threads, &mut world);
            (secs, time(one, &mut twin))
        } else {
            let serial = time(one, &mut twin);
            (time(threads, &mut world), serial)
        };
        ratios.push(serial / secs.max(1e-12));
        batches.add(secs, batch, n, world.total_pair_collisions - before);
    }
    let threads = threads.current_num_threads();
    batches.row(
        method,
        broad,
        &world,
        bytes,
        threads,
        Some(median(&mut ratios)),
    )
}

/// The bench's gas of `n` discs for `method` and `broad`, warmed up by two
/// steps; with the bytes it holds and how many steps make a timed batch of
/// about `batch_seconds`.
fn warmed(
    method: Method,
    broad: BroadPhaseKind,
    n: usize,
    batch_seconds: f64,
) -> (impulse::World, usize, u64) {
    let before = live_bytes();
    let mut world = Gas {
        count: n,
        ..Gas::default()
    }
    .build_fixed(method, broad);
    let warm = Instant::now();
    for _ in 0..2 {
        world.step(DT);
    }
    let per_step = (warm.elapsed().as_secs_f64() / 2.0).max(1e-7);
    let bytes = live_bytes().saturating_sub(before);
    let batch = ((batch_seconds / per_step).round() as u64).clamp(1, 100_000);
    (world, bytes, batch)
}

/// What the timed batches of one configuration added up to.
#[derive(Default)]
struct Batches {
    /// Each batch's ns per disc-step.
    samples: Vec<f64>,
    steps: u64,
    collisions: u64,
    seconds: f64,
}

impl Batches {
    /// A batch of `batch` steps of `n` discs that took `secs` and had
    /// `collisions` pair collisions.
    fn add(&mut self, secs: f64, batch: u64, n: usize, collisions: u64) {
        self.samples.push(secs * 1e9 / (batch as f64 * n as f64));
        self.steps += batch;
        self.collisions += collisions;
        self.seconds += secs;
    }

    /// The table's row: the median batch, the bytes `world` holds.
    fn row(
        mut self,
        method: Method,
        broad: BroadPhaseKind,
        world: &impulse::World,
        bytes: usize,
        threads: usize,
        speed_up: Option<f64>,
    ) -> Row {
        let n = world.particles.len();
        Row {
            method,
            broad_phase: if method == Method::Exact {
                "cells".into()
            } else {
                broad.name().into()
            },
            threads,
            parallel: world.plan().is_some_and(|p| p.parallel),
            n,
            ns_per_particle_step: median(&mut self.samples),
            bytes_per_particle: bytes as f64 / n as f64,
            collisions_per_second: self.collisions as f64 / self.seconds.max(1e-12),
            steps: self.steps,
            speed_up,
        }
    }
}

/// The middle value (mean of the two middle ones for an even count).
pub fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    match values.len() {
        0 => f64::NAN,
        len if len % 2 == 1 => values[len / 2],
        len => 0.5 * (values[len / 2 - 1] + values[len / 2]),
    }
}

fn label(row: &Row) -> String {
    if row.threads > 1 {
        format!(
            "{} / {}, {} threads",
            row.method, row.broad_phase, row.threads
        )
    } else {
        format!("{} / {}", row.method, row.broad_phase)
    }
}

fn table(rows: &[Row], skipped: &[String]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "| method / broad phase | n | ns per particle-step (median) | speed-up over 1 thread | bytes per disc | collisions per second |"
    );
    let _ = writeln!(out, "|---|---:|---:|---:|---:|---:|");
    for r in rows {
        let serial = rows.iter().find(|s| {
            s.threads == 1 && s.method == r.method && s.broad_phase == r.broad_phase && s.n == r.n
        });
        let ratio = r.speed_up.or_else(|| {
            serial
                .filter(|_| r.threads > 1)
                .map(|s| s.ns_per_particle_step / r.ns_per_particle_step)
        });
        let speed_up = match ratio {
            Some(ratio) => format!("{ratio:.2}{}", if r.parallel { "" } else { " (serial)" }),
            None => String::new(),
        };
        let _ = writeln!(
            out,
            "| {} | {} | {:.1} | {speed_up} | {:.0} | {:.3e} |",
            label(r),
            r.n,
            r.ns_per_particle_step,
            r.bytes_per_particle,
            r.collisions_per_second
        );
    }
    for s in skipped {
        let _ = writeln!(out, "\nskipped: {s}");
    }
    out
}

fn write_csv(path: &Path, rows: &[Row]) -> anyhow::Result<()> {
    let mut csv = String::from(
        "method,broad_phase,threads,parallel,n,ns_per_particle_step,bytes_per_particle,collisions_per_second,steps,speed_up\n",
    );
    for r in rows {
        let _ = writeln!(
            csv,
            "{},{},{},{},{},{},{},{},{},{}",
            r.method,
            r.broad_phase,
            r.threads,
            r.parallel,
            r.n,
            r.ns_per_particle_step,
            r.bytes_per_particle,
            r.collisions_per_second,
            r.steps,
            r.speed_up.map(|x| x.to_string()).unwrap_or_default()
        );
    }
    Ok(crate::files::write_atomically(path, csv.as_bytes())?)
}

/// The chart of ns per particle-step against n, `bench.png` and `.svg`.
pub(crate) fn write_bench_chart(rows: &[Row], out: &Path) -> anyhow::Result<(PathBuf, PathBuf)> {
    let series = series_of(rows);
    let threads = rows.iter().map(|r| r.threads).max().unwrap_or(1);
    let subtitle = if threads > 1 {
        format!("colour: method · line: broad phase (brute solid, grid dashed, sap dotted, quadtree dash-dot; exact's cells solid) · hollow triangles: {threads} threads")
    } else {
        "colour: method · line: broad phase (brute solid, grid dashed, sap dotted, quadtree dash-dot; exact's cells solid)".to_owned()
    };
    let chart = Chart {
        title: "Cost of a step per disc (gas, 30 % area fraction)",
        subtitle: &subtitle,
        x_label: "discs n",
        y_label: "ns per particle-step",
        log_x: true,
        log_y: true,
        series: &series,
        highlight: None,
        direct_labels: true,
        floor: None,
    };
    write_chart(&chart, &out.join("bench"))
}

/// The line style of a broad phase: brute solid, grid dashed, sap dotted,
/// quadtree dash-dot (`exact`'s own cells solid).
fn broad_phase_line(name: &str) -> usize {
    match name {
        "grid" => 1,
        "sap" => 2,
        "quadtree" => 3,
        _ => 0,
    }
}

/// One series per row label (method, broad phase, threads): a colour per
/// method (as in every chart), a line style per broad phase, filled circles
/// on one thread and hollow triangles on several.
pub(crate) fn series_of(rows: &[Row]) -> Vec<Series> {
    let mut series: Vec<Series> = Vec::new();
    for r in rows {
        let name = label(r);
        let xy = (r.n as f64, r.ns_per_particle_step);
        match series.iter_mut().find(|s| s.name == name) {
            Some(s) => s.points.push(xy),
            None => series.push(Series {
                name,
                points: vec![xy],
                colour: Some(method_colour(r.method)),
                line: Some(broad_phase_line(&r.broad_phase)),
                marker: Some(if r.threads > 1 { 2 } else { 0 }),
                hollow: r.threads > 1,
                ..Default::default()
            }),
        }
    }
    for s in &mut series {
        s.points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    series
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_is_the_middle() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 2.0, 3.0]), 2.5);
        assert!(median(&mut []).is_nan());
    }

    #[test]
    fn the_speed_up_is_measured_against_a_one_thread_twin_and_shown() {
        let (one, two) = (pool(1).expect("a pool"), pool(2).expect("a pool"));
        let row = measure_against_one_thread(
            Method::Impulse,
            BroadPhaseKind::Grid,
            200,
            0.001,
            (&one, &two),
        );
        assert_eq!(row.threads, 2);
        let ratio = row.speed_up.expect("a speed-up");
        // 200 discs stay serial, so the ratio is near 1 but it is measured:
        // a wide bound, only a wrong computation (or none) falls outside.
        assert!(ratio > 0.2 && ratio < 5.0, "{row:?}");
        let serial = one.install(|| measure(Method::Impulse, BroadPhaseKind::Grid, 200, 0.001));
        let shown = table(&[serial, row], &[]);
        let line = shown
            .lines()
            .find(|l| l.contains("2 threads"))
            .expect("its line");
        assert!(line.contains(&format!("{ratio:.2} (serial)")), "{line}");
    }

    #[test]
    fn every_configuration_measures_a_positive_cost_and_the_gas_collides() {
        for (method, broad, threads) in configurations(2) {
            let row = pool(threads)
                .expect("a pool")
                .install(|| measure(method, broad, 200, 0.001));
            assert!(
                row.ns_per_particle_step > 0.0 && row.ns_per_particle_step.is_finite(),
                "{row:?}"
            );
            assert_eq!(row.threads, threads);
            assert!(!row.parallel, "200 discs stay serial: {row:?}");
            // A row's bytes are not checked here: the other tests of this
            // binary allocate and free alongside, on other threads, and the
            // counter is global. tests/memory.rs measures worlds in a binary
            // of their own.
        }
        // The binary counts allocations: a block far larger than anything
        // the other tests hold shows in the count.
        let before = live_bytes();
        let block = std::hint::black_box(vec![1u8; 64 << 20]);
        let grown = live_bytes().saturating_sub(before);
        drop(block);
        assert!(grown >= 32 << 20, "a 64 MiB block counted as {grown} bytes");
        let t = exact_throughput(300, 2_000);
        assert!(t.collisions_per_second > 0.0, "{t:?}");
        assert!(
            t.collisions >= 2_000,
            "runs until the collisions asked for: {t:?}"
        );
        assert!(
            t.energy_change < 1e-12,
            "exact keeps the gas's energy: {t:?}"
        );
    }
}
