//! Fixed steps resolve an impact where the discs touched: an isolated
//! off-centre impact, smooth or rough, at the default step gives the
//! closed form in `impulse` as in `exact` (velocities, spins and the
//! positions after it), keeps the total angular momentum, and a disc
//! bouncing off a wall comes back along its mirror path. `seed`, the
//! presentation's method, still takes the normal where the discs overlap.

mod common;

use common::disc;
use impulse::method::{Method, Setting};
use impulse::{Boundary, DVec2, Particle, World};

const DT: f64 = 1.0 / 240.0;

/// The closed-form rough impact of uniform discs a and b (I = ½·m·r²),
/// unit normal `n` from a to b, restitution `e`, tangential restitution
/// `beta`, Coulomb μ (Walton's effective β, as in `tests/rough.rs`).
fn closed_form(a: &Particle, b: &Particle, n: DVec2, law: Law) -> (Particle, Particle) {
    let Law { e, beta, mu, .. } = law;
    let t = n.perp();
    let g_n = (a.vel - b.vel).dot(n);
    let g_t = (a.vel - b.vel).dot(t) + a.spin * a.radius + b.spin * b.radius;
    let beta = match mu {
        Some(mu) if g_t != 0.0 => beta.min(-1.0 + 3.0 * mu * (1.0 + e) * g_n.abs() / g_t.abs()),
        _ => beta,
    };
    let reduced = if b.mass.is_infinite() {
        a.mass
    } else {
        a.mass * b.mass / (a.mass + b.mass)
    };
    let (j_n, j_t) = (
        (1.0 + e) * reduced * g_n,
        (1.0 + beta) * reduced * g_t / 3.0,
    );
    let impulse = j_n * n + j_t * t; // on b; −impulse on a
    let (mut a2, mut b2) = (*a, *b);
    a2.vel -= impulse / a.mass;
    a2.spin -= 2.0 * j_t / (a.mass * a.radius);
    if b.mass.is_finite() {
        b2.vel += impulse / b.mass;
        b2.spin -= 2.0 * j_t / (b.mass * b.radius);
    }
    (a2, b2)
}

#[derive(Clone, Copy, Debug)]
struct Law {
    e: f64,
    beta: f64,
    mu: Option<f64>,
    /// m_b / m_a.
    ratio: f64,
}

/// Smooth, the rough cases (β = 1, β = 0.4, with and without μ),
/// and unequal masses with loss.
const LAWS: [Law; 6] = [
    Law {
        e: 1.0,
        beta: -1.0,
        mu: None,
        ratio: 1.0,
    },
    Law {
        e: 1.0,
        beta: 1.0,
        mu: None,
        ratio: 1.0,
    },
    Law {
        e: 1.0,
        beta: 0.4,
        mu: None,
        ratio: 1.0,
    },
    Law {
        e: 1.0,
        beta: 0.4,
        mu: Some(0.2),
        ratio: 1.0,
    },
    Law {
        e: 0.7,
        beta: 1.0,
        mu: Some(0.1),
        ratio: 3.0,
    },
    Law {
        e: 0.5,
        beta: -1.0,
        mu: None,
        ratio: 0.25,
    },
];

fn open_world(method: Method, law: Law) -> World {
    let mut w = World::new(DVec2::splat(10.0));
    w.laws.boundary = Boundary::Open;
    w.laws.restitution = law.e;
    w.laws.wall_restitution = law.e;
    w.laws.tangential_restitution = law.beta;
    w.laws.wall_tangential_restitution = law.beta;
    w.laws.friction = law.mu;
    w.method = Setting::Fixed(method);
    w
}

/// Total angular momentum about the origin (orbital plus spin) and the
/// scale it is compared with, Σ|L_i|.
fn angular_momentum(w: &World) -> (f64, f64) {
    let total = w.particles.iter().map(|p| p.angular_momentum()).sum();
    let scale = w.particles.iter().map(|p| p.angular_momentum().abs()).sum();
    (total, scale)
}

/// The impact: disc a at 3 m/s strikes b, at rest, off-centre by
/// 0.6 of the sum of the radii, spinning both, from 1.3 m away; both
/// methods at the default step. After 1.5 s each disc has the closed-form
/// velocity and spin and is where the closed form puts it (touch, then
/// straight on) to 1e-9; the total angular momentum is unchanged to 1e-12.
#[test]
fn an_off_centre_impact_at_the_default_step_gives_the_closed_form() {
    for method in [Method::Impulse, Method::Exact] {
        for law in LAWS {
            let (ra, rb) = (0.5, 0.35);
            let reach = ra + rb;
            let offset = 0.6 * reach;
            let b = Particle {
                spin: -2.0,
                ..disc([0.0, offset], [0.0, 0.0], law.ratio, rb)
            };
            let a = Particle {
                spin: 3.0,
                ..disc([-1.3, 0.0], [3.0, 0.0], 1.0, ra)
            };
            // Where and when they touch: a at (x, 0) with |b − a| = reach.
            let x = -(reach * reach - offset * offset).sqrt();
            let t_touch = (x - a.pos.x) / a.vel.x;
            let touching = Particle {
                pos: DVec2::new(x, 0.0),
                ..a
            };
            let n = (b.pos - touching.pos) / reach;
            let (mut want_a, mut want_b) = closed_form(&touching, &b, n, law);
            let mut w = open_world(method, law);
            w.particles = vec![a, b];
            let (l_before, scale) = angular_momentum(&w);
            for _ in 0..360 {
                w.step(DT);
            }
            want_a.pos += want_a.vel * (w.time - t_touch);
            want_b.pos += want_b.vel * (w.time - t_touch);
            let what = format!("{method:?}, {law:?}");
            assert_eq!(w.total_pair_collisions, 1, "{what}: one impact");
            for (got, want, name) in [
                (&w.particles[0], &want_a, "a"),
                (&w.particles[1], &want_b, "b"),
            ] {
                let off = [
                    (got.vel - want.vel).length(),
                    (got.spin - want.spin).abs() * want.radius,
                    (got.pos - want.pos).length(),
                ];
                assert!(
                    off.iter().all(|&o| o < 1e-9),
                    "{what}, {name}: off by {off:?} (velocity, spin·r, position) from the \
                     closed form; got {got:?}, want {want:?}"
                );
            }
            let (l_after, _) = angular_momentum(&w);
            assert!(
                (l_after - l_before).abs() < 1e-12 * scale,
                "{what}: angular momentum {l_before} → {l_after}"
            );
        }
    }
}

/// `seed` is the presentation's method, the baseline of every chart: it
/// still takes the normal where the discs overlap, so the struck disc of
/// the same impact leaves off the line of centres at the touch.
#[test]
fn seed_still_resolves_where_the_discs_overlap() {
    let law = LAWS[0];
    let reach = 1.0;
    let offset = 0.6 * reach;
    let mut w = open_world(Method::Seed, law);
    w.particles = vec![
        disc([-1.3, 0.0], [3.0, 0.0], 1.0, 0.5),
        disc([0.0, offset], [0.0, 0.0], 1.0, 0.5),
    ];
    for _ in 0..360 {
        w.step(DT);
    }
    let x = -(reach * reach - offset * offset).sqrt();
    let line = DVec2::new(-x, offset).normalize();
    let heading = w.particles[1].vel.normalize();
    let degrees = line.angle_between(heading).abs().to_degrees();
    // One step of overlap at 3 m/s turns the normal by about
    // (3·dt·sin θ)/reach rad ≈ 0.4°; at the touch it would be 0.
    assert!(
        degrees > 0.05,
        "seed's struck disc leaves {degrees}° off the line of centres at the touch"
    );
}

/// A rough spinning disc strikes a wall at an angle at the default step:
/// velocity and spin by the closed form of a disc against an immovable
/// one, and its place after the bounce on the mirror path, to 1e-9.
#[test]
fn a_wall_bounce_at_the_default_step_gives_the_closed_form() {
    for method in [Method::Impulse, Method::Exact] {
        for law in LAWS {
            let mut w = open_world(method, law);
            w.laws.boundary = Boundary::Box;
            let r = 0.4;
            let a = Particle {
                spin: 2.5,
                ..disc([7.0, 5.0], [2.3, -1.1], 1.5, r)
            };
            // It touches the right wall (x = 10 − r) at t_touch.
            let t_touch = (10.0 - r - a.pos.x) / a.vel.x;
            let touching = Particle {
                pos: a.pos + a.vel * t_touch,
                ..a
            };
            let wall = Particle {
                mass: f64::INFINITY,
                vel: DVec2::ZERO,
                spin: 0.0,
                ..touching
            };
            let (mut want, _) = closed_form(&touching, &wall, DVec2::X, law);
            w.particles = vec![a];
            for _ in 0..480 {
                w.step(DT);
            }
            want.pos += want.vel * (w.time - t_touch);
            let got = &w.particles[0];
            let what = format!("{method:?} wall, {law:?}");
            assert_eq!(w.total_wall_hits, 1, "{what}: one bounce");
            let off = [
                (got.vel - want.vel).length(),
                (got.spin - want.spin).abs() * r,
                (got.pos - want.pos).length(),
            ];
            assert!(
                off.iter().all(|&o| o < 1e-9),
                "{what}: off by {off:?} (velocity, spin·r, position); got {got:?}, want {want:?}"
            );
        }
    }
}
