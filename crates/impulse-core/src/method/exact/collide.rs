//! What an event does: a pair collision (alone or with others at the same
//! instant), a wall hit, a crossing into the next cell. Rough contacts add
//! their tangential impulse ([`crate::rough`]): rotation does not change
//! when discs touch, only what an impact does to them.

use super::kinematics::CREEP;
use super::{simultaneous, Body, Sim, CONTACT_DURATION, SIMULTANEOUS_TOLERANCE};
use crate::ledger::{Collision, Impact, Wall, WallHit};
use crate::resolution::collision_velocities;
use crate::rough::{Side, Tangential};
use glam::DVec2;

impl Sim {
    pub(super) fn collide_pair(&mut self, i: u32, j: u32) {
        self.advance_to(i, self.now);
        self.advance_to(j, self.now);
        if self.asleep(i) || self.asleep(j) {
            return self.meet_sleeper(i, j);
        }
        if self.queue.another_by(i, self.now) {
            // Another event at this very instant: maybe a disc meeting two
            // others at once.
            let touches = self.touches_now(i, j);
            if touches.len() > 1 {
                self.collide_together(&touches);
                // Both were advanced to now; re-predict them even if the
                // pair itself was not among the touches.
                self.predict(i);
                self.predict(j);
                return;
            }
        }
        let (a, b) = (self.bodies[i as usize], self.bodies[j as usize]);
        let (normal, dist) = self.contact_normal(&a, &b);
        if self.rests_on_held([i, j], normal) && self.join_held([i, j]) {
            return; // a flying disc resting on a held one: held too
        }
        self.bounce([i, j], [a, b], normal, dist);
        self.predict(i);
        self.predict(j);
    }

    /// The unit normal from body `a` to body `b` (both at the current
    /// time), and their distance.
    #[inline]
    pub(super) fn contact_normal(&self, a: &Body, b: &Body) -> (DVec2, f64) {
        let d = self.laws.boundary.separation(a.pos, b.pos, self.laws.size);
        let dist = d.length();
        let normal = if dist > 0.0 && (d / dist).is_finite() {
            d / dist
        } else {
            crate::narrow_phase::COINCIDENT_NORMAL
        };
        (normal, dist)
    }

    /// Discs `k` (their bodies `before`, at the current time and `dist`
    /// apart) bounce off each other along `normal` if they approach: new
    /// velocities and generations, the contact-duration rule, a rough
    /// contact's spin, the ledger and the counts.
    #[inline]
    pub(super) fn bounce(&mut self, k: [u32; 2], before: [Body; 2], normal: DVec2, dist: f64) {
        let ([i, j], [a, b]) = (k, before);
        if (b.vel - a.vel).dot(normal) < -CREEP {
            let (ia, ib) = (self.aux[i as usize], self.aux[j as usize]);
            let rapid = self.now - ia.last_hit < CONTACT_DURATION
                || self.now - ib.last_hit < CONTACT_DURATION;
            let closing = (a.vel - b.vel).dot(normal);
            let e = if rapid { 1.0 } else { self.laws.restitution };
            let (va, vb) = collision_velocities(ia.mass, ib.mass, a.vel, b.vel, normal, e);
            let spins = if self.record {
                self.spins_of(k)
            } else {
                [0.0; 2]
            };
            for (k, v) in [(i, va), (j, vb)] {
                let body = &mut self.bodies[k as usize];
                body.vel = v;
                body.gen += 1;
                self.aux[k as usize].last_hit = self.now;
            }
            if self.rough {
                let impulse = ia.mass * (va - a.vel).dot(normal).abs();
                self.rub_pair(i, j, normal, impulse, self.laws.rough());
            }
            let after = [self.bodies[i as usize].vel, self.bodies[j as usize].vel];
            self.record_pair(k, normal, [a.vel, b.vel], after, spins);
            self.count(i, closing);
            self.max_overlap = self.max_overlap.max(a.radius + b.radius - dist);
        }
    }

    /// Keeps a pair collision of bodies `k` for the ledger (when it is on),
    /// with their spins before it (after it they are the current ones).
    fn record_pair(
        &mut self,
        k: [u32; 2],
        normal: DVec2,
        before: [DVec2; 2],
        after: [DVec2; 2],
        spins_before: [f64; 2],
    ) {
        if self.record {
            self.impacts.push(Impact::Pair(Collision {
                time: self.now,
                discs: k.map(|b| self.order[b as usize] as usize),
                normal,
                masses: k.map(|b| self.aux[b as usize].mass),
                before,
                after,
                radii: k.map(|b| self.bodies[b as usize].radius),
                spins_before,
                spins_after: self.spins_of(k),
            }));
        }
    }

    /// Keeps a wall hit of body `i` on `wall` for the ledger (when it is
    /// on), with its velocity and spin before it (after it they are the
    /// current ones).
    fn record_wall(&mut self, i: u32, wall: Wall, (before, spin_before): (DVec2, f64)) {
        if self.record {
            self.impacts.push(Impact::Wall(WallHit {
                time: self.now,
                disc: self.order[i as usize] as usize,
                wall,
                mass: self.aux[i as usize].mass,
                radius: self.bodies[i as usize].radius,
                before,
                after: self.bodies[i as usize].vel,
                spin_before,
                spin_after: self.spin(i),
            }));
        }
    }

    /// Whether `laws` make any contact rough.
    pub(super) fn is_rough(laws: &crate::laws::Laws) -> bool {
        !laws.rough().is_smooth()
            || !laws.wall_rough().is_smooth()
            || laws.friction.is_some() && laws.gravity != DVec2::ZERO
    }

    /// The spins of bodies `k`.
    fn spins_of(&self, k: [u32; 2]) -> [f64; 2] {
        k.map(|b| self.spin(b))
    }

    /// The spin of body `k` (none is kept while nothing turns).
    pub(super) fn spin(&self, k: u32) -> f64 {
        self.spins.get(k as usize).map_or(0.0, |s| s.spin)
    }

    /// Body `k` (at the current time) as one side of a rough contact.
    fn side(&self, k: u32) -> Side {
        Side {
            mass: self.aux[k as usize].mass,
            radius: self.bodies[k as usize].radius,
            vel: self.bodies[k as usize].vel,
            spin: self.spin(k),
        }
    }

    /// Gives body `k` (at the current time) the velocity and spin of `side`.
    fn set_side(&mut self, k: u32, side: Side) {
        let now = self.now;
        let body = &mut self.bodies[k as usize];
        if body.vel != side.vel {
            body.vel = side.vel;
            body.gen += 1;
        }
        let s = &mut self.spins[k as usize];
        *s = super::Spin {
            spin: side.spin,
            angle: s.angle_at(now),
            since: now,
        };
    }

    /// The tangential impulse of `law` between bodies `i` and `j` (normal
    /// from `i` to `j`) after a normal impulse `impulse`.
    fn rub_pair(&mut self, i: u32, j: u32, normal: DVec2, impulse: f64, law: Tangential) {
        if let Some((a, b)) = law.pair(normal, impulse, self.side(i), self.side(j)) {
            self.set_side(i, a);
            self.set_side(j, b);
        }
    }

    /// The tangential impulse of `law` on body `i` against a still support
    /// (a wall, a sleeper) whose normal `into` points from the disc into it.
    pub(super) fn rub_still(&mut self, i: u32, into: DVec2, impulse: f64, law: Tangential) {
        if let Some(a) = law.wall(into, impulse, self.side(i)) {
            self.set_side(i, a);
        }
    }

    /// A moving disc meets a sleeping one (either may own the event; both
    /// are at the current time): the sleeper wakes if the collision would
    /// set it moving faster than its sleep speed, and the collision is the
    /// ordinary one; if not, it stays put and the mover bounces off it as
    /// off the floor, and may fall asleep on it (see [`super::sleep`]).
    fn meet_sleeper(&mut self, i: u32, j: u32) {
        let (mover, sleeper) = if self.asleep(i) { (j, i) } else { (i, j) };
        let (a, b) = (self.bodies[mover as usize], self.bodies[sleeper as usize]);
        let d = self.laws.boundary.separation(a.pos, b.pos, self.laws.size);
        let dist = d.length();
        if dist.is_nan() || dist <= 0.0 {
            self.predict(i);
            self.predict(j);
            return; // sharing a centre: set-up separates those
        }
        let normal = d / dist;
        let closing = a.vel.dot(normal);
        // Slower than gravity presses it on within a contact duration (or
        // not approaching at all): resting on the sleeper, not hitting it
        // (see [`super::sleep`]).
        if closing <= 0.0 || self.rest_on(mover, -normal, closing) {
            if closing <= 0.0 {
                self.rest_on(mover, -normal, 0.0);
            }
            self.predict(i);
            self.predict(j);
            return;
        }
        let (am, asl) = (self.aux[mover as usize], self.aux[sleeper as usize]);
        let rapid = self.rapid(mover);
        let e = if rapid { 1.0 } else { self.laws.restitution };
        let (vm, vs) = collision_velocities(am.mass, asl.mass, a.vel, DVec2::ZERO, normal, e);
        let wakes = vs.length() > self.sleep_speed(sleeper);
        let (vm, vs) = if wakes {
            (vm, vs)
        } else {
            (a.vel - (1.0 + e) * closing * normal, DVec2::ZERO)
        };
        let spins = self.spins_of([mover, sleeper]);
        self.count(mover, closing);
        self.max_overlap = self.max_overlap.max(a.radius + b.radius - dist);
        let body = &mut self.bodies[mover as usize];
        body.vel = vm;
        body.gen += 1;
        self.aux[mover as usize].last_hit = self.now;
        if wakes {
            let woken = self.wake(sleeper);
            self.bodies[sleeper as usize].vel = vs;
            self.aux[sleeper as usize].last_hit = self.now;
            if self.rough {
                let impulse = am.mass * (vm - a.vel).dot(normal).abs();
                self.rub_pair(mover, sleeper, normal, impulse, self.laws.rough());
            }
            let after = [
                self.bodies[mover as usize].vel,
                self.bodies[sleeper as usize].vel,
            ];
            self.record_pair([mover, sleeper], normal, [a.vel, DVec2::ZERO], after, spins);
            self.predict(mover);
            self.predict(sleeper);
            for k in woken {
                self.predict(k);
            }
        } else {
            if self.rough {
                let impulse = am.mass * (1.0 + e) * closing;
                self.rub_still(mover, normal, impulse, self.laws.rough());
            }
            let after = [self.bodies[mover as usize].vel, DVec2::ZERO];
            self.record_pair([mover, sleeper], normal, [a.vel, DVec2::ZERO], after, spins);
            self.unwedge(mover);
            self.maybe_sleep(mover);
            self.predict(mover);
            self.predict(sleeper);
        }
    }

    /// The contacts, approaching and touching right now (to round-off), of
    /// `i` and `j` with each other and with their neighbours; each disc
    /// involved is advanced to now. Pairs are (body, body, normal).
    pub(super) fn touches_now(&mut self, i: u32, j: u32) -> Vec<(u32, u32, DVec2)> {
        let mut around = Vec::new();
        for d in [i, j] {
            let cell = self.bodies[d as usize].cell;
            self.grid.for_each_neighbour(cell, |c, _| {
                around.extend(self.grid.members(&self.bodies, c).map(|k| (d, k)));
            });
        }
        let mut touches = Vec::new();
        for (d, k) in around {
            if k == d || (d == j && k == i) || self.asleep(k) {
                continue;
            }
            if touches.iter().any(|&(x, y, _)| (x, y) == (k, d)) {
                continue;
            }
            self.advance_to(k, self.now);
            let (a, b) = (self.bodies[d as usize], self.bodies[k as usize]);
            let sep = self.laws.boundary.separation(a.pos, b.pos, self.laws.size);
            let dist = sep.length();
            let reach = a.radius + b.radius;
            if dist > 0.0 && dist <= reach * (1.0 + SIMULTANEOUS_TOLERANCE) {
                let normal = sep / dist;
                if (b.vel - a.vel).dot(normal) < -CREEP {
                    touches.push((d, k, normal));
                }
            }
        }
        touches
    }

    /// Resolves `touches` together (see [`simultaneous`]).
    pub(super) fn collide_together(&mut self, touches: &[(u32, u32, DVec2)]) {
        let mut ids: Vec<u32> = touches.iter().flat_map(|&(a, b, _)| [a, b]).collect();
        ids.sort_unstable();
        ids.dedup();
        let slot = |k: u32| ids.binary_search(&k).unwrap_or(0);
        let masses: Vec<f64> = ids.iter().map(|&k| self.aux[k as usize].mass).collect();
        let velocities: Vec<DVec2> = ids.iter().map(|&k| self.bodies[k as usize].vel).collect();
        let rapid = ids
            .iter()
            .any(|&k| self.now - self.aux[k as usize].last_hit < CONTACT_DURATION);
        let e = if rapid { 1.0 } else { self.laws.restitution };
        let list: Vec<simultaneous::Touch> = touches
            .iter()
            .map(|&(a, b, normal)| simultaneous::Touch {
                a: slot(a),
                b: slot(b),
                normal,
            })
            .collect();
        let after = simultaneous::simultaneous_velocities(&masses, &velocities, &list, e);
        let spins_before: Vec<f64> = ids.iter().map(|&k| self.spin(k)).collect();
        for (&k, v) in ids.iter().zip(&after) {
            let body = &mut self.bodies[k as usize];
            body.vel = *v;
            body.gen += 1;
            self.aux[k as usize].last_hit = self.now;
        }
        if self.rough {
            // Each touch rubs with the normal impulse a two-disc collision
            // of the same closing speed would have.
            for t in &list {
                let (ma, mb) = (masses[t.a], masses[t.b]);
                let closing = (velocities[t.a] - velocities[t.b]).dot(t.normal).max(0.0);
                let impulse = (1.0 + e) * closing * ma * mb / (ma + mb);
                self.rub_pair(ids[t.a], ids[t.b], t.normal, impulse, self.laws.rough());
            }
        }
        if self.record {
            for t in &list {
                self.impacts.push(Impact::Pair(Collision {
                    time: self.now,
                    discs: [
                        self.order[ids[t.a] as usize] as usize,
                        self.order[ids[t.b] as usize] as usize,
                    ],
                    normal: t.normal,
                    masses: [masses[t.a], masses[t.b]],
                    before: [velocities[t.a], velocities[t.b]],
                    after: [
                        self.bodies[ids[t.a] as usize].vel,
                        self.bodies[ids[t.b] as usize].vel,
                    ],
                    radii: [
                        self.bodies[ids[t.a] as usize].radius,
                        self.bodies[ids[t.b] as usize].radius,
                    ],
                    spins_before: [spins_before[t.a], spins_before[t.b]],
                    spins_after: [self.spin(ids[t.a]), self.spin(ids[t.b])],
                }));
            }
        }
        for t in &list {
            self.count(ids[t.a], (velocities[t.a] - velocities[t.b]).dot(t.normal));
        }
        for &k in &ids {
            // A held one whose new course is not clear flies again (it is
            // predicted then).
            if !self.let_go_unless_clear(k) {
                self.predict(k);
            }
        }
    }

    pub(super) fn hit_wall(&mut self, i: u32, axis: usize, upper: bool) {
        self.advance_to(i, self.now);
        let rapid = self.now - self.aux[i as usize].last_hit < CONTACT_DURATION;
        let e = if rapid {
            1.0
        } else {
            self.laws.wall_restitution
        };
        let size = self.laws.size[axis];
        let b = &mut self.bodies[i as usize];
        let into_wall = if upper {
            b.vel[axis] > 0.0
        } else {
            b.vel[axis] < 0.0
        };
        b.pos[axis] = if upper { size - b.radius } else { b.radius };
        let speed = b.vel[axis].abs();
        if !into_wall {
            // On the wall with gravity pressing it on: resting there.
            self.rest_on_wall(i, axis, upper, 0.0);
        } else if self.rest_on_wall(i, axis, upper, speed) {
            self.wall_impulse += self.aux[i as usize].mass * speed;
            self.rested(i);
        } else {
            let came_in = (self.bodies[i as usize].vel, self.spin(i));
            let b = &mut self.bodies[i as usize];
            let aux = &mut self.aux[i as usize];
            let impulse = aux.mass * (1.0 + e) * b.vel[axis].abs();
            self.wall_impulse += impulse;
            b.vel[axis] *= -e;
            b.gen += 1;
            aux.last_hit = self.now;
            if self.rough {
                let mut into = DVec2::ZERO;
                into[axis] = if upper { 1.0 } else { -1.0 };
                self.rub_still(i, into, impulse, self.laws.wall_rough());
            }
            // Recorded either way; `Exact::advance` keeps the impacts
            // for the ledger, as it does with pairs.
            self.record_wall(i, Wall::at(axis, upper), came_in);
            if crate::impact::is_impact(speed, self.impact_speed) {
                self.wall_hits += 1;
            } else {
                self.rested(i);
            }
            self.unwedge(i);
            self.maybe_sleep(i);
        }
        self.predict(i);
    }

    /// Whether body `i` collided within a contact duration.
    fn rapid(&self, i: u32) -> bool {
        self.now - self.aux[i as usize].last_hit < CONTACT_DURATION
    }

    /// Counts a pair collision of body `i` closing at `closing` m/s: an
    /// impact or a resting contact.
    fn count(&mut self, i: u32, closing: f64) {
        if crate::impact::is_impact(closing, self.impact_speed) {
            self.collisions += 1;
        } else {
            self.rested(i);
        }
    }

    /// Counts body `i` as resting on something, once per step: a disc at
    /// rest meets its support event after event, and the count is of discs
    /// resting, not of those events.
    pub(super) fn rested(&mut self, i: u32) {
        let stamp = &mut self.rest_stamps[i as usize];
        if *stamp != self.step_id {
            *stamp = self.step_id;
            self.resting += 1;
        }
    }

    pub(super) fn cross_cell(&mut self, i: u32, axis: usize, upper: bool) {
        self.advance_to(i, self.now);
        self.move_to_next_cell(i, axis, upper);
        if !self.let_go_unless_clear(i) {
            self.predict_after_crossing(i, axis, upper);
        }
    }

    /// Moves disc `i` (at the current time, on its cell's border) into the
    /// next cell along `axis`; across a periodic edge it comes in at the
    /// other side, by one world's length.
    #[inline]
    pub(super) fn move_to_next_cell(&mut self, i: u32, axis: usize, upper: bool) {
        let from = self.bodies[i as usize].cell;
        let mut to = from;
        to[axis] += if upper { 1 } else { -1 };
        if self.grid.periodic {
            let n = self.grid.dims[axis];
            let size = self.laws.size[axis];
            let b = &mut self.bodies[i as usize];
            if to[axis] >= n {
                to[axis] = 0;
                b.pos[axis] -= size;
            } else if to[axis] < 0 {
                to[axis] = n - 1;
                b.pos[axis] += size;
            }
        }
        to[axis] = to[axis].clamp(0, self.grid.dims[axis] - 1);
        self.grid.remove(&mut self.bodies, i, from);
        self.grid.insert(&mut self.bodies, i, to);
        self.bodies[i as usize].cell = to;
    }
}
