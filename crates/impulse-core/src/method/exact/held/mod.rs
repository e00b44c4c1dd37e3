//! Discs in lasting contact (*held*): a contact solve at the start of each
//! step instead of events.
//!
//! Under gravity the weight of a pile has to reach the floor. Hard discs
//! carry it only by collisions, g·N/(2v) of them a second for a disc under
//! N layers rattling at v, so a pile that still moves costs events without
//! end (inelastic collapse), and sleeping ([`super::sleep`]) only helps once
//! it is still. A held disc is a hybrid of event-driven and time-stepped
//! contact dynamics: held discs meet each other, sleepers and walls through
//! a contact solve once a step, as a fixed-step method does; flying discs
//! meet everything by events, as before.
//!
//! - **Becoming held.** At the start of a step: a disc that collided
//!   [`HOLD_HITS`] times in the step before, and a flying one touching a
//!   held one (within [`HOLD_SKIN`]) slower than an impact. In mid-step: a
//!   disc on its [`HOLD_HITS`]th collision of the step, and a flying disc
//!   that meets a held one slower than gravity presses it on within a
//!   contact duration (resting, as on a sleeper).
//! - **The step.** A held disc takes the step's gravity at once (a kick of
//!   g·dt, or of g times what is left of the step) and flies straight
//!   (symplectic Euler). Projected Gauss–Seidel over the held discs'
//!   contacts, warm-started with last step's impulses (Catto's sequential
//!   impulses), takes out whatever would close a gap faster than half of it
//!   in the step: restitution zero, lasting contacts do not bounce.
//! - **No overlap.** Held discs fly straight, so two of them, or one and a
//!   sleeper or wall, close at a constant rate: the settle
//!   ([`Sim::settle`]) leaves no such gap closing within the step, by
//!   perfectly inelastic pushes along the normal, stopping a disc pushed
//!   [`FIXES`] times. A held disc crossing into a cell, or hit by a flying
//!   one, is checked against its new neighbours for the rest of the step.
//! - **Leaving.** A held disc whose new course is not clear, or would
//!   climb higher than its step paid for, flies again; one without
//!   contacts flies again at the next step.
//! - **Sleeping.** A slow held disc that sleepers and walls hold up falls
//!   asleep ([`Sim::maybe_sleep`]); so do groups resting on each other
//!   that have barely moved ([`BALANCED`]) for [`QUIET_TIME`].
//! - **Energy.** Kick and drift lose ½·m·g²·dt² a step for a disc in free
//!   fall; the solve and the settle only take kinetic energy out. What could
//!   put energy in, a push that lifts a disc during the drift, is paid for
//!   ahead: the held discs' step, Σ ½m|v|² − m·g·v·dt − ½m|v₀|², is made
//!   non-positive by slowing them all by one factor (which closes no gap).
//!   A disc let go in mid-step leaves at the speed that keeps the energy
//!   its step paid for; what still rises by the step's end is taken out of
//!   the held discs' speeds ([`Sim::pay_back`]).
//!
//! What it changes, measured (docs/lab/NOTES.md): a held disc falls on a
//! straight line within a step instead of a parabola (at most ½·g·dt² off,
//! 85 µm at 240 steps a second); lasting contacts do not bounce; settled
//! piles are looser than with events alone (the 300-disc pile's centre of
//! mass 6.6 % higher, 8 seeds; area fraction 0.81 against 0.85), not in
//! full static equilibrium: given to `impulse` they sink back.

mod events;
mod solve;

use super::sleep::Rest;
use super::Sim;
use glam::DVec2;
use solve::Contact;

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

/// Whether `exact` holds discs in lasting contact under these laws: under
/// gravity with restitution below 1 (where discs come to rest), in a box,
/// smooth (the contact solve has no friction). Elsewhere it runs on events
/// alone, as before.
pub fn holds_discs(laws: &crate::laws::Laws) -> bool {
    Sim::may_sleep(laws) && !Sim::is_rough(laws) && laws.boundary == crate::boundary::Boundary::Box
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
        holds_discs(&self.laws)
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

    /// The discs in the grid cells around disc `i`, `i` left out, into
    /// `near` (emptied first).
    fn gather_near(&self, i: u32, near: &mut Vec<u32>) {
        near.clear();
        self.grid
            .for_each_neighbour(self.bodies[i as usize].cell, |c, _| {
                near.extend(self.grid.members(&self.bodies, c).filter(|&k| k != i));
            });
    }

    /// Between a disc at `a` of radius `ra` and one at `b` of radius `rb`:
    /// the unit normal along the boundary's separation of `a` from `b`, and
    /// the gap between their surfaces (negative: they overlap); `None` where
    /// their centres coincide.
    fn normal_and_gap(&self, a: DVec2, ra: f64, b: DVec2, rb: f64) -> Option<(DVec2, f64)> {
        let d = self.laws.boundary.separation(a, b, self.laws.size);
        let dist = d.length();
        (dist > 0.0).then(|| (d / dist, dist - ra - rb))
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
            let (pa, pb) = (
                self.bodies[held[a] as usize].pos,
                self.bodies[held[b] as usize].pos,
            );
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
    fn sleep_still_groups(
        &mut self,
        held: &[u32],
        awake: &mut Vec<usize>,
        carried: &[bool],
        contacts: &[Contact],
    ) {
        const LEVEL: f64 = 1e-9;
        let up = -self.laws.gravity.normalize();
        let n = self.bodies.len();
        let mut still = vec![false; n];
        for &k in awake.iter() {
            let i = held[k];
            still[i as usize] =
                carried[k] && self.bodies[i as usize].vel.length() < self.sleep_speed(i);
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
        let root = (-linear
            + (linear * linear - 4.0 * quadratic * constant)
                .max(0.0)
                .sqrt())
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
                .map(|&k| {
                    0.5 * self.aux[k as usize].mass * self.bodies[k as usize].vel.length_squared()
                })
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
            self.gather_near(i, &mut near);
            for &k in &near {
                if chosen[k as usize] || self.rest[k as usize] != Rest::Free {
                    continue;
                }
                let other = self.bodies[k as usize];
                let Some((normal, gap)) =
                    self.normal_and_gap(me.pos, me.radius, other.pos, other.radius)
                else {
                    continue;
                };
                if gap <= HOLD_SKIN * me.radius.min(other.radius)
                    && (me.vel - other.vel).dot(normal).abs() < self.impact_speed
                {
                    chosen[k as usize] = true;
                    joining.push(k);
                }
            }
        }
        joining
    }
}
