//! The warnings say what the method cannot promise, when it applies and
//! only then, and what they say is true of the physics.

use impulse::method::{Method, Setting};
use impulse::warnings::{self, warnings, Warning};
use impulse::{Color, DVec2, Particle, Scene, World};

const DT: f64 = impulse::scene::DEFAULT_DT;

fn preset(file: &str) -> World {
    let path = format!("{}/assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
    Scene::load(std::path::Path::new(&path))
        .and_then(|s| s.build(&path))
        .unwrap()
}

fn codes(w: &[Warning]) -> Vec<&'static str> {
    w.iter().map(|w| w.code).collect()
}

fn run(world: &mut World, seconds: f64) {
    for _ in 0..(seconds / DT).round() as usize {
        world.step(DT);
    }
}

#[test]
fn verlet_is_named_while_it_runs_and_it_does_lose_the_energy_it_warns_of() {
    for method in [Method::Impulse, Method::Exact, Method::Verlet] {
        let mut w = preset("preset-1-head-on.toml");
        w.method = Setting::Fixed(method);
        let before = w.metrics().kinetic_energy;
        run(&mut w, 4.0); // past the collision at 2.4 s
        let lost = 1.0 - w.metrics().kinetic_energy / before;
        let said = codes(&warnings(&w, DT));
        if method == Method::Verlet {
            assert_eq!(said, [warnings::VERLET]);
            assert!(
                lost > 0.1,
                "verlet lost {lost:.3} of the energy: the warning would lie"
            );
            assert!(warnings(&w, DT)[0].text.contains("e = 1"));
        } else {
            assert!(said.is_empty(), "{method:?}: {said:?}");
            assert!(lost.abs() < 1e-9, "{method:?} lost {lost}");
        }
    }
}

#[test]
fn seed_is_named_and_a_lone_disc_needs_no_warning() {
    let mut w = preset("preset-1-head-on.toml");
    w.method = Setting::Fixed(Method::Seed);
    assert_eq!(codes(&warnings(&w, DT)), [warnings::SEED]);
    w.particles.truncate(1);
    assert!(warnings(&w, DT).is_empty());
}

#[test]
fn a_fixed_substep_count_is_named_exactly_when_a_disc_outruns_its_radius() {
    let mut w = preset("preset-1-head-on.toml");
    w.method = Setting::Fixed(Method::Impulse);
    w.substeps = Setting::Fixed(1);
    // radius 0.6 m, dt 1/240 s: the limit is 144 m/s.
    let radius = w.particles[0].radius;
    for (speed, warned) in [(0.9 * radius / DT, false), (1.1 * radius / DT, true)] {
        w.particles[0].vel.x = speed;
        assert_eq!(
            codes(&warnings(&w, DT)).contains(&warnings::SUBSTEPS),
            warned,
            "{speed} m/s"
        );
    }
    // Two substeps halve the distance per substep: no warning at 1.1×.
    w.substeps = Setting::Fixed(2);
    assert!(warnings(&w, DT).is_empty());
    // auto picks its own substeps: no warning from this rule.
    w.substeps = Setting::Auto;
    w.particles[0].vel.x = 10.0 * radius / DT;
    assert!(!codes(&warnings(&w, DT)).contains(&warnings::SUBSTEPS));
}

#[test]
fn a_step_cut_short_is_named_from_the_steps_own_report() {
    // A disc at 10⁶ m/s in a 2 m box, one-second steps: about 10⁶ wall hits
    // a step, past exact's event cap.
    let mut w = World::new(DVec2::new(2.0, 2.0));
    w.method = Setting::Fixed(Method::Exact);
    w.particles = vec![Particle::new(
        DVec2::new(1.0, 1.0),
        DVec2::new(1e6, 0.3),
        1.0,
        0.5,
        Color::palette(0),
    )];
    let quiet = codes(&warnings(&w, 1.0)).contains(&warnings::STALL);
    assert!(!quiet, "nothing said before a step");
    let t = w.time;
    let stats = w.step(1.0);
    assert!(stats.truncated, "the event cap cut the step");
    assert!(w.time - t < 1.0, "a cut step advances less than dt");
    assert!(codes(&warnings(&w, 1.0)).contains(&warnings::STALL));
    // The pile that used to stall exact now settles, and nothing is said.
    let mut w = preset("preset-0-pile.toml");
    w.method = Setting::Fixed(Method::Exact);
    for _ in 0..(3.0 / DT) as usize {
        let stats = w.step(DT);
        let said = codes(&warnings(&w, DT)).contains(&warnings::STALL);
        assert!(
            !stats.truncated && !said,
            "exact on the pile cut short at {} s",
            w.time
        );
    }
}

#[test]
fn warnings_serialise_as_code_and_text() {
    let mut w = preset("preset-1-head-on.toml");
    w.method = Setting::Fixed(Method::Verlet);
    let json = serde_json::to_value(warnings(&w, DT)).unwrap();
    assert_eq!(json[0]["code"], "verlet_loses_energy");
    assert!(json[0]["text"].as_str().unwrap().starts_with("verlet"));
}

/// A disc far too fast for any fixed step (9×10⁷ m/s in a 1 m box, steps
/// of 0.5 s): `auto` does not pick a plan that misses its wall hits, and
/// `impulse`, asked for by name, says what it may miss, measured.
#[test]
fn a_bullet_is_never_stepped_in_silence() {
    let text = "[world]\nsize = [1.0, 1.0]\n\n[[particles]]\npos = [0.5, 0.5]\nvel = [9e7, 0.0]\nmass = 1.0\nradius = 0.1\n";
    let scene = impulse::Scene::parse(text, "bullet.toml").unwrap();
    let mut world = scene.build("bullet.toml").unwrap();
    world.method = impulse::method::Setting::Auto;
    world.substeps = impulse::method::Setting::Auto;
    let plan = world.plan_for(0.5);
    assert_eq!(
        plan.method,
        impulse::method::Method::Exact,
        "{}",
        plan.reason
    );
    world.method = impulse::method::Setting::Fixed(impulse::method::Method::Impulse);
    let said = impulse::warnings::warnings(&world, 0.5);
    let substeps = said
        .iter()
        .find(|w| w.code == impulse::warnings::SUBSTEPS)
        .unwrap_or_else(|| panic!("no substeps warning: {said:?}"));
    // The travel per substep it measured: 9e7 m/s × (0.5 s / 64) / 0.1 m.
    let radii = substeps
        .values
        .iter()
        .find(|(n, _)| *n == "radii")
        .unwrap()
        .1;
    let k = substeps
        .values
        .iter()
        .find(|(n, _)| *n == "substeps")
        .unwrap()
        .1;
    assert!(
        (radii - 9e7 * 0.5 / k / 0.1).abs() < 1e-6 * radii,
        "{radii} with {k}"
    );
}

/// The travel a warning quotes is measured by the steps that ran, not
/// guessed from the speeds at the end: a disc at 2 radii per substep that
/// a dead wall (restitution 0) stops is at rest when the run ends, yet the
/// run's warnings say it moved 2 radii in a substep (48 m/s × 1/240 s /
/// 0.1 m), and its last step, measured at rest, no longer warns the top bar.
#[test]
fn the_travel_a_warning_quotes_is_measured_over_the_run() {
    let mut w = World::new(DVec2::splat(10.0));
    w.laws.wall_restitution = 0.0;
    w.method = Setting::Fixed(Method::Impulse);
    w.substeps = Setting::Fixed(1);
    w.particles = vec![Particle::new(
        DVec2::new(5.0, 5.0),
        DVec2::new(48.0, 0.0),
        1.0,
        0.1,
        Color::palette(0),
    )];
    let mut travelled = 0.0f64;
    for _ in 0..120 {
        travelled = travelled.max(w.step(DT).max_travel);
    }
    assert_eq!(w.particles[0].vel, DVec2::ZERO, "stopped by the wall");
    assert!((travelled - 2.0).abs() < 1e-12, "measured {travelled}");
    let said = warnings::warnings_with_travel(&w, DT, Some(travelled));
    let substeps = said
        .iter()
        .find(|x| x.code == warnings::SUBSTEPS)
        .unwrap_or_else(|| panic!("the run's warnings: {said:?}"));
    assert!(substeps.text.contains("moved 2.0×"), "{}", substeps.text);
    assert!(
        !codes(&warnings(&w, DT)).contains(&warnings::SUBSTEPS),
        "the last step, at rest, moved nothing"
    );
}
