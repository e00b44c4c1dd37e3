//! Step statistics: what the last step did and how long each stage took.

use crate::clock::Instant;
use serde::Serialize;
use std::time::Duration;

/// Measures consecutive stages: each [`Lap::lap`] returns the time since
/// the previous one.
pub(crate) struct Lap(Instant);

impl Lap {
    pub(crate) fn start() -> Self {
        Lap(Instant::now())
    }

    /// Time since the start (or the last lap).
    pub(crate) fn elapsed(&self) -> Duration {
        self.0.elapsed()
    }

    pub(crate) fn lap(&mut self) -> Duration {
        let now = Instant::now();
        let elapsed = now.duration_since(self.0);
        self.0 = now;
        elapsed
    }
}

/// Wall-clock time spent in each stage of one step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct StageTimings {
    /// Broad phase.
    pub broad_phase: Duration,
    /// Narrow phase.
    pub narrow_phase: Duration,
    /// Collision resolution and push-apart.
    pub resolution: Duration,
    /// Integration.
    pub integration: Duration,
    /// Boundaries.
    pub boundary: Duration,
}

impl StageTimings {
    /// Time for the whole step.
    pub fn total(&self) -> Duration {
        self.broad_phase + self.narrow_phase + self.resolution + self.integration + self.boundary
    }
}

/// Counts and extremes from one step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct StepStats {
    /// Pairs the broad phase proposed.
    pub candidate_pairs: usize,
    /// Pairs that overlapped.
    pub contacts: usize,
    /// Pair impacts resolved: approaching faster than the
    /// [`crate::impact::threshold`].
    pub pair_collisions: usize,
    /// Of the pair impacts, those `impulse` resolved where the discs
    /// touched, neither disc changed by an earlier contact of its pass:
    /// each keeps the angular momentum exactly (the rest: where they
    /// overlap, or a disc met twice in one pass; see
    /// [`crate::resolution::ResolutionReport::at_touch`]).
    pub at_touch: usize,
    /// Of the pair impacts, those resolved at the touch along a velocity an
    /// earlier contact of the pass had changed (a disc met twice in one
    /// pass): each moves the angular momentum by at most τ·J·|Δg|.
    pub at_touch_changed: usize,
    /// Contacts resolved on several threads side by side (by bands of
    /// height, or by spans of discs); the rest were resolved in order on one
    /// thread. The result is the same either way.
    pub contacts_side_by_side: usize,
    /// Discs that hit a wall faster than the threshold.
    pub wall_hits: usize,
    /// Resting contacts met, between discs and at walls: approaching, but
    /// slower than the threshold (counted apart from the impacts).
    pub resting_contacts: usize,
    /// Momentum the walls transferred, Σ m·|Δv| (kg·m/s).
    pub wall_impulse: f64,
    /// Deepest pair overlap before it was pushed apart (m).
    pub max_overlap: f64,
    /// Substeps the step was split into.
    pub substeps: u32,
    /// The largest distance a disc moved in one substep, in its own radii
    /// (fixed-step methods; 0 for `exact`, which never passes a disc
    /// through another). Above 1 a disc may have passed through another.
    pub max_travel: f64,
    /// Events the exact method processed (collisions, wall hits, cell
    /// crossings, re-predictions of stale events).
    pub events: usize,
    /// The exact method hit its per-step event cap and stopped early.
    pub truncated: bool,
    /// Overlapping pairs the exact method pushed apart before the step, as
    /// it took the discs over (after another method, an edit, or a scene
    /// that starts overlapping); 0 when it continued its last step.
    pub separated_pairs: usize,
    /// Potential energy those moves added (J): discs put back inside the
    /// walls rise (the pushes themselves keep each pair's centre of mass).
    pub separation_energy: f64,
    /// Per-stage wall-clock time.
    pub timings: StageTimings,
}
