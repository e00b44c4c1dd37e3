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
//!
//! For large scenes the per-disc and per-pair stages run on rayon's pool
//! (`pipeline.parallel`, see [`crate::parallel`]); resolution goes in
//! ascending pair order, or for large contact lists band by band, side by
//! side ([`crate::resolution::Banded`]); the result is the same bit for bit.

use crate::laws::Laws;
use crate::ledger::Ledger;
#[cfg(feature = "parallel")]
use crate::parallel::CHUNK;
use crate::pipeline::Pipeline;
use crate::resolution::Rule;
use crate::stats::{Lap, StepStats};
use crate::Particle;
use glam::DVec2;
#[cfg(feature = "parallel")]
use rayon::prelude::*;

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
    let report = pipeline.resolve(particles, (laws, h), rule, (ledger, time));
    stats.pair_collisions += report.collisions;
    stats.resting_contacts += report.resting;
    stats.max_overlap = stats.max_overlap.max(report.max_overlap);
    stats.timings.resolution += lap.lap();
    pipeline.integrate(particles, laws.gravity, h);
    stats.timings.integration += lap.lap();
    pipeline.apply_boundary(particles, laws, h, stats);
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
    let previous = &mut pipeline.previous_positions;
    previous.clear();
    crate::parallel::pool_or_here!(
        pipeline.parallel,
        {
            previous.par_extend(particles.par_iter().map(|p| p.pos));
        },
        {
            previous.extend(particles.iter().map(|p| p.pos));
        }
    );
    pipeline.integrate(particles, laws.gravity, h);
    stats.timings.integration += lap.lap();
    pipeline.detect(particles, laws, stats);
    let mut lap = Lap::start();
    // Projection changes no velocity: nothing to record.
    // Projection changes no velocity, so which contacts are impacts is read
    // off the velocities the discs came in with (implied by the last substep).
    let impact_speed = crate::impact::threshold(laws.gravity, h);
    for c in &pipeline.contacts {
        let closing = (particles[c.i as usize].vel - particles[c.j as usize].vel).dot(c.normal);
        if crate::impact::is_impact(closing, impact_speed) {
            stats.pair_collisions += 1;
        } else if closing > 0.0 {
            stats.resting_contacts += 1;
        }
    }
    let report = pipeline.resolve(
        particles,
        (laws, h),
        Rule::PROJECTION,
        (&mut Ledger::default(), 0.0),
    );
    stats.max_overlap = stats.max_overlap.max(report.max_overlap);
    let implied = |(p, previous): (&mut Particle, &DVec2)| p.vel = (p.pos - *previous) / h;
    crate::parallel::pool_or_here!(
        pipeline.parallel,
        {
            let chunks = particles.par_chunks_mut(CHUNK);
            chunks
                .zip(pipeline.previous_positions.par_chunks(CHUNK))
                .for_each(|(ps, prev)| ps.iter_mut().zip(prev).for_each(implied));
        },
        {
            particles
                .iter_mut()
                .zip(&pipeline.previous_positions)
                .for_each(implied);
        }
    );
    stats.timings.resolution += lap.lap();
    pipeline.apply_boundary(particles, laws, h, stats);
    stats.timings.boundary += lap.lap();
}
