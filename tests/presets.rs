//! The classroom presets, `assets/scenes/preset-*.toml` (the number keys of
//! the window): every one loads and reads well on a projector, and every
//! physics preset does what its description promises, run headlessly with
//! the event-driven `exact` method and checked against the textbook
//! formulas (never against numbers copied from a run).

use impulse::method::{Method, Setting};
use impulse::{Color, DVec2, Particle, Scene, World};
use std::path::{Path, PathBuf};

/// The window's default step (s), for scenes that set none.
const WINDOW_DT: f64 = impulse::scene::DEFAULT_DT;

/// Longest description (English): two lines of the strip under the world
/// hold it whole from 1024×768 up.
const MAX_DESCRIPTION_CHARS: usize = 140;

fn scenes_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes")
}

/// Every `preset-*.toml`, sorted: a new preset is tested without listing it.
fn preset_paths() -> Vec<PathBuf> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(scenes_dir())
        .expect("assets/scenes is readable")
        .map(|entry| entry.expect("directory entry").path())
        .filter(|path| {
            let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
            name.starts_with("preset-") && name.ends_with(".toml")
        })
        .collect();
    paths.sort();
    paths
}

/// A preset and its world as the window would open it (method on `auto`
/// unless the file fixes it).
fn load(file: &str) -> (Scene, World) {
    let path = scenes_dir().join(file);
    let origin = path.display().to_string();
    let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let world = scene.build(&origin).unwrap_or_else(|e| panic!("{e}"));
    (scene, world)
}

/// A preset's world stepped by the event-driven `exact` method, and its step.
fn exact(file: &str) -> (World, f64) {
    let (scene, mut world) = load(file);
    world.method = Setting::Fixed(Method::Exact);
    (world, scene.simulation.dt.unwrap_or(WINDOW_DT))
}

/// Steps until `done` holds, for at most `max_seconds` of simulated time;
/// whether it came to hold.
fn step_until(
    world: &mut World,
    dt: f64,
    max_seconds: f64,
    mut done: impl FnMut(&World) -> bool,
) -> bool {
    let steps = (max_seconds / dt).ceil() as u64;
    for _ in 0..steps {
        world.step(dt);
        if done(world) {
            return true;
        }
    }
    false
}

/// Steps to the end of the step with the first disc–disc collision, and
/// checks that no wall was touched before it, so the pair's velocities are
/// the collision's result alone.
fn through_the_first_collision(world: &mut World, dt: f64, file: &str) {
    let collided = step_until(world, dt, 30.0, |w| w.total_pair_collisions > 0);
    assert!(collided, "{file}: the discs never collide");
    assert_eq!(
        world.total_wall_hits, 0,
        "{file}: a wall is hit before (or with) the first collision"
    );
}

/// Textbook one-dimensional collision with restitution `e` (e = 1 gives
/// v₁′ = (m₁ − m₂)/(m₁ + m₂)·v₁ + 2m₂/(m₁ + m₂)·v₂ and its mirror image).
fn head_on(m1: f64, v1: f64, m2: f64, v2: f64, e: f64) -> (f64, f64) {
    let m = m1 + m2;
    (
        (m1 - e * m2) / m * v1 + (1.0 + e) * m2 / m * v2,
        (m2 - e * m1) / m * v2 + (1.0 + e) * m1 / m * v1,
    )
}

fn kinetic_energy(world: &World) -> f64 {
    world.particles.iter().map(Particle::kinetic_energy).sum()
}

/// Asserts that `got` is `want` to `tol`, naming the quantity.
fn assert_close(got: f64, want: f64, tol: f64, what: &str) {
    assert!(
        (got - want).abs() <= tol,
        "{what}: got {got}, want {want} (difference {:e}, tolerance {tol:e})",
        (got - want).abs()
    );
}

/// Two discs on one horizontal line moving along it: the preset is really
/// head-on. Returns their masses and x velocities.
fn head_on_pair(world: &World, file: &str) -> [(f64, f64); 2] {
    let [a, b] = world.particles.as_slice() else {
        panic!("{file}: want two discs, have {}", world.particles.len());
    };
    assert_eq!(a.pos.y, b.pos.y, "{file}: discs not on one line");
    assert_eq!(
        (a.vel.y, b.vel.y),
        (0.0, 0.0),
        "{file}: motion off the line"
    );
    let closing = (b.pos.x - a.pos.x) * (a.vel.x - b.vel.x);
    assert!(closing > 0.0, "{file}: the discs do not approach");
    [(a.mass, a.vel.x), (b.mass, b.vel.x)]
}

/// Checks a head-on preset's first collision against the 1D formula with
/// the scene's restitution; returns the velocities before and after.
fn check_head_on(file: &str) -> ([(f64, f64); 2], [f64; 2]) {
    let (mut world, dt) = exact(file);
    let before = head_on_pair(&world, file);
    let [(m1, v1), (m2, v2)] = before;
    through_the_first_collision(&mut world, dt, file);
    let (want1, want2) = head_on(m1, v1, m2, v2, world.laws.restitution);
    let tol = 1e-9 * v1.abs().max(v2.abs());
    let [a, b] = [world.particles[0].vel, world.particles[1].vel];
    assert_close(a.x, want1, tol, &format!("{file}: first disc's velocity"));
    assert_close(b.x, want2, tol, &format!("{file}: second disc's velocity"));
    assert_eq!((a.y, b.y), (0.0, 0.0), "{file}: sideways motion");
    (before, [a.x, b.x])
}

#[test]
fn every_preset_parses_builds_and_has_a_short_name_and_a_one_line_description() {
    let paths = preset_paths();
    assert!(paths.len() >= 11, "keys 0–9 and the empty box at least");
    for path in &paths {
        let file = path.display();
        let scene = Scene::load(path).unwrap_or_else(|e| panic!("{e}"));
        let world = scene
            .build(&file.to_string())
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(world.laws.size.min_element() > 0.0, "{file}: empty box");
        let name = scene.name.as_deref().unwrap_or("");
        assert!(!name.trim().is_empty(), "{file}: no name");
        assert!(
            !name.contains('\n') && name.chars().count() <= 40,
            "{file}: name {name:?} is not a short title"
        );
        let description = scene.description.as_deref().unwrap_or("");
        assert!(!description.trim().is_empty(), "{file}: no description");
        assert!(
            !description.contains('\n'),
            "{file}: description is not one line"
        );
        let chars = description.chars().count();
        assert!(
            chars <= MAX_DESCRIPTION_CHARS,
            "{file}: description has {chars} characters, more than {MAX_DESCRIPTION_CHARS} fit on screen"
        );
    }
}

#[test]
fn every_digit_key_has_exactly_one_preset_and_there_is_an_empty_box() {
    let names: Vec<String> = preset_paths()
        .iter()
        .filter_map(|p| p.file_name()?.to_str().map(String::from))
        .collect();
    for digit in 0..=9 {
        let prefix = format!("preset-{digit}-");
        let count = names.iter().filter(|n| n.starts_with(&prefix)).count();
        assert_eq!(count, 1, "key {digit}: {count} presets in {names:?}");
    }
    let (_, empty) = load("preset-empty.toml");
    assert!(empty.particles.is_empty(), "the empty box has discs");
    assert_eq!(empty.laws.gravity, DVec2::ZERO, "the empty box has gravity");
    assert_eq!(
        (empty.laws.restitution, empty.laws.wall_restitution),
        (1.0, 1.0)
    );
    let (_, default) = load("default.toml");
    assert_eq!(
        empty.laws.size, default.laws.size,
        "not the default scene's box"
    );
}

#[test]
fn every_listed_disc_colour_is_from_the_okabe_ito_palette() {
    let palette: Vec<Color> = (0..7).map(Color::palette).collect();
    for path in preset_paths() {
        let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        for (k, p) in scene.particles.iter().enumerate() {
            let color = p.color.expect("presets give every disc a colour");
            assert!(
                palette.contains(&color),
                "{}: particles[{k}] has {color}, not an Okabe–Ito colour",
                path.display()
            );
        }
    }
}

#[test]
fn head_on_equal_masses_exchange_velocities() {
    let file = "preset-1-head-on.toml";
    let ([(m1, v1), (m2, v2)], [after1, after2]) = check_head_on(file);
    assert_eq!(m1, m2, "{file}: masses differ");
    let tol = 1e-9 * v1.abs().max(v2.abs());
    assert_close(
        after1,
        v2,
        tol,
        "first disc leaves with the second's velocity",
    );
    assert_close(
        after2,
        v1,
        tol,
        "second disc leaves with the first's velocity",
    );
}

#[test]
fn heavy_hits_light_matches_the_1d_elastic_formulas() {
    let file = "preset-2-heavy-hits-light.toml";
    let (_, world) = load(file);
    let [heavy, light] = world.particles.as_slice() else {
        panic!("{file}: want two discs");
    };
    assert_close(heavy.mass / light.mass, 10.0, 1e-12, "mass ratio (10×)");
    assert!(heavy.radius > light.radius, "the heavy disc looks bigger");
    assert!(
        heavy.vel.x != 0.0 && light.vel == DVec2::ZERO,
        "light at rest"
    );
    assert_eq!(world.laws.restitution, 1.0, "{file}: not elastic");
    let ([(m1, v1), (m2, _)], [after1, after2]) = check_head_on(file);
    // The advertised outcome: the heavy one keeps going, slower; the light
    // one leaves faster than the heavy one came (2m₁/(m₁ + m₂) > 1).
    assert!(after1 * v1 > 0.0 && after1.abs() < v1.abs(), "heavy slows");
    assert_close(after2, 2.0 * m1 / (m1 + m2) * v1, 1e-9 * v1.abs(), "light");
    assert!(
        m2 < m1 && after2.abs() > v1.abs(),
        "light faster than heavy was"
    );
}

#[test]
fn light_hits_heavy_matches_the_1d_elastic_formulas() {
    let file = "preset-3-light-hits-heavy.toml";
    let (_, world) = load(file);
    let [light, heavy] = world.particles.as_slice() else {
        panic!("{file}: want two discs");
    };
    assert_close(heavy.mass / light.mass, 10.0, 1e-12, "mass ratio (10×)");
    assert!(heavy.radius > light.radius, "the heavy disc looks bigger");
    assert!(
        light.vel.x != 0.0 && heavy.vel == DVec2::ZERO,
        "heavy at rest"
    );
    assert_eq!(world.laws.restitution, 1.0, "{file}: not elastic");
    let ([(m1, v1), (m2, _)], [after1, after2]) = check_head_on(file);
    // The advertised outcome: the light one bounces back, the heavy one
    // moves on slowly in the light one's original direction.
    assert_close(after1, (m1 - m2) / (m1 + m2) * v1, 1e-9 * v1.abs(), "light");
    assert!(after1 * v1 < 0.0, "the light disc bounces back");
    assert!(
        after2 * v1 > 0.0 && after2.abs() < v1.abs(),
        "heavy creeps on"
    );
}

#[test]
fn glancing_equal_masses_leave_at_right_angles() {
    let file = "preset-4-glancing.toml";
    let (mut world, dt) = exact(file);
    let [a, b] = world.particles.as_slice() else {
        panic!("{file}: want two discs");
    };
    assert_eq!(a.mass, b.mass, "{file}: masses differ");
    assert_eq!(world.laws.restitution, 1.0, "{file}: not elastic");
    assert!(
        a.vel == DVec2::ZERO || b.vel == DVec2::ZERO,
        "{file}: the 90° rule needs a target at rest"
    );
    // Impact parameter: the distance between the centres across the
    // relative motion, about half the sum of the radii.
    let relative = b.vel - a.vel;
    let offset = b.pos - a.pos;
    let impact = offset.perp_dot(relative).abs() / relative.length();
    let fraction = impact / (a.radius + b.radius);
    assert!(
        (0.4..=0.6).contains(&fraction),
        "{file}: impact parameter {fraction:.3} of the sum of radii, want about ½"
    );
    let speed_sq = relative.length_squared();
    through_the_first_collision(&mut world, dt, file);
    let [a, b] = [world.particles[0].vel, world.particles[1].vel];
    // Both really move (a head-on hit would give 90° trivially, with one
    // disc at rest), and their directions are perpendicular.
    for v in [a, b] {
        assert!(
            v.length_squared() > 0.1 * speed_sq,
            "{file}: a disc stopped"
        );
    }
    assert_close(a.dot(b) / speed_sq, 0.0, 1e-9, "v₁′·v₂′ / v₀²");
    assert_close(
        a.length_squared() + b.length_squared(),
        speed_sq,
        1e-9 * speed_sq,
        "speeds² add up to the arrival speed² (energy)",
    );
}

#[test]
fn perfectly_inelastic_pair_moves_on_together_at_the_momentum_conserving_speed() {
    let file = "preset-5-inelastic.toml";
    let (mut world, dt) = exact(file);
    assert_eq!(world.laws.restitution, 0.0, "{file}: restitution is not 0");
    let [(m1, v1), (m2, v2)] = head_on_pair(&world, file);
    assert_eq!(m1, m2, "{file}: masses differ");
    let energy_before = kinetic_energy(&world);
    through_the_first_collision(&mut world, dt, file);
    let together = (m1 * v1 + m2 * v2) / (m1 + m2);
    let tol = 1e-9 * v1.abs().max(v2.abs());
    for p in &world.particles {
        assert_close(p.vel.x, together, tol, "common velocity");
        assert_eq!(p.vel.y, 0.0, "{file}: sideways motion");
    }
    // The energy lost is the relative motion's, ½·μ·(v₁ − v₂)² with
    // μ = m₁m₂/(m₁ + m₂): for equal masses, from one at rest, half of it.
    let lost = 0.5 * m1 * m2 / (m1 + m2) * (v1 - v2).powi(2);
    assert_close(
        kinetic_energy(&world),
        energy_before - lost,
        1e-9 * energy_before,
        "kinetic energy after",
    );
    // And they stay together until the wall: a second later, unchanged.
    step_until(&mut world, dt, 1.0, |_| false);
    assert_eq!(world.total_wall_hits, 0, "{file}: wall hit within 1 s");
    for p in &world.particles {
        assert_close(p.vel.x, together, tol, "still together 1 s later");
    }
}

#[test]
fn cradle_last_disc_leaves_at_the_arrival_speed_and_the_others_stay() {
    let file = "preset-6-cradle.toml";
    let (mut world, dt) = exact(file);
    assert_eq!(world.laws.restitution, 1.0, "{file}: not elastic");
    let moving: Vec<usize> = (0..world.particles.len())
        .filter(|&k| world.particles[k].vel != DVec2::ZERO)
        .collect();
    let [arriving] = moving[..] else {
        panic!("{file}: want one arriving disc, have {}", moving.len());
    };
    let v0 = world.particles[arriving].vel;
    let along = v0.normalize();
    let first = &world.particles[arriving];
    // The row: five equal discs at rest on the arriving disc's line,
    // touching (or no more than a micrometre apart).
    let mut row: Vec<usize> = (0..world.particles.len())
        .filter(|&k| k != arriving)
        .collect();
    assert_eq!(row.len(), 5, "{file}: want a row of five");
    row.sort_by(|&i, &j| {
        let (pi, pj) = (world.particles[i].pos, world.particles[j].pos);
        along.dot(pi).total_cmp(&along.dot(pj))
    });
    for pair in row.windows(2) {
        let (p, q) = (&world.particles[pair[0]], &world.particles[pair[1]]);
        assert_eq!((p.mass, p.radius), (first.mass, first.radius), "unequal");
        let gap = (q.pos - p.pos).length() - p.radius - q.radius;
        assert!((0.0..=1e-6).contains(&gap), "{file}: row gap {gap:e} m");
        let off_line = (q.pos - first.pos).perp_dot(along).abs();
        assert!(off_line <= 1e-12, "{file}: row off the line");
    }
    let last = *row.last().expect("a row");
    through_the_first_collision(&mut world, dt, file);
    // Let the pulse run through the row (instantly for touching discs);
    // the last disc is still well short of the wall half a second later.
    step_until(&mut world, dt, 0.5, |_| false);
    assert_eq!(world.total_wall_hits, 0, "{file}: wall hit too soon");
    let tol = 1e-9 * v0.length();
    for (k, p) in world.particles.iter().enumerate() {
        let want = if k == last { v0 } else { DVec2::ZERO };
        assert!(
            (p.vel - want).length() <= tol,
            "{file}: disc {k} moves at {} m/s, want {want}",
            p.vel
        );
    }
}

#[test]
fn pi_blocks_count_31_collisions_for_a_mass_ratio_of_100() {
    let file = "preset-7-pi-blocks.toml";
    let (mut world, dt) = exact(file);
    let [light, heavy] = world.particles.as_slice() else {
        panic!("{file}: want the light disc, then the heavy one");
    };
    assert_eq!(light.pos.y, heavy.pos.y, "{file}: not on one line");
    assert!(light.pos.x < heavy.pos.x, "light between wall and heavy");
    assert!(light.vel == DVec2::ZERO && heavy.vel.x < 0.0 && heavy.vel.y == 0.0);
    assert_eq!(
        (world.laws.restitution, world.laws.wall_restitution),
        (1.0, 1.0)
    );
    let ratio = heavy.mass / light.mass;
    assert_close(ratio, 100.0, 1e-12, "mass ratio");
    // Mass ratio 100^k counts ⌊π·10^k⌋ = ⌊π·√ratio⌋ collisions.
    let expected = (std::f64::consts::PI * ratio.sqrt()).floor() as u64;
    assert_eq!(expected, 31);
    // Done once the heavy disc moves away at least as fast as the light one
    // can ever follow; a light disc still heading for the wall then has
    // exactly one collision left, with the wall.
    let mut count = None;
    let finished = step_until(&mut world, dt, 60.0, |w| {
        let (light, heavy) = (w.particles[0].vel.x, w.particles[1].vel.x);
        let done = heavy > 0.0 && light.abs() <= heavy;
        if done {
            count = Some(w.total_pair_collisions + w.total_wall_hits + u64::from(light < 0.0));
        }
        done
    });
    assert!(finished, "{file}: the heavy disc never got away in 60 s");
    assert_eq!(count, Some(expected), "{file}: pair + wall collisions");
}

#[test]
fn billiards_break_keeps_momentum_until_the_first_cushion_and_energy_between_balls() {
    let file = "preset-9-billiards.toml";
    let (mut world, dt) = exact(file);
    assert_eq!(world.particles.len(), 16, "{file}: cue ball and 15 balls");
    assert_eq!(world.laws.gravity, DVec2::ZERO, "{file}: gravity");
    assert_eq!(world.laws.restitution, 1.0, "{file}: balls not elastic");
    assert_close(
        world.laws.wall_restitution,
        0.9,
        0.05,
        "cushion restitution",
    );
    let first = world.particles[0];
    for p in &world.particles {
        assert_eq!((p.mass, p.radius), (first.mass, first.radius), "unequal");
    }
    let p0 = world.metrics().momentum;
    let mut energy = kinetic_energy(&world);
    let mut walls = 0;
    let mut clean_steps = 0;
    // Three seconds: the break, and about a dozen cushion hits after it.
    for _ in 0..(3.0 / dt) as u64 {
        world.step(dt);
        let now = kinetic_energy(&world);
        if world.total_wall_hits == walls {
            // Only ball–ball collisions (e = 1) in this step: energy kept.
            assert_close(now, energy, 1e-9 * energy, "energy between balls");
        } else {
            // A cushion (e < 1) can only take energy.
            assert!(now <= energy * (1.0 + 1e-12), "a cushion gave energy");
        }
        if world.total_wall_hits == 0 {
            let p = world.metrics().momentum;
            assert!(
                (p - p0).length() <= 1e-9 * p0.length(),
                "momentum before the first cushion: {p} against {p0}"
            );
            clean_steps += 1;
        }
        walls = world.total_wall_hits;
        energy = now;
    }
    assert!(walls > 0, "{file}: no ball reached a cushion in 3 s");
    assert!(clean_steps > 0, "{file}: a cushion was hit at once");
    assert!(
        world.total_pair_collisions >= 15,
        "{file}: the rack was hardly touched ({} collisions)",
        world.total_pair_collisions
    );
}

/// The Kolmogorov–Smirnov distance between the discs' speeds and the 2D
/// Maxwell–Boltzmann (Rayleigh) law with ⟨v²⟩ = s²: F(v) = 1 − e^(−v²/s²).
fn rayleigh_distance(world: &World, s: f64) -> f64 {
    let mut speeds: Vec<f64> = world.particles.iter().map(|p| p.vel.length()).collect();
    speeds.sort_by(f64::total_cmp);
    let n = speeds.len() as f64;
    speeds
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let f = 1.0 - (-(v * v) / (s * s)).exp();
            (f - i as f64 / n).abs().max((i as f64 + 1.0) / n - f)
        })
        .fold(0.0, f64::max)
}

#[test]
fn gas_keeps_its_energy_and_spreads_from_one_speed_towards_maxwell_boltzmann() {
    let file = "preset-8-gas.toml";
    let (mut world, dt) = exact(file);
    let n = world.particles.len();
    assert!(
        (150..=250).contains(&n),
        "{file}: {n} discs, want about 200"
    );
    assert_eq!(
        (world.laws.restitution, world.laws.wall_restitution),
        (1.0, 1.0)
    );
    let first = world.particles[0];
    let speed = first.vel.length();
    for p in &world.particles {
        assert_eq!((p.mass, p.radius), (first.mass, first.radius), "unequal");
        assert_close(p.vel.length(), speed, 1e-12 * speed, "starting speed");
    }
    let energy = kinetic_energy(&world);
    // Box walls reverse momentum, so only the energy is conserved.
    step_until(&mut world, dt, 3.0, |_| false);
    assert_close(kinetic_energy(&world), energy, 1e-9 * energy, "energy");
    assert!(
        world.total_pair_collisions as usize >= n,
        "{file}: too few collisions to spread the speeds"
    );
    // The speeds have relaxed from the single spike to the 2D
    // Maxwell–Boltzmann (Rayleigh) law with the same ⟨v²⟩ = s²: the
    // Kolmogorov–Smirnov distance passes at the 1 % level, D < 1.63/√n
    // (0.115 for 200 discs). The spike is 1 − e⁻¹ ≈ 0.63 away from it.
    let distance = rayleigh_distance(&world, speed);
    let critical = 1.63 / (n as f64).sqrt();
    assert!(
        distance < critical,
        "{file}: speeds {distance:.3} from the Rayleigh law after 3 s (1 % critical value \
         {critical:.3})"
    );
    for p in &world.particles {
        let r = DVec2::splat(p.radius);
        assert!(
            p.pos.cmpge(r).all() && p.pos.cmple(world.laws.size - r).all(),
            "{file}: a disc left the box: {}",
            p.pos
        );
    }
}

#[test]
fn pile_settles_inside_the_box_under_auto_within_six_seconds() {
    let file = "preset-0-pile.toml";
    let (scene, mut world) = load(file);
    let dt = scene.simulation.dt.unwrap_or(WINDOW_DT);
    let g = world.laws.gravity.length();
    assert!(g > 0.0, "{file}: no gravity");
    assert!(
        world.laws.restitution < 1.0,
        "{file}: elastic discs never settle"
    );
    // Potential energy the discs can give up: each disc's bottom above the
    // floor, m·g·(y − r).
    let potential: f64 = world
        .particles
        .iter()
        .map(|p| p.mass * g * (p.pos.y - p.radius))
        .sum();
    // By the geometric series of its bounces a disc dropped from the top
    // on the floor (e < 1) would be at rest after √(2h/g) + 2e·v₀/(g(1 − e))
    // (≈ 4.2 s here); landing on others it rests sooner. Six seconds is
    // past that: no disc is still bouncing, and what moves is frictionless
    // discs settling into gaps, one at a time, each with at most the energy
    // of dropping by its own diameter, m·g·2r.
    let top = world
        .particles
        .iter()
        .map(|p| p.pos.y - p.radius)
        .fold(0.0, f64::max);
    let e = world.laws.restitution.max(world.laws.wall_restitution);
    let v0 = (2.0 * g * top).sqrt();
    let series = (2.0 * top / g).sqrt() + 2.0 * e * v0 / (g * (1.0 - e));
    assert!(series < 6.0, "{file}: bounces for {series:.2} s");
    let settling = world
        .particles
        .iter()
        .map(|p| p.mass * g * 2.0 * p.radius)
        .fold(0.0, f64::max);
    step_until(&mut world, dt, 6.0, |_| false);
    let tol = 1e-6;
    for (k, p) in world.particles.iter().enumerate() {
        let r = DVec2::splat(p.radius - tol * p.radius);
        assert!(
            p.pos.cmpge(r).all() && p.pos.cmple(world.laws.size - r).all(),
            "{file}: disc {k} outside the box at {}",
            p.pos
        );
    }
    let kinetic = kinetic_energy(&world);
    assert!(
        kinetic < settling,
        "{file}: still moving after 6 s: KE {kinetic:.3} J, more than one disc settling \
         into a gap ({settling:.2} J; {potential:.1} J of height at the start)"
    );
}
