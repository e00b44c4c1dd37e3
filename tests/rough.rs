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

const CASES: [(f64, f64, Option<f64>, f64); 6] = [
    // (e, β, μ, m_b / m_a)
    (1.0, 1.0, None, 1.0),
    (0.5, 0.0, None, 3.0),
    (0.8, 0.6, Some(0.1), 0.2),
    (1.0, 1.0, Some(0.05), 10.0),
    (0.9, -0.3, Some(1.0), 1.0),
    (0.3, -1.0, Some(0.5), 2.0),
];

/// The default step (1/240 s): the fixed-step methods meet the impact
/// somewhere inside a step, not at its start.
const DT: f64 = 1.0 / 240.0;

/// How far each disc is off the closed form: velocity, spin·r, position.
fn off(got: &Particle, want: &Particle) -> [f64; 3] {
    [
        (got.vel - want.vel).length(),
        (got.spin - want.spin).abs() * want.radius,
        (got.pos - want.pos).length(),
    ]
}

/// Disc a (spinning) runs into disc b (spinning the other way, at rest)
/// off-centre from 0.7 m away at the default step. `impulse` and `exact`
/// resolve the impact where the discs touched: each disc ends with the
/// closed-form velocity and spin and where the closed form puts it (touch,
/// then straight on), to 1e-9 (tests/at_touch.rs, the same rule).
///
/// `seed` and `verlet` take the impact where they find the discs
/// overlapping, up to one step of approach (2 m/s · 1/240 s ≈ 8 mm) past
/// the touch, so their normal is turned by up to that over the reach
/// (here 0.8 m, about 0.6°), and `verlet` ignores the restitutions: the
/// closed form is not theirs to match. What both do promise is asserted:
/// no force from outside, so the total momentum is kept (seed's push-apart
/// moves positions only, verlet's inverse-mass projection keeps it), one
/// impact, and — both being at most as elastic as the law, e ≤ 1 and
/// |β| ≤ 1 — no energy gained beyond rounding. For `seed`, which does apply
/// the law, the normal impulse is also bounded from the step: the
/// relative normal speed after the impact is e times the one before, along
/// its (slightly turned) normal, so its momentum exchange is that of the
/// closed form to within (1 + e)·m*·|g|·θ, θ = the turn above.
#[test]
fn two_disc_impacts_match_the_closed_form_rough_disc_result() {
    let (ra, rb, offset): (f64, f64, f64) = (0.5, 0.3, 0.3);
    let reach = ra + rb;
    let along = (reach * reach - offset * offset).sqrt();
    let n = DVec2::new(along, offset) / reach;
    let (speed, gap) = (2.0, 0.7);
    for method in Method::ALL {
        for (e, beta, mu, ratio) in CASES {
            let mut w = rough_world(100.0, e, beta, mu, method);
            // b waits where a, moving along x, touches it after gap/speed.
            let b = Particle {
                spin: -5.0,
                ..disc([50.0 + along, 50.0 + offset], [0.0, 0.0], ratio, rb)
            };
            let a = Particle {
                spin: 3.0,
                ..disc([50.0 - gap, 50.0], [speed, 0.0], 1.0, ra)
            };
            let t_touch = gap / speed;
            let touching = Particle {
                pos: DVec2::new(50.0, 50.0),
                ..a
            };
            let (mut want_a, mut want_b) = closed_form(&touching, &b, n, e, beta, mu);
            w.particles = vec![a, b];
            let p0 = a.momentum() + b.momentum();
            let e0 = w.total_energy();
            for _ in 0..120 {
                w.step(DT);
            }
            want_a.pos += want_a.vel * (w.time - t_touch);
            want_b.pos += want_b.vel * (w.time - t_touch);
            let what = format!("{method:?}, e {e}, β {beta}, μ {mu:?}, m_b/m_a {ratio}");
            let [got_a, got_b] = [w.particles[0], w.particles[1]];
            let p1 = got_a.momentum() + got_b.momentum();
            // Rounding: verlet turns positions (~50 m) into velocities by
            // dividing by the step, 4·n·M·ε·|x|/dt.
            let rounding = 4.0 * 2.0 * (1.0 + ratio) * f64::EPSILON * 51.0 / DT;
            assert!(
                (p1 - p0).length() <= 1e-12 * p0.length() + rounding,
                "{what}: momentum {p0} → {p1}"
            );
            let e1 = w.total_energy();
            assert!(e1 <= e0 * (1.0 + 1e-12), "{what}: energy {e0} → {e1}");
            if matches!(method, Method::Impulse | Method::Exact) {
                assert_eq!(w.total_pair_collisions, 1, "{what}: one impact");
                for (got, want, name) in [(&got_a, &want_a, "a"), (&got_b, &want_b, "b")] {
                    let off = off(got, want);
                    assert!(
                        off.iter().all(|&o| o < 1e-9),
                        "{what}, {name}: off by {off:?} (velocity, spin·r, position) from \
                         the closed form; got {got:?}, want {want:?}"
                    );
                }
            } else if method == Method::Seed {
                let reduced = ratio / (1.0 + ratio);
                let turn = speed * DT / reach;
                let bound = (1.0 + e) * reduced * speed * turn;
                let exchanged = (got_b.vel - b.vel) * b.mass;
                let want = (want_b.vel - b.vel) * b.mass;
                let normal_off = (exchanged - want).dot(n).abs();
                assert!(
                    normal_off <= bound,
                    "{what}: normal momentum exchange off the closed form by {normal_off:e}, \
                     more than a step's turn of the normal allows ({bound:e})"
                );
            }
        }
    }
}

/// A spinning disc bounces off the floor, starting 0.6 m above it, at the
/// default step: `impulse` and `exact` give the closed form for a disc
/// against an immovable one (the wall's own β, the same μ), velocity and
/// spin, and put it on the path the closed form gives after the touch, to
/// 1e-9. `seed` and `verlet` meet the floor up to a step past the touch:
/// the floor's normal is the same wherever they meet it, so `seed`, which
/// applies the law, matches the closed form's velocity and spin to
/// rounding, only its place being off by up to a step's travel
/// (|v|·dt); `verlet` ignores the restitutions, so only that it stays in
/// the box and gains no energy (e ≤ 1, |β| ≤ 1) is asserted for it.
#[test]
fn wall_impacts_match_the_closed_form() {
    for method in Method::ALL {
        for (e, beta, mu, _) in CASES {
            let mut w = rough_world(10.0, e, -1.0, mu, method);
            w.laws.wall_tangential_restitution = beta;
            let r = 0.5;
            let a = Particle {
                spin: 4.0,
                ..disc([3.0, r + 0.6], [3.0, -2.0], 2.0, r)
            };
            let t_touch = 0.6 / 2.0;
            let touching = Particle {
                pos: a.pos + a.vel * t_touch,
                ..a
            };
            // The floor as a disc of enormous mass, touched along −y.
            let floor = Particle {
                spin: 0.0,
                ..disc([touching.pos.x, -1e6], [0.0, 0.0], 1e300, 1e6)
            };
            let (mut want, _) = closed_form(&touching, &floor, DVec2::new(0.0, -1.0), e, beta, mu);
            w.particles = vec![a];
            let e0 = w.total_energy();
            for _ in 0..120 {
                w.step(DT);
            }
            want.pos += want.vel * (w.time - t_touch);
            let got = w.particles[0];
            let what = format!("{method:?} wall, e {e}, β {beta}, μ {mu:?}");
            assert!(
                w.total_energy() <= e0 * (1.0 + 1e-12),
                "{what}: energy {e0} → {}",
                w.total_energy()
            );
            let off = off(&got, &want);
            match method {
                Method::Impulse | Method::Exact => {
                    assert_eq!(w.total_wall_hits, 1, "{what}: one bounce");
                    assert!(
                        off.iter().all(|&o| o < 1e-9),
                        "{what}: off by {off:?} (velocity, spin·r, position); got {got:?}, \
                         want {want:?}"
                    );
                }
                Method::Seed | Method::Verlet => {
                    // The normal is the floor's wherever it is met: the law
                    // gives the closed form's velocity and spin. The disc is
                    // found up to a step past the touch and put back on the
                    // floor: off the mirror path by at most the step's
                    // travel before and after, (|v| + |v'|)·dt.
                    let travel = (a.vel.length() + want.vel.length()) * DT;
                    assert!(
                        off[0] < 1e-9 && off[1] < 1e-9 && off[2] <= travel,
                        "{what}: off by {off:?} (velocity, spin·r, position; a step's travel \
                         {travel}); got {got:?}, want {want:?}"
                    );
                }
            }
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

/// `impulse` keeps the angular momentum too, now that it resolves each
/// impact at the touch: the impulse acts along the line of centres there,
/// and the tangential one at the contact point, so no torque about the
/// origin acts on the pair. Its fallback does not: a contact it cannot
/// rewind to a touch within the substep (a pair found overlapping without
/// closing, or deeper than one substep of closing makes, as when a disc
/// hit another in the substep before) is pushed apart by its depth d along
/// n, which moves L by m*·d·|n × g|, g the relative velocity; and a disc
/// met by two others in one pass is rewound, at its second contact, along
/// a velocity the first changed, which moves L by τ·J·|Δg| ≤ 4·m*·|g|²·h.
/// A step whose every contact is an impact resolved cleanly at the touch
/// keeps L to rounding. Over the run, L may move by at most m*·|g|·d for
/// each contact pushed apart (those
/// neither in `StepStats::at_touch` nor in `at_touch_changed`) plus
/// 4·m*·|g|²·h for each of `at_touch_changed`, with d the step's deepest
/// overlap and |g| ≤ 2·(v + ω·r) of its fastest disc. A torque at
/// each impact (a wrong lever arm or moment of inertia) moves L at every
/// impact instead, by about m*·|g|·r.
#[test]
fn impulse_keeps_angular_momentum_in_an_open_rough_gas() {
    for beta in [1.0, 0.5] {
        let world = format!(
            "[world]\nsize = [40.0, 40.0]\nboundary = \"open\"\ntangential_restitution = {beta}\n"
        );
        let mut w = gas(&world, 1500, 5, 2.0);
        w.method = Setting::Fixed(Method::Impulse);
        let reduced = w.particles.iter().map(|p| p.mass).fold(0.0, f64::max) / 2.0;
        let (before, scale) = angular_momentum(&w);
        let (mut allowed, mut at_touch, mut clean_steps) = (0.0, 0, 0);
        while w.total_pair_collisions < 5_000 {
            let fastest = w
                .particles
                .iter()
                .map(|p| p.vel.length() + p.spin.abs() * p.radius)
                .fold(0.0, f64::max);
            let (l_before, _) = angular_momentum(&w);
            let stats = w.step(DT);
            let changed = stats.at_touch_changed;
            let pushed = (stats.contacts - stats.at_touch - changed) as f64;
            if pushed == 0.0 && changed == 0 && stats.at_touch > 0 {
                // Every contact of the step an impact resolved cleanly at
                // the touch: L to rounding.
                let (l_after, _) = angular_momentum(&w);
                assert!(
                    (l_after - l_before).abs() <= 1e-12 * scale,
                    "β = {beta}: a step of {} clean impacts moved L by {:e} of Σ|L|",
                    stats.at_touch,
                    (l_after - l_before).abs() / scale
                );
                clean_steps += 1;
            }
            let (g, h) = (2.0 * fastest, DT / f64::from(stats.substeps.max(1)));
            allowed += reduced * g * (pushed * stats.max_overlap + changed as f64 * 4.0 * g * h);
            at_touch += stats.at_touch;
            assert!(w.time < 60.0, "the gas stopped colliding");
        }
        assert!(
            clean_steps > 100,
            "{clean_steps} steps of clean impacts only"
        );
        let (after, _) = angular_momentum(&w);
        let moved = (after - before).abs();
        eprintln!(
            "impulse β = {beta}: {} collisions, {at_touch} at the touch, L moved by {:e} of Σ|L|, \
             allowed {:e}",
            w.total_pair_collisions,
            moved / scale,
            allowed / scale
        );
        assert!(
            at_touch as f64 > 0.9 * w.total_pair_collisions as f64,
            "most impacts of a dilute gas are resolved at the touch"
        );
        assert!(
            moved <= allowed + 1e-12 * scale,
            "β = {beta}: L moved by {moved:e}, more than fallbacks allow ({allowed:e})"
        );
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
