//! The `verlet` method's substep: position Verlet with overlap projection.
//!
//! The stages in another order: integration first (x ← x + v·h + g·h²),
//! then broad phase → narrow phase, projection of the overlaps on the
//! positions only (no velocity changes), velocity implied by the positions
//! (v = Δx / h), then boundaries. Rough discs take their tangential
//! impulse on the implied velocities, with the normal impulse projection
//! gave each contact. `impulse` and `seed` run the stages in
//! the usual order in [`crate::world::World::step`].
//!
//! For large scenes the per-disc and per-pair stages run on rayon's pool
//! (`pipeline.parallel`, see [`crate::parallel`]); the result is the same
//! bit for bit.

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

/// One position-Verlet substep of length `h` starting at `time`;
/// `previous` is scratch for the positions it started from. The ledger
/// gets the wall hits (the wall stage reflects the implied velocity, as in
/// the other methods) but no pair collisions: projection moves positions
/// only, and the velocity a disc leaves with comes out of all its contacts
/// of the substep and the walls together, so there is no before and after
/// of one collision to record.
pub(crate) fn substep(
    pipeline: &mut Pipeline,
    previous: &mut Vec<DVec2>,
    particles: &mut [Particle],
    laws: &Laws,
    h: f64,
    stats: &mut StepStats,
    (ledger, time): (&mut Ledger, f64),
) {
    let lap = Lap::start();
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
    stats.timings.integration += lap.elapsed();
    pipeline.integrate(particles, laws.gravity, h, stats);
    pipeline.detect(particles, laws, stats);
    // Projection changes no velocity, so which contacts are impacts is read
    // off the velocities the discs came in with (implied by the last substep).
    let lap = Lap::start();
    let impact_speed = crate::impact::threshold(laws.gravity, h);
    let mut closings = Vec::new();
    for c in &pipeline.contacts {
        let closing = (particles[c.i as usize].vel - particles[c.j as usize].vel).dot(c.normal);
        if !laws.rough().is_smooth() {
            closings.push(closing);
        }
        if crate::impact::is_impact(closing, impact_speed) {
            stats.pair_collisions += 1;
        } else if closing > 0.0 {
            stats.resting_contacts += 1;
        }
    }
    stats.timings.resolution += lap.elapsed();
    // No pair to record: projection changes no velocity.
    let no_ledger = (&mut Ledger::default(), 0.0);
    pipeline.resolve(particles, (laws, h), Rule::PROJECTION, no_ledger, stats);
    let lap = Lap::start();
    let implied = |(p, previous): (&mut Particle, &DVec2)| p.vel = (p.pos - *previous) / h;
    crate::parallel::pool_or_here!(
        pipeline.parallel,
        {
            let chunks = particles.par_chunks_mut(CHUNK);
            chunks
                .zip(previous.par_chunks(CHUNK))
                .for_each(|(ps, prev)| ps.iter_mut().zip(prev).for_each(implied));
        },
        {
            particles.iter_mut().zip(previous.iter()).for_each(implied);
        }
    );
    // Rough discs: each contact that came in approaching rubs with the
    // normal impulse projection gave it (it stopped the approach).
    let rough = laws.rough();
    if !rough.is_smooth() {
        for (c, closing) in pipeline.contacts.iter().zip(closings) {
            let (i, j) = (c.i as usize, c.j as usize);
            let (head, tail) = particles.split_at_mut(j);
            let (a, b) = (&mut head[i], &mut tail[0]);
            let impulse = closing.max(0.0) * a.mass * b.mass / (a.mass + b.mass);
            if impulse > 0.0 {
                let rubs = if crate::impact::is_impact(closing, impact_speed) {
                    Some(rough)
                } else {
                    rough.resting()
                };
                if let Some(rubs) = rubs {
                    crate::resolution::rough_pair(a, b, c.normal, impulse, rubs);
                }
            }
        }
    }
    stats.timings.resolution += lap.elapsed();
    pipeline.apply_boundary(particles, laws, (h, false), (ledger, time + h), stats);
}
