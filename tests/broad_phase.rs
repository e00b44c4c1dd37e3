//! Every broad phase against brute force: same overlapping pairs, sorted, no
//! duplicates, on random and adversarial scenes, cold and warm-started; and a
//! world steps bit for bit the same whatever the broad phase.

use impulse::broad_phase::{BroadPhase, BroadPhaseKind, BruteForce, Pair};
use impulse::narrow_phase::contact_between;
use impulse::{Boundary, Color, DVec2, Particle, World};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// Counts this thread's allocations, to check that a warmed-up broad phase
/// allocates nothing.
struct CountingAllocator;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count_allocation() {
    let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
}

// SAFETY: every call is passed on unchanged to the system allocator.
unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count_allocation();
        // SAFETY: the caller's contract is the system allocator's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count_allocation();
        // SAFETY: as above.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: CountingAllocator = CountingAllocator;

/// The accelerated kinds (brute force is the reference).
const FAST: [BroadPhaseKind; 3] = [
    BroadPhaseKind::Grid,
    BroadPhaseKind::Sap,
    BroadPhaseKind::Quadtree,
];

fn disc(pos: DVec2, radius: f64) -> Particle {
    Particle::new(pos, DVec2::ZERO, 1.0, radius, Color::rgb(200, 200, 200))
}

/// The pairs among `pairs` whose discs really overlap.
fn overlapping(
    pairs: &[Pair],
    particles: &[Particle],
    boundary: Boundary,
    size: DVec2,
) -> Vec<Pair> {
    pairs
        .iter()
        .copied()
        .filter(|p| {
            let (a, b) = (&particles[p.i as usize], &particles[p.j as usize]);
            contact_between(a, b, boundary, size).is_some()
        })
        .collect()
}

/// Runs `phase` on the scene and holds it to brute force.
fn check(
    kind: BroadPhaseKind,
    phase: &mut dyn BroadPhase,
    particles: &[Particle],
    boundary: Boundary,
    size: DVec2,
) -> Result<(), TestCaseError> {
    let mut got = vec![Pair { i: 7, j: 3 }]; // stale content must be replaced
    phase.candidate_pairs(particles, boundary, size, &mut got);
    let n = particles.len() as u32;
    for w in got.windows(2) {
        prop_assert!(
            w[0] < w[1],
            "{kind}: {:?} then {:?}: not sorted or duplicated",
            w[0],
            w[1]
        );
    }
    for p in &got {
        prop_assert!(p.i < p.j && p.j < n, "{kind}: bad pair {p:?} for n = {n}");
    }
    let mut reference = Vec::new();
    BruteForce.candidate_pairs(particles, boundary, size, &mut reference);
    let (want, have) = (
        overlapping(&reference, particles, boundary, size),
        overlapping(&got, particles, boundary, size),
    );
    if want != have {
        let missing: Vec<_> = want
            .iter()
            .filter(|p| have.binary_search(p).is_err())
            .take(5)
            .collect();
        let extra: Vec<_> = have
            .iter()
            .filter(|p| want.binary_search(p).is_err())
            .take(5)
            .collect();
        return Err(TestCaseError::fail(format!(
            "{kind} {boundary:?}: {} overlaps, brute force {}; missing {missing:?}, extra {extra:?}",
            have.len(),
            want.len()
        )));
    }
    if boundary != Boundary::Periodic && kind != BroadPhaseKind::Grid {
        // Closed and open worlds use brute force's very test: same candidates
        // (except the grid, whose skin list adds near misses on purpose).
        // Both are sorted: binary search keeps big scenes quick.
        let missing: Vec<_> = reference
            .iter()
            .filter(|p| got.binary_search(p).is_err())
            .take(5)
            .collect();
        let extra: Vec<_> = got
            .iter()
            .filter(|p| reference.binary_search(p).is_err())
            .take(5)
            .collect();
        prop_assert!(
            missing.is_empty() && extra.is_empty(),
            "{kind} {boundary:?}: candidates differ from brute force: missing {missing:?}, extra {extra:?}"
        );
    }
    Ok(())
}

/// What a random scene is made of.
#[derive(Clone, Debug)]
struct Recipe {
    boundary: Boundary,
    size: DVec2,
    count: usize,
    radii: u8,
    snap: bool,
    coincident: bool,
    seed: u64,
}

fn recipes() -> impl Strategy<Value = Recipe> {
    (
        prop_oneof![
            Just(Boundary::Box),
            Just(Boundary::Open),
            Just(Boundary::Periodic)
        ],
        (1.0f64..40.0, 1.0f64..40.0),
        0usize..120,
        0u8..4,
        any::<bool>(),
        any::<bool>(),
        any::<u64>(),
    )
        .prop_map(
            |(boundary, (w, h), count, radii, snap, coincident, seed)| Recipe {
                boundary,
                size: DVec2::new(w, h),
                count,
                radii,
                snap,
                coincident,
                seed,
            },
        )
}

/// Equal radii, mixed radii, extreme radii (1e-3..10), or tiny discs with a
/// few huge ones; positions snapped to a lattice (discs exactly touching and
/// on cell borders), coincident discs, discs partly or far outside the box.
fn build(recipe: &Recipe) -> Vec<Particle> {
    let mut rng = ChaCha8Rng::seed_from_u64(recipe.seed);
    let size = recipe.size;
    let equal = rng.random_range(0.05..2.0);
    let radius = |rng: &mut ChaCha8Rng| -> f64 {
        match recipe.radii {
            0 => equal,
            1 => rng.random_range(0.1..1.0),
            2 => 10f64.powf(rng.random_range(-3.0..1.0)),
            _ if rng.random_bool(0.05) => rng.random_range(5.0..10.0),
            _ => rng.random_range(0.01..0.05),
        }
    };
    let lattice = [0.25, 0.5, 1.0, equal, 2.0 * equal][rng.random_range(0..5)];
    let mut particles: Vec<Particle> = Vec::with_capacity(recipe.count);
    for _ in 0..recipe.count {
        let r = radius(&mut rng);
        let mut pos = DVec2::new(rng.random_range(0.0..size.x), rng.random_range(0.0..size.y));
        match recipe.boundary {
            Boundary::Box if rng.random_bool(0.1) => {
                pos += DVec2::new(rng.random_range(-r..r), rng.random_range(-r..r));
            }
            Boundary::Open if rng.random_bool(0.05) => {
                pos = DVec2::new(rng.random_range(-1e6..1e6), rng.random_range(-1e6..1e6));
            }
            Boundary::Open => pos = pos * 2.0 - size * 0.5,
            Boundary::Periodic if rng.random_bool(0.1) => {
                pos += DVec2::new(rng.random_range(-2.0..2.0), rng.random_range(-2.0..2.0));
            }
            Boundary::Periodic if rng.random_bool(0.05) => {
                pos = DVec2::new(
                    [0.0, size.x][rng.random_range(0..2)],
                    [0.0, size.y][rng.random_range(0..2)],
                );
            }
            _ => {}
        }
        if recipe.snap {
            pos = (pos / lattice).round() * lattice;
        }
        if recipe.coincident && !particles.is_empty() && rng.random_bool(0.2) {
            pos = particles[rng.random_range(0..particles.len())].pos;
        }
        particles.push(disc(pos, r));
    }
    particles
}

/// Moves every disc a little, as a step would (wrapping when periodic).
fn jiggle(particles: &mut [Particle], boundary: Boundary, size: DVec2, rng: &mut ChaCha8Rng) {
    for p in particles.iter_mut() {
        let step = 0.02 * (0.1 + p.radius.min(1.0));
        p.pos += DVec2::new(rng.random_range(-step..step), rng.random_range(-step..step));
        if boundary == Boundary::Periodic {
            p.pos = p.pos.rem_euclid(size);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn every_broad_phase_finds_exactly_the_overlaps_brute_force_finds(recipe in recipes()) {
        let mut particles = build(&recipe);
        let (boundary, size) = (recipe.boundary, recipe.size);
        let mut phases: Vec<_> = FAST.iter().map(|k| (*k, k.build())).collect();
        let mut rng = ChaCha8Rng::seed_from_u64(recipe.seed ^ 0x5eed);
        // Cold, then warm-started on slightly moved discs, then after a disc
        // is removed and another added, then with the order shuffled.
        for round in 0..4 {
            match round {
                1 => jiggle(&mut particles, boundary, size, &mut rng),
                2 if !particles.is_empty() => {
                    let gone = rng.random_range(0..particles.len());
                    particles.remove(gone);
                    particles.push(disc(size * 0.5, 0.3));
                }
                3 => particles.shuffle(&mut rng),
                _ => {}
            }
            for (kind, phase) in phases.iter_mut() {
                check(*kind, phase.as_mut(), &particles, boundary, size)?;
            }
        }
    }
}

/// Scenes no broad phase may panic on, loop on, or get wrong.
#[test]
fn adversarial_scenes_match_brute_force() {
    let p = |x: f64, y: f64, r: f64| disc(DVec2::new(x, y), r);
    let box10 = DVec2::splat(10.0);
    let mut lattice = Vec::new();
    for k in 0..400 {
        // 20 × 20 discs exactly touching, on exact multiples of the diameter.
        lattice.push(p((k % 20) as f64, (k / 20) as f64, 0.5));
    }
    let mut tiny_and_huge: Vec<_> = (0..500)
        .map(|k| p((k % 25) as f64 * 0.4, (k / 25) as f64 * 0.4, 1e-4))
        .collect();
    tiny_and_huge.push(p(5.0, 5.0, 1e3));
    tiny_and_huge.push(p(2.0, 3.0, 1.0));
    let scenes: Vec<(&str, Vec<Particle>, DVec2)> = vec![
        ("empty", vec![], box10),
        ("one disc", vec![p(1.0, 1.0, 0.5)], box10),
        (
            "two coincident",
            vec![p(1.0, 1.0, 0.5), p(1.0, 1.0, 0.5)],
            box10,
        ),
        (
            "fifty coincident",
            (0..50).map(|_| p(3.0, 3.0, 0.2)).collect(),
            box10,
        ),
        ("touching lattice", lattice, DVec2::splat(20.0)),
        ("tiny among huge", tiny_and_huge, box10),
        (
            "far away",
            vec![
                p(1.0, 1.0, 0.5),
                p(1.5, 1.0, 0.5),
                p(1e6, -1e6, 0.5),
                p(1e6 + 0.5, -1e6, 0.5),
                p(-1e300, 1e300, 1.0),
                p(-1e300, 1e300, 1.0),
                p(f64::MAX, f64::MAX, 1.0),
            ],
            box10,
        ),
        (
            "a million metres out",
            vec![
                p(1e6 + 0.3, 2.0, 0.5),
                p(0.9, 2.0, 0.5),
                p(-1e6 + 9.8, 2.2, 0.5),
                p(5.0, 1e6 + 5.0, 0.5),
                p(5.0, 5.4, 0.5),
            ],
            box10,
        ),
        (
            "not finite",
            vec![
                p(f64::NAN, 1.0, 0.5),
                p(1.0, 1.0, 0.5),
                p(f64::INFINITY, 1.0, 0.5),
                p(1.2, 1.0, f64::NAN),
                p(1.1, 1.0, 0.5),
                p(f64::NEG_INFINITY, f64::NAN, 0.5),
            ],
            box10,
        ),
        (
            "odd radii",
            vec![
                p(1.0, 1.0, 0.0),
                p(1.0, 1.0, 0.0),
                p(1.0, 1.2, -0.1),
                p(1.0, 1.5, 0.5),
                p(4.0, 4.0, f64::INFINITY),
                p(6.0, 6.0, f64::NEG_INFINITY),
                p(9.0, 9.0, 0.3),
                p(9.0, 1.0, 1e-300),
            ],
            box10,
        ),
        (
            "radii 1e-4 to 1e3",
            (0..300)
                .map(|k| {
                    let r = 10f64.powf(-4.0 + 7.0 * (k as f64 / 299.0));
                    p((k * 37 % 100) as f64 * 0.1, (k * 53 % 100) as f64 * 0.1, r)
                })
                .collect(),
            box10,
        ),
    ];
    let sizes = [
        box10,
        DVec2::new(0.7, 10.0),
        DVec2::new(2.5, 2.5),
        DVec2::new(-10.0, 10.0),
        DVec2::new(0.0, 10.0),
        DVec2::new(f64::INFINITY, 10.0),
        DVec2::new(f64::NAN, 10.0),
    ];
    for (name, particles, size) in &scenes {
        for boundary in Boundary::ALL {
            let periodic_sizes: &[DVec2] = if boundary == Boundary::Periodic {
                &sizes
            } else {
                std::slice::from_ref(size)
            };
            for &size in periodic_sizes {
                if boundary == Boundary::Periodic
                    && particles.iter().any(|p| p.pos.abs().max_element() > 1e12)
                {
                    // Brute force's own minimum image is rounding noise there.
                    continue;
                }
                for kind in FAST {
                    let mut phase = kind.build();
                    for _ in 0..2 {
                        check(kind, phase.as_mut(), particles, boundary, size)
                            .unwrap_or_else(|e| panic!("{name}, size {size}: {e}"));
                    }
                }
            }
        }
    }
}

#[test]
fn a_warmed_up_broad_phase_allocates_nothing() {
    for boundary in Boundary::ALL {
        let recipe = Recipe {
            boundary,
            size: DVec2::new(60.0, 40.0),
            count: 2000,
            radii: 1,
            snap: false,
            coincident: false,
            seed: 3,
        };
        let mut rng = ChaCha8Rng::seed_from_u64(4);
        let mut scenes = vec![build(&recipe)];
        for _ in 0..4 {
            let mut next = scenes.last().unwrap().clone();
            jiggle(&mut next, boundary, recipe.size, &mut rng);
            scenes.push(next);
        }
        for kind in FAST {
            let mut phase = kind.build();
            let mut out = Vec::new();
            // The first round grows the buffers to what these scenes need.
            for particles in &scenes {
                phase.candidate_pairs(particles, boundary, recipe.size, &mut out);
            }
            let before = ALLOCATIONS.with(Cell::get);
            for particles in &scenes {
                phase.candidate_pairs(particles, boundary, recipe.size, &mut out);
            }
            let allocations = ALLOCATIONS.with(Cell::get) - before;
            assert_eq!(allocations, 0, "{kind} {boundary:?}: allocated when warm");
            assert!(!out.is_empty());
        }
    }
}

/// A 300-disc gas as a scene file would make it.
fn gas(boundary: &str, seed: u64, extra: &str) -> World {
    let text = format!(
        r#"
        [world]
        size = [24.0, 22.0]
        boundary = "{boundary}"
        [simulation]
        method = "impulse"
        substeps = 1
        {extra}
        [fill]
        count = 300
        seed = {seed}
        radius = [0.2, 0.5]
        speed = [0.5, 3.0]
        "#
    );
    let scene = impulse::Scene::parse(&text, "gas").expect("valid gas scene");
    scene.build("gas").expect("gas fits")
}

#[test]
fn a_world_steps_bit_for_bit_the_same_whatever_the_broad_phase() {
    let big_disc = r#"
        [[particles]]
        pos = [12.0, 11.0]
        vel = [0.3, 0.1]
        mass = 30.0
        radius = 3.0
    "#;
    for (boundary, extra) in [("periodic", ""), ("box", big_disc), ("open", "")] {
        let mut hashes = Vec::new();
        for kind in BroadPhaseKind::ALL {
            let mut world = gas(boundary, 11, extra);
            world.set_broad_phase(kind);
            for _ in 0..500 {
                world.step(1.0 / 240.0);
            }
            assert!(world.total_pair_collisions > 50, "{boundary}: a real gas");
            hashes.push((kind, world.state_hash(), world.total_pair_collisions));
        }
        let (_, first, collisions) = hashes[0];
        for &(kind, hash, c) in &hashes {
            assert_eq!(
                (hash, c),
                (first, collisions),
                "{boundary}: {kind} differs from brute force"
            );
        }
    }
}

#[test]
fn an_edit_between_steps_is_seen_by_the_kept_list() {
    // The grid keeps its pair list from step to step, and on one thread the
    // narrow phase checks as it goes that no disc has moved too far from
    // where the list was built, or changed size. A disc put elsewhere
    // between steps (a drag, an edit) or grown must meet the discs it now
    // touches in the very next step, exactly as brute force finds them.
    for edit in ["moved onto another", "grown", "nudged within the skin"] {
        let mut results = Vec::new();
        for kind in [BroadPhaseKind::Brute, BroadPhaseKind::Grid] {
            let mut world = gas("periodic", 5, "");
            world.set_broad_phase(kind);
            for _ in 0..20 {
                world.step(1.0 / 240.0);
            }
            let target = world.particles[1].pos;
            let p = &mut world.particles;
            match edit {
                "moved onto another" => p[0].pos = target + DVec2::new(0.05, 0.0),
                "grown" => p[2].radius *= 3.0,
                _ => p[3].pos += DVec2::new(1e-3, 0.0),
            }
            let stats = world.step(1.0 / 240.0);
            results.push((stats.contacts, world.state_hash()));
        }
        assert_eq!(
            results[0], results[1],
            "{edit}: the grid differs from brute force"
        );
        if edit == "moved onto another" {
            assert!(results[0].0 >= 1, "the disc put onto another touches it");
        }
    }
}

/// Release-mode cost of `World::step` per disc for each broad phase:
/// `cargo test --release --test broad_phase -- --ignored --nocapture`.
#[test]
#[ignore = "a measurement printed for a person (release, --nocapture), not a check"]
fn measure_step_cost() {
    let dt = 0.005; // speeds ~1 m/s: a disc moves 1 % of its radius per step
    println!("ns per particle-step of World::step (median of 5 batches)");
    println!("equal discs r = 0.5 at 30 % area fraction, periodic, dt = {dt} s");
    println!(
        "{:>8} {:>10} {:>10} {:>10} {:>10}",
        "n", "brute", "grid", "sap", "quadtree"
    );
    for n in [1_000usize, 10_000, 100_000] {
        // From the lattice start, let the gas mix (at ten times the step) so
        // that discs have neighbours as in a real gas.
        let mut gas = random_gas(n, 0.3, 1);
        gas.set_broad_phase(BroadPhaseKind::Grid);
        for _ in 0..100 {
            gas.step(10.0 * dt);
        }
        let mut row = format!("{n:>8}");
        for kind in BroadPhaseKind::ALL {
            if kind == BroadPhaseKind::Brute && n > 10_000 {
                row += &format!(" {:>10}", "-");
                continue;
            }
            let mut world = gas.clone();
            world.set_broad_phase(kind);
            let steps = (2_000_000 / n).clamp(2, 200);
            let steps = if kind == BroadPhaseKind::Brute {
                (steps / 20).max(2)
            } else {
                steps
            };
            for _ in 0..steps.min(20) {
                world.step(dt);
            }
            let mut runs: Vec<f64> = (0..5)
                .map(|_| {
                    let t = std::time::Instant::now();
                    for _ in 0..steps {
                        world.step(dt);
                    }
                    t.elapsed().as_nanos() as f64 / (steps * n) as f64
                })
                .collect();
            runs.sort_by(f64::total_cmp);
            row += &format!(" {:>10.1}", runs[2]);
        }
        println!("{row}");
    }
}

/// `n` discs of radius 0.5 at area fraction `phi` in a periodic square, on a
/// jittered lattice (no overlaps), in random index order, speeds ~1 m/s.
fn random_gas(n: usize, phi: f64, seed: u64) -> World {
    let r = 0.5;
    let side = (n as f64 * std::f64::consts::PI * r * r / phi).sqrt();
    let per_row = (n as f64).sqrt().ceil() as usize;
    let spacing = side / per_row as f64;
    let jitter = 0.5 * (spacing - 2.0 * r) * 0.99;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut particles: Vec<Particle> = (0..n)
        .map(|k| {
            let centre =
                DVec2::new((k % per_row) as f64 + 0.5, (k / per_row) as f64 + 0.5) * spacing;
            let pos = centre
                + DVec2::new(
                    rng.random_range(-jitter..=jitter),
                    rng.random_range(-jitter..=jitter),
                );
            let vel = DVec2::from_angle(rng.random_range(0.0..std::f64::consts::TAU))
                * rng.random_range(0.5..1.5);
            Particle::new(pos, vel, 1.0, r, Color::rgb(200, 200, 200))
        })
        .collect();
    particles.shuffle(&mut rng);
    let mut world = World::new(DVec2::splat(side));
    world.laws.boundary = Boundary::Periodic;
    world.particles = particles;
    world
}

/// Makes a broad phase, behind the trait as a world holds it.
type MakePhase = fn() -> Box<dyn BroadPhase + Send>;

/// The grid on rayon's pool gives exactly the pairs it gives serially, on
/// any number of threads: on scenes large enough for several chunks of
/// particles and bands of rows, with every boundary and radius mix, discs
/// far outside, coincident ones, and discs with a NaN or infinite centre
/// (which leave gaps in the gathered chunks).
#[test]
fn the_grid_in_parallel_finds_the_same_pairs_on_any_pool() {
    let pools: Vec<_> = [1, 2, 3]
        .map(|k| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(k)
                .build()
                .expect("a thread pool")
        })
        .into();
    let mut cases = 0;
    for boundary in Boundary::ALL {
        for radii in 0..4 {
            let recipe = Recipe {
                boundary,
                size: DVec2::new(300.0, 200.0),
                count: 3 * impulse::parallel::CHUNK + 100,
                radii,
                snap: radii == 1,
                coincident: radii == 0,
                seed: 11 + u64::from(radii),
            };
            let mut particles = build(&recipe);
            for k in [
                5,
                impulse::parallel::CHUNK + 3,
                2 * impulse::parallel::CHUNK,
            ] {
                particles[k].pos = DVec2::new(f64::NAN, 1.0);
                particles[k + 1].pos = DVec2::new(1.0, f64::INFINITY);
            }
            let kinds: [(&str, MakePhase); 2] = [
                ("grid", || Box::<impulse::broad_phase::Grid>::default()),
                ("skinned grid", || BroadPhaseKind::Grid.build()),
            ];
            for (name, make) in kinds {
                let mut serial = make();
                let mut want = Vec::new();
                serial.candidate_pairs(&particles, boundary, recipe.size, &mut want);
                assert!(!want.is_empty(), "{name} {boundary:?} radii {radii}");
                for pool in &pools {
                    let mut phase = make();
                    phase.set_parallel(true);
                    let mut got = Vec::new();
                    pool.install(|| {
                        phase.candidate_pairs(&particles, boundary, recipe.size, &mut got)
                    });
                    assert!(
                        got == want,
                        "{name} {boundary:?} radii {radii} on {} threads: {} pairs, serially {}",
                        pool.current_num_threads(),
                        got.len(),
                        want.len()
                    );
                    cases += 1;
                }
            }
        }
    }
    assert_eq!(cases, 3 * 4 * 2 * 3);
}
