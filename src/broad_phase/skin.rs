//! A Verlet neighbour list ("skin") around another broad phase.
//!
//! Discs move a few percent of a radius per step, so the pairs that can
//! touch change slowly. The wrapped broad phase is asked for the pairs of
//! discs inflated by half a skin each; that list stays a superset of the
//! overlapping pairs until some disc has moved more than half the skin from
//! where it was when the list was built, and only then is it rebuilt. Each
//! step in between costs one pass over the discs (how far has each moved?)
//! instead of a full broad phase. Adding, removing or resizing a disc, or
//! changing the box, rebuilds at once.

use super::{BroadPhase, Pair};
use crate::boundary::Boundary;
use crate::particle::Particle;
use glam::DVec2;

/// Skin width as a fraction of the mean disc radius.
pub const SKIN_FRACTION: f64 = 1.0;

/// A broad phase whose answer is reused while it stays valid.
#[derive(Debug, Default)]
pub struct Skinned<B> {
    inner: B,
    pairs: Vec<Pair>,
    anchors: Vec<DVec2>,
    radii: Vec<f64>,
    inflated: Vec<Particle>,
    skin: f64,
    built_for: Option<(Boundary, [u64; 2])>,
}

impl<B: BroadPhase> Skinned<B> {
    fn still_valid(&self, particles: &[Particle], boundary: Boundary, size: DVec2) -> bool {
        if self.built_for != Some((boundary, [size.x.to_bits(), size.y.to_bits()]))
            || self.anchors.len() != particles.len()
        {
            return false;
        }
        let limit = 0.5 * self.skin;
        let limit_sq = limit * limit;
        particles
            .iter()
            .zip(self.anchors.iter().zip(&self.radii))
            .all(|(p, (anchor, &radius))| {
                p.radius == radius
                    && boundary.separation(*anchor, p.pos, size).length_squared() <= limit_sq
            })
    }

    fn rebuild(&mut self, particles: &[Particle], boundary: Boundary, size: DVec2) {
        let n = particles.len().max(1) as f64;
        let mean_radius = particles
            .iter()
            .map(|p| p.radius)
            .filter(|r| r.is_finite())
            .sum::<f64>()
            / n;
        self.skin = (SKIN_FRACTION * mean_radius).max(0.0);
        self.inflated.clear();
        self.inflated.extend(particles.iter().map(|p| Particle {
            radius: p.radius + 0.5 * self.skin,
            ..*p
        }));
        self.inner
            .candidate_pairs(&self.inflated, boundary, size, &mut self.pairs);
        self.anchors.clear();
        self.anchors.extend(particles.iter().map(|p| p.pos));
        self.radii.clear();
        self.radii.extend(particles.iter().map(|p| p.radius));
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
        out.extend_from_slice(&self.pairs);
    }
}
