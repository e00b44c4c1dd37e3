//! `exact`: event-driven hard discs.
//!
//! Discs fly on exact trajectories (straight lines, or parabolas under
//! gravity) between events. A priority queue holds each disc's earliest
//! predicted event: a collision with a disc in its own or a neighbouring cell,
//! a wall hit, or a crossing into the next cell of a grid whose cells are at
//! least one diameter wide (so predicting an event costs O(1) and processing
//! one O(log n)). Each step takes the earliest event, advances the discs
//! involved to that instant, resolves it, re-predicts them, and repeats until
//! the end of the step; then every disc is advanced to the end.
//!
//! - Invalidation: each disc has a generation counter, bumped only when its
//!   trajectory changes (a collision or a wall hit). An event remembers the
//!   generations it was predicted with; a stale one is dropped, or, if only
//!   the partner changed, its owner is re-predicted *without* a bump, so two
//!   discs can never invalidate each other forever.
//! - Round-off can leave a pair a hair inside contact; a pair that overlaps
//!   and approaches collides at once (time zero), never at a negative time
//!   (Bannerman et al. 2014). A pair that overlaps but separates is left to
//!   separate.
//! - Relative motion of two discs is straight even under gravity (both fall
//!   alike), so pair times solve a quadratic; walls and cell borders under
//!   gravity solve a quadratic too.
//! - Inelastic collapse (e < 1 can produce infinitely many collisions in
//!   finite time): the TC rule of Luding & McNamara (1998): a collision of a
//!   disc that already collided within [`TC_FRACTION`] of the step is
//!   elastic. It keeps the count of collisions per step finite while changing
//!   the dissipation only in those rare rapid sequences. A hard cap of
//!   [`EVENTS_PER_DISC`]·n + [`EVENTS_BASE`] events per step bounds the work
//!   in any case; hitting it ends the step early and is reported
//!   (`StepStats::truncated`).
//! - Overlap present at the start (a scene may place discs that way) is
//!   pushed apart once, by inverse mass and positions only, so nothing
//!   starts moving and the centre of mass stays.
//! - Speed: the discs are copied into a local array sorted by cell, so
//!   neighbours sit close in memory, and each cell keeps its first few discs
//!   inline; the results are written back in the caller's order. [`Exact`]
//!   keeps that array, the cells and the queue (with the events that lie past
//!   the step) from one step to the next; a step first checks that every
//!   disc is exactly where the last one left it, and only an edit (or a
//!   change of size, gravity or boundary) makes it start afresh.

use crate::boundary::Boundary;
use crate::ledger::{Collision, Ledger};
use crate::particle::Particle;
use crate::resolution::collision_velocities;
use crate::stats::StepStats;
use crate::world::Laws;
use glam::DVec2;
use grid::Grid;
use kinematics::{first_crossing, pair_time};
use std::time::Instant;

mod grid;
mod kinematics;
mod queue;
mod simultaneous;

use queue::{Event, EventQueue};

/// TC-model window, as a fraction of the step.
pub const TC_FRACTION: f64 = 1e-4;
/// Event budget per disc and step.
pub const EVENTS_PER_DISC: usize = 1_000;
/// Event budget per step on top of the per-disc one.
pub const EVENTS_BASE: usize = 100_000;
/// Overlap, as a fraction of the two radii, that set-up pushes apart
/// (anything shallower is round-off, which the collide-now rule handles).
pub const OVERLAP_TOLERANCE: f64 = 1e-9;
/// Two discs this close to touching (as a fraction of the two radii) when
/// another collision happens count as colliding at the same instant.
pub const SIMULTANEOUS_TOLERANCE: f64 = 1e-9;
/// Most sweeps of push-apart per set-up; what is left waits for the next
/// step, which starts afresh.
pub const SEPARATION_SWEEPS: usize = 100;

/// The exact method's state between steps. While nobody edits the world,
/// the next step continues the event calendar where the last one stopped
/// instead of sorting the discs and predicting every event afresh.
#[derive(Default)]
pub struct Exact {
    sim: Option<Sim>,
    /// End a step at its first pair collision, at the instant of impact.
    pub stop_at_collision: bool,
}

impl Exact {
    /// Advances `particles` by `dt`; returns the time actually simulated
    /// (less than `dt` only if the event cap was hit).
    pub fn advance(
        &mut self,
        particles: &mut [Particle],
        laws: &Laws,
        dt: f64,
        stats: &mut StepStats,
        (ledger, start): (&mut Ledger, f64),
    ) -> f64 {
        let started = Instant::now();
        let mut sim = match self.sim.take() {
            Some(mut sim) if sim.continues(particles, laws) => {
                sim.restart(laws, dt);
                sim
            }
            _ => Sim::new(particles, laws, dt),
        };
        sim.record = ledger.is_on();
        sim.stop_at_collision = self.stop_at_collision;
        sim.stopped = false;
        sim.run();
        for mut c in sim.collided.drain(..) {
            c.time += start;
            ledger.push(c);
        }
        let end = if sim.truncated || sim.stopped {
            sim.now
        } else {
            sim.end
        };
        sim.finish(end, particles);
        stats.pair_collisions += sim.collisions;
        stats.wall_hits += sim.wall_hits;
        stats.wall_impulse += sim.wall_impulse;
        stats.events += sim.events;
        stats.truncated |= sim.truncated;
        stats.max_overlap = stats.max_overlap.max(sim.max_overlap);
        self.sim = Some(sim);
        // Detection, resolution and flight interleave event by event, so the
        // whole step is booked as resolution.
        stats.timings.resolution += started.elapsed();
        end
    }

    /// Drops the carried state (another method moved the discs).
    pub fn forget(&mut self) {
        self.sim = None;
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// Collision with `partner`, predicted when it had generation `gen`.
    Pair { partner: u32, gen: u32 },
    /// Hit on the wall of `axis` (upper or lower).
    Wall { axis: u8, upper: bool },
    /// Crossing into the next cell along `axis`.
    Cell { axis: u8, upper: bool },
    /// Open boundary: leaving the grid's region; the grid is rebuilt.
    Leave,
}

/// A disc during a step: its state at its own local time.
#[derive(Clone, Copy, Debug)]
struct Body {
    pos: DVec2,
    vel: DVec2,
    /// The time `pos` and `vel` refer to.
    time: f64,
    radius: f64,
    mass: f64,
    /// When it last collided (for the TC rule).
    last_hit: f64,
    /// Bumped whenever its trajectory changes.
    gen: u32,
    /// Its grid cell.
    cell: [i32; 2],
}

struct Sim {
    laws: Laws,
    end: f64,
    now: f64,
    t_c: f64,
    /// The discs in cell order; `order[k]` is body k's index in the caller's slice.
    bodies: Vec<Body>,
    order: Vec<u32>,
    grid: Grid,
    queue: EventQueue<Kind>,
    cap: usize,
    events: usize,
    collisions: usize,
    wall_hits: usize,
    wall_impulse: f64,
    max_overlap: f64,
    truncated: bool,
    /// The time [`Sim::finish`] put every disc at.
    finished_at: f64,
    /// Overlaps were left after separating: start afresh next step.
    overlapping: bool,
    /// End the step at the first pair collision (run to the next collision).
    stop_at_collision: bool,
    /// The step ended there.
    stopped: bool,
    /// Collisions of this step, for the ledger (when it is on).
    record: bool,
    collided: Vec<Collision>,
}

impl Sim {
    fn new(particles: &[Particle], laws: &Laws, dt: f64) -> Self {
        let n = particles.len();
        let mut sim = Sim {
            laws: *laws,
            end: dt,
            now: 0.0,
            t_c: TC_FRACTION * dt,
            bodies: Vec::with_capacity(n),
            order: Vec::with_capacity(n),
            grid: Grid::new(particles, laws),
            queue: EventQueue::new(n),
            cap: EVENTS_PER_DISC
                .saturating_mul(n)
                .saturating_add(EVENTS_BASE),
            events: 0,
            collisions: 0,
            wall_hits: 0,
            wall_impulse: 0.0,
            max_overlap: 0.0,
            truncated: false,
            finished_at: 0.0,
            overlapping: false,
            stop_at_collision: false,
            stopped: false,
            record: false,
            collided: Vec::new(),
        };
        let wrap = laws.boundary == Boundary::Periodic;
        let mut keyed: Vec<(usize, u32)> = particles
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let pos = if wrap {
                    p.pos.rem_euclid(laws.size)
                } else {
                    p.pos
                };
                (sim.grid.index(sim.grid.cell_of(pos)), i as u32)
            })
            .collect();
        keyed.sort_unstable();
        for (k, &(_, i)) in keyed.iter().enumerate() {
            let p = &particles[i as usize];
            let pos = if wrap {
                p.pos.rem_euclid(laws.size)
            } else {
                p.pos
            };
            let cell = sim.grid.cell_of(pos);
            sim.bodies.push(Body {
                pos,
                vel: p.vel,
                time: 0.0,
                radius: p.radius,
                mass: p.mass,
                last_hit: f64::NEG_INFINITY,
                gen: 0,
                cell,
            });
            sim.order.push(i);
            sim.grid.insert(k as u32, cell);
        }
        sim.overlapping = !sim.separate_overlaps();
        sim.predict_all();
        sim
    }

    /// Pushes overlapping discs apart (positions only, shares by inverse
    /// mass, so no velocity and no momentum appear and the centre of mass
    /// stays), sweeping up to [`SEPARATION_SWEEPS`] times; returns whether
    /// every overlap deeper than [`OVERLAP_TOLERANCE`] is gone. Hard discs
    /// never overlap by themselves, but a scene may start that way; a disc
    /// pushed across a cell border is moved to its new cell.
    fn separate_overlaps(&mut self) -> bool {
        for _ in 0..SEPARATION_SWEEPS {
            let mut moved = false;
            for i in 0..self.bodies.len() as u32 {
                let cell = self.bodies[i as usize].cell;
                let mut partners: Vec<u32> = Vec::new();
                self.grid.for_each_neighbour(cell, |c, _| {
                    partners.extend(self.grid.cells[c].iter().filter(|&&j| j > i));
                });
                for j in partners {
                    moved |= self.push_apart(i, j);
                }
            }
            if !moved {
                return true;
            }
            for k in 0..self.bodies.len() as u32 {
                let b = &mut self.bodies[k as usize];
                if self.laws.boundary == Boundary::Box {
                    let lo = DVec2::splat(b.radius);
                    b.pos = b.pos.clamp(lo, (self.laws.size - lo).max(lo));
                } else if self.laws.boundary == Boundary::Periodic {
                    b.pos = b.pos.rem_euclid(self.laws.size);
                }
                let to = self.grid.cell_of(b.pos);
                if to != b.cell {
                    let from = b.cell;
                    b.cell = to;
                    self.grid.remove(k, from);
                    self.grid.insert(k, to);
                }
            }
        }
        false
    }

    /// Moves discs `i` and `j` apart if they overlap beyond the tolerance.
    fn push_apart(&mut self, i: u32, j: u32) -> bool {
        let (a, b) = (self.bodies[i as usize], self.bodies[j as usize]);
        let d = self.laws.boundary.separation(a.pos, b.pos, self.laws.size);
        let reach = a.radius + b.radius;
        let dist = d.length();
        let depth = reach - dist;
        if depth <= OVERLAP_TOLERANCE * reach {
            return false;
        }
        let normal = if dist > 0.0 {
            d / dist
        } else {
            crate::narrow_phase::COINCIDENT_NORMAL
        };
        let total = a.mass + b.mass;
        self.bodies[i as usize].pos -= normal * (depth * b.mass / total);
        self.bodies[j as usize].pos += normal * (depth * a.mass / total);
        true
    }

    /// Whether the discs are exactly as the last step left them, under the
    /// same geometry, so the queued events still hold.
    fn continues(&self, particles: &[Particle], laws: &Laws) -> bool {
        let same_geometry = laws.size == self.laws.size
            && laws.gravity == self.laws.gravity
            && laws.boundary == self.laws.boundary;
        same_geometry
            && !self.overlapping
            && particles.len() == self.bodies.len()
            && self.order.iter().zip(&self.bodies).all(|(&i, b)| {
                let p = &particles[i as usize];
                p.pos == self.written_pos(b)
                    && p.vel == b.vel
                    && p.mass == b.mass
                    && p.radius == b.radius
            })
    }

    /// Starts a new step of `dt` from where the last one ended: every disc is
    /// at the end time, which becomes time zero.
    fn restart(&mut self, laws: &Laws, dt: f64) {
        let shift = self.finished_at;
        for b in &mut self.bodies {
            b.time -= shift;
            b.last_hit -= shift;
        }
        self.queue.shift_times(shift);
        self.laws = *laws; // restitutions may have changed
        self.now = 0.0;
        self.end = dt;
        self.t_c = TC_FRACTION * dt;
        self.events = 0;
        self.collisions = 0;
        self.wall_hits = 0;
        self.wall_impulse = 0.0;
        self.max_overlap = 0.0;
        self.truncated = false;
    }

    fn predict_all(&mut self) {
        self.queue.clear();
        for i in 0..self.bodies.len() as u32 {
            self.predict(i);
        }
    }

    fn run(&mut self) {
        while let Some(ev) = self.queue.peek() {
            if ev.time > self.end {
                break; // it stays queued for the next step
            }
            if self.events >= self.cap {
                self.truncated = true;
                break;
            }
            self.queue.pop();
            self.events += 1;
            let i = ev.owner;
            self.now = ev.time;
            match ev.kind {
                Kind::Pair { partner, gen } => {
                    if self.bodies[partner as usize].gen != gen {
                        // Only the partner changed: re-predict the owner
                        // without a bump, so nobody else is invalidated.
                        self.advance_to(i, self.now);
                        self.predict(i);
                    } else {
                        self.collide_pair(i, partner);
                        if self.stop_at_collision && self.collisions > 0 {
                            self.stopped = true;
                            break;
                        }
                    }
                }
                Kind::Wall { axis, upper } => self.hit_wall(i, usize::from(axis), upper),
                Kind::Cell { axis, upper } => self.cross_cell(i, usize::from(axis), upper),
                Kind::Leave => self.rebuild_grid(),
            }
        }
    }

    /// Open space: a disc left the grid's region; grow the grid round all.
    fn rebuild_grid(&mut self) {
        for j in 0..self.bodies.len() as u32 {
            self.advance_to(j, self.now);
        }
        let as_particles: Vec<Particle> = self
            .bodies
            .iter()
            .map(|b| Particle::new(b.pos, b.vel, b.mass, b.radius, crate::Color::rgb(0, 0, 0)))
            .collect();
        self.grid = Grid::new(&as_particles, &self.laws);
        for (k, b) in self.bodies.iter_mut().enumerate() {
            b.cell = self.grid.cell_of(b.pos);
            self.grid.insert(k as u32, b.cell);
        }
        self.predict_all();
    }

    /// Puts every disc at time `t` and writes them back.
    fn finish(&mut self, t: f64, particles: &mut [Particle]) {
        for k in 0..self.order.len() {
            self.advance_to(k as u32, t);
            let b = &self.bodies[k];
            let p = &mut particles[self.order[k] as usize];
            p.pos = self.written_pos(b);
            p.vel = b.vel;
        }
        self.finished_at = t;
    }

    /// Where a disc is reported: in the periodic world's rectangle.
    fn written_pos(&self, b: &Body) -> DVec2 {
        let size = self.laws.size;
        let inside = b.pos.cmpge(DVec2::ZERO).all() && b.pos.cmplt(size).all();
        if self.laws.boundary == Boundary::Periodic && !inside {
            b.pos.rem_euclid(size)
        } else {
            b.pos
        }
    }

    fn advance_to(&mut self, i: u32, t: f64) {
        let g = self.laws.gravity;
        let b = &mut self.bodies[i as usize];
        let tau = t - b.time;
        if tau != 0.0 {
            b.pos += b.vel * tau + 0.5 * g * tau * tau;
            b.vel += g * tau;
            b.time = t;
        }
    }

    /// Queues disc `i`'s earliest event (`i` must be at the current time).
    /// Events past the step stay queued for the steps after.
    fn predict(&mut self, i: u32) {
        let me = self.bodies[i as usize];
        let g = self.laws.gravity;
        let mut best = match (g == DVec2::ZERO, self.grid.images_by_cell()) {
            (true, true) => self.nearest_pair::<false, true>(i, &me),
            (false, true) => self.nearest_pair::<true, true>(i, &me),
            (true, false) => self.nearest_pair::<false, false>(i, &me),
            (false, false) => self.nearest_pair::<true, false>(i, &me),
        };
        let consider = |tau: Option<f64>, kind: Kind, best: &mut Option<(f64, Kind)>| {
            if let Some(tau) = tau {
                if best.is_none_or(|(b, _)| tau < b) {
                    *best = Some((tau, kind));
                }
            }
        };

        for axis in 0..2 {
            let (p, v, ga) = (me.pos[axis], me.vel[axis], g[axis]);
            let a = axis as u8;
            if self.laws.boundary == Boundary::Box {
                let hi = self.laws.size[axis] - me.radius;
                consider(
                    first_crossing(p, v, ga, me.radius, -1.0),
                    Kind::Wall {
                        axis: a,
                        upper: false,
                    },
                    &mut best,
                );
                consider(
                    first_crossing(p, v, ga, hi, 1.0),
                    Kind::Wall {
                        axis: a,
                        upper: true,
                    },
                    &mut best,
                );
            }
            let (lo, hi) = self.grid.bounds(me.cell, axis);
            let last = self.grid.dims[axis] - 1;
            for (upper, bound, sign) in [(false, lo, -1.0), (true, hi, 1.0)] {
                let at_edge = if upper {
                    me.cell[axis] == last
                } else {
                    me.cell[axis] == 0
                };
                let kind = match (at_edge, self.laws.boundary) {
                    (true, Boundary::Box) => continue, // the wall comes first
                    (true, Boundary::Open) => Kind::Leave,
                    _ => Kind::Cell { axis: a, upper },
                };
                consider(first_crossing(p, v, ga, bound, sign), kind, &mut best);
            }
        }

        let event = best
            .map(|(tau, kind)| Event {
                time: self.now + tau,
                owner: i,
                kind,
            })
            .filter(|e| e.time.is_finite());
        self.queue.set(i, event);
    }

    /// Disc `i`'s earliest collision with a disc in its own or a
    /// neighbouring cell, as (time from now, event). Specialised on whether
    /// there is gravity and whether a neighbour's periodic image follows from
    /// its cell, since this loop is where the method spends its time.
    #[inline]
    fn nearest_pair<const GRAVITY: bool, const IMAGES_BY_CELL: bool>(
        &self,
        i: u32,
        me: &Body,
    ) -> Option<(f64, Kind)> {
        let (bodies, laws, now) = (&self.bodies, &self.laws, self.now);
        let g = laws.gravity;
        let mut best: Option<(f64, Kind)> = None;
        self.grid.for_each_neighbour(me.cell, |cell, shift| {
            for &j in &self.grid.cells[cell] {
                if j == i {
                    continue;
                }
                let other = &bodies[j as usize];
                let tau = now - other.time;
                let (pj, vj) = if GRAVITY {
                    (
                        other.pos + other.vel * tau + 0.5 * g * tau * tau,
                        other.vel + g * tau,
                    )
                } else {
                    (other.pos + other.vel * tau, other.vel)
                };
                let d = if IMAGES_BY_CELL {
                    pj + shift - me.pos
                } else {
                    laws.boundary.separation(me.pos, pj, laws.size)
                };
                if let Some(t) = pair_time(d, vj - me.vel, me.radius + other.radius) {
                    if best.is_none_or(|(b, _)| t < b) {
                        best = Some((
                            t,
                            Kind::Pair {
                                partner: j,
                                gen: other.gen,
                            },
                        ));
                    }
                }
            }
        });
        best
    }

    fn collide_pair(&mut self, i: u32, j: u32) {
        self.advance_to(i, self.now);
        self.advance_to(j, self.now);
        if self.queue.peek().is_some_and(|next| next.time <= self.now) {
            // Another event at this very instant: maybe a disc meeting two
            // others at once.
            let touches = self.touches_now(i, j);
            if touches.len() > 1 {
                self.collide_together(&touches);
                return;
            }
        }
        let (a, b) = (self.bodies[i as usize], self.bodies[j as usize]);
        let d = self.laws.boundary.separation(a.pos, b.pos, self.laws.size);
        let dist = d.length();
        let normal = if dist > 0.0 && (d / dist).is_finite() {
            d / dist
        } else {
            crate::narrow_phase::COINCIDENT_NORMAL
        };
        if (b.vel - a.vel).dot(normal) < 0.0 {
            let rapid = self.now - a.last_hit < self.t_c || self.now - b.last_hit < self.t_c;
            let e = if rapid { 1.0 } else { self.laws.restitution };
            let (va, vb) = collision_velocities(a.mass, b.mass, a.vel, b.vel, normal, e);
            if self.record {
                self.collided.push(Collision {
                    time: self.now,
                    discs: [
                        self.order[i as usize] as usize,
                        self.order[j as usize] as usize,
                    ],
                    normal,
                    masses: [a.mass, b.mass],
                    before: [a.vel, b.vel],
                    after: [va, vb],
                });
            }
            for (k, v) in [(i, va), (j, vb)] {
                let body = &mut self.bodies[k as usize];
                body.vel = v;
                body.gen += 1;
                body.last_hit = self.now;
            }
            self.collisions += 1;
            self.max_overlap = self.max_overlap.max(a.radius + b.radius - dist);
        }
        self.predict(i);
        self.predict(j);
    }

    /// The contacts, approaching and touching right now (to round-off), of
    /// `i` and `j` with each other and with their neighbours; each disc
    /// involved is advanced to now. Pairs are (body, body, normal).
    fn touches_now(&mut self, i: u32, j: u32) -> Vec<(u32, u32, DVec2)> {
        let mut around = Vec::new();
        for d in [i, j] {
            let cell = self.bodies[d as usize].cell;
            self.grid.for_each_neighbour(cell, |c, _| {
                around.extend(self.grid.cells[c].iter().map(|&k| (d, k)));
            });
        }
        let mut touches = Vec::new();
        for (d, k) in around {
            if k == d || (d == j && k == i) {
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
                if (b.vel - a.vel).dot(normal) < 0.0 {
                    touches.push((d, k, normal));
                }
            }
        }
        touches
    }

    /// Resolves `touches` together (see [`simultaneous`]).
    fn collide_together(&mut self, touches: &[(u32, u32, DVec2)]) {
        let mut ids: Vec<u32> = touches.iter().flat_map(|&(a, b, _)| [a, b]).collect();
        ids.sort_unstable();
        ids.dedup();
        let slot = |k: u32| ids.binary_search(&k).unwrap_or(0);
        let masses: Vec<f64> = ids.iter().map(|&k| self.bodies[k as usize].mass).collect();
        let velocities: Vec<DVec2> = ids.iter().map(|&k| self.bodies[k as usize].vel).collect();
        let rapid = ids
            .iter()
            .any(|&k| self.now - self.bodies[k as usize].last_hit < self.t_c);
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
        if self.record {
            for t in &list {
                self.collided.push(Collision {
                    time: self.now,
                    discs: [
                        self.order[ids[t.a] as usize] as usize,
                        self.order[ids[t.b] as usize] as usize,
                    ],
                    normal: t.normal,
                    masses: [masses[t.a], masses[t.b]],
                    before: [velocities[t.a], velocities[t.b]],
                    after: [after[t.a], after[t.b]],
                });
            }
        }
        for (&k, v) in ids.iter().zip(after) {
            let body = &mut self.bodies[k as usize];
            body.vel = v;
            body.gen += 1;
            body.last_hit = self.now;
        }
        self.collisions += touches.len();
        for &k in &ids {
            self.predict(k);
        }
    }

    fn hit_wall(&mut self, i: u32, axis: usize, upper: bool) {
        self.advance_to(i, self.now);
        let rapid = self.now - self.bodies[i as usize].last_hit < self.t_c;
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
        if into_wall {
            self.wall_impulse += b.mass * (1.0 + e) * b.vel[axis].abs();
            b.vel[axis] *= -e;
            b.gen += 1;
            b.last_hit = self.now;
            self.wall_hits += 1;
        }
        self.predict(i);
    }

    fn cross_cell(&mut self, i: u32, axis: usize, upper: bool) {
        self.advance_to(i, self.now);
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
        self.grid.remove(i, from);
        self.grid.insert(i, to);
        self.bodies[i as usize].cell = to;
        self.predict(i);
    }
}
