//! The world: discs in a rectangle, and [`World::step`], the whole pipeline.

use crate::boundary::Boundary;
use crate::broad_phase::{BroadPhase, BroadPhaseKind, Pair};
use crate::integration::integrate;
use crate::metrics::Metrics;
use crate::narrow_phase::{find_contacts, Contact};
use crate::particle::Particle;
use crate::resolution::resolve_contacts;
use crate::stats::StepStats;
use glam::DVec2;
use std::hash::{Hash, Hasher};
use std::time::Instant;

/// Discs in the rectangle (0,0)–`size`, with the laws they obey.
pub struct World {
    /// The discs, in a stable order (indices are identities within a step).
    pub particles: Vec<Particle>,
    /// Width and height of the world rectangle (m).
    pub size: DVec2,
    /// Uniform gravitational acceleration (m/s²); y is up.
    pub gravity: DVec2,
    /// Coefficient of restitution e between discs, 0 (sticky) to 1 (elastic).
    pub restitution: f64,
    /// Coefficient of restitution at the walls.
    pub wall_restitution: f64,
    /// What the edges do.
    pub boundary: Boundary,
    /// Simulated time so far (s).
    pub time: f64,
    /// Steps taken so far.
    pub steps: u64,
    /// Pair collisions resolved since the world was made.
    pub total_pair_collisions: u64,
    /// Wall bounces since the world was made.
    pub total_wall_hits: u64,
    broad_phase_kind: BroadPhaseKind,
    broad_phase: Box<dyn BroadPhase + Send>,
    last_stats: StepStats,
    pairs: Vec<Pair>,
    contacts: Vec<Contact>,
}

impl World {
    /// An empty closed box of the given size: no gravity, elastic everywhere.
    pub fn new(size: DVec2) -> Self {
        let kind = BroadPhaseKind::default();
        Self {
            particles: Vec::new(),
            size,
            gravity: DVec2::ZERO,
            restitution: 1.0,
            wall_restitution: 1.0,
            boundary: Boundary::Box,
            time: 0.0,
            steps: 0,
            total_pair_collisions: 0,
            total_wall_hits: 0,
            broad_phase_kind: kind,
            broad_phase: kind.build(),
            last_stats: StepStats::default(),
            pairs: Vec::new(),
            contacts: Vec::new(),
        }
    }

    /// The broad phase in use.
    pub fn broad_phase(&self) -> BroadPhaseKind {
        self.broad_phase_kind
    }

    /// Switches the broad phase (results do not depend on it).
    pub fn set_broad_phase(&mut self, kind: BroadPhaseKind) {
        self.broad_phase_kind = kind;
        self.broad_phase = kind.build();
    }

    /// Advances the world by `dt` seconds, stage by stage:
    /// broad phase → narrow phase → resolution → integration → boundary.
    ///
    /// A `dt` that is not a positive finite number leaves the world unchanged.
    pub fn step(&mut self, dt: f64) -> StepStats {
        if !(dt > 0.0 && dt.is_finite()) {
            return StepStats::default();
        }
        let mut stats = StepStats::default();
        let mut clock = Instant::now();
        let mut lap = || {
            let now = Instant::now();
            let elapsed = now - clock;
            clock = now;
            elapsed
        };

        self.broad_phase.candidate_pairs(
            &self.particles,
            self.boundary,
            self.size,
            &mut self.pairs,
        );
        stats.candidate_pairs = self.pairs.len();
        stats.timings.broad_phase = lap();

        find_contacts(
            &self.particles,
            &self.pairs,
            self.boundary,
            self.size,
            &mut self.contacts,
        );
        stats.contacts = self.contacts.len();
        stats.timings.narrow_phase = lap();

        let report = resolve_contacts(&mut self.particles, &self.contacts, self.restitution);
        stats.pair_collisions = report.collisions;
        stats.max_overlap = report.max_overlap;
        stats.timings.resolution = lap();

        integrate(&mut self.particles, self.gravity, dt);
        stats.timings.integration = lap();

        stats.wall_hits = self.boundary.apply(
            &mut self.particles,
            self.size,
            self.gravity,
            self.wall_restitution,
        );
        stats.timings.boundary = lap();

        self.time += dt;
        self.steps += 1;
        self.total_pair_collisions += stats.pair_collisions as u64;
        self.total_wall_hits += stats.wall_hits as u64;
        self.last_stats = stats;
        stats
    }

    /// What the last step did.
    pub fn last_stats(&self) -> &StepStats {
        &self.last_stats
    }

    /// Momentum, energy and centre of mass right now.
    pub fn metrics(&self) -> Metrics {
        Metrics::measure(&self.particles)
    }

    /// Kinetic plus gravitational potential energy (J).
    pub fn total_energy(&self) -> f64 {
        self.metrics().kinetic_energy + Metrics::potential_energy(&self.particles, self.gravity)
    }

    /// Index of the disc under a world point (the topmost, i.e. last drawn).
    pub fn particle_at(&self, point: DVec2) -> Option<usize> {
        self.particles.iter().rposition(|p| p.contains(point))
    }

    /// Whether a disc of `radius` at `pos` would lie inside the walls (for a
    /// closed box) and overlap no other disc.
    pub fn is_free(&self, pos: DVec2, radius: f64) -> bool {
        let inside = self.boundary != Boundary::Box
            || (pos.cmpge(DVec2::splat(radius)).all()
                && pos.cmple(self.size - DVec2::splat(radius)).all());
        inside
            && self.particles.iter().all(|p| {
                self.boundary.separation(p.pos, pos, self.size).length() >= p.radius + radius
            })
    }

    /// The free spot for a disc of `radius` nearest to `wanted` (searched on
    /// rings of growing size), or `None` if the world is too crowded.
    pub fn free_spot_near(&self, wanted: DVec2, radius: f64) -> Option<DVec2> {
        if !(radius > 0.0 && radius.is_finite() && wanted.is_finite()) {
            return None;
        }
        let start = match self.boundary {
            Boundary::Box => wanted.clamp(DVec2::splat(radius), self.size - DVec2::splat(radius)),
            Boundary::Open | Boundary::Periodic => wanted,
        };
        if self.is_free(start, radius) {
            return Some(start);
        }
        let ring_step = 0.25 * radius;
        let max_rings = ((self.size.length() / ring_step).ceil() as usize).min(4000);
        (1..=max_rings).find_map(|ring| {
            let r = ring as f64 * ring_step;
            let samples = 8 * ring.min(64);
            (0..samples)
                .map(|k| {
                    let angle = std::f64::consts::TAU * k as f64 / samples as f64;
                    start + r * DVec2::from_angle(angle)
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

impl Clone for World {
    fn clone(&self) -> Self {
        let mut copy = World::new(self.size);
        copy.particles = self.particles.clone();
        copy.gravity = self.gravity;
        copy.restitution = self.restitution;
        copy.wall_restitution = self.wall_restitution;
        copy.boundary = self.boundary;
        copy.time = self.time;
        copy.steps = self.steps;
        copy.total_pair_collisions = self.total_pair_collisions;
        copy.total_wall_hits = self.total_wall_hits;
        copy.set_broad_phase(self.broad_phase_kind);
        copy.last_stats = self.last_stats;
        copy
    }
}

impl std::fmt::Debug for World {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("World")
            .field("size", &self.size)
            .field("particles", &self.particles.len())
            .field("boundary", &self.boundary)
            .field("time", &self.time)
            .finish_non_exhaustive()
    }
}
