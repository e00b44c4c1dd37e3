//! Sleeping discs: how `exact` comes to rest.
//!
//! Event-driven hard discs cannot rest: a disc on a support under gravity
//! collides with it again and again, ever faster (inelastic collapse), and
//! the TC rule only turns that into endless elastic micro-bounces. Here a
//! slow disc whose weight is carried falls *asleep*, as in DynamO's
//! sleeping particles (S. González, "Sleeping of particles in DynamO",
//! `docs/sleeping.tex` of github.com/dynamomd/DynamO; M. N. Bannerman,
//! R. Sargant, L. Lue, J. Comput. Chem. 32, 3329 (2011)):
//!
//! - **Falling asleep.** Right after a disc meets a support (a wall, or a
//!   disc already asleep), it sleeps if it moves slower than its sleep
//!   speed √(2·g·[`SLEEP_LIFT`]·r) (the speed that would lift it a
//!   thousandth of its radius) and its supports hold it: for frictionless
//!   discs, the upward direction lies between the normals of the supports
//!   it touches (within [`SUPPORT_GAP`]), so a disc in a groove or on the
//!   floor sleeps and one balanced on a single disc rolls off. It stops
//!   dead (its last kinetic energy, under ½·m·g·r/1000, is lost) and
//!   neither moves nor feels gravity until woken.
//! - **Meeting a sleeper.** A moving disc meets a sleeping one as a still
//!   disc, at the instant the quartic of the `kinematics` module gives. If
//!   the two-disc collision would set the sleeper moving faster than its
//!   sleep speed, it wakes and the collision is the ordinary one; if not,
//!   the sleeper stays put as the floor would, and the moving disc bounces
//!   off it with the restitution.
//! - **Waking.** A woken disc wakes every sleeper it holds up (touching it,
//!   above it), and those wake the ones they hold, so nothing floats.
//! - **Resting contact without sleep.** A disc that meets a still support
//!   (a wall or a sleeper) gravity presses it on, slower than gravity
//!   presses within a contact duration t_c, but too fast to sleep (sliding
//!   along the floor), *glances* off it: its velocity turns, its speed
//!   kept, to leave the support at half that pressing speed, so it comes
//!   back after t_c. Hard discs would instead bounce ever lower, with no
//!   end to the events (the TC rule keeps such bounces elastic, but at
//!   whatever tiny speed they had). Energy is unchanged; momentum along
//!   the support shrinks by a relative (g·t_c/2v)²/2, under 10⁻⁵ for
//!   anything faster than 0.2 m/s.
//!
//! Only scenes with gravity and a restitution below 1 sleep: without either
//! nothing comes to rest, and the events are those of plain `exact`.

use super::{Sim, CONTACT_DURATION};
use glam::DVec2;

/// Whether a disc flies or sleeps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Rest {
    /// Flying under gravity.
    Free,
    /// Still, without gravity, until woken.
    Asleep,
    /// Flying, in lasting contact with other held discs: they meet without
    /// events, through a contact solve at the start of each step (see
    /// [`super::held`]).
    Held,
}

/// A disc sleeps below the speed that would lift it this fraction of its
/// radius against gravity.
pub const SLEEP_LIFT: f64 = 1e-3;
/// A support holds a disc within this gap, as a fraction of the smaller
/// radius (a disc settling in a groove bounces between its two supports,
/// ever lower, and touches one of them only at a time).
pub const SUPPORT_GAP: f64 = 1e-2;

/// How far a disc resting on a sleeper that cannot hold it steps down the
/// tangent, as a fraction of its radius (`Sim::slide_off`).
pub const SLIDE_STEP: f64 = 1e-4;

/// The 2D cross product a × b.
fn cross(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

impl Sim {
    /// Whether discs may fall asleep under these laws.
    pub(super) fn may_sleep(laws: &crate::laws::Laws) -> bool {
        laws.gravity != DVec2::ZERO && (laws.restitution < 1.0 || laws.wall_restitution < 1.0)
    }

    /// Whether body `i` is asleep.
    #[inline]
    pub(super) fn asleep(&self, i: u32) -> bool {
        self.sleepers > 0 && self.rest[i as usize] == Rest::Asleep
    }

    /// Body `i`'s acceleration: gravity, or what is left of it at rest.
    #[inline]
    pub(super) fn accel(&self, i: u32) -> DVec2 {
        let g = self.laws.gravity;
        if self.sleepers == 0 {
            return g;
        }
        match self.rest[i as usize] {
            Rest::Free => g,
            // Held discs take the step's gravity at once ([`super::held`]).
            Rest::Held | Rest::Asleep => DVec2::ZERO,
        }
    }

    /// Sets body `i`'s way of moving, keeping the count of resting ones.
    pub(super) fn set_rest(&mut self, i: u32, rest: Rest) {
        let was = std::mem::replace(&mut self.rest[i as usize], rest);
        match (was == Rest::Free, rest == Rest::Free) {
            (true, false) => self.sleepers += 1,
            (false, true) => self.sleepers -= 1,
            _ => {}
        }
    }

    /// Body `i` (at the current time) meets a still support — the wall
    /// across `axis` (`upper` or lower) — `speed` m/s into it: a resting
    /// contact if slower than gravity presses it on within a contact
    /// duration; then it sleeps or glances off. Returns whether it was one.
    pub(super) fn rest_on_wall(&mut self, i: u32, axis: usize, upper: bool, speed: f64) -> bool {
        let mut out = DVec2::ZERO; // from the wall into the box
        out[axis] = if upper { -1.0 } else { 1.0 };
        self.rest_on(i, out, speed)
    }

    /// Body `i` meets a still support along `out` (unit, from the support
    /// to the disc), closing at `closing` m/s: see [`Sim::rest_on_wall`].
    pub(super) fn rest_on(&mut self, i: u32, out: DVec2, closing: f64) -> bool {
        let pressing = -self.laws.gravity.dot(out);
        if !self.sleeping || pressing <= 0.0 || closing > pressing * CONTACT_DURATION {
            return false;
        }
        if self.maybe_sleep(i) {
            return true;
        }
        let pressed = self.bodies[i as usize].vel.dot(out);
        if self.glance(i, out, pressing) {
            // Rough: the contact rubs with Coulomb friction, μ times the
            // normal impulse the glance took.
            if let (true, Some(law)) = (self.rough, self.laws.rough().resting()) {
                let turned = self.bodies[i as usize].vel.dot(out);
                let impulse = self.aux[i as usize].mass * (turned - pressed).abs();
                self.rub_still(i, -out, impulse, law);
            }
        } else {
            self.slide_off(i, -out);
        }
        true
    }

    /// Turns body `i`'s velocity, its speed kept, to leave the support
    /// along `out` at half of what `pressing` (m/s²) builds in a contact
    /// duration; false if it is slower than that.
    fn glance(&mut self, i: u32, out: DVec2, pressing: f64) -> bool {
        let leave = 0.5 * pressing * CONTACT_DURATION;
        let body = &mut self.bodies[i as usize];
        let v = body.vel;
        let speed = v.length();
        if speed <= leave {
            return false;
        }
        let along = v - v.dot(out) * out;
        body.vel = match along.try_normalize() {
            Some(t) => leave * out + (speed * speed - leave * leave).sqrt() * t,
            None => speed * out,
        };
        body.gen += 1;
        self.aux[i as usize].last_hit = self.now;
        true
    }

    /// Stops body `i` (at the current time) turning, as it falls asleep.
    fn stop_spinning(&mut self, i: u32) {
        let now = self.now;
        let Some(s) = self.spins.get_mut(i as usize) else {
            return;
        };
        if s.spin != 0.0 {
            *s = super::Spin {
                spin: 0.0,
                angle: s.angle_at(now),
                since: now,
            };
        }
    }

    /// The speed below which body `i` may fall asleep (m/s).
    pub(super) fn sleep_speed(&self, i: u32) -> f64 {
        let r = self.bodies[i as usize].radius;
        (2.0 * self.laws.gravity.length() * SLEEP_LIFT * r).sqrt()
    }

    /// Puts body `i` (at the current time, just after meeting a support) to
    /// sleep if it is slow and held; returns whether it fell asleep.
    pub(super) fn maybe_sleep(&mut self, i: u32) -> bool {
        if !self.sleeping || self.asleep(i) {
            return false;
        }
        let b = self.bodies[i as usize];
        let rolling = self.spin(i).abs() * b.radius;
        let slow = b.vel.length().max(rolling) < self.sleep_speed(i);
        if !slow || !self.is_held(i) {
            return false;
        }
        self.sleep_now(i);
        true
    }

    /// Puts body `i` to sleep where it is.
    pub(super) fn sleep_now(&mut self, i: u32) {
        let body = &mut self.bodies[i as usize];
        body.vel = DVec2::ZERO;
        body.gen += 1;
        self.stop_spinning(i);
        self.set_rest(i, Rest::Asleep);
    }

    /// After body `i` bounced off a still support, takes out whatever of
    /// its velocity still drives it into another one it touches (a wall or
    /// a sleeper, to round-off): wedged between two, a bounce off each
    /// sent it straight back into the other, at the same instant, forever.
    pub(super) fn unwedge(&mut self, i: u32) {
        if !self.sleeping {
            return;
        }
        let me = self.bodies[i as usize];
        let tolerance = super::SIMULTANEOUS_TOLERANCE;
        let outs = self.still_supports(i, tolerance * me.radius, |dist, mine, its| {
            dist <= (mine + its) * (1.0 + tolerance)
        });
        if outs.len() < 2 {
            return;
        }
        // The least change that drives into none of them: the velocity as
        // it is, or without its part into one support, or (in the plane,
        // two supports at once) nothing.
        let creep = super::kinematics::CREEP;
        let frees = |w: DVec2| outs.iter().all(|o| w.dot(*o) >= -creep);
        let v = me.vel;
        if frees(v) {
            return;
        }
        let mut best: Option<(f64, DVec2)> = None;
        for &out in &outs {
            let into = v.dot(out);
            let w = v - into * out;
            if into < 0.0 && frees(w) && best.is_none_or(|(least, _)| -into < least) {
                best = Some((-into, w));
            }
        }
        self.bodies[i as usize].vel = best.map_or(DVec2::ZERO, |(_, w)| w);
    }

    /// The outward normals (unit, from the support to body `i`) of the
    /// walls within `wall_gap` of it and of the sleeping discs that
    /// `touching(distance between centres, its radius, theirs)` accepts.
    fn still_supports(
        &self,
        i: u32,
        wall_gap: f64,
        touching: impl Fn(f64, f64, f64) -> bool,
    ) -> Vec<DVec2> {
        let me = self.bodies[i as usize];
        let mut normals = Vec::new();
        if self.laws.boundary == crate::boundary::Boundary::Box {
            for axis in 0..2 {
                let mut n = DVec2::ZERO;
                n[axis] = 1.0;
                if self.laws.walls.at(axis, false) && me.pos[axis] - me.radius <= wall_gap {
                    normals.push(n);
                }
                let top = self.laws.size[axis] - me.radius;
                if self.laws.walls.at(axis, true) && top - me.pos[axis] <= wall_gap {
                    normals.push(-n);
                }
            }
        }
        if self.sleepers == 0 {
            return normals;
        }
        self.grid.for_each_neighbour(me.cell, |c, _| {
            for k in self.grid.members(&self.bodies, c) {
                if k == i || !self.asleep(k) {
                    continue;
                }
                let other = &self.bodies[k as usize];
                let d = self
                    .laws
                    .boundary
                    .separation(other.pos, me.pos, self.laws.size);
                let dist = d.length();
                if dist > 0.0 && touching(dist, me.radius, other.radius) {
                    normals.push(d / dist);
                }
            }
        });
        normals
    }

    /// Whether body `i`'s supports (walls and sleeping discs within
    /// [`SUPPORT_GAP`]) can carry its weight without friction: the upward
    /// direction lies in the cone of their normals.
    fn is_held(&self, i: u32) -> bool {
        self.can_bear(i, -self.laws.gravity.normalize())
    }

    /// Whether body `i`'s supports (as in [`Sim::is_held`]) can push it
    /// along the unit vector `up` without friction: a load the other way
    /// is carried.
    pub(super) fn can_bear(&self, i: u32, up: DVec2) -> bool {
        let me = self.bodies[i as usize];
        let normals = self.still_supports(i, SUPPORT_GAP * me.radius, |dist, mine, its| {
            dist - mine - its <= SUPPORT_GAP * mine.min(its)
        });
        if normals.iter().any(|n| n.dot(up) >= 1.0 - 1e-9) {
            return true;
        }
        normals.iter().any(|&a| {
            cross(a, up) > 0.0
                && normals
                    .iter()
                    .any(|&b| cross(up, b) > 0.0 && cross(a, b) > 0.0)
        })
    }

    /// Moving body `i` rests on a sleeper along `normal` (from it to the
    /// sleeper) without being held: it slides off. A hard disc would slide
    /// round the sleeper's surface, which event by event is an endless
    /// train of ever smaller bounces; instead it steps [`SLIDE_STEP`] of its
    /// radius down the tangent and takes the speed that drop gives
    /// (kinetic plus potential energy unchanged), which opens a gap of a
    /// few billionths of its radius for it to fall through. Where the step
    /// would overlap something, it stops instead (wedged).
    pub(super) fn slide_off(&mut self, i: u32, normal: DVec2) {
        let g = self.laws.gravity;
        let along = g - g.dot(normal) * normal;
        let me = self.bodies[i as usize];
        let step = SLIDE_STEP * me.radius;
        let (Some(tangent), true) = (along.try_normalize(), step > 0.0) else {
            return;
        };
        let to = me.pos + step * tangent;
        if self.would_overlap(i, to) {
            let body = &mut self.bodies[i as usize];
            body.vel = DVec2::ZERO;
            body.gen += 1;
            self.stop_spinning(i);
            self.set_rest(i, Rest::Asleep);
            return;
        }
        let drop = along.length() * step; // potential energy per kg given up
        let v_t = me.vel.dot(tangent);
        let w = -v_t + (v_t * v_t + 2.0 * drop).sqrt();
        let body = &mut self.bodies[i as usize];
        body.pos = to;
        body.vel += w * tangent;
        body.gen += 1;
        let (from, cell) = (me.cell, self.grid.cell_of(to));
        if cell != from {
            self.grid.remove(&mut self.bodies, i, from);
            self.grid.insert(&mut self.bodies, i, cell);
            self.bodies[i as usize].cell = cell;
        }
    }

    /// Whether body `i` placed at `to` would overlap a wall or a disc
    /// (sleeping discs where they lie, moving ones where they are now).
    fn would_overlap(&mut self, i: u32, to: DVec2) -> bool {
        let r = self.bodies[i as usize].radius;
        if self.laws.boundary == crate::boundary::Boundary::Box
            && (to.cmplt(DVec2::splat(r)).any() || to.cmpgt(self.laws.size - r).any())
        {
            return true;
        }
        let mut near = Vec::new();
        let cell = self.grid.cell_of(to);
        self.grid.for_each_neighbour(cell, |c, _| {
            near.extend(self.grid.members(&self.bodies, c).filter(|&k| k != i));
        });
        near.into_iter().any(|k| {
            self.advance_to(k, self.now);
            let other = &self.bodies[k as usize];
            let d = self.laws.boundary.separation(to, other.pos, self.laws.size);
            d.length() < r + other.radius
        })
    }

    /// Wakes sleeping body `i` (at the current time, still at rest) and,
    /// through them, every sleeper it holds up; returns the others woken,
    /// which the caller re-predicts.
    pub(super) fn wake(&mut self, i: u32) -> Vec<u32> {
        let up = -self.laws.gravity.normalize_or_zero();
        let mut woken = Vec::new();
        self.rouse(i);
        let mut stack = vec![i];
        while let Some(k) = stack.pop() {
            let below = self.bodies[k as usize];
            let mut held = Vec::new();
            self.grid.for_each_neighbour(below.cell, |c, _| {
                for s in self.grid.members(&self.bodies, c) {
                    if !self.asleep(s) {
                        continue;
                    }
                    let above = &self.bodies[s as usize];
                    let d = self
                        .laws
                        .boundary
                        .separation(below.pos, above.pos, self.laws.size);
                    let gap = d.length() - below.radius - above.radius;
                    if d.dot(up) > 0.0 && gap <= SUPPORT_GAP * below.radius.min(above.radius) {
                        held.push(s);
                    }
                }
            });
            for s in held {
                if self.asleep(s) {
                    self.rouse(s);
                    woken.push(s);
                    stack.push(s);
                }
            }
        }
        woken
    }

    /// Marks sleeping body `i` awake, at rest at the current time.
    fn rouse(&mut self, i: u32) {
        self.advance_to(i, self.now);
        self.set_rest(i, Rest::Free);
        self.bodies[i as usize].gen += 1;
    }

    /// Wakes every sleeper (the laws no longer let discs rest); every disc
    /// must be at the current time.
    pub(super) fn wake_all(&mut self) {
        for i in 0..self.bodies.len() as u32 {
            if self.rest[i as usize] != Rest::Free {
                self.set_rest(i, Rest::Free);
                self.bodies[i as usize].gen += 1;
            }
        }
    }

    /// Counts every sleeping disc as resting this step.
    pub(super) fn count_sleepers(&mut self) {
        if self.sleepers == 0 {
            return;
        }
        for i in 0..self.bodies.len() as u32 {
            if self.rest[i as usize] != Rest::Free {
                self.rested(i);
            }
        }
    }
}
