//! Held discs in the middle of a step: what an event does to them (a
//! flying disc hits one, one crosses into a cell), when a flying disc joins
//! them, and when one flies again.

use super::HOLD_HITS;
use crate::method::exact::sleep::Rest;
use crate::method::exact::Sim;
use glam::DVec2;

impl Sim {
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
        self.gather_near(k, &mut near);
        near.into_iter().all(|j| {
            if self.rest[j as usize] == Rest::Free {
                return true;
            }
            let other = self.bodies[j as usize];
            let pos = other.pos + other.vel * (self.now - other.time);
            self.normal_and_gap(me.pos, me.radius, pos, other.radius)
                .is_some_and(|(normal, gap)| clear(gap, (me.vel - other.vel).dot(normal)))
        })
    }

    /// After an event of `bodies` (their generations before it in `gens`):
    /// a held one whose new course is not clear to the end of the step
    /// flies again, or settles ([`Sim::unless_clear`]).
    pub(in crate::method::exact) fn let_go_if_moved(&mut self, bodies: [u32; 2], gens: [u32; 2]) {
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
    pub(in crate::method::exact) fn let_go_unless_clear(&mut self, k: u32) -> bool {
        self.sleepers > 0 && self.rest[k as usize] == Rest::Held && self.unless_clear(k)
    }

    /// If held body `k`'s course (at the current time) is not clear of
    /// what it meets without events till the end of the step, it flies
    /// again ([`Sim::let_go_keeping_energy`]), or, where it cannot, it and
    /// what it would run into stop ([`Sim::settle`]); each body changed is
    /// predicted again. Returns whether anything changed.
    pub(in crate::method::exact) fn unless_clear(&mut self, k: u32) -> bool {
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

    /// Whether, of `pair` (at the current time, `normal` from the first to
    /// the second), one flies and one is held and they close slower than
    /// gravity presses the flying one on within a contact duration (or
    /// not at all): resting, not colliding, as on a sleeper (see
    /// [`Sim::rest_on`]).
    pub(in crate::method::exact) fn rests_on_held(&self, pair: [u32; 2], normal: DVec2) -> bool {
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
        closing <= pressing.max(0.0) * crate::method::exact::CONTACT_DURATION
    }

    /// A flying disc rests on a held one (`pair`, both at the current time;
    /// see [`Sim::rests_on_held`]): it is in lasting contact, and is held
    /// from now on ([`Sim::hold_now`]). Returns whether it was (then both
    /// have been predicted again).
    pub(in crate::method::exact) fn join_held(&mut self, pair: [u32; 2]) -> bool {
        let (flying, other) = match pair.map(|k| self.rest[k as usize]) {
            [Rest::Held, Rest::Free] => (pair[1], pair[0]),
            [Rest::Free, Rest::Held] => (pair[0], pair[1]),
            _ => return false,
        };
        self.hold_now(flying);
        self.predict(other);
        true
    }

    /// Flying discs of `pair` (at the current time) that have collided
    /// [`HOLD_HITS`] times in this step already are held at once
    /// ([`Sim::hold_now`]).
    pub(in crate::method::exact) fn hold_if_busy(&mut self, pair: [u32; 2]) {
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
}
