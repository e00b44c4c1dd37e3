//! The stability suite: where each method fails, measured.
//!
//! Twelve scenarios, each a scene file in `assets/scenes/stress-*.toml` (so
//! it can be watched in the window) and a function here that runs it under a
//! method and measures one figure against a pass criterion written next to
//! it. `impulse stress` prints the table and chart; `tests/stress.rs` asserts
//! what each method must achieve, so a regression either way is noticed.
//!
//! Every method runs with `auto` substeps and broad phase, as the sandbox
//! does, so the cures `auto` applies (more substeps for fast discs) count.

use crate::method::{Method, Setting};
use crate::scene::Scene;
use crate::{Boundary, StepStats, World};
use std::panic::{catch_unwind, AssertUnwindSafe};

mod ensembles;
mod one_shot;

/// The methods every scenario runs under, in table order.
pub const METHODS: [Setting<Method>; 5] = [
    Setting::Fixed(Method::Seed),
    Setting::Fixed(Method::Impulse),
    Setting::Fixed(Method::Verlet),
    Setting::Fixed(Method::Exact),
    Setting::Auto,
];

/// How long the runs are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    /// Short runs for `cargo test` and `--quick` (seconds in all).
    Quick,
    /// The runs the issue asks for (minutes in all).
    Full,
}

/// What one run measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// The scenario's figure (its unit is in [`Scenario::figure`]).
    pub figure: f64,
    /// The figure and what else was seen, in words.
    pub summary: String,
    /// Whether the pass criterion held.
    pub pass: bool,
}

impl Outcome {
    fn failed(summary: String) -> Outcome {
        Outcome {
            figure: f64::NAN,
            summary,
            pass: false,
        }
    }
}

/// A scenario of the suite.
pub struct Scenario {
    /// Short name, used in file names and the CSV.
    pub key: &'static str,
    /// Title for the table.
    pub title: &'static str,
    /// The title of the quick runs, where they differ from the full ones.
    pub quick_title: Option<&'static str>,
    /// What the figure measures, with its unit.
    pub figure: &'static str,
    /// The pass criterion, in words.
    pub criterion: &'static str,
    /// The criterion's threshold on the figure, short (for a table row).
    pub threshold: &'static str,
    /// The scene file it starts from, relative to the repository.
    pub scene_path: &'static str,
    /// The scene file's text (compiled in).
    pub scene: &'static str,
    run: fn(Setting<Method>, Size) -> Result<Outcome, String>,
}

impl Scenario {
    /// The title of the runs of `size`.
    pub fn title_for(&self, size: Size) -> &'static str {
        match (size, self.quick_title) {
            (Size::Quick, Some(title)) => title,
            _ => self.title,
        }
    }

    /// Runs the scenario under `method`. A panic or an error is a failed
    /// outcome that says what happened, never a crash of the suite.
    pub fn run(&self, method: Setting<Method>, size: Size) -> Outcome {
        match catch_unwind(AssertUnwindSafe(|| (self.run)(method, size))) {
            Ok(Ok(outcome)) => outcome,
            Ok(Err(message)) => Outcome::failed(message),
            Err(panic) => {
                let what = panic
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| panic.downcast_ref::<String>().cloned())
                    .unwrap_or_default();
                Outcome::failed(format!("panicked: {what}"))
            }
        }
    }
}

/// The scenarios, in the order.
pub fn scenarios() -> Vec<Scenario> {
    vec![
        one_shot::BULLET,
        one_shot::PI_BLOCKS,
        one_shot::CRADLE,
        ensembles::PILE,
        ensembles::COLLAPSE,
        one_shot::MASS_RATIO,
        ensembles::DENSE_START,
        ensembles::LONG_RUN,
        one_shot::SYMMETRY,
        one_shot::DEGENERATE,
        ensembles::RELAXATION,
        ensembles::ROUGH,
    ]
}

/// A scenario's world under `method`, with `auto` substeps and broad phase.
fn load(text: &str, origin: &str, method: Setting<Method>) -> Result<World, String> {
    let scene = Scene::parse(text, origin).map_err(|e| e.to_string())?;
    let mut world = scene.build(origin).map_err(|e| e.to_string())?;
    world.method = method;
    world.substeps = Setting::Auto;
    world.broad_phase = Setting::Auto;
    Ok(world)
}

/// The time step a scene file asks for, or the default.
fn scene_dt(text: &str, origin: &str) -> f64 {
    Scene::parse(text, origin).map_or(crate::scene::DEFAULT_DT, |s| s.step_for(None))
}

/// A step that hit the event cap: the method stalled.
#[derive(Debug)]
struct Stalled {
    at: f64,
}

impl Stalled {
    fn outcome(&self) -> Outcome {
        Outcome::failed(format!(
            "stalls: the event cap ended a step early at t = {:.3} s",
            self.at
        ))
    }
}

/// Steps `world` for `duration` at `dt`, calling `each` after every step.
fn run_for(
    world: &mut World,
    dt: f64,
    duration: f64,
    mut each: impl FnMut(&World, &StepStats),
) -> Result<(), Stalled> {
    let steps = (duration / dt).round() as u64;
    for _ in 0..steps {
        let stats = world.step(dt);
        if stats.truncated {
            return Err(Stalled { at: world.time });
        }
        each(world, &stats);
    }
    Ok(())
}

/// Every disc finite and (in a box) inside it, to `slack` metres.
fn finite_and_inside(world: &World, slack: f64) -> bool {
    world.particles.iter().all(|p| {
        let finite = p.pos.is_finite() && p.vel.is_finite();
        let inside = world.laws.boundary != Boundary::Box
            || (p.pos.x >= p.radius - slack
                && p.pos.x <= world.laws.size.x - p.radius + slack
                && p.pos.y >= p.radius - slack
                && p.pos.y <= world.laws.size.y - p.radius + slack);
        finite && inside
    })
}

/// The deepest overlap between any two discs, as a fraction of the smaller
/// radius (brute force: the suite's scenes are small).
fn max_relative_overlap(world: &World) -> f64 {
    let ps = &world.particles;
    let mut worst = 0.0f64;
    for i in 0..ps.len() {
        for j in i + 1..ps.len() {
            let d = world
                .laws
                .boundary
                .separation(ps[i].pos, ps[j].pos, world.laws.size)
                .length();
            let depth = ps[i].radius + ps[j].radius - d;
            if depth > 0.0 {
                worst = worst.max(depth / ps[i].radius.min(ps[j].radius));
            }
        }
    }
    worst
}
