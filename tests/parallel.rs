//! Results do not depend on the number of threads: a gas large enough that
//! `auto` runs the parallel path steps bit for bit the same on one thread
//! (serial), on one thread through the parallel code, and on two threads, for
//! every method that uses the grid, in a periodic box and in a closed one
//! under gravity (where `impulse` switches to resting contact).

use impulse::auto::PARALLEL_MIN_DISCS;
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::{Method, Setting};
use impulse::presets::Gas;
use impulse::resolution::{BANDED_MIN_CONTACTS, SPANS_MIN_CONTACTS};
use impulse::{Boundary, DVec2, World};

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
}

/// What a run ends with: the state's hash and the totals the walls and
/// collisions added up (sums over chunks, so they must match too).
#[derive(Debug, PartialEq)]
struct Outcome {
    hash: u64,
    collisions: u64,
    wall_hits: u64,
    wall_impulse: u64,
    parallel: bool,
}

/// Steps `world` on `threads` threads with the given `parallel` setting.
fn run(mut world: World, threads: usize, parallel: Setting<bool>, steps: usize) -> Outcome {
    world.parallel = parallel;
    pool(threads).install(|| {
        for _ in 0..steps {
            world.step(0.02);
        }
    });
    Outcome {
        hash: world.state_hash(),
        collisions: world.total_pair_collisions,
        wall_hits: world.total_wall_hits,
        wall_impulse: world.total_wall_impulse.to_bits(),
        parallel: world.plan().is_some_and(|p| p.parallel),
    }
}

/// A gas just above the parallel threshold, in 5 chunks of discs and about
/// ten bands of grid rows.
fn gas(method: Method, boundary: Boundary, gravity: bool) -> World {
    let mut world = Gas {
        count: 2 * PARALLEL_MIN_DISCS,
        boundary,
        seed: 5,
        ..Gas::default()
    }
    .build();
    world.method = Setting::Fixed(method);
    world.broad_phase = Setting::Fixed(BroadPhaseKind::Grid);
    world.substeps = Setting::Fixed(1);
    if gravity {
        world.laws.gravity = DVec2::new(0.0, -9.81);
        world.laws.restitution = 0.5;
    }
    world
}

/// A gas of `count` discs on the grid, filling `area_fraction` of its box
/// at `speed`, with restitution 0.9 (so contacts last a while).
fn bouncing_gas(
    method: Method,
    count: usize,
    (area_fraction, speed): (f64, f64),
    seed: u64,
) -> World {
    let mut world = Gas {
        count,
        area_fraction,
        speed,
        seed,
        ..Gas::default()
    }
    .build_fixed(method, BroadPhaseKind::Grid);
    world.laws.restitution = 0.9;
    world
}

#[test]
fn one_and_two_threads_step_bit_for_bit_alike_for_every_grid_method() {
    let cases = [
        (Method::Impulse, Boundary::Periodic, false),
        (Method::Seed, Boundary::Periodic, false),
        (Method::Verlet, Boundary::Periodic, false),
        (Method::Impulse, Boundary::Box, true), // resting contact
        (Method::Verlet, Boundary::Box, true),
    ];
    for (method, boundary, gravity) in cases {
        let world = gas(method, boundary, gravity);
        let start = world.state_hash();
        // 40 steps of 0.02 s: the fastest discs cross half a skin several
        // times, so the grid is rebuilt (in parallel) more than once.
        let steps = 40;
        let serial = run(world.clone(), 1, Setting::Auto, steps);
        let one = run(world.clone(), 1, Setting::Fixed(true), steps);
        let two = run(world.clone(), 2, Setting::Auto, steps);
        let case = format!("{method} {boundary:?} gravity {gravity}");
        assert!(!serial.parallel, "{case}: auto on one thread stays serial");
        assert!(
            one.parallel && two.parallel,
            "{case}: the parallel path ran"
        );
        assert_ne!(serial.hash, start, "{case}: the world moved");
        assert!(serial.collisions > 0, "{case}: discs collided");
        if boundary == Boundary::Box {
            assert!(serial.wall_hits > 0, "{case}: discs hit the walls");
        }
        assert_eq!(
            one,
            Outcome {
                parallel: true,
                ..serial
            },
            "{case}: parallel code on one thread"
        );
        assert_eq!(one, two, "{case}: one thread against two");
    }
}

/// The grid's rebuild cuts its work into one part per thread (runs of discs,
/// of bands of rows, ranges of first index): with 3 threads, and with 16,
/// more than the gas has chunks of discs or bands of rows (some parts
/// empty), it still steps bit for bit as serially.
#[test]
fn any_number_of_threads_steps_bit_for_bit_alike() {
    let world = gas(Method::Impulse, Boundary::Periodic, false);
    let serial = run(world.clone(), 1, Setting::Auto, 40);
    for threads in [3, 16] {
        let many = run(world.clone(), threads, Setting::Auto, 40);
        assert!(many.parallel, "{threads} threads: the parallel path ran");
        assert_eq!(
            many,
            Outcome {
                parallel: true,
                ..serial
            },
            "{threads} threads"
        );
    }
}

#[test]
fn auto_runs_small_scenes_on_one_thread_and_says_so() {
    let mut small = gas(Method::Impulse, Boundary::Periodic, false);
    small.particles.truncate(PARALLEL_MIN_DISCS / 2);
    let two = pool(2);
    let plan_on_two = |world: &World| {
        let world = world.clone();
        two.install(move || world.plan_for(0.01))
    };
    let plan = plan_on_two(&small);
    assert!(!plan.parallel);
    assert!(plan.reason.contains("1 thread"), "{}", plan.reason);
    small.particles = gas(Method::Impulse, Boundary::Periodic, false).particles;
    let plan = plan_on_two(&small);
    assert!(plan.parallel);
    assert!(plan.reason.contains("2 threads"), "{}", plan.reason);
    // Exact keeps its own calendar and never runs in parallel.
    small.method = Setting::Fixed(Method::Exact);
    assert!(!plan_on_two(&small).parallel);
}

/// Resolution goes by bands from `BANDED_MIN_CONTACTS` contacts on, side by
/// side when the step runs in parallel: a crowded, fast gas with that many
/// contacts per step still steps bit for bit alike on one and two threads,
/// and serially, and keeps its momentum.
#[test]
fn crowded_gas_resolved_by_bands_steps_alike_on_one_and_two_threads() {
    for method in [Method::Impulse, Method::Verlet, Method::Seed] {
        let world = bouncing_gas(method, 4 * PARALLEL_MIN_DISCS, (0.75, 40.0), 9);
        let mut probe = world.clone();
        let contacts: Vec<usize> = (0..4).map(|_| probe.step(0.02).contacts).collect();
        assert!(
            contacts[1..].iter().all(|&c| c >= BANDED_MIN_CONTACTS),
            "{method}: contacts per step {contacts:?}, too few to resolve by bands"
        );
        let before = world.metrics().momentum;
        let steps = 4;
        let serial = run(world.clone(), 1, Setting::Fixed(false), steps);
        let two = run(world.clone(), 2, Setting::Fixed(true), steps);
        assert_eq!(
            two,
            Outcome {
                parallel: true,
                ..serial
            },
            "{method}: serial against two threads"
        );
        if method == Method::Impulse {
            let mut moved = world;
            for _ in 0..steps {
                moved.step(0.02);
            }
            let after = moved.metrics().momentum;
            let scale: f64 = moved
                .particles
                .iter()
                .map(|p| p.mass * p.vel.length())
                .sum();
            assert!(
                (after - before).length() <= 1e-12 * scale,
                "{before} -> {after}"
            );
        }
    }
}

/// Fewer contacts than bands need, but enough to share: each thread
/// resolves the contacts among the discs it integrates, the rest after in
/// list order (`resolution::spans`). Bit for bit the serial result, and
/// most contacts were in fact resolved side by side.
#[test]
fn a_gas_resolved_by_spans_of_discs_steps_alike_on_one_and_two_threads() {
    for method in [Method::Impulse, Method::Verlet, Method::Seed] {
        let world = || bouncing_gas(method, 2 * PARALLEL_MIN_DISCS, (0.45, 3.0), 11);
        let (mut serial, mut two) = (world(), world());
        serial.parallel = Setting::Fixed(false);
        two.parallel = Setting::Fixed(true);
        let pool = pool(2);
        let mut shared = 0;
        for step in 0..6 {
            let alone = serial.step(0.02);
            let both = pool.install(|| two.step(0.02));
            let contacts = alone.contacts;
            // The gas starts with no overlap.
            assert!(
                step == 0 || (SPANS_MIN_CONTACTS..BANDED_MIN_CONTACTS).contains(&contacts),
                "{method}: {contacts} contacts in step {step}"
            );
            assert_eq!(alone.contacts_side_by_side, 0, "{method}: serial");
            shared += both.contacts_side_by_side;
            assert_eq!(
                serial.state_hash(),
                two.state_hash(),
                "{method}: step {step}, serial against two threads"
            );
        }
        assert!(shared > 0, "{method}: no contact was resolved side by side");
    }
}

/// The kept pair list on two threads: a disc put onto another between
/// steps (a drag), in the first thread's discs or the second's, fails the
/// list's check on that thread, which stops the other too; the list is
/// rebuilt and the step comes out as the serial one, bit for bit.
#[test]
fn an_edit_between_steps_is_seen_on_two_threads() {
    let world = || {
        let mut world = Gas {
            count: 2 * PARALLEL_MIN_DISCS,
            seed: 7,
            ..Gas::default()
        }
        .build_fixed(Method::Impulse, BroadPhaseKind::Grid);
        world.substeps = Setting::Fixed(1);
        world
    };
    let last = 2 * PARALLEL_MIN_DISCS - 1;
    for (moved, onto) in [(0, 1), (last, last - 1), (1, last)] {
        let (mut serial, mut two) = (world(), world());
        serial.parallel = Setting::Fixed(false);
        two.parallel = Setting::Fixed(true);
        let pool = pool(2);
        for _ in 0..5 {
            serial.step(0.02);
            pool.install(|| two.step(0.02));
        }
        for w in [&mut serial, &mut two] {
            let target = w.particles[onto].pos;
            w.particles[moved].pos = target + DVec2::new(0.05, 0.0);
        }
        let alone = serial.step(0.02);
        let both = pool.install(|| two.step(0.02));
        assert!(
            alone.contacts >= 1,
            "disc {moved} put onto {onto} touches it"
        );
        assert_eq!(alone.contacts, both.contacts, "disc {moved}: contacts");
        assert_eq!(
            serial.state_hash(),
            two.state_hash(),
            "disc {moved} put onto {onto}: serial against two threads"
        );
        assert!(two.plan().is_some_and(|p| p.parallel), "ran on two threads");
    }
}
