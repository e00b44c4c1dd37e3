//! Two-disc collisions against the analytic results.

mod common;
use common::{disc, world_with};
use impulse::{Boundary, DVec2};

/// Textbook 1D result, written in the centre-of-mass form (a different
/// algebraic form from the one the engine uses).
fn analytic(m1: f64, m2: f64, v1: f64, v2: f64, e: f64) -> (f64, f64) {
    let vcm = (m1 * v1 + m2 * v2) / (m1 + m2);
    (vcm - e * (v1 - vcm), vcm - e * (v2 - vcm))
}

#[test]
fn head_on_matches_the_formula_for_mass_ratios_and_restitutions() {
    for (m1, m2) in [
        (1.0, 1.0),
        (1.0, 3.0),
        (5.0, 1.0),
        (1.0, 1000.0),
        (0.01, 1.0),
    ] {
        for e in [1.0, 0.5, 0.0] {
            let (v1, v2) = (2.0, -1.0);
            let mut w = world_with(
                [100.0, 100.0],
                Boundary::Open,
                vec![
                    disc([10.0, 50.0], [v1, 0.0], m1, 0.5),
                    disc([12.0, 50.0], [v2, 0.0], m2, 0.5),
                ],
            );
            w.laws.restitution = e;
            let p0 = w.metrics().momentum;
            for _ in 0..2000 {
                w.step(1e-3);
            }
            assert_eq!(
                w.total_pair_collisions, 1,
                "m1={m1} m2={m2} e={e}: one collision"
            );
            let (want1, want2) = analytic(m1, m2, v1, v2, e);
            let (got1, got2) = (w.particles[0].vel, w.particles[1].vel);
            let tol = 1e-12 * (v1.abs() + v2.abs());
            assert!(
                (got1.x - want1).abs() < tol,
                "m1={m1} m2={m2} e={e}: v1 {} vs {want1}",
                got1.x
            );
            assert!(
                (got2.x - want2).abs() < tol,
                "m1={m1} m2={m2} e={e}: v2 {} vs {want2}",
                got2.x
            );
            assert_eq!(
                (got1.y, got2.y),
                (0.0, 0.0),
                "no sideways motion from a head-on hit"
            );
            let p1 = w.metrics().momentum;
            assert!((p1 - p0).length() < 1e-12 * (m1 * v1.abs() + m2 * v2.abs()));
            // Kinetic energy lost: ½·μ·(1 − e²)·v_rel².
            let mu = m1 * m2 / (m1 + m2);
            let ke0 = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;
            let lost = ke0 - w.metrics().kinetic_energy;
            let want_lost = 0.5 * mu * (1.0 - e * e) * (v1 - v2).powi(2);
            assert!(
                (lost - want_lost).abs() < 1e-12 * ke0,
                "KE lost {lost} vs {want_lost}"
            );
        }
    }
}

#[test]
fn equal_masses_glancing_elastic_leave_at_right_angles() {
    for offset in [0.1, 0.4, 0.7, 0.95] {
        let mut w = world_with(
            [100.0, 100.0],
            Boundary::Open,
            vec![
                disc([10.0, 50.0 + offset], [3.0, 0.0], 2.0, 0.5),
                disc([14.0, 50.0], [0.0, 0.0], 2.0, 0.5),
            ],
        );
        for _ in 0..3000 {
            w.step(1e-3);
        }
        assert_eq!(w.total_pair_collisions, 1);
        let (a, b) = (w.particles[0].vel, w.particles[1].vel);
        assert!(
            a.length() > 1e-3 && b.length() > 1e-3,
            "both move after a glancing hit"
        );
        let cos = a.dot(b) / (a.length() * b.length());
        assert!(
            cos.abs() < 1e-12,
            "offset {offset}: cos(angle) = {cos}, want 0 (90°)"
        );
        let ke = a.length_squared() + b.length_squared();
        assert!((ke - 9.0).abs() < 1e-12 * 9.0, "kinetic energy conserved");
    }
}

#[test]
fn a_separating_pair_is_never_re_resolved() {
    // Overlapping, but already moving apart: the seeds' "sticky" case.
    let mut w = world_with(
        [100.0, 100.0],
        Boundary::Open,
        vec![
            disc([10.0, 50.0], [-1.0, 0.5], 1.0, 0.5),
            disc([10.6, 50.0], [1.0, 0.2], 3.0, 0.5),
        ],
    );
    let before: Vec<DVec2> = w.particles.iter().map(|p| p.vel).collect();
    let stats = w.step(1e-3);
    assert_eq!(stats.contacts, 1, "the pair overlaps");
    assert_eq!(
        stats.pair_collisions, 0,
        "but it separates, so it is not resolved"
    );
    let after: Vec<DVec2> = w.particles.iter().map(|p| p.vel).collect();
    assert_eq!(before, after, "velocities untouched");
    let gap = w.particles[0].pos.distance(w.particles[1].pos);
    assert!(
        gap >= 1.0 - 1e-12,
        "push-apart removed the overlap: gap {gap}"
    );
}

#[test]
fn slow_deep_overlap_does_not_stick() {
    // The tutorial's sticky problem: a deep overlap with a slow approach used
    // to flip the velocities every frame and trap the pair. Here it collides
    // once and the discs part.
    let mut w = world_with(
        [100.0, 100.0],
        Boundary::Open,
        vec![
            disc([10.0, 50.0], [0.1, 0.0], 1.0, 0.5),
            disc([10.3, 50.0], [-0.1, 0.0], 1.0, 0.5),
        ],
    );
    for _ in 0..200 {
        w.step(1e-2);
    }
    assert_eq!(w.total_pair_collisions, 1);
    assert!(w.particles[0].pos.distance(w.particles[1].pos) > 1.0);
    assert!(w.particles[0].vel.x < 0.0 && w.particles[1].vel.x > 0.0);
}

#[test]
fn the_ledger_records_each_collision_with_its_momentum_and_energy() {
    // A glancing collision at e = 0.5 under impulse and exact: the ledger's
    // entry keeps momentum, loses ½·μ·(1 − e²)·u² of kinetic energy, leaves
    // the tangential components alone and reverses the normal approach
    // times e.
    use impulse::method::{Method, Setting};
    for method in [Method::Impulse, Method::Exact] {
        let mut w = world_with(
            [40.0, 40.0],
            Boundary::Open,
            vec![
                disc([10.0, 20.0], [2.0, 0.0], 1.0, 0.5),
                disc([14.0, 20.6], [0.0, 0.0], 3.0, 0.5),
            ],
        );
        w.laws.restitution = 0.5;
        w.method = Setting::Fixed(method);
        w.ledger.keep(8);
        for _ in 0..(4 * 240) {
            w.step(1.0 / 240.0);
        }
        let entries: Vec<_> = w.ledger.entries().copied().collect();
        assert_eq!(entries.len(), 1, "{method:?}: one collision");
        let c = entries[0];
        assert_eq!(c.discs, [0, 1]);
        assert!(c.time > 1.0 && c.time < 2.0, "{}", c.time);
        let (dp, dke) = c.total_change();
        assert!(dp.length() < 1e-12, "{method:?}: momentum kept");
        let u = (c.before[1] - c.before[0]).dot(c.normal);
        let mu = 1.0 * 3.0 / 4.0;
        let loss = 0.5 * mu * (1.0 - 0.25) * u * u;
        assert!((dke + loss).abs() < 1e-12, "{method:?}: {dke} vs -{loss}");
        for k in 0..2 {
            let ((_, t0), (_, t1)) = c.components(k);
            assert!((t0 - t1).abs() < 1e-12, "{method:?}: tangent kept");
        }
        let u_after = (c.after[1] - c.after[0]).dot(c.normal);
        assert!((u_after + 0.5 * u).abs() < 1e-12, "{method:?}: e·u");
    }
}

#[test]
fn run_to_next_collision_stops_exact_at_the_instant_of_impact() {
    // Discs 4 m apart closing at 2 m/s, radii summing to 1: they touch after
    // exactly 1.5 s; exact must stop there with the discs just touching.
    use impulse::method::{Method, Setting};
    let mut w = world_with(
        [40.0, 40.0],
        Boundary::Open,
        vec![
            disc([10.0, 20.0], [1.0, 0.0], 1.0, 0.5),
            disc([14.0, 20.0], [-1.0, 0.0], 1.0, 0.5),
        ],
    );
    w.method = Setting::Fixed(Method::Exact);
    let c = w
        .run_to_next_collision(1.0 / 60.0, 10.0)
        .expect("they collide");
    assert!((c.time - 1.5).abs() < 1e-12, "impact at {}", c.time);
    assert!(
        (w.time - 1.5).abs() < 1e-12,
        "the world stops at {}",
        w.time
    );
    let gap = (w.particles[1].pos - w.particles[0].pos).length() - 1.0;
    assert!(gap.abs() < 1e-12, "touching: gap {gap:e}");
    // Nothing else to hit: the search gives up at the limit.
    assert!(w.run_to_next_collision(1.0 / 60.0, 2.0).is_none());
    assert!((w.time - 3.5).abs() < 1e-9);
}
