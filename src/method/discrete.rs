//! The fixed-step methods: `seed`, `impulse` and `verlet`.
//!
//! All three share the detection stages (broad phase → narrow phase) and
//! differ in resolution and in where velocity comes from:
//!
//! - `impulse`: broad → narrow → resolution (approaching pairs, restitution,
//!   inverse-mass push-apart) → integration → boundaries, K times per step;
//! - `seed`: the same stages with the presentation's rule (every overlapping
//!   pair, half-each push-apart), once per step whatever K says;
//! - `verlet`: integration first (position Verlet: x ← x + v·h + g·h²),
//!   then detection, overlap projection on positions only, velocity implied
//!   by the positions (v = Δx / h), then boundaries; K times per step.

use crate::integration::integrate;
use crate::ledger::Ledger;
use crate::resolution::{resolve_contacts, Rule};
use crate::stats::{Lap, StepStats};
use crate::world::{Laws, Pipeline};
use crate::Particle;

/// One impulse-method substep of length `h`, starting at world time `time`
/// (for the collision ledger).
pub(crate) fn impulse_substep(
    pipeline: &mut Pipeline,
    particles: &mut [Particle],
    laws: &Laws,
    h: f64,
    rule: Rule,
    stats: &mut StepStats,
    (ledger, time): (&mut Ledger, f64),
) {
    if rule == Rule::IMPULSE && super::resting::applies(laws) {
        super::resting::substep(pipeline, particles, laws, h, stats, (ledger, time));
        return;
    }
    pipeline.detect(particles, laws, stats);
    let mut lap = Lap::start();
    let report = resolve_contacts(
        particles,
        &pipeline.contacts,
        laws.restitution,
        rule,
        ledger,
        time,
    );
    stats.pair_collisions += report.collisions;
    stats.max_overlap = stats.max_overlap.max(report.max_overlap);
    stats.timings.resolution += lap.lap();
    integrate(particles, laws.gravity, h);
    stats.timings.integration += lap.lap();
    laws.apply_boundary(particles, stats);
    stats.timings.boundary += lap.lap();
}

/// One position-Verlet substep of length `h`.
pub(crate) fn verlet_substep(
    pipeline: &mut Pipeline,
    particles: &mut [Particle],
    laws: &Laws,
    h: f64,
    stats: &mut StepStats,
) {
    let mut lap = Lap::start();
    pipeline.previous_positions.clear();
    pipeline
        .previous_positions
        .extend(particles.iter().map(|p| p.pos));
    integrate(particles, laws.gravity, h);
    stats.timings.integration += lap.lap();
    pipeline.detect(particles, laws, stats);
    let mut lap = Lap::start();
    let report = resolve_contacts(
        particles,
        &pipeline.contacts,
        laws.restitution,
        Rule::PROJECTION,
        &mut Ledger::default(), // projection changes no velocity: nothing to record
        0.0,
    );
    stats.max_overlap = stats.max_overlap.max(report.max_overlap);
    // Contacts that were projected count as collisions for the statistics.
    stats.pair_collisions += pipeline.contacts.len();
    for (p, previous) in particles.iter_mut().zip(&pipeline.previous_positions) {
        p.vel = (p.pos - *previous) / h;
    }
    stats.timings.resolution += lap.lap();
    laws.apply_boundary(particles, stats);
    stats.timings.boundary += lap.lap();
}
