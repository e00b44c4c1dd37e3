//! `auto`: model no more than a scene needs.
//!
//! Chooses the collision method, the broad phase and the substep count from
//! the scene, for every setting left on `auto` (fixed settings are kept). The
//! rules, and the measurements behind their thresholds:
//!
//! - **Method.** `exact` when its event rate is affordable and nothing in
//!   the scene defeats it: at most [`EXACT_MAX_DISCS`] discs, or extreme mass
//!   ratios (≥ [`EXTREME_MASS_RATIO`], where the discrete methods miscount
//!   collisions) up to [`EXACT_MAX_DISCS_ACCURACY`] discs; but never where
//!   discs will come to rest in contact (gravity with restitution below 1 at
//!   walls or between discs), because resting contact is an endless sequence
//!   of events for an event-driven method. Otherwise `impulse`.
//! - **Broad phase.** `brute` up to [`BRUTE_MAX_DISCS`] discs, `grid` above.
//!   Measured (`impulse bench`, 1 core, ns per particle-step, impulse): brute
//!   65 / 59 / 91 / 152 at n = 8 / 16 / 32 / 64 against the grid's 95 / 64 /
//!   70 / 49, so the crossover lies between 16 and 32. The quadtree was meant
//!   for mixed radii, but the grid beat it in every mix measured (10,000
//!   discs, radii spread 4x to 64x, or one disc 4x to 64x the rest: grid 45–75
//!   ns, quadtree 110–170 ns), so `auto` does not choose it.
//! - **Substeps** (discrete methods): enough that the fastest disc travels at
//!   most [`MAX_TRAVEL_PER_SUBSTEP`] of the smallest radius per substep, so
//!   nothing tunnels, capped at [`MAX_SUBSTEPS`].

use crate::broad_phase::BroadPhaseKind;
use crate::method::{Method, Setting};
use crate::world::World;
use serde::Serialize;

/// `exact` is chosen up to this many discs.
pub const EXACT_MAX_DISCS: usize = 500;
/// Mass ratio above which accuracy needs `exact`.
pub const EXTREME_MASS_RATIO: f64 = 1e3;
/// `exact` is chosen for extreme mass ratios up to this many discs.
pub const EXACT_MAX_DISCS_ACCURACY: usize = 5_000;
/// Brute force is chosen up to this many discs.
pub const BRUTE_MAX_DISCS: usize = 24;
/// Largest travel per substep, as a fraction of the smallest radius.
pub const MAX_TRAVEL_PER_SUBSTEP: f64 = 0.5;
/// Most substeps `auto` will ask for.
pub const MAX_SUBSTEPS: u32 = 64;

/// What a step will use, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Plan {
    /// Collision method.
    pub method: Method,
    /// Broad phase.
    pub broad_phase: BroadPhaseKind,
    /// Substeps per step (1 for `seed` and `exact`).
    pub substeps: u32,
    /// One line: why these were chosen.
    pub reason: String,
    /// Disc count the plan was made for.
    pub particles: usize,
    /// Step the plan was made for (s).
    pub dt: f64,
}

/// Resolves every `auto` setting of `world` for a step of `dt`.
pub fn plan(world: &World, dt: f64) -> Plan {
    let n = world.particles.len();
    let mut reasons = Vec::new();
    let (mut min_r, mut max_r, mut min_m, mut max_m, mut max_speed) =
        (f64::INFINITY, 0.0f64, f64::INFINITY, 0.0f64, 0.0f64);
    for p in &world.particles {
        min_r = min_r.min(p.radius);
        max_r = max_r.max(p.radius);
        min_m = min_m.min(p.mass);
        max_m = max_m.max(p.mass);
        max_speed = max_speed.max(p.vel.length());
    }
    let mass_ratio = if n > 0 { max_m / min_m } else { 1.0 };

    let method = match world.method {
        Setting::Fixed(m) => m,
        Setting::Auto => {
            let dissipative = world.restitution < 1.0 || world.wall_restitution < 1.0;
            let resting = world.gravity != glam::DVec2::ZERO && dissipative;
            if resting {
                reasons.push("impulse: discs will rest in contact (gravity, e < 1)".to_string());
                Method::Impulse
            } else if n <= EXACT_MAX_DISCS {
                reasons.push(format!("exact: {n} discs <= {EXACT_MAX_DISCS}"));
                Method::Exact
            } else if mass_ratio >= EXTREME_MASS_RATIO && n <= EXACT_MAX_DISCS_ACCURACY {
                reasons.push(format!("exact: mass ratio {mass_ratio:.0e}"));
                Method::Exact
            } else {
                reasons.push(format!("impulse: {n} discs"));
                Method::Impulse
            }
        }
    };

    let broad_phase = match world.broad_phase {
        Setting::Fixed(b) => b,
        Setting::Auto => {
            let choice = if n <= BRUTE_MAX_DISCS {
                BroadPhaseKind::Brute
            } else {
                BroadPhaseKind::Grid
            };
            reasons.push(format!("{} for {n} discs", choice.name()));
            choice
        }
    };

    let substeps = if !method.uses_substeps() {
        1
    } else {
        match world.substeps {
            Setting::Fixed(k) => k.max(1),
            Setting::Auto => {
                let fastest = max_speed + world.gravity.length() * dt;
                let allowed = MAX_TRAVEL_PER_SUBSTEP * min_r;
                let k = if n == 0 || allowed <= 0.0 {
                    1.0
                } else {
                    (fastest * dt / allowed)
                        .ceil()
                        .clamp(1.0, f64::from(MAX_SUBSTEPS))
                };
                reasons.push(format!(
                    "{k} substeps (travel {:.2} r)",
                    fastest * dt / min_r.max(1e-300)
                ));
                k as u32
            }
        }
    };

    Plan {
        method,
        broad_phase,
        substeps,
        reason: reasons.join("; "),
        particles: n,
        dt,
    }
}
