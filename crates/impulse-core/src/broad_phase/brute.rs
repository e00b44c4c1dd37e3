//! Brute force: test every pair.
//!
//! For each i and every j > i, the bounding boxes of the two discs are
//! compared along x and y (with the minimum-image separation when periodic).
//! Cost: n(n−1)/2 tests per step, O(n²) time and O(1) extra memory. Pairs come
//! out in `(i, j)` order without sorting. It is the reference the other broad
//! phases are tested against, and the fastest for a few dozen discs.

use super::{BroadPhase, Pair};
use crate::boundary::Boundary;
use crate::particle::Particle;
use glam::DVec2;

/// Tests every pair i < j with a bounding-box check: O(n²).
#[derive(Clone, Copy, Debug, Default)]
pub struct BruteForce;

impl BroadPhase for BruteForce {
    fn candidate_pairs(
        &mut self,
        particles: &[Particle],
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    ) {
        out.clear();
        for (i, a) in particles.iter().enumerate() {
            for (j, b) in particles.iter().enumerate().skip(i + 1) {
                let reach = a.radius + b.radius;
                let d = boundary.separation(a.pos, b.pos, size).abs();
                if d.x <= reach && d.y <= reach {
                    out.push(Pair {
                        i: i as u32,
                        j: j as u32,
                    });
                }
            }
        }
    }
}
