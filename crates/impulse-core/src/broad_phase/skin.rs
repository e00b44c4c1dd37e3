//! A Verlet neighbour list ("skin") around another broad phase.
//!
//! Discs move a few percent of a radius per step, so the pairs that can
//! touch change slowly. The wrapped broad phase is asked for the pairs of
//! discs inflated by half a skin each
//! ([`BroadPhase::candidate_pairs_inflated`]: the grid adds it as it reads
//! the discs, with no inflated copy of them); that list stays a superset of
//! the overlapping pairs until some disc has moved more than half the skin
//! from where it was when the list was built, and only then is it rebuilt.
//! Each step in between costs a check of every disc (how far has it moved?)
//! instead of a full broad phase; the pipeline has the narrow phase make it
//! as it reads the discs anyway ([`BroadPhase::kept_unchecked`]).
//! Adding, removing or resizing a disc, or changing the box, rebuilds at
//! once.
//!
//! The pipeline reads the list in place ([`BroadPhase::kept_pairs`]);
//! [`BroadPhase::candidate_pairs`] copies it. In parallel
//! ([`BroadPhase::set_parallel`]) the check, the rebuild's copies and the
//! copy of the list run on rayon's pool, chunk by chunk; the mean
//! radius is summed per [`CHUNK`] and the chunk sums in order either way, so
//! the list is the same whatever the threads.

use super::{BroadPhase, KeptCheck, Pair};
use crate::boundary::Boundary;
use crate::parallel::CHUNK;
use crate::particle::Particle;
use glam::DVec2;
#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Skin width as a fraction of the mean disc radius.
pub const SKIN_FRACTION: f64 = 1.0;

/// A broad phase whose answer is reused while it stays valid.
#[derive(Debug, Default)]
pub struct Skinned<B> {
    inner: B,
    pairs: Vec<Pair>,
    anchors: Vec<DVec2>,
    radii: Vec<f64>,
    skin: f64,
    built_for: Option<(Boundary, [u64; 2])>,
    parallel: bool,
    /// Scratch: the radii summed per chunk.
    sums: Vec<f64>,
}

impl<B: BroadPhase> Skinned<B> {
    fn still_valid(&self, particles: &[Particle], boundary: Boundary, size: DVec2) -> bool {
        if self.built_for != Some((boundary, [size.x.to_bits(), size.y.to_bits()]))
            || self.anchors.len() != particles.len()
        {
            return false;
        }
        let check = self.check(boundary, size);
        let near = |(p, (anchor, &radius)): (&Particle, (&DVec2, &f64))| {
            p.radius == radius
                && boundary.separation(*anchor, p.pos, size).length_squared() <= check.limit_sq
        };
        crate::parallel::pool_or_here!(
            self.parallel,
            {
                let n = particles.len();
                let (anchors, radii) = (&self.anchors, &self.radii);
                crate::parallel::on_each_run(n.div_ceil(CHUNK), |run| {
                    let span = run.start * CHUNK..(run.end * CHUNK).min(n);
                    let (anchors, radii) = (&anchors[span.clone()], &radii[span.clone()]);
                    particles[span]
                        .iter()
                        .zip(anchors.iter().zip(radii))
                        .all(near)
                })
                .into_iter()
                .all(|near| near)
            },
            {
                particles
                    .iter()
                    .zip(self.anchors.iter().zip(&self.radii))
                    .all(near)
            }
        )
    }

    /// What every disc must satisfy for the list to hold.
    fn check(&self, boundary: Boundary, size: DVec2) -> KeptCheck<'_> {
        let limit = 0.5 * self.skin;
        KeptCheck {
            anchors: &self.anchors,
            radii: &self.radii,
            limit_sq: limit * limit,
            boundary,
            size,
        }
    }

    fn rebuild(&mut self, particles: &[Particle], boundary: Boundary, size: DVec2) {
        let n = particles.len().max(1) as f64;
        let radii = |chunk: &[Particle]| {
            let finite = chunk.iter().map(|p| p.radius).filter(|r| r.is_finite());
            finite.sum::<f64>()
        };
        self.sums.clear();
        crate::parallel::pool_or_here!(
            self.parallel,
            {
                // Thread k sums the run of chunks it checks every step.
                let count = particles.len().div_ceil(CHUNK);
                let per_thread = crate::parallel::on_each_run(count, |run| {
                    let span = (run.start * CHUNK).min(particles.len())
                        ..(run.end * CHUNK).min(particles.len());
                    particles[span]
                        .chunks(CHUNK)
                        .map(radii)
                        .collect::<Vec<f64>>()
                });
                self.sums.extend(per_thread.into_iter().flatten());
            },
            {
                self.sums.extend(particles.chunks(CHUNK).map(radii));
            }
        );
        let mean_radius = self.sums.iter().sum::<f64>() / n;
        self.skin = (SKIN_FRACTION * mean_radius).max(0.0);
        let half_skin = 0.5 * self.skin;
        self.inner.set_parallel(self.parallel);
        self.inner
            .candidate_pairs_inflated(particles, half_skin, boundary, size, &mut self.pairs);
        // Last, so that the next step's check finds them in the caches.
        let n = particles.len();
        self.anchors.resize(n, DVec2::ZERO);
        self.radii.resize(n, 0.0);
        let take = |discs: &[Particle], anchors: &mut [DVec2], radii: &mut [f64]| {
            for ((p, anchor), radius) in discs.iter().zip(anchors).zip(radii) {
                *anchor = p.pos;
                *radius = p.radius;
            }
        };
        crate::parallel::pool_or_here!(
            self.parallel,
            {
                // Thread k takes the run of chunks it checks every step
                // (`parallel::on_each_run`), so they stay in its caches.
                let spans = crate::parallel::spans_of(n, CHUNK, crate::parallel::threads());
                let anchors = crate::parallel::split_by(&mut self.anchors, &spans);
                let radii = crate::parallel::split_by(&mut self.radii, &spans);
                let discs = spans.iter().map(|span| &particles[span.clone()]);
                let work: Vec<_> = discs
                    .zip(anchors)
                    .zip(radii)
                    .map(|((d, a), r)| (d, a, r))
                    .collect();
                crate::parallel::on_each_thread(work, |(discs, anchors, radii)| {
                    take(discs, anchors, radii)
                });
            },
            {
                take(particles, &mut self.anchors, &mut self.radii);
            }
        );
        self.built_for = Some((boundary, [size.x.to_bits(), size.y.to_bits()]));
    }
}

impl<B: BroadPhase> BroadPhase for Skinned<B> {
    fn candidate_pairs(
        &mut self,
        particles: &[Particle],
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    ) {
        if !self.still_valid(particles, boundary, size) {
            self.rebuild(particles, boundary, size);
        }
        out.clear();
        crate::parallel::pool_or_here!(
            self.parallel,
            {
                out.par_extend(self.pairs.par_iter().copied());
            },
            {
                out.extend_from_slice(&self.pairs);
            }
        );
    }

    fn set_parallel(&mut self, parallel: bool) {
        self.parallel = parallel;
    }

    fn refresh_kept(&mut self, particles: &[Particle], boundary: Boundary, size: DVec2) -> bool {
        if !self.still_valid(particles, boundary, size) {
            self.rebuild(particles, boundary, size);
        }
        true
    }

    fn kept_pairs(&self) -> &[Pair] {
        &self.pairs
    }

    fn kept_unchecked(
        &self,
        count: usize,
        boundary: Boundary,
        size: DVec2,
    ) -> Option<(&[Pair], KeptCheck<'_>)> {
        let built = self.built_for == Some((boundary, [size.x.to_bits(), size.y.to_bits()]));
        (built && self.anchors.len() == count)
            .then(|| (&self.pairs[..], self.check(boundary, size)))
    }
}
