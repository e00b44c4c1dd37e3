//! The ledger records wall hits beside pair collisions, in every method,
//! as many as the counters count; `run_to_next_impact` stops at either.
//! Every expected number comes from a formula written out here.

use impulse_core::catalogue::{self, SceneFile};
use impulse_core::ledger::{Impact, Wall};
use impulse_core::method::{Method, Setting};
use impulse_core::{Color, DVec2, Particle, Scene, World};

const DT: f64 = 1.0 / 60.0;

/// The fixed-step methods and `exact`.
const METHODS: [Method; 4] = [Method::Seed, Method::Impulse, Method::Verlet, Method::Exact];

fn disc(pos: [f64; 2], vel: [f64; 2], mass: f64, radius: f64) -> Particle {
    Particle::new(
        pos.into(),
        vel.into(),
        mass,
        radius,
        Color::rgb(200, 200, 200),
    )
}

/// A closed 10 m × 10 m box without gravity, elastic between discs.
fn closed_box(method: Method, particles: Vec<Particle>) -> World {
    let mut w = World::new(DVec2::new(10.0, 10.0));
    w.method = Setting::Fixed(method);
    w.particles = particles;
    w
}

fn shipped(file: SceneFile, method: Method) -> World {
    let mut w = Scene::parse(file.text, file.path)
        .and_then(|s| s.build(file.path))
        .expect("a shipped scene builds");
    w.method = Setting::Fixed(method);
    w
}

/// How closely a method's impact time can match the formula: to round-off
/// for `exact`, within the step that caught it for the others.
fn on_time(method: Method, time: f64, formula: f64) -> bool {
    if method == Method::Exact {
        (time - formula).abs() < 1e-9
    } else {
        time >= formula - 1e-9 && time <= formula + DT + 1e-9
    }
}

#[test]
fn run_to_next_impact_stops_at_a_wall_hit_in_every_method() {
    // 2 kg, r = 0.5, at x = 3.1 moving at (−2.3, 0.4) towards the left
    // wall, which it touches when x = r: after (3.1 − 0.5)/2.3 s. Wall
    // restitution 0.8: the wall's impulse is −(1 + e)·m·vₙ along its
    // normal (+x), here +(1.8·2·2.3, 0), and the tangent is kept.
    let (m, r, e) = (2.0, 0.5, 0.8);
    let v = DVec2::new(-2.3, 0.4);
    let touch = (3.1 - r) / 2.3;
    for method in METHODS {
        let mut w = closed_box(method, vec![disc([3.1, 4.0], v.into(), m, r)]);
        w.laws.wall_restitution = e;
        let found = w.run_to_next_impact(DT, 60.0);
        let Some(Impact::Wall(hit)) = found else {
            panic!("{method:?}: no wall hit but {found:?}");
        };
        assert_eq!((hit.disc, hit.wall), (0, Wall::Left), "{method:?}");
        assert!(
            on_time(method, hit.time, touch),
            "{method:?}: hit at {} s, touching at {touch} s",
            hit.time
        );
        assert!(
            (w.time - hit.time).abs() < 1e-9 || method != Method::Exact,
            "{method:?}: exact stops at the instant of impact, not {}",
            w.time
        );
        if method == Method::Exact {
            let gap = w.particles[0].pos.x - r;
            assert!(gap.abs() < 1e-9, "touching the wall: gap {gap:e}");
        }
        assert!(w.time <= hit.time + DT, "{method:?}: left after the hit");
        // verlet reads velocities off positions: round-off, no more.
        let tol = 1e-9;
        assert!((hit.before - v).length() < tol, "{method:?}: {hit:?}");
        let expected = DVec2::new((1.0 + e) * m * 2.3, 0.0);
        assert!(
            (hit.wall_impulse() - expected).length() < tol,
            "{method:?}: impulse {} vs {expected}",
            hit.wall_impulse()
        );
        let (p0, p1) = hit.momentum();
        assert!((p0 - m * v).length() < tol, "{method:?}");
        assert!((p1 - p0 - hit.wall_impulse()).length() < 1e-12);
        assert!((p1 - m * w.particles[0].vel).length() < tol, "{method:?}");
        let ((n0, t0), (n1, t1)) = hit.components();
        assert!((n1 + e * n0).abs() < tol && (t1 - t0).abs() < tol);
        let (dp, dke) = found.unwrap().total_change();
        assert_eq!(dp, hit.wall_impulse());
        let loss = 0.5 * m * (1.0 - e * e) * 2.3 * 2.3;
        assert!((dke + loss).abs() < 1e-9, "{method:?}: ΔKE {dke}");
        assert_eq!(w.ledger.recorded_walls, 1, "{method:?}");
        assert_eq!(w.ledger.recorded, 0, "{method:?}");
        assert_eq!(w.total_wall_hits, 1, "{method:?}");
    }
}

#[test]
fn run_to_next_collision_runs_past_walls_and_run_to_next_impact_does_not() {
    // Disc A at x = 2.05 moving left at 2 m/s touches the left wall after
    // (2.05 − 0.5)/2 = 0.775 s, comes back at 2 m/s and touches the resting
    // disc B (x = 6) when x = 5: 4.5/2 = 2.25 s later, at 3.025 s. The
    // discrete methods put A back on the wall (up to a step behind) and
    // see the pair's overlap at the start of the next step: up to two
    // steps late.
    for method in [Method::Seed, Method::Impulse, Method::Exact] {
        let discs = || {
            vec![
                disc([2.05, 5.0], [-2.0, 0.0], 1.0, 0.5),
                disc([6.0, 5.0], [0.0, 0.0], 1.0, 0.5),
            ]
        };
        let mut w = closed_box(method, discs());
        let hit = w.run_to_next_impact(DT, 60.0).expect("the wall");
        assert!(hit.wall().is_some(), "{method:?}: {hit:?}");
        assert!(on_time(method, hit.time(), 0.775), "{method:?}: {hit:?}");

        let mut w = closed_box(method, discs());
        let c = w.run_to_next_collision(DT, 60.0).expect("the pair");
        assert_eq!(c.discs, [0, 1], "{method:?}");
        if method == Method::Exact {
            assert!((c.time - 3.025).abs() < 1e-9, "{}", c.time);
            assert!((w.time - 3.025).abs() < 1e-9, "stopped at {}", w.time);
        } else {
            let late = c.time - 3.025;
            assert!((0.0..=2.0 * DT).contains(&late), "{method:?}: {}", c.time);
        }
        assert_eq!(
            w.ledger.recorded_walls, 1,
            "{method:?}: the wall on the way"
        );
        // B leaves at 2 m/s, A stays (equal masses, e = 1): B's hit on the
        // right wall is next.
        let next = w
            .run_to_next_impact(DT, 60.0)
            .expect("B reaches the right wall");
        let wall = next.wall().expect("a wall hit");
        assert_eq!((wall.disc, wall.wall), (1, Wall::Right), "{method:?}");
    }
}

#[test]
fn the_ledger_counts_what_the_counters_count() {
    // Two discs crossing a closed box many times (pairs and walls), and a
    // pile falling under gravity (impacts at first, then resting contacts,
    // which are neither counted nor recorded).
    for method in METHODS {
        let two = closed_box(
            method,
            vec![
                disc([3.0, 5.0], [2.0, 0.7], 1.0, 0.5),
                disc([7.0, 5.2], [-2.0, -0.3], 3.0, 0.8),
            ],
        );
        let pile = shipped(catalogue::PRESET_0_PILE, method);
        for (name, mut w, seconds) in [("two discs", two, 30.0), ("pile", pile, 6.0)] {
            w.ledger.keep(usize::MAX);
            for _ in 0..(seconds / DT) as usize {
                w.step(DT);
            }
            let what = format!("{method:?}, {name}");
            assert!(w.total_wall_hits > 0, "{what}: no wall hit to check");
            assert_eq!(w.ledger.recorded_walls, w.total_wall_hits, "{what}");
            assert_eq!(w.ledger.wall_hits().count() as u64, w.total_wall_hits);
            if method == Method::Verlet {
                // Projection: no before and after of a pair to record.
                assert_eq!(w.ledger.recorded, 0, "{what}");
            } else {
                assert!(w.total_pair_collisions > 0, "{what}: no pair to check");
                assert_eq!(w.ledger.recorded, w.total_pair_collisions, "{what}");
            }
            assert_eq!(
                w.ledger.recorded_impacts(),
                w.ledger.recorded + w.ledger.recorded_walls
            );
            let mut last = f64::NEG_INFINITY;
            for impact in w.ledger.impacts() {
                assert!(impact.closing_speed() > 0.0, "{what}: {impact:?}");
                assert!(impact.time() >= last - 1e-9, "{what}: out of order");
                last = impact.time();
                if let Impact::Wall(hit) = impact {
                    let along_normal = hit.wall_impulse().dot(hit.normal());
                    assert!(along_normal > 0.0, "{what}: the wall pushes: {hit:?}");
                }
            }
        }
    }
}

#[test]
fn the_spin_off_a_wall_preset_finds_its_bounce() {
    // From the scene file: 1 kg, r = 1 m, in at (2, −2) m/s with
    // ω = 2.5 rad/s onto a perfectly rough floor (β = 1, e = 1), touching
    // it after (6 − 1)/2 = 2.5 s. At a still wall the velocity along it
    // becomes v_t − (1 + β)/3·(v_t + ω·r) and the rim's slip reverses.
    let (vt, w0, r, beta) = (2.0, 2.5, 1.0, 1.0);
    let slip = vt + w0 * r;
    let vt_after = vt - (1.0 + beta) / 3.0 * slip;
    let w_after = (-beta * slip - vt_after) / r;
    for method in METHODS {
        let mut w = shipped(catalogue::PRESET_SPIN_OFF_A_WALL, method);
        assert!(
            w.run_to_next_collision(DT, 3.0).is_none(),
            "{method:?}: one disc, no pair"
        );
        let mut w = shipped(catalogue::PRESET_SPIN_OFF_A_WALL, method);
        let found = w.run_to_next_impact(DT, 60.0);
        let Some(Impact::Wall(hit)) = found else {
            panic!("{method:?}: the bounce, not {found:?}");
        };
        assert!(hit.time < 60.0);
        assert_eq!(hit.wall, Wall::Bottom, "{method:?}");
        assert!(on_time(method, hit.time, 2.5), "{method:?}: {}", hit.time);
        let tol = 1e-9;
        assert!(
            (hit.before - DVec2::new(vt, -2.0)).length() < tol,
            "{hit:?}"
        );
        assert!(
            (hit.after - DVec2::new(vt_after, 2.0)).length() < tol,
            "{method:?}: out at {}, not ({vt_after}, 2)",
            hit.after
        );
        assert!((hit.spin_before - w0).abs() < tol);
        assert!(
            (hit.spin_after - w_after).abs() < tol,
            "{method:?}: {hit:?}"
        );
        // β = 1, e = 1: what translation loses, rotation gains.
        let (_, dke) = hit.total_change();
        let drot = found.unwrap().rotational_change();
        assert!(dke < 0.0 && (dke + drot).abs() < tol, "{dke} + {drot}");
        if method == Method::Exact {
            assert!((w.time - 2.5).abs() < 1e-9, "stopped at {}", w.time);
            // The top wall next: the centre rises from y = 1 m to
            // 10 − 1 = 9 m at 2 m/s, 4 s later.
            let next = w.run_to_next_impact(DT, 60.0).expect("the top wall");
            let top = next.wall().expect("a wall hit");
            assert_eq!(top.wall, Wall::Top);
            assert!((top.time - (2.5 + 8.0 / 2.0)).abs() < 1e-9, "{}", top.time);
            assert!((w.time - top.time).abs() < 1e-9);
        }
    }
}

#[test]
fn a_full_ledger_still_returns_the_collision_of_the_step() {
    // Off, `run_to_next_collision` turns the ledger on with room for one.
    // Here the first step resolves a pair (approaching and overlapping at
    // the start) and then a third disc crosses the right wall: the pair
    // must still be found, though the wall hit came after it.
    for method in [Method::Seed, Method::Impulse] {
        let mut w = closed_box(
            method,
            vec![
                disc([4.0, 5.0], [1.0, 0.0], 1.0, 0.5),
                disc([4.9, 5.0], [-1.0, 0.0], 1.0, 0.5),
                disc([9.45, 2.0], [6.0, 0.0], 1.0, 0.5),
            ],
        );
        let c = w.run_to_next_collision(DT, 1.0).expect("the pair");
        assert_eq!(c.discs, [0, 1], "{method:?}");
        assert_eq!(w.steps, 1);
        assert_eq!(w.total_wall_hits, 1, "{method:?}: the third disc's hit");
        assert_eq!(w.ledger.capacity(), 1);
        let newest = w.ledger.last_impact().expect("kept");
        assert_eq!(newest.wall().map(|h| h.disc), Some(2), "{method:?}");
    }
}

#[test]
fn wall_hits_of_large_scenes_name_the_right_disc_on_any_thread_count() {
    // More discs than one chunk of the wall stage (4,096): the hits of the
    // later chunks must carry their own index. After a one-substep step the
    // wall stage is the last to move a disc, and `impulse` places a disc
    // that hit a wall as from the touch, within the step: each disc hit in
    // the last step is off its wall by at most its speed away times DT.
    let text = r#"
        [world]
        size = [120.0, 120.0]
        [simulation]
        method = "impulse"
        substeps = 1
        [fill]
        count = 9000
        seed = 3
        radius = [0.2, 0.3]
        speed = [2.0, 6.0]
    "#;
    let scene = Scene::parse(text, "big").unwrap();
    let mut ledgers = Vec::new();
    for parallel in [false, true] {
        let mut w = scene.build("big").unwrap();
        w.parallel = Setting::Fixed(parallel);
        w.ledger.keep(usize::MAX);
        for _ in 0..30 {
            let before = w.ledger.recorded_walls;
            w.step(DT);
            let new = (w.ledger.recorded_walls - before) as usize;
            let size = w.laws.size;
            for hit in w.ledger.wall_hits().rev().take(new) {
                let p = &w.particles[hit.disc];
                let (axis, at) = (hit.wall.axis(), p.pos[hit.wall.axis()]);
                let off_wall = if hit.wall.is_upper() {
                    size[axis] - p.radius - at
                } else {
                    at - p.radius
                };
                let reach = hit.after[axis].abs() * DT;
                assert!((0.0..=reach * (1.0 + 1e-12)).contains(&off_wall), "{hit:?}");
                assert_eq!((hit.mass, hit.radius), (p.mass, p.radius));
            }
        }
        assert!(w.total_wall_hits > 100, "{}", w.total_wall_hits);
        assert!(
            w.ledger.wall_hits().any(|h| h.disc >= 4096),
            "a later chunk"
        );
        assert_eq!(w.ledger.recorded_walls, w.total_wall_hits);
        ledgers.push(w.ledger);
    }
    assert_eq!(
        ledgers[0], ledgers[1],
        "the same ledger on any thread count"
    );
}

#[test]
fn verlet_stops_at_a_pair_collision_it_cannot_record() {
    // Head-on, 1 m/s each, centres 3 m apart, radii 0.5: contact after 1 s.
    let mut w = closed_box(
        Method::Verlet,
        vec![
            disc([3.5, 5.0], [1.0, 0.0], 1.0, 0.5),
            disc([6.5, 5.0], [-1.0, 0.0], 1.0, 0.5),
        ],
    );
    let found = w.run_to_next_impact(DT, 60.0);
    assert_eq!(found, None, "nothing recorded");
    assert_eq!((w.total_pair_collisions, w.total_wall_hits), (1, 0));
    assert!(
        (w.time - 1.0).abs() <= 2.0 * DT,
        "stopped at the collision: {}",
        w.time
    );
}

#[test]
fn impacts_at_the_same_instant_are_one_stop_and_a_moment_apart_are_two() {
    // Two equal discs (r = 0.5, 10 m box) at y = 3.5 and 6.5, moving apart
    // at 2 m/s: each touches its wall (y = 0.5 and 9.5 for the centre)
    // after 3/2 = 1.5 s. Mirror images: the same instant, so the
    // total momentum goes from 0 to 0 in one stop, never through half of
    // it. Then the upper disc 1 µm nearer its wall: two stops, 0.5 µs apart.
    for method in METHODS {
        let mut w = closed_box(
            method,
            vec![
                disc([3.0, 3.5], [0.0, -2.0], 1.0, 0.5),
                disc([7.0, 6.5], [0.0, 2.0], 1.0, 0.5),
            ],
        );
        let hit = w.run_to_next_impact(DT, 60.0).expect("the walls");
        assert!(on_time(method, hit.time(), 1.5), "{method:?}: {hit:?}");
        assert_eq!(w.ledger.recorded_walls, 2, "{method:?}: both walls");
        let p: DVec2 = w.particles.iter().map(|d| d.mass * d.vel).sum();
        assert!(p.length() < 1e-9, "{method:?}: momentum {p} after the stop");
        // Each came back off its wall: the upper one moves down.
        for d in &w.particles {
            let back = if d.pos.y > 5.0 { -2.0 } else { 2.0 };
            assert!((d.vel.y - back).abs() < 1e-9, "{method:?}: {d:?}");
        }
    }
    let mut w = closed_box(
        Method::Exact,
        vec![
            disc([3.0, 3.5], [0.0, -2.0], 1.0, 0.5),
            disc([7.0, 6.5 + 1e-6], [0.0, 2.0], 1.0, 0.5),
        ],
    );
    let first = w.run_to_next_impact(DT, 60.0).expect("the ceiling");
    assert_eq!(first.wall().map(|h| h.wall), Some(Wall::Top));
    assert_eq!(w.ledger.recorded_walls, 1, "the floor is 0.5 µs later");
    let second = w.run_to_next_impact(DT, 60.0).expect("the floor");
    assert_eq!(second.wall().map(|h| h.wall), Some(Wall::Bottom));
    let apart = second.time() - first.time();
    assert!((apart - 0.5e-6).abs() < 1e-9, "{apart:e} s apart");
}
