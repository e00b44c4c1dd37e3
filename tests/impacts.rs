//! Counters count impacts, not contacts: discs resting on each other or on
//! a wall are counted apart (see `impulse::impact`), for every method.

use impulse::impact::{threshold, RESTING_SPEED};
use impulse::method::{Method, Setting};
use impulse::{Color, DVec2, Particle, Scene, World};

const DT: f64 = impulse::scene::DEFAULT_DT;

fn preset(file: &str) -> World {
    let path = format!("{}/assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
    Scene::load(std::path::Path::new(&path))
        .and_then(|s| s.build(&path))
        .unwrap()
}

fn impacts(w: &World) -> u64 {
    w.total_pair_collisions + w.total_wall_hits
}

#[test]
fn the_pile_comes_to_rest_and_stops_counting() {
    let mut w = preset("preset-0-pile.toml");
    let steps = |s: f64| (s / DT).round() as usize;
    for _ in 0..steps(10.0) {
        w.step(DT);
    }
    let (at_10, energy_at_10) = (impacts(&w), w.total_energy());
    for _ in 0..steps(10.0) {
        w.step(DT);
    }
    let late = impacts(&w) - at_10;
    assert!(
        late < 50,
        "{late} impacts in the last 10 s of a resting pile"
    );
    // It rests on something, and says so.
    assert!(
        w.resting_contacts > w.particles.len() / 2,
        "{}",
        w.resting_contacts
    );
    // Its kinetic energy is down at the jitter floor: a resting disc gains
    // g·h towards its support each step and loses it at the contact, so
    // each carries about ½·m·(g·h)² (allow twice that).
    let v = w.laws.gravity.length() * DT;
    let floor: f64 = w.particles.iter().map(|p| 0.5 * p.mass * v * v).sum();
    let ke = w.metrics().kinetic_energy;
    assert!(
        ke < 2.0 * floor,
        "KE {ke} J above twice the floor {floor} J"
    );
    // And resting, it gains no energy: kinetic plus potential does not rise.
    let gained = w.total_energy() - energy_at_10;
    assert!(gained < floor, "the resting pile gained {gained} J");
}

/// A ball dropped from `height` onto the floor with restitution `e`: its
/// k-th bounce starts at eᵏ·√(2gH). Those faster than the impact speed
/// (`RESTING_SPEED`·g·dt) plus `margin` are impacts; it comes to rest
/// after them.
fn bounces_above(height: f64, e: f64, g: f64, margin: f64) -> u64 {
    let v0 = (2.0 * g * height).sqrt();
    let limit = RESTING_SPEED * g * DT + margin;
    (0..).take_while(|&k| v0 * e.powi(k) > limit).count() as u64
}

#[test]
fn a_dropped_ball_counts_its_bounces_and_then_rests() {
    let (g, e, height) = (9.81, 0.7, 2.0);
    let expected = bounces_above(height - 0.5, e, g, 0.0);
    // impulse meets the floor inside a step whose gravity kick g·dt it has
    // already taken in full (semi-implicit Euler): reflected at the touch,
    // its bounce leaves up to (1 + e)·g·dt slower than e times its arrival
    // (measured: about 1.2·g·dt). Over the bounces that loss adds up to
    // at most (1 + e)·g·dt·(1 + e + e² + …) = (1 + e)·g·dt/(1 − e), so every
    // bounce whose exact speed clears the impact speed by that much is
    // still an impact under impulse. exact has no such loss.
    let impulse_fewest = bounces_above(height - 0.5, e, g, (1.0 + e) * g * DT / (1.0 - e));
    for method in [Method::Exact, Method::Impulse] {
        let mut w = World::new(DVec2::new(4.0, 4.0));
        w.laws.gravity = DVec2::new(0.0, -g);
        w.laws.wall_restitution = e;
        w.laws.restitution = 0.5;
        w.method = Setting::Fixed(method);
        w.particles = vec![Particle::new(
            DVec2::new(2.0, height),
            DVec2::ZERO,
            1.0,
            0.5,
            Color::palette(0),
        )];
        for _ in 0..(20.0 / DT) as usize {
            w.step(DT);
        }
        let hits = w.total_wall_hits;
        // For exact, rounding of the event times can move the last impact
        // across the line by one.
        let fewest = if method == Method::Exact {
            expected - 1
        } else {
            impulse_fewest
        };
        assert!(
            (fewest..=expected + 1).contains(&hits),
            "{method:?}: {hits} wall impacts, expected {expected}"
        );
        // One disc rests on one floor: one resting contact, however many
        // events its rest takes.
        assert!(
            w.resting_contacts <= 1,
            "{method:?}: {}",
            w.resting_contacts
        );
        let p = &w.particles[0];
        assert!(
            // (impulse holds a resting disc within its slop of the floor)
            p.pos.y < 0.5 + 0.01 && p.vel.y.abs() <= threshold(w.laws.gravity, DT),
            "{method:?}: not at rest on the floor: {p:?}"
        );
    }
}

#[test]
fn without_gravity_every_collision_is_an_impact() {
    for method in Method::ALL {
        let mut w = preset("preset-1-head-on.toml");
        w.method = Setting::Fixed(method);
        for _ in 0..(6.0 / DT) as usize {
            w.step(DT);
        }
        // 2.4 s to meet, then the struck disc runs 6.4 m to the right wall
        // (5.6 s), and is on its way back at 6 s.
        assert_eq!(w.resting_contacts, 0, "{method:?}");
        if method == Method::Verlet {
            // verlet projects overlaps over more than one step and reads
            // velocities off positions: it may count one meeting twice (its
            // warning says its collisions are not to be trusted).
            assert!((1..=2).contains(&w.total_pair_collisions), "{method:?}");
            continue;
        }
        assert_eq!(w.total_pair_collisions, 1, "{method:?}");
        assert_eq!(w.total_wall_hits, 1, "{method:?}");
    }
}

#[test]
fn the_ledger_records_only_impacts() {
    let mut w = preset("preset-0-pile.toml");
    w.ledger.keep(1_000_000);
    for _ in 0..(20.0 / DT) as usize {
        w.step(DT);
    }
    assert_eq!(w.ledger.recorded, w.total_pair_collisions);
    assert!(w.ledger.recorded > 100, "the pile's fall has impacts");
    for c in w.ledger.entries() {
        let closing = (c.before[0] - c.before[1]).dot(c.normal);
        assert!(closing > 0.0, "recorded without approaching: {closing} m/s");
    }
}
