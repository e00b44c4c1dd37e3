//! The world: discs in a rectangle, and [`World::step`], which runs the
//! chosen collision method over the shared pipeline.

use crate::auto::{self, Plan};
use crate::boundary::{Boundary, Walls};
use crate::broad_phase::BroadPhaseKind;
pub use crate::laws::Laws;
use crate::ledger::{Collision, Impact, Ledger};
use crate::method::{resting, verlet, Method, MethodState, Setting};
use crate::metrics::Metrics;
use crate::parallel;
use crate::particle::Particle;
use crate::pipeline::Pipeline;
use crate::resolution::Rule;
use crate::stats::StepStats;
use glam::DVec2;
use std::hash::{Hash, Hasher};

/// Discs in the rectangle (0,0)–`size`, with the laws they obey and the
/// method that steps them.
pub struct World {
    /// The discs, in a stable order (indices are identities within a step).
    pub particles: Vec<Particle>,
    /// The world's size and the laws its discs obey.
    pub laws: Laws,
    /// Collision method, or `auto`.
    pub method: Setting<Method>,
    /// Broad phase, or `auto`.
    pub broad_phase: Setting<BroadPhaseKind>,
    /// Substeps per step for `impulse` and `verlet`, or `auto`.
    pub substeps: Setting<u32>,
    /// Whether the discrete methods run their order-free stages on rayon's
    /// pool (`auto`: for large scenes when there is more than one thread).
    /// Results are bit-identical either way; see [`crate::parallel`].
    pub parallel: Setting<bool>,
    /// Simulated time so far (s).
    pub time: f64,
    /// Steps taken so far.
    pub steps: u64,
    /// Pair collisions resolved since the world was made.
    pub total_pair_collisions: u64,
    /// Wall impacts since the world was made.
    pub total_wall_hits: u64,
    /// Resting contacts (discs on discs or on walls) in the last step; see
    /// [`crate::impact`].
    pub resting_contacts: usize,
    /// Momentum transferred by the walls since the world was made (kg·m/s).
    pub total_wall_impulse: f64,
    /// The last impacts, pair collisions and wall hits, when turned on
    /// (`ledger.keep(n)`).
    pub ledger: Ledger,
    pipeline: Pipeline,
    methods: MethodState,
    plan: Option<Plan>,
    plan_key: Option<PlanKey>,
    last_stats: StepStats,
}

/// What a plan was made for; a different key means plan again.
#[derive(Clone, Copy, Debug, PartialEq)]
struct PlanKey {
    choices: auto::Choices,
    threads: usize,
    /// The step's bits.
    dt: u64,
    laws: Laws,
    particles: usize,
}

/// What [`World::run_to_next_collision`] and [`World::run_to_next_impact`]
/// run to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Next {
    /// A pair collision.
    Collision,
    /// A pair collision or a wall hit.
    Impact,
}

/// Most discs [`World::collisions_over`] looks at (it checks every pair).
pub const FORECAST_LIMIT: usize = 256;

/// How often `auto` looks at the scene again (steps).
const REPLAN_EVERY: u64 = 30;

/// Shortest step taken (s). Shorter ones leave the world unchanged, like a
/// zero step: `verlet` divides displacements by the step, and a step of
/// 10⁻³⁰⁰ s or a subnormal one turned a start's overlap into an infinite
/// velocity.
pub const MIN_DT: f64 = 1e-12;

impl World {
    /// An empty closed box of the given size: no gravity, elastic
    /// everywhere, the `impulse` method with one substep, brute force.
    pub fn new(size: DVec2) -> Self {
        Self {
            particles: Vec::new(),
            laws: Laws::new(size),
            method: Setting::Fixed(Method::Impulse),
            broad_phase: Setting::Fixed(BroadPhaseKind::Brute),
            substeps: Setting::Fixed(1),
            parallel: Setting::Auto,
            time: 0.0,
            steps: 0,
            total_pair_collisions: 0,
            total_wall_hits: 0,
            resting_contacts: 0,
            total_wall_impulse: 0.0,
            ledger: Ledger::default(),
            pipeline: Pipeline::new(BroadPhaseKind::Brute),
            methods: MethodState::default(),
            plan: None,
            plan_key: None,
            last_stats: StepStats::default(),
        }
    }

    /// Switches to a fixed broad phase (results do not depend on it).
    pub fn set_broad_phase(&mut self, kind: BroadPhaseKind) {
        self.broad_phase = Setting::Fixed(kind);
    }

    /// The four settings `auto` resolves.
    pub fn choices(&self) -> auto::Choices {
        auto::Choices {
            method: self.method,
            broad_phase: self.broad_phase,
            substeps: self.substeps,
            parallel: self.parallel,
        }
    }

    /// What the last step used: method, broad phase, substeps, and why.
    pub fn plan(&self) -> Option<&Plan> {
        self.plan.as_ref()
    }

    /// Decides method, broad phase and substeps for a step of `dt`:
    /// fixed settings as given, `auto` ones from the scene.
    pub fn plan_for(&self, dt: f64) -> Plan {
        auto::plan(&self.particles, &self.laws.in_effect(), self.choices(), dt)
    }

    /// Advances the world by `dt` seconds with the chosen method.
    ///
    /// A `dt` that is not a finite number of at least [`MIN_DT`] seconds
    /// leaves the world unchanged.
    pub fn step(&mut self, dt: f64) -> StepStats {
        if !(dt >= MIN_DT && dt.is_finite()) {
            return StepStats::default();
        }
        let (method, substeps) = self.replan(dt);
        let laws = self.laws.in_effect();
        let line = self.hold_to_line();
        let mut stats = StepStats::default();
        let simulated = if method == Method::Exact {
            stats.substeps = 1;
            let ledger = (&mut self.ledger, self.time);
            let exact = &mut self.methods.exact;
            exact.advance(&mut self.particles, &laws, dt, &mut stats, ledger)
        } else {
            self.methods.exact.forget();
            stats.substeps = substeps;
            let h = dt / f64::from(substeps);
            parallel::with_pool_awake(self.pipeline.parallel, || {
                for k in 0..substeps {
                    let time = self.time + f64::from(k) * h;
                    self.substep(method, &laws, (h, time), &mut stats);
                }
            });
            dt
        };
        if let Some(line) = &line {
            line.hold(&mut self.particles);
        }
        self.book(&stats, simulated);
        stats
    }

    /// One substep of `h` seconds of a fixed-step method, starting at
    /// `time`: broad phase → narrow phase → resolution → integration →
    /// boundaries (the last two chunk by chunk in one pass). `verlet` integrates first, and `impulse` under gravity
    /// with e < 1 resolves impacts and resting contacts apart; see
    /// [`crate::method`].
    fn substep(
        &mut self,
        method: Method,
        laws: &Laws,
        (h, time): (f64, f64),
        stats: &mut StepStats,
    ) {
        let (pipeline, particles) = (&mut self.pipeline, &mut self.particles[..]);
        let ledger = &mut self.ledger;
        let rule = match method {
            Method::Verlet => {
                let previous = &mut self.methods.previous_positions;
                let ledger = (ledger, time);
                return verlet::substep(pipeline, previous, particles, laws, h, stats, ledger);
            }
            Method::Impulse if resting::applies(laws) => {
                let scratch = &mut self.methods.resting;
                let ledger = (ledger, time);
                return resting::substep(pipeline, scratch, particles, laws, h, stats, ledger);
            }
            Method::Seed => Rule::SEED,
            Method::Impulse | Method::Exact => Rule::IMPULSE,
        };
        pipeline.broad_phase(particles, laws, stats);
        pipeline.narrow_phase(particles, laws, stats);
        pipeline.resolve(particles, (laws, h), rule, (&mut *ledger, time), stats);
        let at_touch = (h, rule.at_touch);
        pipeline.integrate_and_bound(particles, laws, at_touch, (ledger, time + h), stats);
    }

    /// Plans again when anything `auto` looks at may have changed (the
    /// settings, the laws, the disc count, the step) and every
    /// [`REPLAN_EVERY`] steps for the speeds; readies the pipeline for the
    /// plan. Returns the method and its substeps.
    fn replan(&mut self, dt: f64) -> (Method, u32) {
        let key = PlanKey {
            choices: self.choices(),
            threads: parallel::threads(),
            dt: dt.to_bits(),
            laws: self.laws.in_effect(),
            particles: self.particles.len(),
        };
        let stale = self.plan_key.as_ref() != Some(&key) || self.steps % REPLAN_EVERY == 0;
        let plan = match self.plan.take() {
            Some(plan) if !stale => plan,
            _ => auto::plan(&self.particles, &key.laws, key.choices, dt),
        };
        self.plan_key = Some(key);
        if self.pipeline.use_kind(plan.broad_phase) {
            self.methods.exact.forget();
        }
        self.pipeline.parallel = plan.parallel;
        let substeps = match plan.method {
            Method::Seed | Method::Exact => 1,
            _ => plan.substeps.max(1),
        };
        let method = plan.method;
        self.plan = Some(plan);
        (method, substeps)
    }

    /// In one dimension, holds every disc on the line (its place across it,
    /// no speed across it) and returns the line to hold them to after the
    /// step, whatever the method did (a contact normal off the line cannot
    /// move a disc off it).
    fn hold_to_line(&mut self) -> Option<Line> {
        let axis = self.laws.constrain?;
        let line = Line {
            across: axis.locked(),
            at: self
                .particles
                .iter()
                .map(|p| p.pos[axis.locked()])
                .collect(),
        };
        line.hold(&mut self.particles);
        Some(line)
    }

    /// Adds a step's time and counts to the world's running totals.
    fn book(&mut self, stats: &StepStats, simulated: f64) {
        self.time += simulated;
        self.steps += 1;
        self.total_pair_collisions += stats.pair_collisions as u64;
        self.total_wall_hits += stats.wall_hits as u64;
        self.resting_contacts = stats.resting_contacts;
        self.total_wall_impulse += stats.wall_impulse;
        self.last_stats = *stats;
    }

    /// Steps until the next pair collision (for at most `limit` seconds) and
    /// returns it; the world is left just after it: with `exact` at the very
    /// instant of impact (the step is cut there), with the discrete methods
    /// at the end of the step that resolved it (the newest of that step's
    /// collisions is returned). Wall hits do not stop it. Turns the ledger
    /// on if it was off. `verlet` records no pair collisions (see
    /// [`crate::ledger`]), so with it this runs to the limit.
    pub fn run_to_next_collision(&mut self, dt: f64, limit: f64) -> Option<Collision> {
        match self.run_to_next(Next::Collision, dt, limit, &mut |_, _| {})? {
            Impact::Pair(c) => Some(c),
            Impact::Wall(_) => None,
        }
    }

    /// Steps until the next impact, a pair collision or a wall hit (for at
    /// most `limit` seconds), and returns it; the world is left just after
    /// it: with `exact` at the very instant of impact, with the discrete
    /// methods at the end of the step that resolved it (the newest of that
    /// step's impacts is returned). Turns the ledger on if it was off.
    /// `verlet` counts its pair collisions but cannot record them (see
    /// [`crate::ledger`]): it stops after one all the same and returns
    /// `None`, so the caller tells it from "none within the limit" by the
    /// world's counters.
    pub fn run_to_next_impact(&mut self, dt: f64, limit: f64) -> Option<Impact> {
        self.run_to_next(Next::Impact, dt, limit, &mut |_, _| {})
    }

    /// [`World::run_to_next_impact`], handing the world and the step's
    /// statistics to `watch` after every step, so a caller can record the
    /// way there (its plots, trails and rewind history) as a frame would.
    pub fn run_to_next_impact_watched(
        &mut self,
        dt: f64,
        limit: f64,
        watch: &mut dyn FnMut(&World, &StepStats),
    ) -> Option<Impact> {
        self.run_to_next(Next::Impact, dt, limit, watch)
    }

    /// Steps of `dt` until the ledger records the `next` thing looked for,
    /// or `limit` seconds have passed, or a step makes no progress; `watch`
    /// sees the world after each step.
    fn run_to_next(
        &mut self,
        next: Next,
        dt: f64,
        limit: f64,
        watch: &mut dyn FnMut(&World, &StepStats),
    ) -> Option<Impact> {
        if !self.ledger.is_on() {
            self.ledger.keep(1);
        }
        let keep = self.ledger.capacity();
        let seen = |ledger: &Ledger| match next {
            Next::Collision => ledger.recorded,
            Next::Impact => ledger.recorded_impacts(),
        };
        let before = seen(&self.ledger);
        let counted = self.total_pair_collisions + self.total_wall_hits;
        let until = self.time + limit.max(0.0);
        self.methods.exact.stop_at_collision = true;
        self.methods.exact.stop_at_wall = next == Next::Impact;
        let mut found = None;
        while found.is_none() && self.time < until {
            let time_before = self.time;
            // Within a step, later entries must not push out the one looked
            // for (with room for one, a wall hit after a pair collision
            // would); the ledger goes back to its size after the step.
            self.ledger.keep(usize::MAX);
            let stats = self.step(dt.min(until - self.time).max(f64::MIN_POSITIVE));
            if seen(&self.ledger) > before {
                found = match next {
                    Next::Collision => self.ledger.last().copied().map(Impact::Pair),
                    Next::Impact => self.ledger.last_impact().copied(),
                };
            }
            self.ledger.keep(keep);
            watch(self, &stats);
            if self.time == time_before && found.is_none() {
                break; // no progress (the event cap)
            }
            let unrecorded = self.total_pair_collisions + self.total_wall_hits > counted;
            if found.is_none() && next == Next::Impact && unrecorded {
                break; // counted but not recorded: verlet's pair collisions
            }
        }
        self.methods.exact.stop_at_collision = false;
        self.methods.exact.stop_at_wall = false;
        found
    }

    /// Whether no collision can ever happen again, with a wall or between
    /// discs: no gravity, no disc moving towards a wall it could reach, and
    /// every pair moving apart or keeping its distance. (On straight lines a
    /// pair with d·Δv ≥ 0 never comes closer, since |d + Δv·t|² grows with t
    /// from then on.) False when it cannot tell cheaply: gravity, periodic
    /// edges, or more than [`FORECAST_LIMIT`] discs.
    pub fn collisions_over(&self) -> bool {
        let n = self.particles.len();
        if self.laws.gravity != DVec2::ZERO
            || self.laws.boundary == Boundary::Periodic
            || n > FORECAST_LIMIT
        {
            return false;
        }
        let walls = match self.laws.boundary {
            Boundary::Box => self.laws.walls,
            _ => Walls::NONE,
        };
        let towards_a_wall = self.particles.iter().any(|p| {
            (0..2).any(|axis| {
                (walls.at(axis, false) && p.vel[axis] < 0.0)
                    || (walls.at(axis, true) && p.vel[axis] > 0.0)
            })
        });
        if towards_a_wall {
            return false;
        }
        let ps = &self.particles;
        (0..n)
            .all(|i| (i + 1..n).all(|j| (ps[j].pos - ps[i].pos).dot(ps[j].vel - ps[i].vel) >= 0.0))
    }

    /// What the last step did.
    pub fn last_stats(&self) -> &StepStats {
        &self.last_stats
    }

    /// Momentum, energy and centre of mass right now.
    pub fn metrics(&self) -> Metrics {
        Metrics::measure(&self.particles)
    }

    /// Kinetic (translation and rotation) plus gravitational potential
    /// energy (J).
    pub fn total_energy(&self) -> f64 {
        let m = self.metrics();
        m.kinetic_energy
            + m.rotational_energy
            + Metrics::potential_energy(&self.particles, self.laws.gravity)
    }

    /// Index of the disc under a world point (the topmost, i.e. last drawn).
    pub fn particle_at(&self, point: DVec2) -> Option<usize> {
        self.particles.iter().rposition(|p| p.contains(point))
    }

    /// Whether a disc of `radius` at `pos` would lie inside the walls (for a
    /// closed box) and overlap no other disc.
    pub fn is_free(&self, pos: DVec2, radius: f64) -> bool {
        let inside = self.laws.boundary == Boundary::Periodic
            || self
                .laws
                .boundary
                .admits(self.laws.walls, self.laws.size, pos, radius);
        inside
            && self.particles.iter().all(|p| {
                self.laws
                    .boundary
                    .separation(p.pos, pos, self.laws.size)
                    .length()
                    >= p.radius + radius
            })
    }

    /// The free spot for a disc of `radius` nearest to `wanted` (searched on
    /// rings of growing size), or `None` if the world is too crowded.
    pub fn free_spot_near(&self, wanted: DVec2, radius: f64) -> Option<DVec2> {
        if !(radius > 0.0 && radius.is_finite() && wanted.is_finite()) {
            return None;
        }
        let start = match self.laws.boundary {
            Boundary::Box => {
                let (lo, hi) = (DVec2::splat(radius), self.laws.size - DVec2::splat(radius));
                let w = self.laws.walls;
                DVec2::new(
                    clamp_walled(wanted.x, lo.x, hi.x, [w.left, w.right]),
                    clamp_walled(wanted.y, lo.y, hi.y, [w.bottom, w.top]),
                )
            }
            Boundary::Open | Boundary::Periodic => wanted,
        };
        if self.is_free(start, radius) {
            return Some(start);
        }
        let ring_step = 0.25 * radius;
        let max_rings = ((self.laws.size.length() / ring_step).ceil() as usize).min(4000);
        (1..=max_rings).find_map(|ring| {
            let r = ring as f64 * ring_step;
            let samples = 8 * ring.min(64);
            (0..samples)
                .map(|k| {
                    let angle = std::f64::consts::TAU * k as f64 / samples as f64;
                    start + r * crate::math::unit(angle)
                })
                .find(|&p| self.is_free(p, radius))
        })
    }

    /// A hash of the whole physical state (every bit of every number), for
    /// determinism checks.
    pub fn state_hash(&self) -> u64 {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        self.time.to_bits().hash(&mut h);
        self.steps.hash(&mut h);
        for p in &self.particles {
            for x in [p.pos.x, p.pos.y, p.vel.x, p.vel.y, p.mass, p.radius] {
                x.to_bits().hash(&mut h);
            }
        }
        h.finish()
    }
}

/// Where a one-dimensional world's discs sit across its line.
struct Line {
    /// The axis across the line.
    across: usize,
    /// Each disc's place across the line.
    at: Vec<f64>,
}

impl Line {
    /// Puts every disc back on the line with no velocity across it; values
    /// already right are left as they are (bit for bit, so `exact` carries
    /// its calendar on).
    fn hold(&self, particles: &mut [Particle]) {
        let k = self.across;
        for (p, &at) in particles.iter_mut().zip(&self.at) {
            if p.vel[k] != 0.0 {
                p.vel[k] = 0.0;
            }
            if p.pos[k] != at {
                p.pos[k] = at;
            }
        }
    }
}

/// `x` kept above `lo` if there is a lower wall and below `hi` if there is
/// an upper one.
fn clamp_walled(x: f64, lo: f64, hi: f64, [lower, upper]: [bool; 2]) -> f64 {
    let x = if lower { x.max(lo) } else { x };
    if upper {
        x.min(hi)
    } else {
        x
    }
}

impl Clone for World {
    fn clone(&self) -> Self {
        World {
            particles: self.particles.clone(),
            laws: self.laws,
            method: self.method,
            broad_phase: self.broad_phase,
            substeps: self.substeps,
            parallel: self.parallel,
            time: self.time,
            steps: self.steps,
            total_pair_collisions: self.total_pair_collisions,
            total_wall_hits: self.total_wall_hits,
            resting_contacts: self.resting_contacts,
            total_wall_impulse: self.total_wall_impulse,
            ledger: self.ledger.clone(),
            pipeline: Pipeline::new(self.pipeline.kind),
            methods: MethodState::default(),
            plan: self.plan.clone(),
            plan_key: self.plan_key,
            last_stats: self.last_stats,
        }
    }
}

impl std::fmt::Debug for World {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("World")
            .field("size", &self.laws.size)
            .field("particles", &self.particles.len())
            .field("boundary", &self.laws.boundary)
            .field("method", &self.method)
            .field("time", &self.time)
            .finish_non_exhaustive()
    }
}
