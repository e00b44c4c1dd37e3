//! Conservation laws and invariants over many steps.

mod common;
use common::{disc, periodic_gas, rel, world_with};
use impulse::resolution::push_apart;
use impulse::{Boundary, DVec2, Metrics, Particle, World};
use proptest::prelude::*;

#[test]
fn gas_of_200_discs_conserves_momentum_over_10000_steps() {
    let mut w = periodic_gas(200, 42, 1.0);
    let p0 = w.metrics().momentum;
    let scale = Metrics::momentum_scale(&w.particles);
    for _ in 0..10_000 {
        w.step(1e-3);
    }
    let drift = (w.metrics().momentum - p0).length() / scale;
    assert!(
        w.total_pair_collisions > 1000,
        "a real gas: {} collisions",
        w.total_pair_collisions
    );
    assert!(drift < 1e-12, "relative momentum drift {drift:e}");
}

#[test]
fn elastic_pairs_conserve_kinetic_energy() {
    let mut w = periodic_gas(200, 7, 1.0);
    let ke0 = w.metrics().kinetic_energy;
    for _ in 0..5_000 {
        w.step(1e-3);
    }
    assert!(w.total_pair_collisions > 500);
    let drift = rel(w.metrics().kinetic_energy, ke0, ke0);
    assert!(drift < 1e-10, "relative KE drift {drift:e}");
}

/// Newton's law of restitution on an isolated impact. Where exactly two
/// discs changed velocity over a step (one smooth pair impact, nothing
/// else), the change is an impulse +J·n on b and −J·n on a (n from a to
/// b, momentum kept), the normal relative velocity g_n = (v_a − v_b)·n
/// was approaching (> 0), the tangential one is untouched (smooth discs),
/// and afterwards g_n' = −e·g_n: so the impact lost exactly
/// (1 − e²)/2·m*·g_n² of kinetic energy, m* the reduced mass, which is
/// returned (None for a step that was not one isolated impact).
fn isolated_impact_loss(before: &[Particle], after: &[Particle], e: f64) -> Option<f64> {
    let changed: Vec<usize> = (0..before.len())
        .filter(|&i| before[i].vel != after[i].vel)
        .collect();
    let &[i, j] = changed.as_slice() else {
        return None;
    };
    let (a0, b0, a1, b1) = (&before[i], &before[j], &after[i], &after[j]);
    let (dp_a, dp_b) = ((a1.vel - a0.vel) * a0.mass, (b1.vel - b0.vel) * b0.mass);
    let j_len = dp_b.length();
    assert!(
        (dp_a + dp_b).length() <= 1e-12 * j_len,
        "discs {i}, {j}: impulses {dp_a} and {dp_b} do not balance"
    );
    let n = dp_b / j_len;
    let t = n.perp();
    let (g0, g1) = (a0.vel - b0.vel, a1.vel - b1.vel);
    let speed = g0.length();
    assert!(g0.dot(n) > 0.0, "discs {i}, {j}: struck while separating");
    assert!(
        (g1.dot(n) + e * g0.dot(n)).abs() <= 1e-9 * speed,
        "discs {i}, {j}: normal relative velocity {} → {}, e = {e} says {}",
        g0.dot(n),
        g1.dot(n),
        -e * g0.dot(n)
    );
    assert!(
        (g1.dot(t) - g0.dot(t)).abs() <= 1e-9 * speed,
        "discs {i}, {j}: a smooth impact changed the tangential relative velocity"
    );
    let reduced = a0.mass * b0.mass / (a0.mass + b0.mass);
    Some(0.5 * (1.0 - e * e) * reduced * g0.dot(n).powi(2))
}

/// Steps `w` `steps` times by `dt`, checking Newton's law on every isolated
/// impact; returns how many were checked and the energy they lost.
fn step_checking_impacts(w: &mut World, steps: usize, dt: f64) -> (usize, f64) {
    let e = w.laws.restitution;
    let (mut checked, mut lost) = (0, 0.0);
    for _ in 0..steps {
        let before = w.particles.clone();
        w.step(dt);
        if let Some(loss) = isolated_impact_loss(&before, &w.particles, e) {
            checked += 1;
            lost += loss;
        }
    }
    (checked, lost)
}

/// A gas with e = 0.5: every isolated impact obeys Newton's law (and so
/// loses (1 − e²)/2·m*·g_n²); the other impacts lose something too, so the
/// gas loses at least the sum over the isolated ones. It cannot lose the
/// kinetic energy of its centre of mass, |P|²/2M, since P is kept.
#[test]
fn inelastic_pairs_lose_energy_but_keep_momentum() {
    let mut w = periodic_gas(200, 7, 0.5);
    let m0 = w.metrics();
    let (checked, lost) = step_checking_impacts(&mut w, 3_000, 1e-3);
    let m1 = w.metrics();
    eprintln!(
        "{checked} isolated of {} impacts; they lost {lost:e} of {:e} J lost",
        w.total_pair_collisions,
        m0.kinetic_energy - m1.kinetic_energy
    );
    assert!(
        checked as u64 >= w.total_pair_collisions / 4,
        "only {checked} of {} impacts were isolated",
        w.total_pair_collisions
    );
    let loss = m0.kinetic_energy - m1.kinetic_energy;
    assert!(
        loss >= lost * (1.0 - 1e-9),
        "the gas lost {loss:e} J, its isolated impacts alone {lost:e} J"
    );
    let centre = m0.momentum.length_squared() / (2.0 * m0.mass);
    assert!(
        m1.kinetic_energy >= centre,
        "kinetic energy {:e} J below the centre of mass's {centre:e} J",
        m1.kinetic_energy
    );
    let scale = Metrics::momentum_scale(&w.particles);
    assert!((m1.momentum - m0.momentum).length() < 1e-12 * scale);
}

#[test]
fn elastic_walls_conserve_kinetic_energy() {
    let mut w = world_with(
        [10.0, 6.0],
        Boundary::Box,
        vec![
            disc([3.0, 3.0], [7.3, -5.1], 2.0, 0.4),
            disc([7.0, 1.0], [-3.9, 8.8], 0.5, 0.2),
        ],
    );
    let ke0 = w.metrics().kinetic_energy;
    for _ in 0..20_000 {
        w.step(1e-3);
    }
    assert!(w.total_wall_hits > 50, "{} wall hits", w.total_wall_hits);
    assert!(rel(w.metrics().kinetic_energy, ke0, ke0) < 1e-12);
}

#[test]
fn a_bouncing_ball_never_climbs_higher_than_it_fell_from() {
    // With elastic walls under gravity, pushing a disc back out of the floor
    // must not add height: the old seeds let a ball climb.
    let drop_height = 5.0;
    let mut w = world_with(
        [4.0, 8.0],
        Boundary::Box,
        vec![disc([2.0, drop_height], [0.0, 0.0], 1.0, 0.25)],
    );
    w.laws.gravity = DVec2::new(0.0, -9.81);
    let e0 = w.total_energy();
    let dt = 1.0 / 240.0;
    for _ in 0..(60.0 / dt) as usize {
        w.step(dt);
        // Symplectic Euler's own bounded wobble is g·v·dt-sized.
        assert!(
            w.total_energy() <= e0 + 9.81 * 10.0 * dt,
            "energy grew to {}",
            w.total_energy()
        );
    }
    assert!(w.total_wall_hits >= 10);
    assert!(w.particles[0].pos.y <= drop_height + 9.81 * dt * dt);
}

#[test]
fn no_disc_leaves_a_closed_box() {
    let text = r#"
        [world]
        size = [8.0, 5.0]
        gravity = [0.0, -9.81]
        restitution = 0.5
        wall_restitution = 0.8
        [fill]
        count = 120
        seed = 3
        radius = [0.05, 0.25]
        speed = [5.0, 40.0]
    "#;
    let mut w = impulse::Scene::parse(text, "box")
        .unwrap()
        .build("box")
        .unwrap();
    for _ in 0..3000 {
        w.step(1.0 / 240.0);
        for p in &w.particles {
            assert!(p.pos.is_finite() && p.vel.is_finite());
            assert!(
                p.pos.x >= p.radius && p.pos.x <= w.laws.size.x - p.radius,
                "x {}",
                p.pos.x
            );
            assert!(
                p.pos.y >= p.radius && p.pos.y <= w.laws.size.y - p.radius,
                "y {}",
                p.pos.y
            );
        }
    }
}

#[test]
fn coincident_centres_separate_without_nan() {
    let mut w = world_with(
        [10.0, 10.0],
        Boundary::Box,
        vec![
            disc([5.0, 5.0], [0.0, 0.0], 1.0, 0.5),
            disc([5.0, 5.0], [0.0, 0.0], 2.0, 0.5),
            disc([5.0, 5.0], [1.0, 1.0], 1.0, 0.3),
        ],
    );
    let m0 = w.metrics();
    let com0 = m0.center_of_mass;
    let stats = w.step(1e-3);
    assert!(stats.contacts >= 2);
    for p in &w.particles {
        assert!(p.pos.is_finite() && p.vel.is_finite(), "{p:?}");
    }
    assert!(
        w.particles[0].pos.x < w.particles[1].pos.x,
        "deterministic normal +x"
    );
    // Only the third disc moves, by 1e-3 · (1, 1) · mass share.
    let expected = com0 + DVec2::new(1.0, 1.0) * 1e-3 * (1.0 / 4.0);
    assert!((w.metrics().center_of_mass - expected).length() < 1e-12);
    for _ in 0..100 {
        w.step(1e-3);
    }
    // No wall is reached in 0.1 s at these speeds: the only forces are
    // between the discs, so the momentum stays (1, 1) kg·m/s, the centre
    // of mass moves on at P/M from where it was (push-apart moves no
    // centre of mass), and no kinetic energy appears from pushing
    // overlaps apart (e = 1: the impacts keep it, push-apart moves
    // positions only).
    let m1 = w.metrics();
    let p = m0.momentum;
    assert!(
        (m1.momentum - p).length() < 1e-12 * m0.mass,
        "momentum {} → {}",
        p,
        m1.momentum
    );
    let moved = com0 + p / m0.mass * w.time;
    assert!(
        (m1.center_of_mass - moved).length() < 1e-12,
        "centre of mass at {}, P/M·t puts it at {moved}",
        m1.center_of_mass
    );
    assert!(
        m1.kinetic_energy <= m0.kinetic_energy * (1.0 + 1e-12),
        "kinetic energy {} → {} J",
        m0.kinetic_energy,
        m1.kinetic_energy
    );
    // impulse pushes every overlapping pair apart by its whole depth each
    // substep, shared by inverse mass: after 100 steps none is left.
    let overlap = common::deepest_pair_overlap(&w);
    assert!(overlap < 1e-9, "an overlap of {overlap:e} radii is left");
    assert!(w
        .particles
        .iter()
        .all(|p| p.pos.is_finite() && p.vel.is_finite()));
}

#[test]
fn same_scene_same_state_bit_for_bit() {
    let run = |seed| {
        let mut w = periodic_gas(150, seed, 0.8);
        for _ in 0..2000 {
            w.step(1e-3);
        }
        w.state_hash()
    };
    assert_eq!(run(11), run(11));
    // The hash sees every number: one bit of one disc's velocity, of its
    // radius, or of the clock changes it.
    let w = periodic_gas(150, 11, 0.8);
    let base = w.state_hash();
    let flipped = |change: &dyn Fn(&mut impulse::World)| {
        let mut v = w.clone();
        change(&mut v);
        v.state_hash()
    };
    let next = |x: f64| f64::from_bits(x.to_bits() ^ 1);
    assert_ne!(
        flipped(&|v| v.particles[7].vel.x = next(v.particles[7].vel.x)),
        base
    );
    assert_ne!(
        flipped(&|v| v.particles[149].radius = next(v.particles[149].radius)),
        base
    );
    assert_ne!(flipped(&|v| v.time = next(v.time)), base);
    assert_eq!(flipped(&|_| {}), base);
}

proptest! {
    #[test]
    fn push_apart_leaves_the_centre_of_mass_where_it_was(
        m1 in 1e-6f64..1e6, m2 in 1e-6f64..1e6,
        x in -10.0f64..10.0, y in -10.0f64..10.0,
        angle in 0.0f64..std::f64::consts::TAU, depth in 0.0f64..2.0,
    ) {
        let mut a = disc([x, y], [0.0, 0.0], m1, 1.0);
        let mut b = disc([x + 0.5, y], [0.0, 0.0], m2, 1.0);
        let com = |a: &impulse::Particle, b: &impulse::Particle| (a.pos * a.mass + b.pos * b.mass) / (a.mass + b.mass);
        let before = com(&a, &b);
        let n = DVec2::from_angle(angle);
        push_apart(&mut a, &mut b, n, depth);
        let after = com(&a, &b);
        prop_assert!((after - before).length() <= 1e-14 * (1.0 + before.length() + depth));
        let moved = (b.pos - a.pos) - DVec2::new(0.5, 0.0);
        prop_assert!((moved - n * depth).length() <= 1e-12 * (1.0 + depth));
    }
}

#[test]
fn rewinding_and_resuming_replays_the_same_run_bit_for_bit() {
    // Record a run, rewind to the middle and run again: the discrete
    // methods are deterministic, so the replay ends in the very same state;
    // resuming from the past with another restitution changes the outcome.
    use impulse::history::History;
    use impulse::method::{Method, Setting};
    let mut world = periodic_gas(120, 7, 1.0);
    world.method = Setting::Fixed(Method::Impulse);
    let mut history = History::default();
    history.record(&world);
    for _ in 0..200 {
        world.step(1.0 / 240.0);
        history.record(&world);
    }
    let end = world.state_hash();
    history.scrub(&mut world, -100);
    assert_eq!(world.steps, 100);
    for _ in 0..100 {
        world.step(1.0 / 240.0);
        history.record(&world);
    }
    assert_eq!(world.state_hash(), end);
    history.scrub(&mut world, -100);
    world.laws.restitution = 0.3;
    let before = world.metrics().kinetic_energy;
    let (checked, lost) = step_checking_impacts(&mut world, 100, 1.0 / 240.0);
    // The resumed run obeys the new law: its isolated impacts keep
    // e = 0.3 of their approach (step_checking_impacts), the gas loses at
    // least what they lose, and it is no longer the recorded run.
    let loss = before - world.metrics().kinetic_energy;
    eprintln!("{checked} isolated impacts lost {lost:e} J of {loss:e} J");
    assert!(checked > 0, "no isolated impact to check");
    assert!(
        loss >= lost * (1.0 - 1e-9),
        "e = 0.3: the gas lost {loss:e} J, its isolated impacts alone {lost:e} J"
    );
    assert_ne!(world.state_hash(), end, "e = 0.3 gave the recorded run");
}
