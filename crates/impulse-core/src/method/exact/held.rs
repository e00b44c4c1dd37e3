//! Discs in lasting contact: a contact solver at the start of each step.
//!
//! Under gravity, the weight of a pile has to reach the floor. Hard discs
//! carry it only by collisions, g·N/(2v) of them a second for a disc under
//! N layers that rattles at v, so a pile that is still moving (fed from
//! above, or flowing sideways, as frictionless discs do) costs events
//! without end, and sleeping (see [`super::sleep`]) only helps once it is
//! still. Here a disc in lasting contact is *held*: a hybrid of
//! event-driven and time-stepped contact dynamics, the contacts among held
//! discs solved once a step, as a fixed-step method does, without events.
//!
//! - **Becoming held.** At the start of a step, a disc that collided
//!   [`HOLD_HITS`] times or more in the step before, and a flying disc that
//!   touches a held one (within [`HOLD_SKIN`]) barely moving against it
//!   (slower than an impact), is held.
//! - **The solve.** Every held disc takes the whole step's gravity at once
//!   (a kick of g·dt). Projected Gauss–Seidel over the contacts of held
//!   discs (with each other, with sleepers, with walls), warm-started with
//!   last step's impulses (E. Catto's "sequential impulses"), takes out of
//!   their velocities whatever would close a gap faster than half of it in
//!   the step: restitution zero, lasting contacts do not bounce. Held discs
//!   then fly straight for the step (symplectic Euler: kick, then drift).
//! - **No overlap.** Held discs meet each other without events, so the
//!   solve must leave no pair of them closing a gap within the step: a
//!   straight flight that closes less than the gap cannot overlap. Any pair
//!   the sweeps left closing too fast is stopped, both discs, and their
//!   neighbours are checked again (stopping only ever takes energy out).
//!   Everything else meets a held disc by events, as before: flying discs
//!   on the parabola of their relative motion, sleepers and walls on a line.
//! - **Leaving.** A held disc whose course an event changes (a hit by a
//!   flying disc, a wall, a sleeper) flies again at once, giving back the
//!   part of its kick the rest of the step has not used. One left without
//!   contacts flies again at the next step; a slow one that is held up
//!   falls asleep there.
//! - **Energy.** The kick and drift of a disc at rest on its support change
//!   nothing; a disc falling freely loses ½·m·g²·dt² a step; the solve only
//!   takes energy out, except that a support's push, during the drift,
//!   lifts. The step's change for the held discs, Σ ½m|v|² − ½m|v₀|² −
//!   m·g·v·dt, is computed before the drift, and if it is positive their
//!   velocities are scaled down until it is not.
//!
//! What it changes: a held disc falls on a straight line within a step
//! instead of a parabola (at most ½·g·dt² off, 85 µm at 240 steps a
//! second), lasting contacts do not bounce, and a rattling pile is damped
//! where stopping a pair was needed.

use super::sleep::Rest;
use super::Sim;
use glam::DVec2;

/// Collisions in one step from which a disc is in lasting contact.
pub const HOLD_HITS: u32 = 4;
/// Gaps up to this fraction of the smaller radius are contacts for the
/// solve.
pub const HOLD_SKIN: f64 = 0.05;
/// Changes to one disc's velocity in [`Sim::settle`] before it is
/// stopped instead.
pub const FIXES: u8 = 8;
/// A held disc whose velocity after the solve is under this fraction of
/// g·dt is in balance: the solve carried its weight.
pub const BALANCED: f64 = 0.1;
/// How long a held disc must have been barely moving (under
/// [`BALANCED`]·g·dt) before it may fall asleep with its group (s).
pub const QUIET_TIME: f64 = 0.1;
/// Sweeps of the contact solve.
pub const HOLD_SWEEPS: usize = 20;

/// A contact of the solve: held body `a` with body `b` (held, or still
/// when `b_moves` is false: a sleeper or a wall), unit normal from a to b.
#[derive(Clone, Copy, Debug)]
struct Contact {
    a: u32,
    /// The other body, or `u32::MAX` for a wall.
    b: u32,
    normal: DVec2,
    /// The fastest closing the step allows (m/s): half the gap over dt.
    allowed: f64,
    /// 1 / (1/m_a + 1/m_b), or m_a against something still.
    mass: f64,
    /// Impulse so far (never negative).
    impulse: f64,
    /// Height of the contact, for the bottom-up order.
    height: f64,
}

impl Contact {
    /// Identifies the contact from one step to the next.
    fn key(&self) -> u64 {
        let other = if self.b == u32::MAX {
            // Walls by their direction.
            let side = (self.normal.x > 0.5) as u32 | ((self.normal.y > 0.5) as u32) << 1 | ((self.normal.y.abs() > 0.5) as u32) << 2;
            u32::MAX - side
        } else {
            self.b
        };
        (u64::from(self.a) << 32) | u64::from(other)
    }
}

impl Sim {
    /// Counts a collision of body `i` towards [`HOLD_HITS`].
    #[inline]
    pub(super) fn tally(&mut self, i: u32) {
        if self.sleeping {
            self.hits[i as usize] = self.hits[i as usize].saturating_add(1);
        }
    }

    /// Whether this world holds discs at all: under gravity, with walls,
    /// smooth (the solve has no friction).
    fn holds(&self) -> bool {
        self.sleeping && !self.rough && self.laws.boundary == crate::boundary::Boundary::Box
    }

    /// The walls within `reach` of a disc at `pos` of `radius`: for each,
    /// the unit normal from the disc into it and the gap.
    fn walls_near(&self, pos: DVec2, radius: f64, reach: f64) -> Vec<(DVec2, f64)> {
        let mut walls = Vec::new();
        for axis in 0..2 {
            for upper in [false, true] {
                if !self.laws.walls.at(axis, upper) {
                    continue;
                }
                let gap = if upper {
                    self.laws.size[axis] - radius - pos[axis]
                } else {
                    pos[axis] - radius
                };
                if gap <= reach {
                    let mut normal = DVec2::ZERO;
                    normal[axis] = if upper { 1.0 } else { -1.0 };
                    walls.push((normal, gap));
                }
            }
        }
        walls
    }

    /// Kinetic plus potential energy of the translations (J), every body
    /// at the current time.
    fn energy_now(&self) -> f64 {
        let g = self.laws.gravity;
        self.bodies
            .iter()
            .zip(&self.aux)
            .map(|(b, a)| a.mass * (0.5 * b.vel.length_squared() - g.dot(b.pos)))
            .sum()
    }

    /// At the start of a step (time 0, every body current): makes the
    /// discs in lasting contact held, kicks them with the step's gravity,
    /// solves their contacts, and lets go of those without any; see the
    /// module doc.
    pub(super) fn hold(&mut self, dt: f64) {
        self.energy_at_start = None;
        if !self.holds() {
            return;
        }
        let g = self.laws.gravity;
        let n = self.bodies.len();
        let mut held: Vec<u32> = Vec::new();
        let mut chosen = vec![false; n];
        for i in 0..n as u32 {
            let rest = self.rest[i as usize];
            let busy = self.hits[i as usize] >= HOLD_HITS;
            self.hits[i as usize] = 0;
            if rest == Rest::Free {
                self.quiet[i as usize] = 0;
            }
            if rest == Rest::Held || (rest == Rest::Free && busy) {
                held.push(i);
                chosen[i as usize] = true;
            }
        }
        if held.is_empty() {
            return;
        }
        self.energy_at_start = Some(self.energy_now());
        let joining = self.joining(&held, &mut chosen);
        held.extend(joining);
        for &i in &held {
            if self.rest[i as usize] != Rest::Held {
                self.set_rest(i, Rest::Held);
            }
        }
        let start: Vec<DVec2> = held.iter().map(|&i| self.bodies[i as usize].vel).collect();
        for &i in &held {
            self.bodies[i as usize].vel += g * dt;
        }
        let kicked: Vec<DVec2> = held.iter().map(|&i| self.bodies[i as usize].vel).collect();
        let mut contacts = self.contacts_of(&held, dt);
        contacts.sort_unstable_by(|a, b| a.height.total_cmp(&b.height));
        self.solve(&mut contacts);
        self.take_no_energy_in(&held, &kicked);
        self.stop_closing(&held, dt);
        // Quiet: barely moving, step after step, for QUIET_TIME.
        let needed = (QUIET_TIME / dt).ceil() as u32;
        let carried: Vec<bool> = held
            .iter()
            .map(|&i| {
                let q = &mut self.quiet[i as usize];
                *q = if self.bodies[i as usize].vel.length() <= BALANCED * g.length() * dt {
                    q.saturating_add(1)
                } else {
                    0
                };
                *q >= needed
            })
            .collect();
        let mut touched = vec![false; n];
        for c in &contacts {
            touched[c.a as usize] = true;
            if c.b != u32::MAX {
                touched[c.b as usize] = true;
            }
        }
        // Bottom up, so a disc whose supports just fell asleep can follow.
        let mut order: Vec<usize> = (0..held.len()).collect();
        order.sort_unstable_by(|&a, &b| {
            let (pa, pb) = (self.bodies[held[a] as usize].pos, self.bodies[held[b] as usize].pos);
            (-pa.dot(g)).total_cmp(&-pb.dot(g))
        });
        // Again while any falls asleep: a disc on a held one may be
        // lower than it.
        let mut awake = order;
        loop {
            let before = awake.len();
            awake.retain(|&k| !self.maybe_sleep(held[k]));
            if awake.len() == before {
                break;
            }
        }
        self.sleep_still_groups(&held, &mut awake, &carried, &contacts);
        for &k in &awake {
            let i = held[k];
            if !touched[i as usize] {
                // No contact to solve: it flies as any, if it can.
                self.let_go_keeping_energy(i);
            }
        }
        // What stays held pays for its step.
        let (staying, from): (Vec<u32>, Vec<DVec2>) = awake
            .iter()
            .map(|&k| (held[k], start[k]))
            .filter(|&(i, _)| self.rest[i as usize] == Rest::Held)
            .unzip();
        self.pay_ahead(&staying, &from, dt);
        for &i in &held {
            self.paid[i as usize] = self.bodies[i as usize].vel;
        }
        for &i in &held {
            // Its course changed, or its way of moving did.
            self.bodies[i as usize].gen += 1;
        }
        for &i in &held {
            self.predict(i);
        }
    }

    /// Puts to sleep, together, the held discs (indices into `held`, from
    /// `awake`) that are slow and whose weight the solve carried (`carried`)
    /// and that rest (through `contacts`) only on such discs or on still
    /// ones: a group leaning on each other, none of them held up by
    /// sleepers and walls alone (see [`Sim::maybe_sleep`]), but all in
    /// balance.
    fn sleep_still_groups(&mut self, held: &[u32], awake: &mut Vec<usize>, carried: &[bool], contacts: &[Contact]) {
        const LEVEL: f64 = 1e-9;
        let up = -self.laws.gravity.normalize();
        let n = self.bodies.len();
        let mut still = vec![false; n];
        for &k in awake.iter() {
            let i = held[k];
            still[i as usize] = carried[k] && self.bodies[i as usize].vel.length() < self.sleep_speed(i);
        }
        loop {
            let mut changed = false;
            for c in contacts {
                if c.impulse <= 0.0 || c.b == u32::MAX || self.rest[c.b as usize] != Rest::Held {
                    continue;
                }
                // A disc resting on one that is not still cannot sleep.
                let (a, b) = (c.a as usize, c.b as usize);
                let rise = c.normal.dot(up); // of b over a, per metre apart
                if rise < LEVEL && still[a] && !still[b] {
                    still[a] = false;
                    changed = true;
                }
                if rise > -LEVEL && still[b] && !still[a] {
                    still[b] = false;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        awake.retain(|&k| {
            let i = held[k];
            if still[i as usize] {
                self.sleep_now(i);
            }
            !still[i as usize]
        });
    }

    /// Slows the `held` discs (velocities at the start of the step in
    /// `start`), all by one factor, until the step they are set to fly,
    /// straight for `dt`, gains no energy: Σ ½m|v|² − m·g·v·dt − ½m|v₀|²
    /// ≤ 0. A common factor only slows every approach, so no gap the solve
    /// left open closes.
    fn pay_ahead(&mut self, held: &[u32], start: &[DVec2], dt: f64) {
        let g = self.laws.gravity;
        let (mut quadratic, mut linear, mut constant) = (0.0, 0.0, 0.0);
        for (&i, v0) in held.iter().zip(start) {
            let m = self.aux[i as usize].mass;
            let v = self.bodies[i as usize].vel;
            quadratic += 0.5 * m * v.length_squared();
            linear -= m * g.dot(v) * dt;
            constant -= 0.5 * m * v0.length_squared();
        }
        // E(c) = quadratic·c² + linear·c + constant, E(0) ≤ 0; the largest
        // c in [0, 1] with E(c) ≤ 0.
        if quadratic + linear + constant <= 0.0 {
            return;
        }
        let root = (-linear + (linear * linear - 4.0 * quadratic * constant).max(0.0).sqrt())
            / (2.0 * quadratic);
        let c = (root * (1.0 - 1e-12)).clamp(0.0, 1.0);
        for &i in held {
            self.bodies[i as usize].vel *= c;
        }
    }

    /// At the end of the step (`end`, before the bodies are written): if
    /// the held discs' kicks, drifts and let-gos left the total energy
    /// above where the step began, slows the held discs (else every moving
    /// one) by the least that takes the excess out. Returns the energy
    /// taken (J).
    pub(super) fn pay_back(&mut self, end: f64) -> f64 {
        let Some(start) = self.energy_at_start.take() else {
            return 0.0;
        };
        for k in 0..self.bodies.len() as u32 {
            self.advance_to(k, end);
        }
        let excess = self.energy_now() - start;
        if excess <= 0.0 {
            return 0.0;
        }
        self.now = end;
        for only_held in [true, false] {
            let movers: Vec<u32> = (0..self.bodies.len() as u32)
                .filter(|&k| match self.rest[k as usize] {
                    Rest::Held => true,
                    Rest::Free => !only_held,
                    Rest::Asleep => false,
                })
                .collect();
            let kinetic: f64 = movers
                .iter()
                .map(|&k| 0.5 * self.aux[k as usize].mass * self.bodies[k as usize].vel.length_squared())
                .sum();
            if kinetic > excess || !only_held {
                let scale = (1.0 - excess / kinetic).max(0.0).sqrt() * (1.0 - 1e-15);
                for &k in &movers {
                    self.bodies[k as usize].vel *= scale;
                    self.bodies[k as usize].gen += 1;
                }
                for &k in &movers {
                    self.predict(k);
                }
                return excess;
            }
        }
        excess
    }

    /// Scales back what the solve did to the `held` discs' velocities
    /// (`before` it, in the same order) if it added kinetic energy, which
    /// sweeps stopped short of convergence can; then it takes some out or
    /// none.
    fn take_no_energy_in(&mut self, held: &[u32], before: &[DVec2]) {
        let (mut linear, mut quadratic) = (0.0, 0.0);
        for (&i, v) in held.iter().zip(before) {
            let m = self.aux[i as usize].mass;
            let change = self.bodies[i as usize].vel - *v;
            linear += m * v.dot(change);
            quadratic += 0.5 * m * change.length_squared();
        }
        // KE(s) − KE₀ = s·linear + s²·quadratic, with s = 1 the solve.
        if linear + quadratic <= 0.0 {
            return;
        }
        let s = if linear < 0.0 {
            (-linear / quadratic) * (1.0 - 1e-9)
        } else {
            0.0
        };
        for (&i, v) in held.iter().zip(before) {
            let change = self.bodies[i as usize].vel - *v;
            self.bodies[i as usize].vel = *v + change * s;
        }
    }

    /// Flying discs (at the current time) that touch a `held` one and
    /// barely move against it; marks them `chosen`.
    fn joining(&mut self, held: &[u32], chosen: &mut [bool]) -> Vec<u32> {
        let mut joining = Vec::new();
        let mut near = Vec::new();
        for &i in held {
            let me = self.bodies[i as usize];
            near.clear();
            self.grid.for_each_neighbour(me.cell, |c, _| {
                near.extend(self.grid.members(&self.bodies, c));
            });
            for &k in &near {
                if chosen[k as usize] || self.rest[k as usize] != Rest::Free {
                    continue;
                }
                let other = self.bodies[k as usize];
                let d = self.laws.boundary.separation(me.pos, other.pos, self.laws.size);
                let dist = d.length();
                let gap = dist - me.radius - other.radius;
                if dist > 0.0
                    && gap <= HOLD_SKIN * me.radius.min(other.radius)
                    && (me.vel - other.vel).dot(d / dist).abs() < self.impact_speed
                {
                    chosen[k as usize] = true;
                    joining.push(k);
                }
            }
        }
        joining
    }

    /// Projected Gauss–Seidel over `contacts`, warm-started with the
    /// impulses of the contacts that were there last step.
    fn solve(&mut self, contacts: &mut [Contact]) {
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
    fn stop_closing(&mut self, held: &[u32], dt: f64) {
        self.settle(held.to_vec(), dt, FIXES);
    }

    /// Takes out of held discs, starting from those in `queue`, whatever
    /// relative velocity would close a gap (to a held disc, a sleeper, a
    /// wall) within `left` seconds, one pair at a time (perfectly inelastic
    /// along the normal, down to closing half the gap), and follows each
    /// change to the neighbours; a disc changed [`FIXES`] times is stopped
    /// instead, with what it presses on. Returns the discs whose velocity
    /// changed (all advanced to now).
    fn settle(&mut self, mut queue: Vec<u32>, left: f64, limit: u8) -> Vec<u32> {
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
            near.clear();
            self.grid.for_each_neighbour(me.cell, |c, _| {
                near.extend(self.grid.members(&self.bodies, c));
            });
            for &k in &near {
                let its = self.rest[k as usize];
                if k == i || its == Rest::Free {
                    continue;
                }
                self.advance_to(k, self.now);
                let other = self.bodies[k as usize];
                let d = self.laws.boundary.separation(me.pos, other.pos, self.laws.size);
                let dist = d.length();
                if dist <= 0.0 {
                    continue;
                }
                let normal = d / dist;
                let closing = (me.vel - other.vel).dot(normal);
                let gap = (dist - me.radius - other.radius).max(0.0);
                if closing > 0.0 && closing * left >= gap {
                    let k = if its == Rest::Held { k } else { u32::MAX };
                    pushes.push((k, normal, 0.5 * gap / left));
                }
            }
            for (k, normal, target) in pushes {
                let vb = if k == u32::MAX { DVec2::ZERO } else { self.bodies[k as usize].vel };
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
    fn contacts_of(&mut self, held: &[u32], dt: f64) -> Vec<Contact> {
        let mut contacts = Vec::new();
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
            let mut near = Vec::new();
            self.grid.for_each_neighbour(me.cell, |c, _| {
                near.extend(self.grid.members(&self.bodies, c).filter(|&k| k != i));
            });
            for k in near {
                let its = self.rest[k as usize];
                // Each pair of held discs once; flying ones meet by events.
                if its == Rest::Free || (its == Rest::Held && k < i) {
                    continue;
                }
                let other = self.bodies[k as usize];
                let d = self.laws.boundary.separation(me.pos, other.pos, self.laws.size);
                let dist = d.length();
                let gap = dist - me.radius - other.radius;
                let vb = if its == Rest::Held { other.vel } else { DVec2::ZERO };
                let closing = if dist > 0.0 { (me.vel - vb).dot(d / dist) } else { 0.0 };
                let reach = (HOLD_SKIN * me.radius.min(other.radius)).max(2.0 * closing * dt);
                if dist <= 0.0 || gap > reach {
                    continue;
                }
                let mass = if its == Rest::Held {
                    let mb = self.aux[k as usize].mass;
                    ma * mb / (ma + mb)
                } else {
                    ma
                };
                let normal = d / dist;
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

    /// Whether held body `k` (at the current time), flying straight on its
    /// course, stays clear of every held disc, sleeper and wall till the
    /// end of the step.
    fn safe_till_end(&mut self, k: u32) -> bool {
        let left = self.end - self.now;
        let me = self.bodies[k as usize];
        let clear = |gap: f64, closing: f64| closing <= 0.0 || closing * left < gap;
        let walls = self.walls_near(me.pos, me.radius, f64::INFINITY);
        if !walls.iter().all(|&(n, gap)| clear(gap, me.vel.dot(n))) {
            return false;
        }
        let mut near = Vec::new();
        self.grid.for_each_neighbour(me.cell, |c, _| {
            near.extend(self.grid.members(&self.bodies, c));
        });
        near.into_iter().all(|j| {
            if j == k || self.rest[j as usize] == Rest::Free {
                return true;
            }
            let other = self.bodies[j as usize];
            let pos = other.pos + other.vel * (self.now - other.time);
            let d = self.laws.boundary.separation(me.pos, pos, self.laws.size);
            let dist = d.length();
            dist > 0.0 && clear(dist - me.radius - other.radius, (me.vel - other.vel).dot(d / dist))
        })
    }

    /// After an event of `bodies` (their generations before it in `gens`):
    /// a held one whose new course is not clear to the end of the step
    /// flies again ([`Sim::let_go`]).
    pub(super) fn let_go_if_moved(&mut self, bodies: [u32; 2], gens: [u32; 2]) {
        if self.sleepers == 0 {
            return;
        }
        for (k, gen) in bodies.into_iter().zip(gens) {
            if self.rest[k as usize] == Rest::Held && self.bodies[k as usize].gen != gen {
                self.unless_clear(k);
            }
        }
    }

    /// A held body `k` (at the current time) that just came next to held
    /// discs it was not next to (crossing into a cell): see
    /// [`Sim::unless_clear`]. Returns whether it changed (then it has been
    /// predicted again).
    pub(super) fn let_go_unless_clear(&mut self, k: u32) -> bool {
        self.sleepers > 0 && self.rest[k as usize] == Rest::Held && self.unless_clear(k)
    }

    /// If held body `k`'s course (at the current time) is not clear of
    /// what it meets without events till the end of the step, it flies
    /// again ([`Sim::let_go_keeping_energy`]), or, where it cannot, it and
    /// what it would run into stop ([`Sim::settle`]); each body changed is
    /// predicted again. Returns whether anything changed.
    fn unless_clear(&mut self, k: u32) -> bool {
        if self.safe_till_end(k) && !self.rising(k) {
            return false;
        }
        if self.let_go_keeping_energy(k) {
            self.predict(k);
        } else {
            let changed = self.settle(vec![k], self.end - self.now, 0);
            self.repredict_settled(changed.into_iter().chain([k]));
        }
        true
    }

    /// Whether held body `k`, flying straight on (without gravity), would
    /// end the step higher than on the course its step paid for
    /// ([`Sim::pay_ahead`]), its speed unchanged: energy the step has not
    /// paid for.
    fn rising(&self, k: u32) -> bool {
        let g = self.laws.gravity;
        self.rest[k as usize] == Rest::Held
            && g.dot(self.bodies[k as usize].vel) < g.dot(self.paid[k as usize])
    }

    /// Bodies whose velocity a settle in mid-step changed: a held one that
    /// now rises flies again, keeping its energy (it always can), and
    /// every one is predicted again.
    fn repredict_settled(&mut self, changed: impl Iterator<Item = u32>) {
        for c in changed {
            if self.rising(c) {
                self.let_go_keeping_energy(c);
            } else {
                self.bodies[c as usize].gen += 1;
            }
            self.predict(c);
        }
    }

    /// Held body `k` (at the current time) flies on as any disc, meeting
    /// held discs by events again, without the part of its kick the rest
    /// of the step has not used.
    /// Whether, of `pair` (at the current time, `normal` from the first to
    /// the second), one flies and one is held and they close slower than
    /// gravity presses the flying one on within a contact duration (or
    /// not at all): resting, not colliding, as on a sleeper (see
    /// [`Sim::rest_on`]).
    pub(super) fn rests_on_held(&self, pair: [u32; 2], normal: DVec2) -> bool {
        if self.sleepers == 0 {
            return false;
        }
        let into = match pair.map(|k| self.rest[k as usize]) {
            [Rest::Held, Rest::Free] => -normal, // from the flying one to the held
            [Rest::Free, Rest::Held] => normal,
            _ => return false,
        };
        let (a, b) = (self.bodies[pair[0] as usize], self.bodies[pair[1] as usize]);
        let closing = (a.vel - b.vel).dot(normal);
        let pressing = self.laws.gravity.dot(into);
        closing <= pressing.max(0.0) * super::CONTACT_DURATION
    }

    /// A flying disc rests on a held one (`pair`, both at the current time;
    /// see [`Sim::rests_on_held`]): it is in lasting contact and joins the held discs, with the rest of the step's
    /// gravity at once (a held disc's way of falling), their velocities
    /// settled if that would close a gap within the step. Returns whether
    /// it joined (all bodies concerned predicted again).
    pub(super) fn join_held(&mut self, pair: [u32; 2]) -> bool {
        let rests = pair.map(|k| self.rest[k as usize]);
        let flying = match rests {
            [Rest::Held, Rest::Free] => pair[1],
            [Rest::Free, Rest::Held] => pair[0],
            _ => return false,
        };
        let left = self.end - self.now;
        self.set_rest(flying, Rest::Held);
        let body = &mut self.bodies[flying as usize];
        body.vel += self.laws.gravity * left;
        body.gen += 1;
        self.paid[flying as usize] = self.bodies[flying as usize].vel;
        let mut moved = vec![flying];
        if !self.safe_till_end(flying) {
            moved.extend(self.settle(vec![flying], left, 0));
        }
        let other = if flying == pair[0] { pair[1] } else { pair[0] };
        self.repredict_settled(moved.into_iter().chain([other]));
        true
    }

    /// Flying discs of `pair` (at the current time) that have collided
    /// [`HOLD_HITS`] times in this step already are held at once, as
    /// [`Sim::join_held`] does.
    pub(super) fn hold_if_busy(&mut self, pair: [u32; 2]) {
        if self.sleepers == 0 {
            return;
        }
        for k in pair {
            if self.rest[k as usize] == Rest::Free && self.hits[k as usize] >= HOLD_HITS {
                self.hold_now(k);
            }
        }
    }

    /// Flying body `k` (at the current time) is held from now on: it takes
    /// the rest of the step's gravity at once; if that course is not clear
    /// till the end of the step, it and what it would run into settle.
    /// Every body changed is predicted again.
    fn hold_now(&mut self, k: u32) {
        self.advance_to(k, self.now);
        let left = self.end - self.now;
        self.set_rest(k, Rest::Held);
        let body = &mut self.bodies[k as usize];
        body.vel += self.laws.gravity * left;
        body.gen += 1;
        self.paid[k as usize] = self.bodies[k as usize].vel;
        let mut moved = vec![k];
        if !self.safe_till_end(k) {
            moved.extend(self.settle(vec![k], left, 0));
        }
        self.repredict_settled(moved.into_iter());
    }

    /// Held body `k` (at the current time) flies on as any disc, if it can
    /// without its energy exceeding what its straight flight to the end of
    /// the step would have left it: its velocity turns towards the free
    /// fall's, v − g·s with s the time left, at the speed √(|v|² − 2·g·v·s)
    /// (equal energies at the end of the step). Returns whether it could:
    /// one held back by a slow descent cannot.
    pub(super) fn let_go_keeping_energy(&mut self, k: u32) -> bool {
        if self.sleepers == 0 || self.rest[k as usize] != Rest::Held {
            return false;
        }
        let g = self.laws.gravity;
        let left = self.end - self.now;
        let v = self.bodies[k as usize].vel;
        let square = v.length_squared() - 2.0 * g.dot(self.paid[k as usize]) * left;
        let toward = v - g * left;
        if square < 0.0 {
            return false;
        }
        let u = match toward.try_normalize() {
            Some(dir) => dir * (square.sqrt().min(toward.length())),
            None => DVec2::ZERO,
        };
        let body = &mut self.bodies[k as usize];
        body.vel = u;
        body.gen += 1;
        self.set_rest(k, Rest::Free);
        true
    }

    pub(super) fn let_go(&mut self, k: u32) {
        if self.sleepers > 0 && self.rest[k as usize] == Rest::Held {
            let body = &mut self.bodies[k as usize];
            body.vel -= self.laws.gravity * (self.end - self.now);
            body.gen += 1;
            self.set_rest(k, Rest::Free);
        }
    }
}
