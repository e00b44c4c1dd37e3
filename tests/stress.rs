//! The stability suite (quick size) under every method, checked against
//! each scenario's criterion rather than against a table of past results:
//!
//! - every method passes the scenarios its documentation promises (the
//!   "where it fails" column of `impulse::method`): `auto` all of them,
//!   `exact` all but the resting piles it stalls on, `impulse` all but the
//!   simultaneous three-disc hit and the π count beyond what a fixed step
//!   resolves; `seed` and `verlet` promise only what their rows allow;
//! - in every cell the verdict agrees with the scenario's threshold on its
//!   figure: a pass never carries a figure beyond it;
//! - a documented limit is asserted where physics predicts it: the seed's
//!   single step is longer than the bullet's target, so it must tunnel.

use impulse::method::{Method, Setting};
use impulse::stress::{scenarios, Outcome, Scenario, Size, METHODS};
use impulse::Scene;

const SEED: Setting<Method> = Setting::Fixed(Method::Seed);
const IMPULSE: Setting<Method> = Setting::Fixed(Method::Impulse);
const VERLET: Setting<Method> = Setting::Fixed(Method::Verlet);
const EXACT: Setting<Method> = Setting::Fixed(Method::Exact);
const AUTO: Setting<Method> = Setting::Auto;

fn scenario(key: &str) -> Scenario {
    scenarios()
        .into_iter()
        .find(|s| s.key == key)
        .unwrap_or_else(|| panic!("no scenario {key}"))
}

/// Runs scenario `key` under every method, checks that the `promised`
/// methods pass and that every verdict agrees with `threshold` (whether
/// the figure meets the criterion's number, where the figure alone can
/// say), and returns the outcomes.
fn check(
    key: &str,
    promised: &[Setting<Method>],
    threshold: impl Fn(f64) -> bool,
) -> Vec<(Setting<Method>, Outcome)> {
    let s = scenario(key);
    let outcomes: Vec<_> = METHODS
        .iter()
        .map(|&m| (m, s.run(m, Size::Quick)))
        .collect();
    let mut wrong = Vec::new();
    for (method, o) in &outcomes {
        if promised.contains(method) && !o.pass {
            wrong.push(format!(
                "{key} under {method} is promised but failed: {}",
                o.summary
            ));
        }
        if o.pass && !threshold(o.figure) {
            wrong.push(format!(
                "{key} under {method} passed with a figure beyond the criterion ({}): {}",
                s.criterion, o.summary
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    outcomes
}

fn at(outcomes: &[(Setting<Method>, Outcome)], method: Setting<Method>) -> &Outcome {
    &outcomes
        .iter()
        .find(|(m, _)| *m == method)
        .expect("a suite method")
        .1
}

#[test]
fn every_scenario_has_a_scene_file_that_loads() {
    for s in scenarios() {
        let from_disk = std::fs::read_to_string(s.scene_path).expect(s.scene_path);
        assert_eq!(
            from_disk, s.scene,
            "{} is compiled in as it is on disk",
            s.scene_path
        );
        let scene = Scene::parse(s.scene, s.scene_path).expect("parses");
        scene.build(s.scene_path).expect("builds");
    }
}

#[test]
fn bullet() {
    let o = check("bullet", &[IMPULSE, VERLET, EXACT, AUTO], |tunnellings| {
        tunnellings == 0.0
    });
    // The seed takes one step per frame whatever the speed: when a step
    // carries the bullet further than the target's diameter plus its own,
    // no step ever sees them overlap.
    let s = scenario("bullet");
    let scene = Scene::parse(s.scene, s.scene_path).unwrap();
    let (bullet, target) = (&scene.particles[0], &scene.particles[1]);
    let travel = bullet.vel.length() * scene.step_for(None);
    if travel > 2.0 * (bullet.radius + target.radius) {
        let seed = at(&o, SEED);
        assert!(
            !seed.pass && seed.summary.contains("disc tunnelled"),
            "{}",
            seed.summary
        );
    }
}

#[test]
fn pi_blocks() {
    // The criterion: ⌊π·10^k⌋ collisions up to mass ratio 100⁴ = 10⁸.
    let o = check("pi-blocks", &[EXACT, AUTO], |ratio| ratio >= 1e8);
    // The figure is a mass ratio the scenario tries: 100^k.
    for (method, outcome) in &o {
        if outcome.figure.is_finite() {
            let k = outcome.figure.log(100.0);
            assert!(
                (k - k.round()).abs() < 1e-9 && (0.0..=4.0).contains(&k),
                "{method}: {}",
                outcome.figure
            );
        }
    }
}

#[test]
fn cradle() {
    check("cradle", &[SEED, IMPULSE, EXACT, AUTO], |error| {
        error <= 1e-6
    });
}

#[test]
fn pile() {
    check("pile", &[IMPULSE, AUTO], |overlap| overlap < 0.05);
}

#[test]
fn collapse() {
    // Its figure is the most work in a frame: contacts times substeps, or
    // events, per disc. A disc of radius r touches at most six others of
    // radius r (the kissing number in the plane), so a substep holds at most
    // 3 contacts per disc (each shared by two). The substeps are auto's:
    // enough to keep the fastest disc within r/2 a substep. Energy never
    // rises (the scenario's criterion), so no disc is ever faster than
    // √(2·KE₀/m) = √N·v₀ (all the gas's energy in one disc): with N = 300,
    // v₀ = 1 m/s, r = 0.3 m and frames of 1/60 s that is
    // ⌈√300·(1/60)/0.15⌉ = 2 substeps, so at most 6 per disc a frame. An
    // event-driven method that passes must stay within the same bound:
    // more events than that in a frame is the inelastic collapse (discs
    // meeting the same neighbours over and over) the scenario is about.
    let s = scenario("collapse");
    let scene = Scene::parse(s.scene, s.scene_path).unwrap();
    let n = scene.particles.len() + scene.fill.as_ref().map_or(0, |f| f.count);
    let fill = scene.fill.as_ref().expect("a filled gas");
    let (v0, r) = (fill.speed[1], fill.radius[0]);
    let fastest = (n as f64).sqrt() * v0;
    let frame = 1.0 / 60.0; // the scenario's frame
    let substeps = (fastest * frame / (0.5 * r)).ceil();
    let most = 3.0 * substeps;
    eprintln!("collapse: at most {most} per disc a frame");
    check("collapse", &[SEED, IMPULSE, EXACT, AUTO], |work| {
        work <= most
    });
}

#[test]
fn mass_ratio() {
    // The heavy discs resting on light ones sink less than a tenth of a
    // radius.
    check("mass-ratio", &[IMPULSE, AUTO], |sink| sink < 0.1);
}

#[test]
fn dense_start() {
    check("dense-start", &[SEED, IMPULSE, EXACT, AUTO], |injected| {
        injected < 1e-12
    });
}

#[test]
fn long_run() {
    check("long-run", &[SEED, IMPULSE, EXACT, AUTO], |drift| {
        drift < 1e-9
    });
}

#[test]
fn symmetry() {
    check("symmetry", &[VERLET, EXACT, AUTO], |error| error <= 1e-9);
}

#[test]
fn degenerate() {
    check("degenerate", &METHODS, |failed| failed == 0.0);
}

#[test]
fn relaxation() {
    let s = scenario("relaxation");
    let scene = Scene::parse(s.scene, s.scene_path).unwrap();
    let n = scene.particles.len() + scene.fill.as_ref().map_or(0, |f| f.count);
    // Kolmogorov–Smirnov at the 1 % level.
    let critical = 1.63 / (n as f64).sqrt();
    check("relaxation", &METHODS, |distance| distance < critical);
}

#[test]
fn rough() {
    // Every method gives rough discs their tangential impulse; verlet's
    // projection loses most of the energy at any β, as in the long run.
    check("rough", &[SEED, IMPULSE, EXACT, AUTO], |off| off < 0.03);
}
