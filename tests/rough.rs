//! Rough discs against physics: two-disc and wall impacts against the
//! closed-form rough-disc result, angular momentum and energy kept where
//! they must be, a rough gas sharing its energy with rotation, and a disc
//! sliding on the floor starting to roll when Coulomb friction says.

mod common;

use common::disc;
use impulse::method::{Method, Setting};
use impulse::{Boundary, DVec2, Particle, Scene, World};

/// The closed-form rough collision of uniform discs a and b (I = ½·m·r²)
/// with unit normal `n` from a to b, restitution `e`, tangential
/// restitution `beta` and Coulomb coefficient `mu`: the effective
/// β = min(β, −1 + 3μ(1+e)|g_n|/|g_t|) (Walton), then the normal impulse
/// (1+e)·m*·g_n and the tangential (1+β)·m*·g_t/3, m* the reduced mass.
fn closed_form(
    a: &Particle,
    b: &Particle,
    n: DVec2,
    e: f64,
    beta: f64,
    mu: Option<f64>,
) -> (Particle, Particle) {
    let t = DVec2::new(-n.y, n.x);
    let g_n = (a.vel - b.vel).dot(n);
    let g_t = (a.vel - b.vel).dot(t) + a.spin * a.radius + b.spin * b.radius;
    let beta = match mu {
        Some(mu) if g_t != 0.0 => beta.min(-1.0 + 3.0 * mu * (1.0 + e) * g_n.abs() / g_t.abs()),
        _ => beta,
    };
    let reduced = a.mass * b.mass / (a.mass + b.mass);
    let (j_n, j_t) = (
        (1.0 + e) * reduced * g_n,
        (1.0 + beta) * reduced * g_t / 3.0,
    );
    let impulse = j_n * n + j_t * t; // on b; −impulse on a
    let mut a2 = *a;
    let mut b2 = *b;
    a2.vel -= impulse / a.mass;
    b2.vel += impulse / b.mass;
    a2.spin -= 2.0 * j_t / (a.mass * a.radius);
    b2.spin -= 2.0 * j_t / (b.mass * b.radius);
    (a2, b2)
}

fn rough_world(size: f64, e: f64, beta: f64, mu: Option<f64>, method: Method) -> World {
    let mut w = World::new(DVec2::splat(size));
    w.laws.restitution = e;
    w.laws.wall_restitution = e;
    w.laws.tangential_restitution = beta;
    w.laws.wall_tangential_restitution = beta;
    w.laws.friction = mu;
    w.method = Setting::Fixed(method);
    w
}

fn assert_close(got: &Particle, want: &Particle, what: &str) {
    let scale = want
        .vel
        .length()
        .max(want.spin.abs() * want.radius)
        .max(1.0);
    assert!(
        (got.vel - want.vel).length() < 1e-8 * scale,
        "{what}: velocity {} against {}",
        got.vel,
        want.vel
    );
    assert!(
        (got.spin - want.spin).abs() * want.radius < 1e-8 * scale,
        "{what}: spin {} against {}",
        got.spin,
        want.spin
    );
}

const CASES: [(f64, f64, Option<f64>, f64); 6] = [
    // (e, β, μ, m_b / m_a)
    (1.0, 1.0, None, 1.0),
    (0.5, 0.0, None, 3.0),
    (0.8, 0.6, Some(0.1), 0.2),
    (1.0, 1.0, Some(0.05), 10.0),
    (0.9, -0.3, Some(1.0), 1.0),
    (0.3, -1.0, Some(0.5), 2.0),
];

/// Disc a (spinning) runs into disc b (spinning the other way, at rest)
/// off-centre; both methods give the closed-form velocities and spins.
#[test]
fn two_disc_impacts_match_the_closed_form_rough_disc_result() {
    let (ra, rb, offset): (f64, f64, f64) = (0.5, 0.3, 0.3);
    let reach = ra + rb;
    let along = (reach * reach - offset * offset).sqrt();
    let n = DVec2::new(along, offset) / reach;
    for method in [Method::Impulse, Method::Exact] {
        for (e, beta, mu, ratio) in CASES {
            let mut w = rough_world(100.0, e, beta, mu, method);
            // b sits at the contact point's partner position; a touches it
            // at once (impulse: a hair inside) or after 0.5 s (exact).
            let b = Particle {
                spin: -5.0,
                ..disc([50.0 + along, 50.0 + offset], [0.0, 0.0], ratio, rb)
            };
            let start = if method == Method::Exact { -1.0 } else { 1e-12 };
            let a = Particle {
                spin: 3.0,
                ..disc([50.0 + start, 50.0], [2.0, 0.0], 1.0, ra)
            };
            let (want_a, want_b) = closed_form(&a, &b, n, e, beta, mu);
            w.particles = vec![a, b];
            let dt = if method == Method::Exact { 1.0 } else { 1e-3 };
            w.step(dt);
            let what = format!("{method:?}, e {e}, β {beta}, μ {mu:?}, m_b/m_a {ratio}");
            assert_close(&w.particles[0], &want_a, &format!("{what}, a"));
            assert_close(&w.particles[1], &want_b, &format!("{what}, b"));
        }
    }
}

/// A spinning disc lands on the floor: the closed form for a disc against
/// an immovable one, the wall's own β and the same μ.
#[test]
fn wall_impacts_match_the_closed_form() {
    for method in [Method::Impulse, Method::Exact] {
        for (e, beta, mu, _) in CASES {
            let mut w = rough_world(10.0, e, -1.0, mu, method);
            w.laws.wall_tangential_restitution = beta;
            let r = 0.5;
            let height = if method == Method::Exact {
                r + 1.0
            } else {
                r + 1e-3
            };
            let a = Particle {
                spin: 4.0,
                ..disc([5.0, height], [3.0, -2.0], 2.0, r)
            };
            // The floor as a disc of enormous mass, touched along −y.
            let floor = Particle {
                spin: 0.0,
                ..disc([5.0, -1e6], [0.0, 0.0], 1e300, 1e6)
            };
            let (want, _) = closed_form(&a, &floor, DVec2::new(0.0, -1.0), e, beta, mu);
            w.particles = vec![a];
            w.step(if method == Method::Exact { 1.0 } else { 1e-2 });
            let what = format!("{method:?} wall, e {e}, β {beta}, μ {mu:?}");
            assert_close(&w.particles[0], &want, &what);
        }
    }
}

/// A gas of `n` discs from the scene format, spins random in ±`spin`.
fn gas(text_world: &str, n: usize, seed: u64, spin: f64) -> World {
    let text = format!(
        "{text_world}\n[fill]\ncount = {n}\nseed = {seed}\nradius = [0.2, 0.3]\nspeed = [0.0, 1.0]\n"
    );
    let mut w = Scene::parse(&text, "gas").unwrap().build("gas").unwrap();
    let mut x = seed.wrapping_mul(6364136223846793005).wrapping_add(1);
    for p in &mut w.particles {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let u = (x >> 11) as f64 / (1u64 << 53) as f64;
        p.spin = spin * (2.0 * u - 1.0);
    }
    w.method = Setting::Fixed(Method::Exact);
    w
}

fn angular_momentum(w: &World) -> (f64, f64) {
    let total = w.particles.iter().map(|p| p.angular_momentum()).sum();
    let scale = w.particles.iter().map(|p| p.angular_momentum().abs()).sum();
    (total, scale)
}

/// In open space nothing exerts a torque: `exact` keeps the total angular
/// momentum, orbital plus spin, to 1e-12 of Σ|L_i| over 10⁵ collisions.
#[test]
fn exact_keeps_angular_momentum_in_an_open_rough_gas() {
    for beta in [1.0, 0.5] {
        let world = format!(
            "[world]\nsize = [40.0, 40.0]\nboundary = \"open\"\ntangential_restitution = {beta}\n"
        );
        let mut w = gas(&world, 3000, 5, 2.0);
        // Falling in towards the middle first, so they collide for long.
        for p in &mut w.particles {
            p.vel -= 0.08 * (p.pos - DVec2::splat(20.0));
        }
        let (before, scale) = angular_momentum(&w);
        while w.total_pair_collisions < 100_000 {
            let collisions = w.total_pair_collisions;
            w.step(0.5);
            assert!(
                w.total_pair_collisions > collisions || w.time < 200.0,
                "the gas stopped colliding at {} collisions",
                collisions
            );
        }
        let (after, _) = angular_momentum(&w);
        eprintln!(
            "β = {beta}: {} collisions, L moved by {:e} of Σ|L|",
            w.total_pair_collisions,
            (after - before).abs() / scale
        );
        assert!(
            (after - before).abs() <= 1e-12 * scale,
            "β = {beta}: L moved by {:e} of Σ|L|",
            (after - before).abs() / scale
        );
        let spins: f64 = w.particles.iter().map(|p| p.rotational_energy()).sum();
        assert!(spins > 0.0);
    }
}

/// Elastic and either smooth or perfectly rough, at the walls too: the
/// total energy (translation and rotation) stays to 1e-12 in both methods.
#[test]
fn energy_is_kept_at_e_1_and_beta_plus_or_minus_1() {
    for beta in [-1.0, 1.0] {
        for method in [Method::Exact, Method::Impulse] {
            let world = format!(
                "[world]\nsize = [30.0, 30.0]\ntangential_restitution = {beta}\nwall_tangential_restitution = {beta}\n"
            );
            let mut w = gas(&world, 1500, 8, 2.0);
            w.method = Setting::Fixed(method);
            let before = w.total_energy();
            let steps = if method == Method::Exact { 60 } else { 3000 };
            for _ in 0..steps {
                w.step(if method == Method::Exact { 0.5 } else { 0.01 });
            }
            assert!(
                w.total_pair_collisions > 10_000,
                "{method:?}: too few collisions"
            );
            let after = w.total_energy();
            eprintln!(
                "{method:?}, β = {beta}: {} collisions, energy moved by {:e}",
                w.total_pair_collisions,
                (after - before) / before
            );
            assert!(
                (after - before).abs() <= 1e-12 * before,
                "{method:?}, β = {beta}: energy moved by {:e} of itself",
                (after - before) / before
            );
        }
    }
}

/// Equipartition: a perfectly rough elastic gas shares its energy between
/// translation (two degrees of freedom) and rotation (one), so rotation
/// ends with a third of it; a smooth gas never touches its spins.
#[test]
fn a_rough_gas_relaxes_to_equipartition_and_a_smooth_one_keeps_its_spins() {
    let rough =
        "[world]\nsize = [60.0, 60.0]\nboundary = \"periodic\"\ntangential_restitution = 1.0\n";
    let n = 4000;
    let mut w = gas(rough, n, 3, 0.0);
    // Relax for 30 collisions per disc, then average over 30 more.
    while w.total_pair_collisions < 30 * n as u64 {
        w.step(1.0);
    }
    let (mut share, mut samples) = (0.0, 0);
    while w.total_pair_collisions < 60 * n as u64 {
        w.step(1.0);
        let m = w.metrics();
        share += m.rotational_energy / (m.kinetic_energy + m.rotational_energy);
        samples += 1;
    }
    let share = share / samples as f64;
    eprintln!("rotation's share of the energy: {share:.4} over {samples} samples");
    assert!(
        (share - 1.0 / 3.0).abs() < 0.02,
        "rotation holds {share:.4} of the energy, equipartition says 1/3"
    );

    let smooth = "[world]\nsize = [60.0, 60.0]\nboundary = \"periodic\"\n";
    let mut w = gas(smooth, 4000, 3, 2.0);
    let spins: Vec<f64> = w.particles.iter().map(|p| p.spin).collect();
    for _ in 0..20 {
        w.step(0.5);
    }
    assert!(w.total_pair_collisions > 10_000);
    let after: Vec<f64> = w.particles.iter().map(|p| p.spin).collect();
    assert_eq!(spins, after, "smooth collisions changed a spin");
}

/// A disc sliding on the floor with μ > 0: friction μ·m·g slows it
/// (v = v₀ − μg·t) and spins it up (ω·r = −2μg·t) until the contact point
/// stops, v = −ω·r, at t* = v₀/(3μg) with v = 2v₀/3; then it rolls.
#[test]
fn a_disc_sliding_on_the_floor_starts_to_roll_when_the_formula_says() {
    let (g, mu, v0, r) = (9.81, 0.3, 3.0, 0.4);
    let rolls_at = v0 / (3.0 * mu * g);
    for method in [Method::Impulse, Method::Exact] {
        let mut w = rough_world(20.0, 0.5, -1.0, Some(mu), method);
        w.laws.gravity = DVec2::new(0.0, -g);
        w.particles = vec![disc([2.0, r], [v0, 0.0], 1.0, r)];
        let dt = 1.0 / 240.0;
        let mut rolled = None;
        while w.time < 2.0 * rolls_at {
            w.step(dt);
            let p = w.particles[0];
            let slip = p.vel.x + p.spin * r;
            if w.time < rolls_at - 2.0 * dt {
                let v = v0 - mu * g * w.time;
                assert!(
                    (p.vel.x - v).abs() < 0.01 * v0,
                    "{method:?} at {:.3} s: v = {} against {v}",
                    w.time,
                    p.vel.x
                );
            }
            if rolled.is_none() && slip.abs() < 1e-3 * v0 {
                rolled = Some(w.time);
            }
        }
        let at = rolled.unwrap_or_else(|| panic!("{method:?}: never rolled"));
        eprintln!("{method:?}: rolls from {at:.4} s; formula {rolls_at:.4} s");
        assert!(
            (at - rolls_at).abs() < 3.0 * dt,
            "{method:?}: rolls from {at:.4} s, the formula says {rolls_at:.4} s"
        );
        let p = w.particles[0];
        assert!(
            (p.vel.x - 2.0 * v0 / 3.0).abs() < 0.01 * v0,
            "{method:?}: v = {}",
            p.vel.x
        );
        assert!(
            (p.vel.x + p.spin * r).abs() < 1e-3 * v0,
            "{method:?}: still slipping"
        );
    }
}

#[test]
fn a_smooth_world_is_what_it_was_bit_for_bit() {
    // Absent fields are smooth: the laws equal those of a world that says
    // so, and no disc starts spinning.
    let w = World::new(DVec2::splat(10.0));
    assert_eq!(w.laws.tangential_restitution, -1.0);
    assert_eq!(w.laws.wall_tangential_restitution, -1.0);
    assert_eq!(w.laws.friction, None);
    let mut gas = gas(
        "[world]\nsize = [20.0, 20.0]\nboundary = \"box\"\n",
        300,
        4,
        0.0,
    );
    gas.laws.boundary = Boundary::Box;
    for _ in 0..10 {
        gas.step(0.5);
    }
    assert!(gas
        .particles
        .iter()
        .all(|p| p.spin == 0.0 && p.angle == 0.0));
}
