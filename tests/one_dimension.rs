//! One dimension (`constrain = "x"`): discs move along their line only, in
//! every method, whatever gravity and contact normals say; on the line the
//! collision is the textbook one-dimensional one.

use impulse::method::{Method, Setting};
use impulse::{Axis, Color, DVec2, Particle, World};

const DT: f64 = impulse::scene::DEFAULT_DT;

fn line_world(method: Method, offset: f64) -> World {
    let mut w = World::new(DVec2::new(16.0, 10.0));
    w.laws.constrain = Some(Axis::X);
    w.method = Setting::Fixed(method);
    w.laws.restitution = 0.5;
    w.laws.gravity = DVec2::new(0.0, -9.81); // held by the line
    w.particles = vec![
        Particle::new(
            DVec2::new(3.0, 5.0),
            DVec2::new(2.0, 0.0),
            1.0,
            0.5,
            Color::palette(0),
        ),
        Particle::new(
            DVec2::new(9.0, 5.0 + offset),
            DVec2::ZERO,
            3.0,
            0.5,
            Color::palette(1),
        ),
    ];
    w
}

#[test]
fn every_y_velocity_stays_zero_through_a_collision_in_every_method() {
    for method in Method::ALL {
        // Off the line by a fifth of a radius: the contact normal tilts.
        let mut w = line_world(method, 0.1);
        let ys: Vec<f64> = w.particles.iter().map(|p| p.pos.y).collect();
        for _ in 0..(4.0 / DT) as usize {
            w.step(DT);
            for (p, &y) in w.particles.iter().zip(&ys) {
                assert_eq!(p.vel.y, 0.0, "{method:?}");
                assert_eq!(p.pos.y, y, "{method:?}");
            }
        }
        assert!(w.total_pair_collisions >= 1, "{method:?}: they met");
    }
}

#[test]
fn on_the_line_the_collision_is_the_one_dimensional_law() {
    // m₁ = 1 at 2 m/s, m₂ = 3 at rest, e = 0.5:
    // v₁' = (m₁ − e·m₂)·u/(m₁+m₂) = −0.25 m/s, v₂' = (1+e)·m₁·u/(m₁+m₂) = 0.75 m/s.
    for method in [Method::Impulse, Method::Exact] {
        let mut w = line_world(method, 0.0);
        for _ in 0..(4.0 / DT) as usize {
            w.step(DT);
        }
        let (a, b) = (w.particles[0].vel.x, w.particles[1].vel.x);
        assert!((a + 0.25).abs() < 1e-9, "{method:?}: {a}");
        assert!((b - 0.75).abs() < 1e-9, "{method:?}: {b}");
    }
}

#[test]
fn a_scene_says_constrain_and_a_save_keeps_it() {
    let text = "[world]\nsize = [10.0, 4.0]\nconstrain = \"x\"\n";
    let scene = impulse::Scene::parse(text, "t.toml").unwrap();
    let world = scene.build("t.toml").unwrap();
    assert_eq!(world.laws.constrain, Some(Axis::X));
    let again = impulse::Scene::from_world(&world, None, None).to_toml();
    assert!(again.contains("constrain = \"x\""), "{again}");
    let bad = text.replace("\"x\"", "\"z\"");
    assert!(impulse::Scene::parse(&bad, "t.toml").is_err());
}
