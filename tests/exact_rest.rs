//! `exact` where discs come to rest (sleeping discs, see
//! `impulse::method::exact::sleep`): piles settle without overlap and
//! without gaining energy, a dropped ball rests when the geometric series
//! of its bounces says, and a resting pile still answers a hit.

use impulse::method::exact::sleep::SLEEP_LIFT;
use impulse::method::{Method, Setting};
use impulse::{Color, DVec2, Particle, World};

mod common;

const DT: f64 = impulse::scene::DEFAULT_DT;

fn preset(file: &str) -> World {
    common::scene_with(file, Method::Exact)
}

#[test]
fn a_pile_settles_under_exact_without_overlap_stall_or_energy_gain() {
    let mut w = preset("stress-pile.toml");
    let mut energy = w.total_energy();
    for step in 0..(6.0 / DT) as usize {
        let stats = w.step(DT);
        assert!(!stats.truncated, "step {step} cut short");
        let now = w.total_energy();
        assert!(
            now - energy <= 1e-12 * energy.abs(),
            "step {step}: energy rose by {:e} of itself",
            (now - energy) / energy.abs()
        );
        energy = now;
        if step % 240 == 0 {
            let o = common::deepest_pair_overlap(&w);
            assert!(o < 1e-9, "step {step}: overlap {o:e} of a radius");
        }
    }
    assert!(common::deepest_pair_overlap(&w) < 1e-9);
    // At rest: every disc asleep or held. Frictionless discs keep finding
    // room now and then (one disc at a time slides a little further into a
    // gap, millimetres per second), so "at rest" is the stability suite's
    // criterion made ten thousand times stricter: kinetic energy under
    // 1e-6·m·g·r per disc.
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
    assert_eq!(w.resting_contacts, w.particles.len(), "all counted resting");
}

/// A ball of radius r dropped from centre height H onto a floor with
/// restitution e first lands after t₀ = √(2h/g), h = H − r, at v₀ = √(2gh);
/// its bounces then last 2e·v₀/(g(1 − e)) in all (a geometric series). It
/// falls asleep when a bounce would leave slower than its sleep speed
/// v_s = √(2g·SLEEP_LIFT·r), which skips the last bounces: at most
/// 2v_s/(g(1 − e)) early.
#[test]
fn a_dropped_ball_rests_when_the_geometric_series_says() {
    for (e, height) in [(0.5, 3.0), (0.7, 2.0), (0.9, 1.5)] {
        let (g, r) = (9.81, 0.25);
        let mut w = World::new(DVec2::new(4.0, 4.0));
        w.laws.gravity = DVec2::new(0.0, -g);
        w.laws.wall_restitution = e;
        w.laws.restitution = e;
        w.method = Setting::Fixed(Method::Exact);
        w.particles = vec![Particle::new(
            DVec2::new(2.0, height),
            DVec2::ZERO,
            1.0,
            r,
            Color::palette(0),
        )];
        let h = height - r;
        let v0 = (2.0 * g * h).sqrt();
        let rest = (2.0 * h / g).sqrt() + 2.0 * e * v0 / (g * (1.0 - e));
        let early = 2.0 * (2.0 * g * SLEEP_LIFT * r).sqrt() / (g * (1.0 - e));
        let started = std::time::Instant::now();
        let mut rested_at = None;
        for _ in 0..((rest + 1.0) / DT) as usize {
            w.step(DT);
            let p = &w.particles[0];
            match (rested_at, p.vel == DVec2::ZERO) {
                (None, true) => rested_at = Some(w.time),
                (Some(_), false) => rested_at = None,
                _ => {}
            }
        }
        let at = rested_at.expect("never came to rest");
        assert!(
            at >= rest - early - DT && at <= rest + DT,
            "e = {e}: at rest from {at:.4} s, the series says {rest:.4} s (up to {early:.4} s early)"
        );
        assert!((w.particles[0].pos.y - r).abs() < 1e-12, "on the floor");
        assert!(
            started.elapsed().as_secs_f64() < 5.0,
            "{:?}",
            started.elapsed()
        );
    }
}

#[test]
fn a_resting_pile_still_answers_a_hit() {
    let mut w = preset("preset-0-pile.toml");
    for _ in 0..(8.0 / DT) as usize {
        w.step(DT);
    }
    assert_eq!(w.metrics().kinetic_energy, 0.0, "settled");
    let before: Vec<DVec2> = w.particles.iter().map(|p| p.pos).collect();
    let pile = w.particles.len();
    let pile_energy = w.total_energy();
    // A disc thrown hard at the pile from high up on the left.
    w.particles.push(Particle::new(
        DVec2::new(1.0, 8.0),
        DVec2::new(12.0, -6.0),
        3.0,
        0.3,
        Color::palette(1),
    ));
    let total = w.total_energy();
    let mut energy = total;
    for step in 0..(1.5 / DT) as usize {
        w.step(DT);
        // e = 0.5 ≤ 1 everywhere and exact moves discs on their parabolas
        // exactly: no step may add energy beyond rounding.
        let now = w.total_energy();
        assert!(
            now - energy <= 1e-12 * total.abs(),
            "step {step}: energy rose by {:e} J",
            now - energy
        );
        energy = now;
    }
    let moved = before
        .iter()
        .zip(&w.particles)
        .filter(|(b, p)| (**b - p.pos).length() > 1e-3)
        .count();
    assert!(moved >= 3, "only {moved} discs of the pile moved");
    assert!(common::deepest_pair_overlap(&w) < 1e-9);
    // The hit is answered with energy: the resting pile sat at rest (no
    // kinetic energy); what it holds now above that came from the thrown
    // disc, which gave up energy to it, and whatever the impacts lost
    // (e = 0.5 keeps a quarter of each approach's kinetic energy) left the
    // whole with less than it started with.
    let mut pile_now = w.clone();
    pile_now.particles.truncate(pile);
    let gained = pile_now.metrics().kinetic_energy + pile_now.metrics().rotational_energy;
    let thrown_left = w.total_energy() - pile_now.total_energy();
    let thrown_given = (total - pile_energy) - thrown_left;
    eprintln!(
        "pile KE {gained:e} J; thrown gave {thrown_given:e} J of {:e}",
        total - pile_energy
    );
    assert!(gained > 0.0, "the pile took no kinetic energy from the hit");
    assert!(
        thrown_given > 0.0,
        "the thrown disc gave up no energy ({thrown_given:e} J)"
    );
    assert!(
        w.total_energy() < total,
        "inelastic impacts lost nothing: {} J → {} J",
        total,
        w.total_energy()
    );
}
