//! The contact solve of held discs: their contacts, projected
//! Gauss–Seidel over them, and the settle that leaves no gap closing
//! within the step.

use super::{FIXES, HOLD_SKIN, HOLD_SWEEPS};
use crate::method::exact::sleep::Rest;
use crate::method::exact::Sim;
use glam::DVec2;

/// A contact of the solve: held body `a` with body `b` (held, or still
/// when `b_moves` is false: a sleeper or a wall), unit normal from a to b.
#[derive(Clone, Copy, Debug)]
pub(super) struct Contact {
    pub(super) a: u32,
    /// The other body, or `u32::MAX` for a wall.
    pub(super) b: u32,
    pub(super) normal: DVec2,
    /// The fastest closing the step allows (m/s): half the gap over dt.
    pub(super) allowed: f64,
    /// 1 / (1/m_a + 1/m_b), or m_a against something still.
    pub(super) mass: f64,
    /// Impulse so far (never negative).
    pub(super) impulse: f64,
    /// Height of the contact, for the bottom-up order.
    pub(super) height: f64,
}

impl Contact {
    /// Identifies the contact from one step to the next.
    fn key(&self) -> u64 {
        let other = if self.b == u32::MAX {
            // Walls by their direction.
            let side = (self.normal.x > 0.5) as u32
                | ((self.normal.y > 0.5) as u32) << 1
                | ((self.normal.y.abs() > 0.5) as u32) << 2;
            u32::MAX - side
        } else {
            self.b
        };
        (u64::from(self.a) << 32) | u64::from(other)
    }
}

impl Sim {
    /// Projected Gauss–Seidel over `contacts`, warm-started with the
    /// impulses of the contacts that were there last step.
    pub(super) fn solve(&mut self, contacts: &mut [Contact]) {
        let mut warm = std::mem::take(&mut self.warm);
        for c in contacts.iter_mut() {
            if let Ok(k) = warm.binary_search_by_key(&c.key(), |w| w.0) {
                let impulse = warm[k].1;
                c.impulse = impulse;
                self.push_contact(c, impulse);
            }
        }
        for _ in 0..HOLD_SWEEPS {
            for c in contacts.iter_mut() {
                let closing = self.closing(c);
                let total = (c.impulse + c.mass * (closing - c.allowed)).max(0.0);
                let change = total - c.impulse;
                if change != 0.0 {
                    c.impulse = total;
                    self.push_contact(c, change);
                }
            }
        }
        warm.clear();
        warm.extend(
            contacts
                .iter()
                .filter(|c| c.impulse > 0.0)
                .map(|c| (c.key(), c.impulse)),
        );
        warm.sort_unstable_by_key(|w| w.0);
        self.warm = warm;
    }

    /// Whether contact `c`'s other side is a held disc (which the solve
    /// moves) rather than a sleeper or a wall.
    fn other_moves(&self, c: &Contact) -> bool {
        c.b != u32::MAX && self.rest[c.b as usize] == Rest::Held
    }

    /// How fast contact `c` closes (m/s).
    fn closing(&self, c: &Contact) -> f64 {
        let va = self.bodies[c.a as usize].vel;
        let vb = if self.other_moves(c) {
            self.bodies[c.b as usize].vel
        } else {
            DVec2::ZERO
        };
        (va - vb).dot(c.normal)
    }

    /// Applies `impulse` (N·s) along contact `c`, pushing its sides apart.
    fn push_contact(&mut self, c: &Contact, impulse: f64) {
        let ma = self.aux[c.a as usize].mass;
        self.bodies[c.a as usize].vel -= c.normal * (impulse / ma);
        if self.other_moves(c) {
            let mb = self.aux[c.b as usize].mass;
            self.bodies[c.b as usize].vel += c.normal * (impulse / mb);
        }
    }

    /// Stops every `held` disc that would, flying straight, close the gap
    /// to a held disc, a sleeper or a wall within the step `dt` (both
    /// discs of a held pair), and checks the neighbours of each stopped one
    /// again, so that held discs, which meet those without events, never
    /// overlap them.
    pub(super) fn stop_closing(&mut self, held: &[u32], dt: f64) {
        self.settle(held.to_vec(), dt, FIXES);
    }

    /// Takes out of held discs, starting from those in `queue`, whatever
    /// relative velocity would close a gap (to a held disc, a sleeper, a
    /// wall) within `left` seconds, one pair at a time (perfectly inelastic
    /// along the normal, down to closing half the gap), and follows each
    /// change to the neighbours; a disc changed [`FIXES`] times is stopped
    /// instead, with what it presses on. Returns the discs whose velocity
    /// changed (all advanced to now).
    pub(super) fn settle(&mut self, mut queue: Vec<u32>, left: f64, limit: u8) -> Vec<u32> {
        let mut counts = std::mem::take(&mut self.fix_counts);
        counts.resize(self.bodies.len(), 0);
        let mut fixed: Vec<u32> = Vec::new();
        let mut count = |k: u32| -> u8 {
            let c = &mut counts[k as usize];
            if *c == 0 {
                fixed.push(k);
            }
            *c = c.saturating_add(1);
            *c
        };
        let mut near = Vec::new();
        while let Some(i) = queue.pop() {
            if self.rest[i as usize] != Rest::Held {
                continue;
            }
            self.advance_to(i, self.now);
            let me = self.bodies[i as usize];
            let mut pushes: Vec<(u32, DVec2, f64)> = Vec::new();
            for (normal, gap) in self.walls_near(me.pos, me.radius, f64::INFINITY) {
                let closing = me.vel.dot(normal);
                if closing > 0.0 && closing * left >= gap {
                    pushes.push((u32::MAX, normal, 0.5 * gap.max(0.0) / left));
                }
            }
            self.gather_near(i, &mut near);
            for &k in &near {
                let its = self.rest[k as usize];
                if its == Rest::Free {
                    continue;
                }
                self.advance_to(k, self.now);
                let other = self.bodies[k as usize];
                let Some((normal, gap)) =
                    self.normal_and_gap(me.pos, me.radius, other.pos, other.radius)
                else {
                    continue;
                };
                let closing = (me.vel - other.vel).dot(normal);
                let gap = gap.max(0.0);
                if closing > 0.0 && closing * left >= gap {
                    let k = if its == Rest::Held { k } else { u32::MAX };
                    pushes.push((k, normal, 0.5 * gap / left));
                }
            }
            for (k, normal, target) in pushes {
                let vb = if k == u32::MAX {
                    DVec2::ZERO
                } else {
                    self.bodies[k as usize].vel
                };
                let excess = (self.bodies[i as usize].vel - vb).dot(normal) - target;
                if excess <= 0.0 {
                    continue; // an earlier push settled it
                }
                let mine = count(i);
                let its = if k == u32::MAX { 0 } else { count(k) };
                let stuck = mine > limit || its > limit;
                if stuck {
                    for s in [i, k] {
                        if s != u32::MAX && self.bodies[s as usize].vel != DVec2::ZERO {
                            self.bodies[s as usize].vel = DVec2::ZERO;
                            queue.push(s);
                        }
                    }
                    continue;
                }
                let ma = self.aux[i as usize].mass;
                let mass = if k == u32::MAX {
                    ma
                } else {
                    let mb = self.aux[k as usize].mass;
                    ma * mb / (ma + mb)
                };
                self.bodies[i as usize].vel -= normal * (mass * excess / ma);
                queue.push(i);
                if k != u32::MAX {
                    let mb = self.aux[k as usize].mass;
                    self.bodies[k as usize].vel += normal * (mass * excess / mb);
                    queue.push(k);
                }
            }
        }
        for &k in &fixed {
            counts[k as usize] = 0;
        }
        self.fix_counts = counts;
        fixed
    }

    /// The contacts of the `held` discs (all at the current time) with each
    /// other, with sleepers and with walls.
    pub(super) fn contacts_of(&mut self, held: &[u32], dt: f64) -> Vec<Contact> {
        let mut contacts = Vec::new();
        let mut near = Vec::new();
        let up = -self.laws.gravity.normalize_or_zero();
        for &i in held {
            let me = self.bodies[i as usize];
            let ma = self.aux[i as usize].mass;
            for (normal, gap) in self.walls_near(me.pos, me.radius, HOLD_SKIN * me.radius) {
                contacts.push(Contact {
                    a: i,
                    b: u32::MAX,
                    normal,
                    allowed: 0.5 * gap.max(0.0) / dt,
                    mass: ma,
                    impulse: 0.0,
                    height: (me.pos + me.radius * normal).dot(up),
                });
            }
            self.gather_near(i, &mut near);
            for &k in &near {
                let its = self.rest[k as usize];
                // Each pair of held discs once; flying ones meet by events.
                if its == Rest::Free || (its == Rest::Held && k < i) {
                    continue;
                }
                let other = self.bodies[k as usize];
                let Some((normal, gap)) =
                    self.normal_and_gap(me.pos, me.radius, other.pos, other.radius)
                else {
                    continue;
                };
                let vb = if its == Rest::Held {
                    other.vel
                } else {
                    DVec2::ZERO
                };
                let closing = (me.vel - vb).dot(normal);
                let reach = (HOLD_SKIN * me.radius.min(other.radius)).max(2.0 * closing * dt);
                if gap > reach {
                    continue;
                }
                let mass = if its == Rest::Held {
                    let mb = self.aux[k as usize].mass;
                    ma * mb / (ma + mb)
                } else {
                    ma
                };
                contacts.push(Contact {
                    a: i,
                    b: k,
                    normal,
                    allowed: 0.5 * gap.max(0.0) / dt,
                    mass,
                    impulse: 0.0,
                    height: (me.pos + me.radius * normal).dot(up),
                });
            }
        }
        contacts
    }
}
