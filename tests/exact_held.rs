//! `exact` through inelastic collapse: discs in lasting contact are *held*
//! (`impulse::method::exact`, `held/`), carried by a contact solve once a
//! step instead of by events. Checked against what the scheme promises: no
//! overlap at any step, no step that gains energy, a stack at rest where
//! statics puts it, and `auto` taking `exact` for a settling pile.

use impulse::method::exact::holds_discs;
use impulse::method::exact::sleep::SUPPORT_GAP;
use impulse::method::{Method, Setting};
use impulse::{Color, DVec2, Particle, World};

mod common;

const DT: f64 = impulse::scene::DEFAULT_DT;

fn scene(file: &str) -> World {
    common::scene_with(file, Method::Exact)
}

/// Steps `w` for `seconds`, checking at every step that none was cut
/// short, that no two discs overlap by 1e-9 of a radius, and that the
/// total energy never rises by more than 1e-12 of itself.
fn run_checked(w: &mut World, seconds: f64) {
    let mut energy = w.total_energy();
    for step in 0..(seconds / DT).round() as usize {
        let stats = w.step(DT);
        assert!(!stats.truncated, "step {step} cut short");
        let now = w.total_energy();
        assert!(
            now - energy <= 1e-12 * energy.abs(),
            "step {step}: energy rose by {:e} of itself",
            (now - energy) / energy.abs()
        );
        energy = now;
        let overlap = common::deepest_pair_overlap(w).max(common::deepest_wall_overlap(w));
        assert!(
            overlap < 1e-9,
            "step {step}: overlap {overlap:e} of a radius"
        );
    }
}

/// The tall pile (360 discs, e = 0.8): with events alone it spent
/// 4.6 of its 5.6 million events between 2 and 4 s. Held, it settles in
/// 15 s without overlap or energy gain, every step checked, and ends with
/// almost no kinetic energy left (under 1e-6·m·g·r per disc).
#[test]
fn the_tall_pile_settles_without_overlap_or_energy_gain_at_any_step() {
    let mut w = scene("stress-pile-tall.toml");
    assert!(holds_discs(&w.laws));
    run_checked(&mut w, 15.0);
    let g = w.laws.gravity.length();
    let bound: f64 = w
        .particles
        .iter()
        .map(|p| 1e-6 * p.mass * g * p.radius)
        .sum();
    let kinetic = w.metrics().kinetic_energy;
    assert!(
        kinetic < bound,
        "kinetic energy {kinetic:e} J >= {bound:e} J"
    );
}

/// A column of equal discs dropped onto the floor with small gaps comes to
/// rest where statics puts it: the k-th disc's centre at (2k + 1)·r, each
/// disc on the one below, up to the gap a sleeping disc may keep to its
/// support ([`SUPPORT_GAP`] of a radius), nothing moving sideways (the
/// column is exactly vertical, so no force has a sideways part).
#[test]
fn a_dropped_column_rests_touching_at_the_heights_statics_gives() {
    let r = 0.2;
    let mut w = World::new(DVec2::new(2.0, 12.0));
    w.laws.gravity = DVec2::new(0.0, -9.81);
    w.laws.restitution = 0.5;
    w.laws.wall_restitution = 0.5;
    w.method = Setting::Fixed(Method::Exact);
    let x = 1.0;
    w.particles = (0..12)
        .map(|k| {
            let y = (2 * k + 1) as f64 * r + 0.1 * (k + 1) as f64;
            Particle::new(DVec2::new(x, y), DVec2::ZERO, 1.0, r, Color::palette(k))
        })
        .collect();
    run_checked(&mut w, 8.0);
    let mut below = -r; // the floor, as the top of a disc centred at -r
    for (k, p) in w.particles.iter().enumerate() {
        let gap = p.pos.y - below - 2.0 * r;
        assert!(
            (-1e-9 * r..=SUPPORT_GAP * r).contains(&gap),
            "disc {k}: {gap:e} m above its support"
        );
        let statics = (2 * k + 1) as f64 * r;
        assert!(p.pos.y - statics <= (k + 1) as f64 * SUPPORT_GAP * r);
        assert_eq!(p.pos.x, x, "disc {k} moved sideways");
        assert_eq!(p.vel, DVec2::ZERO, "disc {k} still moving");
        below = p.pos.y;
    }
}

/// Fast discs rain onto a pile that is still settling: flying discs meet
/// held ones by events, held ones meet each other in the solve; no step may
/// overlap or gain energy through either, and all comes to rest within the
/// time the bounces' geometric series gives.
#[test]
fn a_rain_of_fast_discs_onto_a_settling_pile_keeps_every_promise() {
    let mut w = scene("stress-pile.toml");
    run_checked(&mut w, 2.0);
    let before = w.particles.len();
    for k in 0..20 {
        let pos = DVec2::new(0.5 + 0.55 * k as f64, 14.0 + 0.7 * (k % 3) as f64);
        let vel = DVec2::new(if k % 2 == 0 { 6.0 } else { -6.0 }, -8.0);
        w.particles
            .push(Particle::new(pos, vel, 2.0, 0.22, Color::palette(k)));
    }
    // The rain lands and stops bouncing: a disc of the rain alone on the
    // floor would, by the geometric series of its bounces (e < 1), rest
    // t₀ + 2e·v₀/(g·(1 − e)) after it was thrown, t₀ its fall to the
    // floor and v₀ its speed there; landing on the pile instead (lower,
    // and losing energy to it too) it rests no later. After that no disc
    // bounces: what still moves is frictionless discs settling into gaps
    // one at a time (the settled piles' 1e-6·m·g·r a disc is reached now
    // and then and lost again as one slides), each with at most the
    // energy of dropping by its own diameter, m·g·2r; the rain brought
    // nearly 8000 J. Every step is still checked.
    let g = w.laws.gravity.length();
    let e = w.laws.restitution.max(w.laws.wall_restitution);
    assert!(e < 1.0);
    let rest = w.particles[before..]
        .iter()
        .map(|p| {
            let drop = p.pos.y - p.radius;
            let v0 = (p.vel.y * p.vel.y + 2.0 * g * drop).sqrt();
            let t0 = (v0 + p.vel.y) / g;
            t0 + 2.0 * e * v0 / (g * (1.0 - e))
        })
        .fold(0.0, f64::max);
    run_checked(&mut w, rest);
    let settling = w
        .particles
        .iter()
        .map(|p| p.mass * g * 2.0 * p.radius)
        .fold(0.0, f64::max);
    let kinetic = w.metrics().kinetic_energy;
    assert!(
        kinetic < settling,
        "{rest:.2} s after the rain: kinetic energy {kinetic:e} J, more than one disc \
         settling into a gap ({settling:e} J)"
    );
}

/// Rough discs are not held (the contact solve has no friction), nor discs
/// without gravity or with elastic laws: there `exact` runs on events alone,
/// as before. `auto` takes `exact` for a settling pile of smooth discs.
#[test]
fn only_smooth_discs_resting_in_a_box_are_held_and_auto_takes_exact_for_them() {
    let pile = scene("stress-pile.toml");
    assert!(holds_discs(&pile.laws));
    let mut rough = pile.laws;
    rough.tangential_restitution = 0.0;
    assert!(!holds_discs(&rough));
    let mut elastic = pile.laws;
    elastic.restitution = 1.0;
    elastic.wall_restitution = 1.0;
    assert!(!holds_discs(&elastic));
    let mut weightless = pile.laws;
    weightless.gravity = DVec2::ZERO;
    assert!(!holds_discs(&weightless));
    let mut periodic = pile.laws;
    periodic.boundary = impulse::Boundary::Periodic;
    assert!(!holds_discs(&periodic));

    let mut auto = pile.clone();
    auto.method = Setting::Auto;
    let plan = auto.plan_for(DT);
    assert_eq!(plan.method, Method::Exact, "{}", plan.reason);
    assert!(plan.reason.contains("rest"), "{}", plan.reason);
}
