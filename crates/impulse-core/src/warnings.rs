//! What the chosen method cannot promise, said in plain words while it
//! applies: the window's top bar, its state dump and `run`'s JSON show the
//! same list. Each warning has a stable code (for scripts and tests) and a
//! text (for people).

use crate::method::{Method, Setting};
use crate::world::World;
use serde::Serialize;

/// One warning: a stable code and a sentence for the screen.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Warning {
    /// Stable identifier, e.g. `"verlet_loses_energy"`.
    pub code: &'static str,
    /// What it means for the experiment, in plain words.
    pub text: String,
    /// The numbers in the text, by name (`restitution`, `substeps`,
    /// `radii`), so that a window can say it in its own words.
    pub values: Vec<(&'static str, f64)>,
}

/// `verlet` is in use: its collisions are position corrections, so they
/// lose energy and ignore the restitution.
pub const VERLET: &str = "verlet_loses_energy";
/// `seed` is in use: one pass, no substeps, so fast discs can tunnel.
pub const SEED: &str = "seed_tunnels";
/// A fixed substep count lets a disc move more than its radius per substep.
pub const SUBSTEPS: &str = "substeps_too_few";
/// The last step was cut short: simulated time stopped advancing.
pub const STALL: &str = "step_cut_short";

/// The warnings that apply to `world` stepped at `dt` now: the method the
/// last step used (or would use), how far a disc moved in a substep of the
/// last step (measured; before the first step, from the speeds), and
/// whether the last step was cut short.
pub fn warnings(world: &World, dt: f64) -> Vec<Warning> {
    let measured = (world.steps > 0).then(|| world.last_stats().max_travel);
    warnings_with_travel(world, dt, measured)
}

/// [`warnings`] with the largest travel per substep (in radii) `measured`
/// over a whole run, as `run` reports it (`None`: nothing ran yet, so it
/// is judged from the speeds now).
pub fn warnings_with_travel(world: &World, dt: f64, measured: Option<f64>) -> Vec<Warning> {
    let mut out = Vec::new();
    let plan = world.plan().cloned().unwrap_or_else(|| world.plan_for(dt));
    // A method just switched to applies from the next step on.
    let method = match world.method {
        Setting::Fixed(m) => m,
        Setting::Auto => plan.method,
    };
    let several = world.particles.len() >= 2;
    match method {
        Method::Verlet if several => out.push(Warning {
            code: VERLET,
            text: format!(
                "verlet: collisions lose energy; the restitution e = {} is not honoured",
                trim(world.laws.restitution)
            ),
            values: vec![("restitution", world.laws.restitution)],
        }),
        Method::Seed if several => out.push(Warning {
            code: SEED,
            text: "seed: fast discs can pass through each other".into(),
            values: Vec::new(),
        }),
        _ => {}
    }
    // The substeps in use (fixed, or the plan's), against the discs'
    // speeds now: a disc that moves more than its radius in a substep can
    // pass through another (or a wall) unseen.
    let k = match (world.substeps, method) {
        (_, Method::Seed) => Some(1),
        (Setting::Fixed(k), Method::Impulse | Method::Verlet) => Some(k),
        (Setting::Auto, Method::Impulse | Method::Verlet) => Some(plan.substeps),
        _ => None,
    };
    if let Some(k) = k {
        let h = dt / f64::from(k.max(1));
        // Measured by the steps that ran with these substeps; else judged
        // from the speeds now.
        let measured = measured.filter(|_| world.last_stats().substeps == k.max(1));
        let worst = measured.unwrap_or_else(|| {
            world
                .particles
                .iter()
                .map(|p| p.vel.length() * h / p.radius)
                .fold(0.0, f64::max)
        });
        let plural = if k == 1 { "" } else { "s" };
        let text = match measured {
            Some(_) => format!(
                "{k} substep{plural} per step: a disc moved {worst:.1}× its radius in one substep \
                 and may have passed through others"
            ),
            None => format!(
                "{k} substep{plural} per step: the fastest disc moves {worst:.1}× its radius per \
                 substep and can pass through others"
            ),
        };
        // One disc can miss walls as well as another disc.
        let walls = world.laws.boundary == crate::Boundary::Box;
        if (several || walls && !world.particles.is_empty()) && worst > 1.0 {
            out.push(Warning {
                code: SUBSTEPS,
                text,
                values: vec![("substeps", f64::from(k)), ("radii", worst)],
            });
        }
    }
    if world.last_stats().truncated {
        out.push(Warning {
            code: STALL,
            text: format!(
                "{}: too many collisions at once, so time has stopped; to go on, choose the \
                 method impulse",
                method.name()
            ),
            values: Vec::new(),
        });
    }
    out
}

/// A number without trailing zeros: 1, 0.5, 0.25.
fn trim(x: f64) -> String {
    let s = format!("{x:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}
