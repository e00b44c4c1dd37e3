//! The measurements behind `auto`'s rules, printed after `impulse bench`'s
//! main table: brute force against the grid at small n, the quadtree against
//! the grid as radii spread, serial against parallel steps as n grows, and
//! resolution on one thread against several in a crowded gas.

use super::{measure, time_world};
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::{Method, Setting};
use impulse::presets::Gas;
use std::fmt::Write as _;

/// The measurements behind `auto`'s thresholds: brute force against the
/// grid at small n, and the quadtree against the grid as radii spread.
pub(super) fn crossovers(batch_seconds: f64) -> String {
    let mut out = String::from(
        "\n| crossover: brute vs grid (impulse) | n | brute ns | grid ns |\n|---|---:|---:|---:|\n",
    );
    for n in [8, 16, 32, 64, 128, 256] {
        let brute = measure(Method::Impulse, BroadPhaseKind::Brute, n, batch_seconds);
        let grid = measure(Method::Impulse, BroadPhaseKind::Grid, n, batch_seconds);
        let _ = writeln!(
            out,
            "| | {n} | {:.1} | {:.1} |",
            brute.ns_per_particle_step, grid.ns_per_particle_step
        );
    }
    out.push_str(
        "\n| crossover: grid vs quadtree (impulse, 10,000 discs) | radii | grid ns | quadtree ns |\n|---|---|---:|---:|\n",
    );
    let spread = |ratio: f64| {
        Gas {
            count: 10_000,
            radius_ratio: ratio,
            ..Gas::default()
        }
        .build()
    };
    let giant = |ratio: f64| {
        let mut world = Gas {
            count: 10_000,
            radius: 0.5 / ratio,
            area_fraction: 0.3 / (ratio * ratio),
            ..Gas::default()
        }
        .build();
        world.particles[0].radius = 0.5;
        world
    };
    // A dense gas of small discs with 1 % large ones (the small ones they
    // would overlap removed): the grid's cells grow to the large diameter.
    let bimodal = |ratio: f64, area_fraction: f64| {
        let mut world = Gas {
            count: 10_000,
            radius: 0.5 / ratio,
            area_fraction,
            ..Gas::default()
        }
        .build();
        let big: Vec<glam::DVec2> = world.particles.iter().step_by(100).map(|p| p.pos).collect();
        world.particles.retain(|p| {
            big.iter().all(|b| b.distance(p.pos) >= 0.5 + p.radius) || big.contains(&p.pos)
        });
        for p in world.particles.iter_mut().filter(|p| big.contains(&p.pos)) {
            p.radius = 0.5;
        }
        world
    };
    let cases: [(String, impulse::World); 8] = [
        ("log-uniform, max/min 4".into(), spread(4.0)),
        ("log-uniform, max/min 16".into(), spread(16.0)),
        ("log-uniform, max/min 64".into(), spread(64.0)),
        ("one disc 4x the rest".into(), giant(4.0)),
        ("one disc 16x the rest".into(), giant(16.0)),
        ("one disc 64x the rest".into(), giant(64.0)),
        (
            "1 % of discs 8x the rest, sparse".into(),
            bimodal(8.0, 0.3 / 64.0),
        ),
        ("1 % of discs 8x the rest, dense".into(), bimodal(8.0, 0.3)),
    ];
    for (name, world) in cases {
        let time = |broad| {
            let mut w = world.clone();
            w.method = Setting::Fixed(Method::Impulse);
            w.broad_phase = Setting::Fixed(broad);
            time_world(&mut w, batch_seconds)
        };
        let (g, q) = (time(BroadPhaseKind::Grid), time(BroadPhaseKind::Quadtree));
        let _ = writeln!(out, "| | {name} | {g:.1} | {q:.1} |");
    }
    out
}

/// The measurement behind `auto`'s thread rule: impulse / grid on the
/// current pool, serial against parallel, as n grows.
pub(super) fn thread_crossover(sizes: &[usize], batch_seconds: f64) -> String {
    let threads = rayon::current_num_threads();
    let mut out = format!(
        "\n| crossover: serial vs parallel (impulse / grid, {threads} threads) | n | serial ns | parallel ns | speed-up |\n|---|---:|---:|---:|---:|\n"
    );
    for &n in sizes {
        let time = |parallel| {
            let mut world = Gas {
                count: n,
                ..Gas::default()
            }
            .build_fixed(Method::Impulse, BroadPhaseKind::Grid);
            world.parallel = Setting::Fixed(parallel);
            time_world(&mut world, batch_seconds)
        };
        let (serial, parallel) = (time(false), time(true));
        let _ = writeln!(
            out,
            "| | {n} | {serial:.1} | {parallel:.1} | {:.2} |",
            serial / parallel
        );
    }
    out
}

/// Resolution on one thread against `many`'s threads in a crowded gas (70 %
/// area), where contacts are many: ns per disc-step of the resolution stage
/// and of the whole step (medians over steps), and whether the contact lists
/// were large enough to be resolved by bands
/// ([`impulse::resolution::BANDED_MIN_CONTACTS`]).
pub(super) fn crowded_resolution(
    sizes: &[usize],
    one: &rayon::ThreadPool,
    many: &rayon::ThreadPool,
) -> String {
    const STEPS: usize = 10;
    let threads = many.current_num_threads();
    let mut out = format!(
        "\n| resolution in a crowded gas (70 % area, impulse / grid), 1 vs {threads} threads | n | contacts per step | by bands | resolution ns, 1 thread | {threads} threads | speed-up | step ns, 1 thread | {threads} threads |\n|---|---:|---:|---|---:|---:|---:|---:|---:|\n"
    );
    for &n in sizes {
        let world = Gas {
            count: n,
            area_fraction: 0.7,
            ..Gas::default()
        }
        .build_fixed(Method::Impulse, BroadPhaseKind::Grid);
        // (resolution, step) ns per disc-step, and contacts per step.
        let time = |pool: &rayon::ThreadPool| {
            let mut world = world.clone();
            pool.install(|| {
                for _ in 0..3 {
                    world.step(super::DT);
                }
                let (mut resolution, mut step, mut contacts) = (Vec::new(), Vec::new(), 0);
                for _ in 0..STEPS {
                    let t = std::time::Instant::now();
                    let stats = world.step(super::DT);
                    step.push(t.elapsed().as_secs_f64() * 1e9 / n as f64);
                    resolution.push(stats.timings.resolution.as_secs_f64() * 1e9 / n as f64);
                    contacts += stats.contacts;
                }
                let median = super::median;
                (median(&mut resolution), median(&mut step), contacts / STEPS)
            })
        };
        let (r1, s1, contacts) = time(one);
        let (rn, sn, _) = time(many);
        let banded = if contacts >= impulse::resolution::BANDED_MIN_CONTACTS {
            "yes"
        } else {
            "no"
        };
        let _ = writeln!(
            out,
            "| | {n} | {contacts} | {banded} | {r1:.2} | {rn:.2} | {:.2} | {s1:.1} | {sn:.1} |",
            r1 / rn
        );
    }
    out
}

/// Resting piles, `exact` (held discs, then sleeping ones) against `impulse`:
/// wall-clock seconds for the whole run, medians of 3, and the deepest
/// overlap either left. The measurement behind `auto`'s choice for scenes
/// where discs come to rest, and the target (`exact` within 3× of
/// `impulse` on the 10⁴-disc pile).
pub(super) fn resting_piles(quick: bool) -> String {
    use impulse::catalogue::{PRESET_0_PILE, STRESS_PILE, STRESS_PILE_LARGE, STRESS_PILE_TALL};
    let mut runs = vec![
        (PRESET_0_PILE, 15.0),
        (STRESS_PILE, 15.0),
        (STRESS_PILE, 60.0),
    ];
    if !quick {
        runs.extend([(STRESS_PILE_TALL, 15.0), (STRESS_PILE_LARGE, 10.0)]);
    }
    let mut out = String::from(
        "\n| resting pile | n | simulated | exact s (median of 3) | impulse s | exact ÷ impulse | deepest overlap met, exact (r) | impulse (r) |\n|---|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for (file, seconds) in runs {
        let Ok(scene) = impulse::Scene::parse(file.text, file.path) else {
            continue;
        };
        let time = |method: Method| -> Option<(f64, f64, usize)> {
            let mut walls = Vec::new();
            let mut overlap = 0.0f64;
            let mut n = 0;
            for _ in 0..3 {
                let mut world = scene.build(file.path).ok()?;
                world.method = Setting::Fixed(method);
                n = world.particles.len();
                let min_r = world
                    .particles
                    .iter()
                    .map(|p| p.radius)
                    .fold(f64::INFINITY, f64::min);
                let dt = impulse::scene::DEFAULT_DT;
                let start = std::time::Instant::now();
                for _ in 0..(seconds / dt).round() as usize {
                    let stats = world.step(dt);
                    overlap = overlap.max(stats.max_overlap / min_r);
                }
                walls.push(start.elapsed().as_secs_f64());
            }
            Some((super::median(&mut walls), overlap, n))
        };
        let (Some(exact), Some(impulse)) = (time(Method::Exact), time(Method::Impulse)) else {
            continue;
        };
        let name = file.path.trim_start_matches("assets/scenes/");
        let _ = writeln!(
            out,
            "| {name} | {} | {seconds} s | {:.3} | {:.3} | {:.2} | {:.0e} | {:.0e} |",
            exact.2,
            exact.0,
            impulse.0,
            exact.0 / impulse.0,
            exact.1,
            impulse.1
        );
    }
    out
}
