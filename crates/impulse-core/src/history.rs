//! The recent past, for rewinding: snapshots of the discs taken as the world
//! steps, kept within a memory budget, that can be put back so a run can be
//! scrubbed backwards and forwards and resumed from any moment (with
//! different laws if the user changes them first).
//!
//! A snapshot holds what changes while stepping: the discs, the clock, the
//! running totals and the ledger of the last impacts, so that after a
//! rewind the counters and the ledger still agree. The laws (restitution, gravity, boundary, method)
//! are not restored: they belong to the user, who may rewind precisely to
//! try the same moment with another restitution.

use crate::{Particle, World};
use std::collections::VecDeque;

/// Default memory budget for the snapshots (bytes).
pub const DEFAULT_BUDGET_BYTES: usize = 256 << 20;

/// One moment of a run.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// Simulated time (s).
    pub time: f64,
    /// Steps taken.
    pub steps: u64,
    /// The discs.
    pub particles: Vec<Particle>,
    /// Pair collisions so far.
    pub total_pair_collisions: u64,
    /// Wall hits so far.
    pub total_wall_hits: u64,
    /// Wall impulse so far (kg·m/s).
    pub total_wall_impulse: f64,
    /// The ledger at that moment.
    pub ledger: crate::ledger::Ledger,
}

impl Snapshot {
    /// The moving parts of `world`.
    pub fn of(world: &World) -> Snapshot {
        Snapshot {
            time: world.time,
            steps: world.steps,
            particles: world.particles.clone(),
            total_pair_collisions: world.total_pair_collisions,
            total_wall_hits: world.total_wall_hits,
            total_wall_impulse: world.total_wall_impulse,
            ledger: world.ledger.clone(),
        }
    }

    /// Puts this moment back into `world` (its laws are left alone).
    pub fn restore(&self, world: &mut World) {
        world.time = self.time;
        world.steps = self.steps;
        world.particles.clone_from(&self.particles);
        world.total_pair_collisions = self.total_pair_collisions;
        world.total_wall_hits = self.total_wall_hits;
        world.total_wall_impulse = self.total_wall_impulse;
        world.ledger.clone_from(&self.ledger);
    }

    fn bytes(&self) -> usize {
        std::mem::size_of::<Snapshot>()
            + self.particles.len() * std::mem::size_of::<Particle>()
            + self.ledger.len() * std::mem::size_of::<crate::ledger::Impact>()
    }
}

/// Snapshots, oldest first, within a memory budget, and a cursor: `None`
/// while the run is live, `Some(k)` while the user looks at snapshot k.
#[derive(Clone, Debug)]
pub struct History {
    snapshots: VecDeque<Snapshot>,
    bytes: usize,
    budget: usize,
    cursor: Option<usize>,
}

impl Default for History {
    fn default() -> Self {
        History::with_budget(DEFAULT_BUDGET_BYTES)
    }
}

impl History {
    /// An empty history that keeps at most `budget` bytes of snapshots
    /// (always at least the newest one).
    pub fn with_budget(budget: usize) -> History {
        History {
            snapshots: VecDeque::new(),
            bytes: 0,
            budget,
            cursor: None,
        }
    }

    /// Records the world as it is now. While scrubbed back, recording
    /// resumes the run from the moment shown: the later snapshots go.
    pub fn record(&mut self, world: &World) {
        if let Some(k) = self.cursor.take() {
            while self.snapshots.len() > k + 1 {
                if let Some(s) = self.snapshots.pop_back() {
                    self.bytes -= s.bytes();
                }
            }
        }
        let snapshot = Snapshot::of(world);
        self.bytes += snapshot.bytes();
        self.snapshots.push_back(snapshot);
        while self.bytes > self.budget && self.snapshots.len() > 1 {
            if let Some(s) = self.snapshots.pop_front() {
                self.bytes -= s.bytes();
            }
        }
    }

    /// Forgets everything (a new scene).
    pub fn clear(&mut self) {
        self.snapshots.clear();
        self.bytes = 0;
        self.cursor = None;
    }

    /// Forgets the snapshots from `time` on (an undo back to a moment of
    /// this run: what came after it belongs to the undone timeline) and
    /// stops showing one.
    pub fn keep_before(&mut self, time: f64) {
        while self.snapshots.back().is_some_and(|s| s.time >= time) {
            if let Some(s) = self.snapshots.pop_back() {
                self.bytes -= s.bytes();
            }
        }
        self.cursor = None;
    }

    /// How many snapshots are kept.
    pub fn len(&self) -> usize {
        self.snapshots.len()
    }

    /// Whether nothing is recorded.
    pub fn is_empty(&self) -> bool {
        self.snapshots.is_empty()
    }

    /// The snapshot shown, if the user has scrubbed back.
    pub fn cursor(&self) -> Option<usize> {
        self.cursor
    }

    /// The time span kept: (oldest, newest) simulated time.
    pub fn span(&self) -> Option<(f64, f64)> {
        Some((self.snapshots.front()?.time, self.snapshots.back()?.time))
    }

    /// Moves the cursor by `delta` snapshots (negative: back in time),
    /// clamped to what is kept, and puts that moment into `world`. Returns
    /// the time shown. Moving forward past the newest snapshot stays there.
    pub fn scrub(&mut self, world: &mut World, delta: isize) -> Option<f64> {
        let last = self.snapshots.len().checked_sub(1)?;
        let from = self.cursor.unwrap_or(last);
        let to = from.saturating_add_signed(delta).min(last);
        self.show(world, to)
    }

    /// Back to the run: the cursor let go, if it shows the newest snapshot
    /// (which is where the run is). Returns whether it did.
    pub fn release_at_newest(&mut self) -> bool {
        let newest = self.snapshots.len().checked_sub(1);
        let live = self.cursor.is_some() && self.cursor == newest;
        if live {
            self.cursor = None;
        }
        live
    }

    /// Puts snapshot `k` into `world` and points the cursor at it.
    pub fn show(&mut self, world: &mut World, k: usize) -> Option<f64> {
        let snapshot = self.snapshots.get(k)?;
        snapshot.restore(world);
        self.cursor = Some(k);
        Some(snapshot.time)
    }

    /// Bytes the kept snapshots use.
    pub fn bytes(&self) -> usize {
        self.bytes
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::Gas;

    fn gas() -> World {
        Gas {
            count: 50,
            ..Gas::default()
        }
        .build()
    }

    #[test]
    fn the_budget_drops_the_oldest_but_keeps_the_newest() {
        let mut world = gas();
        let one = Snapshot::of(&world).bytes();
        let mut h = History::with_budget(3 * one);
        for _ in 0..10 {
            world.step(0.01);
            h.record(&world);
        }
        assert_eq!(h.len(), 3);
        assert!(h.bytes() <= 3 * one);
        let (oldest, newest) = h.span().unwrap();
        assert_eq!(newest, world.time);
        assert!((newest - oldest - 0.02).abs() < 1e-12);
        let mut tiny = History::with_budget(1);
        tiny.record(&world);
        assert_eq!(tiny.len(), 1, "the newest is always kept");
    }

    #[test]
    fn scrubbing_clamps_and_recording_after_it_drops_the_future() {
        let mut world = gas();
        let mut h = History::default();
        for _ in 0..5 {
            world.step(0.01);
            h.record(&world);
        }
        let t = h.scrub(&mut world, -2).unwrap();
        assert_eq!(h.cursor(), Some(2));
        assert_eq!(world.time, t);
        assert_eq!(h.scrub(&mut world, -100), Some(h.span().unwrap().0));
        assert_eq!(h.cursor(), Some(0));
        h.scrub(&mut world, 1);
        world.step(0.01);
        h.record(&world);
        assert_eq!(
            h.len(),
            3,
            "snapshots 2..4 were a future that did not happen"
        );
        assert_eq!(h.cursor(), None);
    }
}
