//! Broad phase, the first stage of a step: list the pairs that *might* touch.
//!
//! Every broad phase answers the same question through [`BroadPhase`], so one
//! test can hold each to the brute-force answer. Part 1 ships the O(n²) brute
//! force that the seed presentation used.

use crate::boundary::Boundary;
use crate::particle::Particle;
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// A candidate pair of particle indices, always with `i < j`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Pair {
    /// Lower index.
    pub i: u32,
    /// Higher index.
    pub j: u32,
}

/// Finds candidate pairs: a superset of the overlapping pairs.
pub trait BroadPhase {
    /// Replaces `out` with the candidate pairs, each once, `i < j`, in
    /// ascending order (so that resolution order, and hence results, do not
    /// depend on the broad phase).
    fn candidate_pairs(
        &mut self,
        particles: &[Particle],
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    );
}

/// The broad phases a world can use; scene files and the CLI name them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum BroadPhaseKind {
    /// Every pair i < j: O(n²).
    #[default]
    Brute,
}

impl BroadPhaseKind {
    /// A fresh broad phase of this kind.
    pub fn build(self) -> Box<dyn BroadPhase + Send> {
        match self {
            BroadPhaseKind::Brute => Box::new(BruteForce),
        }
    }

    /// The lowercase name used in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            BroadPhaseKind::Brute => "brute",
        }
    }
}

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
