//! Small builders shared by the physics tests.
#![allow(dead_code)]

use impulse::{Boundary, Color, DVec2, Particle, World};

/// A disc with a neutral colour.
pub fn disc(pos: [f64; 2], vel: [f64; 2], mass: f64, radius: f64) -> Particle {
    Particle::new(
        pos.into(),
        vel.into(),
        mass,
        radius,
        Color::rgb(200, 200, 200),
    )
}

/// A world of the given size, boundary and discs; no gravity, e = 1.
pub fn world_with(size: [f64; 2], boundary: Boundary, particles: Vec<Particle>) -> World {
    let mut w = World::new(DVec2::from(size));
    w.laws.boundary = boundary;
    w.particles = particles;
    w
}

/// A periodic gas of `n` discs at roughly 30 % area fraction with a drift,
/// built from the scene format so the test also exercises the fill; stepped
/// by the `impulse` method (tests/methods.rs covers the others).
pub fn periodic_gas(n: usize, seed: u64, restitution: f64) -> World {
    let text = format!(
        r#"
        [world]
        size = [20.0, 20.0]
        boundary = "periodic"
        restitution = {restitution}
        [simulation]
        method = "impulse"
        [fill]
        count = {n}
        seed = {seed}
        radius = [0.3, 0.5]
        speed = [0.5, 3.0]
        "#
    );
    let scene = impulse::Scene::parse(&text, "gas").expect("valid gas scene");
    let mut w = scene.build("gas").expect("gas fits");
    // A common drift so total momentum is far from zero.
    for p in &mut w.particles {
        p.vel += DVec2::new(0.7, -0.4);
    }
    w
}

/// |a − b| relative to a scale.
pub fn rel(a: f64, b: f64, scale: f64) -> f64 {
    (a - b).abs() / scale
}

/// The shipped scene `assets/scenes/{file}`, built, with its method fixed to
/// `method`.
pub fn scene_with(file: &str, method: impulse::method::Method) -> World {
    let path = format!("{}/assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
    let mut w = impulse::Scene::load(std::path::Path::new(&path))
        .and_then(|s| s.build(&path))
        .unwrap();
    w.method = impulse::method::Setting::Fixed(method);
    w
}

/// The deepest overlap of any two discs, as a fraction of the smaller
/// radius (all pairs: for a few hundred discs).
pub fn deepest_pair_overlap(w: &World) -> f64 {
    let ps = &w.particles;
    let mut worst = 0.0f64;
    for (i, p) in ps.iter().enumerate() {
        for q in &ps[i + 1..] {
            let depth = p.radius + q.radius - (p.pos - q.pos).length();
            worst = worst.max(depth / p.radius.min(q.radius));
        }
    }
    worst
}

/// The deepest a disc reaches past a wall of the box, as a fraction of its
/// radius.
pub fn deepest_wall_overlap(w: &World) -> f64 {
    let mut worst = 0.0f64;
    for p in &w.particles {
        let lo = p.pos - DVec2::splat(p.radius);
        let hi = w.laws.size - p.pos - DVec2::splat(p.radius);
        worst = worst.max(-lo.min_element() / p.radius);
        worst = worst.max(-hi.min_element() / p.radius);
    }
    worst
}

/// The fields of one CSV line (quoted fields may hold commas; `""` is a
/// quote).
pub fn csv_fields(line: &str) -> Vec<String> {
    let (mut out, mut field, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(std::mem::take(&mut field)),
            _ => field.push(c),
        }
    }
    out.push(field);
    out
}
