//! A box with walls on chosen sides: every method reflects at a wall and
//! lets a disc through an open side, and the π blocks, with their wall on
//! the left alone, count π and stop.

use glam::DVec2;
use impulse::method::{Method, Setting};
use impulse::{Boundary, Color, Particle, Walls, World};
use std::process::Command;

const DT: f64 = impulse::scene::DEFAULT_DT;

fn disc(pos: [f64; 2], vel: [f64; 2]) -> Particle {
    Particle::new(pos.into(), vel.into(), 1.0, 0.5, Color::palette(0))
}

/// A 10 m box with a wall on the left and on the floor only.
fn world(method: Method, gravity: f64) -> World {
    let mut w = World::new(DVec2::new(10.0, 10.0));
    w.laws.walls = Walls::from_names(&["left", "bottom"]).unwrap();
    w.method = Setting::Fixed(method);
    w.laws.gravity = DVec2::new(0.0, -gravity);
    w
}

#[test]
fn every_method_reflects_at_a_wall_and_lets_discs_out_through_an_open_side() {
    for method in Method::ALL {
        let mut w = world(method, 0.0);
        w.particles = vec![
            disc([2.0, 2.0], [-3.0, 0.0]), // to the left wall and back
            disc([8.0, 5.0], [3.0, 0.0]),  // out through the open right side
            disc([5.0, 8.0], [0.0, 3.0]),  // out through the open top
        ];
        for _ in 0..(10.0 / DT) as usize {
            w.step(DT);
        }
        let [back, right, up] = [&w.particles[0], &w.particles[1], &w.particles[2]];
        // Elastic: the reflected disc keeps its speed, reversed, and has
        // travelled 1.5 m to the wall and 10 × 3 − 1.5 m back out.
        assert!(
            (back.vel.x - 3.0).abs() < 1e-9,
            "{method:?}: {:?}",
            back.vel
        );
        let expected = 0.5 + (30.0 - 1.5);
        assert!(
            (back.pos.x - expected).abs() < 0.05,
            "{method:?}: {}",
            back.pos.x
        );
        // (verlet reads velocities off displacements: exact to rounding)
        assert!(
            (right.vel - DVec2::new(3.0, 0.0)).length() < 1e-9,
            "{method:?}"
        );
        assert!(
            (right.pos.x - 38.0).abs() < 1e-6,
            "{method:?}: {}",
            right.pos.x
        );
        assert!(
            (up.vel - DVec2::new(0.0, 3.0)).length() < 1e-9,
            "{method:?}"
        );
        assert!((up.pos.y - 38.0).abs() < 1e-6, "{method:?}: {}", up.pos.y);
        assert_eq!(w.total_wall_hits, 1, "{method:?}");
    }
}

#[test]
fn under_gravity_the_floor_holds_and_an_open_side_does_not() {
    for method in Method::ALL {
        let mut w = world(method, 9.81);
        w.particles = vec![
            disc([2.0, 3.0], [0.0, 0.0]), // falls, bounces on the floor
            disc([9.0, 3.0], [2.0, 0.0]), // falls and leaves to the right
        ];
        for _ in 0..(3.0 / DT) as usize {
            w.step(DT);
        }
        let (kept, gone) = (&w.particles[0], &w.particles[1]);
        assert!(
            kept.pos.y >= 0.5 - 1e-9 && kept.pos.y < 3.0 + 1e-6,
            "{method:?}"
        );
        assert!(gone.pos.x > 10.0, "{method:?}: {}", gone.pos.x);
        assert!(
            gone.pos.y > 0.5 - 1e-9,
            "{method:?}: the floor reaches under the open side"
        );
    }
}

#[test]
fn a_scene_names_its_walls_and_a_save_keeps_them() {
    let text = r#"
        [world]
        size = [10.0, 10.0]
        walls = ["left"]
        [[particles]]
        pos = [30.0, 5.0]
        mass = 1.0
        radius = 0.5
    "#;
    let scene = impulse::Scene::parse(text, "t.toml").expect("a disc beyond an open side is fine");
    let world = scene.build("t.toml").unwrap();
    assert_eq!(world.laws.walls, Walls::from_names(&["left"]).unwrap());
    let again = impulse::Scene::from_world(&world, None, None).to_toml();
    assert!(again.contains("walls = [\"left\"]"), "{again}");
    let bad = text.replace("[\"left\"]", "[\"floor\"]");
    let err = impulse::Scene::parse(&bad, "t.toml")
        .unwrap_err()
        .to_string();
    assert!(err.contains("floor") && err.contains("bottom"), "{err}");
    let outside = text.replace("30.0, 5.0", "-3.0, 5.0");
    let err = impulse::Scene::parse(&outside, "t.toml")
        .unwrap_err()
        .to_string();
    assert!(err.contains("outside the box"), "{err}");
    // Four walls are the default and are not written out.
    let boxed = impulse::Scene::from_world(&World::new(DVec2::ONE), None, None).to_toml();
    assert!(!boxed.contains("walls"), "{boxed}");
    assert_eq!(World::new(DVec2::ONE).laws.boundary, Boundary::Box);
}

/// ⌊π·10^k⌋ for a mass ratio of 100^k.
fn pi_count(k: u32) -> u64 {
    (std::f64::consts::PI * 10f64.powi(k as i32)).floor() as u64
}

#[test]
fn the_pi_blocks_count_pi_headless_and_then_stop() {
    for (file, k) in [
        ("pi-blocks-1.toml", 0),
        ("preset-7-pi-blocks.toml", 1),
        ("pi-blocks-10000.toml", 2),
        ("pi-blocks-1000000.toml", 3),
    ] {
        let path = format!("{}/assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
        let out = Command::new(env!("CARGO_BIN_EXE_impulse"))
            .args(["run", &path, "--time", "300", "--json"])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(json["collisions"].as_u64(), Some(pi_count(k)), "{file}");
        assert_eq!(json["collisions_over"].as_bool(), Some(true), "{file}");
        // The heavy disc has left through the open side for good.
        let heavy_x = json["particles"][1]["pos"][0].as_f64().unwrap();
        assert!(heavy_x > 300.0, "{file}: {heavy_x}");
    }
}
