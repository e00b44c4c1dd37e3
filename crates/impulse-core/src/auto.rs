//! `auto`: model no more than a scene needs.
//!
//! Chooses the collision method, the broad phase and the substep count from
//! the scene, for every setting left on `auto` (fixed settings are kept). The
//! rules, and the measurements behind their thresholds:
//!
//! - **Method.** `exact` when it is affordable and nothing in the scene
//!   defeats it, `impulse` otherwise. Affordable: its estimated cost per
//!   simulated second, n·([`EXACT_SETUP_NS`]/dt + ν·[`EXACT_COLLISION_NS`])
//!   with ν = √2·(n/A)·2r̄·v_rms the collision frequency of a 2D gas, stays
//!   within [`EXACT_BUDGET`] seconds (so real time costs at most a quarter of
//!   a core); four times that when masses differ by [`EXTREME_MASS_RATIO`] or
//!   more, where the discrete methods miscount collisions. The two costs are
//!   measured by `impulse bench`: a step of the exact method costs about
//!   15–20 ns per disc before any collision (it carries its event calendar
//!   from step to step and only checks that nothing was edited and moves
//!   every disc to the end of the step; the first step after an edit costs
//!   about 300 ns per disc, for sorting and predicting every disc afresh),
//!   and a collision 0.9–1.7 µs (2.43 events; 1.13·10⁶ collisions per
//!   second at 10⁴ discs, whose events stay in cache, and 5.8·10⁵ at 10⁵,
//!   in the bench run of 2026-11-22, 20:00 UTC). [`EXACT_COLLISION_NS`]
//!   keeps 1.4 µs, between the two, as it was measured when the first
//!   calendar queue made it 7–10·10⁵ at 10⁴ discs and 4·10⁵ at 10⁵; at
//!   0.9 µs `auto` would choose `exact` for scenes about 1.5 times as busy.
//!   Where discs will come to rest in contact (gravity with restitution
//!   below 1), `exact` when it holds them ([`crate::method::exact::holds_discs`]:
//!   smooth discs in a box) and its estimate above stays within what
//!   `impulse` spends on its contacts, n·K·[`IMPULSE_RESTING_NS`]/dt for K
//!   substeps; `impulse` otherwise (rough discs: `exact` has no contact
//!   solve with friction, and its events alone stall in a pile). Settling
//!   costs both about the same; once settled, `exact`'s discs sleep and cost
//!   [`EXACT_SETUP_NS`] a step, while `impulse` solves every contact on
//!   every step. Measured 2026-11-25 (wall clock, medians of 3, `exact`
//!   against `impulse`): 15 s of the 150-disc pile 0.16 against 0.14 s, of
//!   the 300-disc pile 0.35 / 0.30, of the 360-disc tall pile 0.43 / 0.46,
//!   10 s of the 10⁴-disc pile 12.9 / 9.6 s; 60 s of the same small piles
//!   0.18 / 0.59, 0.40 / 1.28, 0.47 / 1.99 s, the mass-ratio stacks 4 / 33
//!   ms, 8 discs thrown into a box 6 / 18 ms. After settling a step costs
//!   `exact` 12–15 ns per disc, `impulse` 175–390 ns.
//! - **Broad phase.** `brute` up to [`BRUTE_MAX_DISCS`] discs, `grid` above.
//!   Measured (`impulse bench`, 1 core, ns per particle-step, impulse): brute
//!   59 / 52 / 65 / 112 at n = 8 / 16 / 32 / 64 against the grid's 60 / 39 /
//!   27 / 22, so the crossover lies between 8 and 16. Mixed radii: the grid
//!   sizes its cells by the ordinary discs and tests up to 32 big ones (over
//!   4x the mean radius) against everyone, and so beat the quadtree in every
//!   smooth mix measured (10,000 discs, radii spread 4x to 64x, or one disc 4x
//!   to 64x the rest: grid 21–86 ns, quadtree 97–149 ns). With more than
//!   [`GRID_MAX_BIG_DISCS`] big discs the grid sizes its cells by them; that
//!   only hurts when many small discs then share a cell: 1 % large discs (8x)
//!   in a sparse gas kept the grid ahead (31 against 116 ns), in a dense one
//!   (about 24 discs per cell) it fell to 386 ns against the quadtree's 226.
//!   So `auto` picks the `quadtree` when the grid would hold more than
//!   [`MAX_DISCS_PER_CELL`] discs per cell on average.
//! - **Substeps** (discrete methods): enough that the fastest disc travels at
//!   most [`MAX_TRAVEL_PER_SUBSTEP`] of the smallest radius per substep, so
//!   nothing tunnels, capped at [`MAX_SUBSTEPS`].
//! - **Threads** (discrete methods): the order-free stages run on rayon's
//!   pool ([`crate::parallel`]) from [`PARALLEL_MIN_DISCS`] discs when the
//!   pool has more than one thread; below that, handing chunks to threads
//!   costs more than it saves. Results are bit-identical either way.
//!   Measured (impulse / grid, a pool of 2 threads, serial against parallel,
//!   ns per particle-step, medians of 3 runs, 2026-11-22, with the second
//!   core busy with other work the whole time): 5,000 discs 36 against 52
//!   (parallel loses 30 %: two chunks of discs, and every stage pays a
//!   hand-off); 10⁴ 52 / 52; 2·10⁴ 45 / 47; 10⁵ 37 / 37. So from 10⁴ the
//!   parallel path costs at most about 5 % even when the second core is not
//!   free, and wins what that core gives when it is; below, it loses. `bench`
//!   prints this crossover table again on every run.

use crate::broad_phase::BroadPhaseKind;
use crate::broad_phase::BroadPhaseKind as Broad;
use crate::laws::Laws;
use crate::method::{Method, Setting};
use crate::particle::Particle;

/// The four settings `auto` resolves, each fixed or `auto`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Choices {
    /// Collision method.
    pub method: Setting<Method>,
    /// Broad phase.
    pub broad_phase: Setting<Broad>,
    /// Substeps per step for `impulse` and `verlet`.
    pub substeps: Setting<u32>,
    /// Whether the order-free stages run on rayon's pool.
    pub parallel: Setting<bool>,
}
use serde::Serialize;

/// Measured cost of the exact method per disc and step, before collisions,
/// while the world is not edited between steps (ns).
pub const EXACT_SETUP_NS: f64 = 20.0;
/// Cost of the exact method per pair collision (ns): measured so with the
/// first calendar queue; today's measurements, 0.9 µs at 10⁴ discs and
/// 1.7 µs at 10⁵, lie on either side (see the module doc).
pub const EXACT_COLLISION_NS: f64 = 1400.0;
/// Measured cost of `impulse` per disc and substep in a resting pile, its
/// contacts solved every step (ns; 175–390 measured, see the module doc).
pub const IMPULSE_RESTING_NS: f64 = 250.0;
/// Most wall-clock seconds per simulated second `auto` spends on `exact`.
pub const EXACT_BUDGET: f64 = 0.25;
/// Mass ratio above which accuracy needs `exact` (budget ×4).
pub const EXTREME_MASS_RATIO: f64 = 1e3;
/// Brute force is chosen up to this many discs.
pub const BRUTE_MAX_DISCS: usize = 12;
/// A disc is "big" for the grid above this multiple of the mean radius.
pub const BIG_DISC_FACTOR: f64 = 4.0;
/// Big discs the grid handles on the side; more, and its cells grow.
pub const GRID_MAX_BIG_DISCS: usize = 32;
/// Mean discs per grid cell above which the quadtree is chosen.
pub const MAX_DISCS_PER_CELL: f64 = 8.0;
/// Largest travel per substep, as a fraction of the smallest radius.
pub const MAX_TRAVEL_PER_SUBSTEP: f64 = 0.5;
/// Most substeps `auto` will ask for.
pub const MAX_SUBSTEPS: u32 = 64;
/// The discrete methods run in parallel from this many discs.
pub const PARALLEL_MIN_DISCS: usize = 10_000;

/// What a step will use, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Plan {
    /// Collision method.
    pub method: Method,
    /// Broad phase.
    pub broad_phase: BroadPhaseKind,
    /// Substeps per step (1 for `seed` and `exact`).
    pub substeps: u32,
    /// Whether the order-free stages run on rayon's pool.
    pub parallel: bool,
    /// One line: why these were chosen.
    pub reason: String,
    /// Disc count the plan was made for.
    pub particles: usize,
    /// Step the plan was made for (s).
    pub dt: f64,
}

/// Mean discs per cell of the grid broad phase: its cells are as wide as
/// the largest disc it does not set aside (it sets aside up to
/// [`GRID_MAX_BIG_DISCS`] discs bigger than [`BIG_DISC_FACTOR`] × the mean).
pub fn grid_crowding(particles: &[Particle], laws: &Laws) -> f64 {
    let n = particles.len();
    if n == 0 {
        return 0.0;
    }
    let mean_r = particles.iter().map(|p| p.radius).sum::<f64>() / n as f64;
    let big_limit = BIG_DISC_FACTOR * mean_r;
    let big = particles.iter().filter(|p| p.radius > big_limit).count();
    let cell_radius = if big <= GRID_MAX_BIG_DISCS {
        // Every big disc is set aside: cells fit the largest ordinary one.
        particles
            .iter()
            .map(|p| p.radius)
            .filter(|&r| r <= big_limit)
            .fold(0.0, f64::max)
    } else {
        // The grid sets aside the largest few; cells fit the next one. Only
        // this rare case pays for a copy of the radii.
        let mut radii: Vec<f64> = particles.iter().map(|p| p.radius).collect();
        let (_, next, _) = radii.select_nth_unstable_by(GRID_MAX_BIG_DISCS, |a, b| b.total_cmp(a));
        *next
    };
    let cell = 2.0 * cell_radius;
    let area = match laws.boundary {
        crate::Boundary::Open => {
            let (lo, hi) = particles.iter().fold(
                (
                    glam::DVec2::splat(f64::INFINITY),
                    glam::DVec2::splat(f64::NEG_INFINITY),
                ),
                |(lo, hi), p| (lo.min(p.pos), hi.max(p.pos)),
            );
            ((hi - lo).x * (hi - lo).y).max(cell * cell)
        }
        _ => laws.size.x * laws.size.y,
    };
    n as f64 * cell * cell / area.max(f64::MIN_POSITIVE)
}

/// Estimated wall-clock seconds `exact` needs per simulated second.
pub fn exact_cost_per_second(particles: &[Particle], laws: &Laws, dt: f64) -> f64 {
    let n = particles.len() as f64;
    if n == 0.0 {
        return 0.0;
    }
    let mean_diameter = particles.iter().map(|p| 2.0 * p.radius).sum::<f64>() / n;
    let v_rms = (particles
        .iter()
        .map(|p| p.vel.length_squared())
        .sum::<f64>()
        / n)
        .sqrt();
    let area = laws.size.x * laws.size.y;
    let frequency = std::f64::consts::SQRT_2 * (n / area) * mean_diameter * v_rms;
    n * (EXACT_SETUP_NS / dt + frequency * EXACT_COLLISION_NS) * 1e-9
}

/// Substeps that keep the fastest disc (its speed plus a step of gravity)
/// within [`MAX_TRAVEL_PER_SUBSTEP`] of the smallest radius per substep.
fn substeps_needed(max_speed: f64, min_r: f64, laws: &Laws, dt: f64, n: usize) -> f64 {
    substeps_unclamped(max_speed, min_r, laws, dt, n).clamp(1.0, f64::from(MAX_SUBSTEPS))
}

/// [`substeps_needed`] without its cap.
fn substeps_unclamped(max_speed: f64, min_r: f64, laws: &Laws, dt: f64, n: usize) -> f64 {
    let fastest = max_speed + laws.gravity.length() * dt;
    let allowed = MAX_TRAVEL_PER_SUBSTEP * min_r;
    if n == 0 || allowed <= 0.0 {
        1.0
    } else {
        (fastest * dt / allowed).ceil().max(1.0)
    }
}

/// Resolves every `auto` setting of `choices` for these discs under these
/// laws, for a step of `dt`.
pub fn plan(particles: &[Particle], laws: &Laws, choices: Choices, dt: f64) -> Plan {
    let n = particles.len();
    let mut reasons = Vec::new();
    let (mut min_r, mut min_m, mut max_m, mut max_speed) =
        (f64::INFINITY, f64::INFINITY, 0.0f64, 0.0f64);
    for p in particles {
        min_r = min_r.min(p.radius);
        min_m = min_m.min(p.mass);
        max_m = max_m.max(p.mass);
        max_speed = max_speed.max(p.vel.length());
    }
    let mass_ratio = if n > 0 { max_m / min_m } else { 1.0 };

    let method = match choices.method {
        Setting::Fixed(m) => m,
        Setting::Auto => {
            let dissipative = laws.restitution < 1.0 || laws.wall_restitution < 1.0;
            let resting = laws.gravity != glam::DVec2::ZERO && dissipative;
            if resting {
                let exact = exact_cost_per_second(particles, laws, dt);
                let substeps = substeps_needed(max_speed, min_r, laws, dt, n);
                let impulse = n as f64 * substeps * IMPULSE_RESTING_NS / dt * 1e-9;
                if !crate::method::exact::holds_discs(laws) {
                    reasons.push(
                        "impulse: discs will rest in contact, which exact cannot hold here (rough discs or no box)"
                            .to_string(),
                    );
                    Method::Impulse
                } else if exact <= impulse {
                    reasons.push(format!(
                        "exact: discs will rest in contact; held, then asleep, they cost less than impulse's {impulse:.2} s/s"
                    ));
                    Method::Exact
                } else {
                    reasons.push(format!(
                        "impulse: exact would cost {exact:.2} s/s > impulse's {impulse:.2} while discs fly"
                    ));
                    Method::Impulse
                }
            } else {
                let cost = exact_cost_per_second(particles, laws, dt);
                let extreme = mass_ratio >= EXTREME_MASS_RATIO;
                let budget = if extreme {
                    4.0 * EXACT_BUDGET
                } else {
                    EXACT_BUDGET
                };
                let why = if extreme {
                    format!(", mass ratio {mass_ratio:.0e}")
                } else {
                    String::new()
                };
                if cost <= budget {
                    reasons.push(format!("exact: est. {cost:.3} s/s <= {budget}{why}"));
                    Method::Exact
                } else {
                    reasons.push(format!(
                        "impulse: exact would cost {cost:.2} s/s > {budget}{why}"
                    ));
                    Method::Impulse
                }
            }
        }
    };

    // A fixed step that cannot keep the fastest disc within its radius even
    // at the most substeps would let it pass through others unseen:
    // `exact`, which finds every impact whatever the speed (and says so
    // when it falls behind), where it can hold these discs.
    let needed = substeps_unclamped(max_speed, min_r, laws, dt, n);
    let method = if choices.method == Setting::Auto
        && method == Method::Impulse
        && needed > f64::from(MAX_SUBSTEPS)
        && (crate::method::exact::holds_discs(laws)
            || !(laws.gravity != glam::DVec2::ZERO
                && (laws.restitution < 1.0 || laws.wall_restitution < 1.0)))
    {
        reasons.push(format!(
            "exact: impulse would need {needed:.0} substeps (at most {MAX_SUBSTEPS}) to keep the fastest disc within half its radius a substep"
        ));
        Method::Exact
    } else {
        method
    };

    let broad_phase = match choices.broad_phase {
        Setting::Fixed(b) => b,
        Setting::Auto => {
            let crowding = grid_crowding(particles, laws);
            let choice = if n <= BRUTE_MAX_DISCS {
                BroadPhaseKind::Brute
            } else if crowding > MAX_DISCS_PER_CELL {
                reasons.push(format!("{crowding:.0} discs per grid cell"));
                BroadPhaseKind::Quadtree
            } else {
                BroadPhaseKind::Grid
            };
            if method != Method::Exact {
                // Exact keeps its own cells; naming a broad phase would mislead.
                reasons.push(format!("{} for {n} discs", choice.name()));
            }
            choice
        }
    };

    let substeps = if !method.uses_substeps() {
        1
    } else {
        match choices.substeps {
            Setting::Fixed(k) => k.max(1),
            Setting::Auto => {
                let k = substeps_needed(max_speed, min_r, laws, dt, n);
                let fastest = max_speed + laws.gravity.length() * dt;
                reasons.push(format!(
                    "{k} substeps (travel {:.2} r)",
                    fastest * dt / min_r.max(1e-300)
                ));
                k as u32
            }
        }
    };

    let discrete = method != Method::Exact;
    let parallel = match choices.parallel {
        Setting::Fixed(on) => on && discrete,
        Setting::Auto if !discrete => false,
        Setting::Auto => {
            let threads = crate::parallel::threads();
            let on = threads > 1 && n >= PARALLEL_MIN_DISCS;
            reasons.push(if on {
                format!("{threads} threads (n >= {PARALLEL_MIN_DISCS})")
            } else if threads > 1 {
                format!("1 thread (n < {PARALLEL_MIN_DISCS})")
            } else {
                "1 thread".to_string()
            });
            on
        }
    };

    Plan {
        method,
        broad_phase,
        substeps,
        parallel,
        reason: reasons.join("; "),
        particles: n,
        dt,
    }
}
