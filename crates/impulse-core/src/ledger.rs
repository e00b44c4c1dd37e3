//! The collision ledger: the last collisions, each with both discs'
//! velocities before and after, so a lesson can show momentum and kinetic
//! energy per disc and in total across one collision, and the normal and
//! tangential components the collision law acts on.
//!
//! Off by default (a lab run does not pay for it); the window turns it on.

use glam::DVec2;
use std::collections::VecDeque;

/// One pair collision.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Collision {
    /// When (s, world time).
    pub time: f64,
    /// The two discs (indices into the world's particles at that moment).
    pub discs: [usize; 2],
    /// Unit normal from the first disc to the second.
    pub normal: DVec2,
    /// Their masses (kg).
    pub masses: [f64; 2],
    /// Velocities just before (m/s).
    pub before: [DVec2; 2],
    /// Velocities just after (m/s).
    pub after: [DVec2; 2],
    /// Their radii (m).
    pub radii: [f64; 2],
    /// Spins just before (rad/s, counter-clockwise).
    pub spins_before: [f64; 2],
    /// Spins just after: they differ only where contacts are rough.
    pub spins_after: [f64; 2],
}

impl Collision {
    /// Momentum of disc `k` (0 or 1) before and after.
    pub fn momentum(&self, k: usize) -> (DVec2, DVec2) {
        (
            self.masses[k] * self.before[k],
            self.masses[k] * self.after[k],
        )
    }

    /// Kinetic energy of disc `k` before and after.
    pub fn kinetic_energy(&self, k: usize) -> (f64, f64) {
        let e = |v: DVec2| 0.5 * self.masses[k] * v.length_squared();
        (e(self.before[k]), e(self.after[k]))
    }

    /// Rotational energy ½·I·ω² of disc `k` before and after.
    pub fn rotational_energy(&self, k: usize) -> (f64, f64) {
        let inertia = 0.5 * self.masses[k] * self.radii[k] * self.radii[k];
        let e = |w: f64| 0.5 * inertia * w * w;
        (e(self.spins_before[k]), e(self.spins_after[k]))
    }

    /// Change of the pair's total momentum and kinetic energy.
    pub fn total_change(&self) -> (DVec2, f64) {
        let mut dp = DVec2::ZERO;
        let mut dke = 0.0;
        for k in 0..2 {
            let (p0, p1) = self.momentum(k);
            let (e0, e1) = self.kinetic_energy(k);
            dp += p1 - p0;
            dke += e1 - e0;
        }
        (dp, dke)
    }

    /// Disc `k`'s velocity split along the normal and the tangent, before
    /// and after: ((normal, tangent) before, (normal, tangent) after).
    pub fn components(&self, k: usize) -> ((f64, f64), (f64, f64)) {
        let t = self.normal.perp();
        let split = |v: DVec2| (v.dot(self.normal), v.dot(t));
        (split(self.before[k]), split(self.after[k]))
    }
}

/// The last collisions, newest last.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ledger {
    entries: VecDeque<Collision>,
    capacity: usize,
    /// Collisions recorded since it was turned on.
    pub recorded: u64,
}

impl Ledger {
    /// Keeps the last `capacity` collisions from now on (0 turns it off).
    pub fn keep(&mut self, capacity: usize) {
        self.capacity = capacity;
        while self.entries.len() > capacity {
            self.entries.pop_front();
        }
    }

    /// Whether collisions are being recorded.
    pub fn is_on(&self) -> bool {
        self.capacity > 0
    }

    /// Records one collision (nothing when off).
    pub fn push(&mut self, collision: Collision) {
        if self.capacity == 0 {
            return;
        }
        if self.entries.len() == self.capacity {
            self.entries.pop_front();
        }
        self.entries.push_back(collision);
        self.recorded += 1;
    }

    /// The kept collisions, oldest first.
    pub fn entries(&self) -> impl DoubleEndedIterator<Item = &Collision> {
        self.entries.iter()
    }

    /// The newest collision.
    pub fn last(&self) -> Option<&Collision> {
        self.entries.back()
    }

    /// Forgets the kept collisions (a new scene or a rewind).
    pub fn clear(&mut self) {
        self.entries.clear();
    }
}
