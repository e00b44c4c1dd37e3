//! Setting a step up: sorting the discs into cells and predicting every
//! event (at the start, or after an edit), separating overlaps a scene
//! starts with (discs sharing a centre laid out on a spiral first, then
//! sweeps over the cells' neighbours that push pairs a little past
//! touching: 2,000 discs on one spot, or 10⁵ random ones at 30 % of the
//! area, come apart in well under a second), and carrying the state into
//! the next step when nothing was edited.

use super::grid::Grid;
use super::predict::PairGuess;
use super::queue::EventQueue;
use super::{
    Aux, Body, Sim, EVENTS_BASE, EVENTS_PER_DISC, OVERLAP_TOLERANCE, PREFETCH_MIN_DISCS,
    SEPARATION_SWEEPS, SEPARATION_WORK,
};
use crate::boundary::Boundary;
use crate::laws::Laws;
use crate::particle::Particle;
use glam::DVec2;

/// How far past touching set-up pushes an overlapping pair apart, as a
/// fraction of the two radii (a millimetre for two 0.5 m discs). Pushed
/// exactly to touching, a crowd's pairs closed again on each other and
/// 20,000 random discs at 30 % still overlapped after 100 sweeps; with the
/// margin they are apart after 42.
const SEPARATION_MARGIN: f64 = 1e-3;

impl Sim {
    pub(super) fn new(particles: &[Particle], laws: &Laws, dt: f64) -> Self {
        let n = particles.len();
        let mut sim = Sim {
            laws: *laws,
            end: dt,
            now: 0.0,
            bodies: Vec::with_capacity(n),
            aux: Vec::with_capacity(n),
            order: Vec::with_capacity(n),
            grid: Grid::new(particles, laws),
            queue: EventQueue::new(n),
            prefetching: n >= PREFETCH_MIN_DISCS,
            cap: EVENTS_PER_DISC
                .saturating_mul(n)
                .saturating_add(EVENTS_BASE),
            events: 0,
            collisions: 0,
            wall_hits: 0,
            resting: 0,
            rest_stamps: vec![0; n],
            step_id: 1,
            impact_speed: crate::impact::threshold(laws.gravity, dt),
            wall_impulse: 0.0,
            max_overlap: 0.0,
            separated: 0,
            separation_energy: 0.0,
            truncated: false,
            finished_at: 0.0,
            overlapping: false,
            stop_at_collision: false,
            stop_at_wall: false,
            stopped: false,
            record: false,
            impacts: Vec::new(),
            sleeping: Sim::may_sleep(laws),
            rest: vec![super::sleep::Rest::Free; n],
            sleepers: 0,
            hits: vec![0; n],
            warm: Vec::new(),
            fix_counts: Vec::new(),
            quiet: vec![0; n],
            paid: vec![DVec2::ZERO; n],
            energy_at_start: None,
            spins: Vec::new(),
            rough: Sim::is_rough(laws),
        };
        let wrap = laws.boundary == Boundary::Periodic;
        let turning = sim.rough || particles.iter().any(|p| p.spin != 0.0 || p.angle != 0.0);
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
                gen: 0,
                cell,
                next_in_cell: super::grid::NIL,
            });
            sim.aux.push(Aux {
                mass: p.mass,
                last_hit: f64::NEG_INFINITY,
                guess: PairGuess::NONE,
            });
            if turning {
                sim.spins.push(super::Spin {
                    spin: p.spin,
                    angle: p.angle,
                    since: 0.0,
                });
            }
            sim.order.push(i);
            sim.grid.insert(&mut sim.bodies, k as u32, cell);
        }
        sim.overlapping = !sim.separate_overlaps();
        // The pushes keep each pair's centre of mass, but a disc put back
        // inside the walls rises: the potential energy that moving added.
        let down = laws.gravity;
        sim.separation_energy = sim
            .bodies
            .iter()
            .zip(&sim.aux)
            .zip(&sim.order)
            .map(|((b, a), &i)| {
                let moved = laws
                    .boundary
                    .separation(particles[i as usize].pos, b.pos, laws.size);
                -a.mass * down.dot(moved)
            })
            .sum();
        sim.predict_all();
        sim
    }

    /// Pushes overlapping discs apart (positions only, shares by inverse
    /// mass, so no velocity and no momentum appear and the centre of mass
    /// stays), sweep after sweep; returns whether every overlap deeper than
    /// [`OVERLAP_TOLERANCE`] is gone. It sweeps [`SEPARATION_SWEEPS`] times
    /// at most, or more while every [`SEPARATION_SWEEPS`] sweeps shrink the
    /// deepest overlap by a tenth, within [`SEPARATION_WORK`]. Hard discs
    /// never overlap by themselves, but a scene may start that way, and
    /// `impulse` leaves a pile overlapping by a percent or two: its lift
    /// climbs about a layer a sweep (1,100 sweeps for the 150-disc pile). A
    /// disc pushed across a cell border is moved to its new cell. The pairs
    /// the first sweep pushed are counted in `separated`.
    pub(super) fn separate_overlaps(&mut self) -> bool {
        self.unstack_coincident();
        let most = (SEPARATION_WORK / self.bodies.len().max(1)).max(SEPARATION_SWEEPS);
        let mut checkpoint = f64::INFINITY;
        for sweep in 0..most {
            let (mut pushed, mut deepest) = (0, 0.0f64);
            for i in 0..self.bodies.len() as u32 {
                let cell = self.bodies[i as usize].cell;
                let mut partners: Vec<u32> = Vec::new();
                self.grid.for_each_neighbour(cell, |c, _| {
                    partners.extend(self.grid.members(&self.bodies, c).filter(|&j| j > i));
                });
                for j in partners {
                    if let Some(depth) = self.push_apart(i, j) {
                        pushed += 1;
                        deepest = deepest.max(depth);
                    }
                }
            }
            if sweep == 0 {
                self.separated = pushed;
            }
            if pushed == 0 {
                return true;
            }
            self.keep_inside_and_recell();
            if (sweep + 1) % SEPARATION_SWEEPS == 0 {
                if deepest > 0.9 * checkpoint {
                    return false; // no longer getting anywhere
                }
                checkpoint = deepest;
            }
        }
        false
    }

    /// Puts every disc back inside a closed box's walls (or wraps it on a
    /// torus) and moves it to the cell its centre is now in.
    fn keep_inside_and_recell(&mut self) {
        for k in 0..self.bodies.len() as u32 {
            let b = &mut self.bodies[k as usize];
            if self.laws.boundary == Boundary::Box {
                let lo = DVec2::splat(b.radius);
                let hi = (self.laws.size - lo).max(lo);
                for axis in 0..2 {
                    if self.laws.walls.at(axis, false) {
                        b.pos[axis] = b.pos[axis].max(lo[axis]);
                    }
                    if self.laws.walls.at(axis, true) {
                        b.pos[axis] = b.pos[axis].min(hi[axis]);
                    }
                }
            } else if self.laws.boundary == Boundary::Periodic {
                b.pos = b.pos.rem_euclid(self.laws.size);
            }
            let to = self.grid.cell_of(b.pos);
            if to != b.cell {
                let from = b.cell;
                b.cell = to;
                self.grid.remove(&mut self.bodies, k, from);
                self.grid.insert(&mut self.bodies, k, to);
            }
        }
    }

    /// Discs that share a centre exactly (a scene may put a pile on one
    /// spot) are laid out on a sunflower spiral around it first, a little
    /// more than a diameter apart, their mass-weighted mean offset removed
    /// so that the centre of mass stays. Pushing them apart pair by pair
    /// spread a pile of 2,000 along one line and then a layer per sweep:
    /// more than 100 sweeps, 13 s. Discs that do not share a centre are
    /// left to the sweeps.
    fn unstack_coincident(&mut self) {
        let mut by_centre: Vec<(u64, u64, u32)> = self
            .bodies
            .iter()
            .enumerate()
            .map(|(k, b)| (b.pos.x.to_bits(), b.pos.y.to_bits(), k as u32))
            .collect();
        by_centre.sort_unstable();
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        let mut moved = false;
        for group in by_centre.chunk_by(|a, b| (a.0, a.1) == (b.0, b.1)) {
            if group.len() < 2 {
                continue;
            }
            let widest = group
                .iter()
                .map(|&(_, _, k)| self.bodies[k as usize].radius)
                .fold(0.0, f64::max);
            // A sunflower's nearest neighbours sit about 1.8 times its
            // spacing apart: this leaves about a tenth of a diameter.
            let spacing = 1.1 * 2.0 * widest / 1.8;
            let offsets: Vec<DVec2> = (0..group.len())
                .map(|n| {
                    let r = spacing * (n as f64 + 0.5).sqrt();
                    r * crate::math::unit(golden * n as f64)
                })
                .collect();
            let (mut weighted, mut total) = (DVec2::ZERO, 0.0);
            for (&(_, _, k), o) in group.iter().zip(&offsets) {
                let m = self.aux[k as usize].mass;
                weighted += m * *o;
                total += m;
            }
            let mean = weighted / total;
            for (&(_, _, k), o) in group.iter().zip(&offsets) {
                self.bodies[k as usize].pos += *o - mean;
            }
            moved = true;
        }
        if moved {
            self.keep_inside_and_recell();
        }
    }

    /// Moves discs `i` and `j` apart if they overlap beyond the tolerance;
    /// returns by how much they did, as a fraction of their radii's sum.
    pub(super) fn push_apart(&mut self, i: u32, j: u32) -> Option<f64> {
        let (a, b) = (self.bodies[i as usize], self.bodies[j as usize]);
        let d = self.laws.boundary.separation(a.pos, b.pos, self.laws.size);
        let reach = a.radius + b.radius;
        let dist = d.length();
        let depth = reach - dist;
        if depth <= OVERLAP_TOLERANCE * reach {
            return None;
        }
        let normal = if dist > 0.0 {
            d / dist
        } else {
            crate::narrow_phase::COINCIDENT_NORMAL
        };
        let (ma, mb) = (self.aux[i as usize].mass, self.aux[j as usize].mass);
        let total = ma + mb;
        // A little past touching ([`SEPARATION_MARGIN`]), so that a crowd's
        // pushes settle instead of undoing each other.
        let push = depth + SEPARATION_MARGIN * reach;
        self.bodies[i as usize].pos -= normal * (push * mb / total);
        self.bodies[j as usize].pos += normal * (push * ma / total);
        Some(depth / reach)
    }

    /// Whether the discs are exactly as the last step left them, under the
    /// same geometry, so the queued events still hold.
    pub(super) fn continues(&self, particles: &[Particle], laws: &Laws) -> bool {
        let same_geometry = laws.size == self.laws.size
            && laws.gravity == self.laws.gravity
            && laws.boundary == self.laws.boundary
            && laws.walls == self.laws.walls;
        let turning = !self.spins.is_empty();
        let unmoved = |p: &Particle, b: &Body, c: &Aux| {
            p.pos == self.written_pos(b)
                && p.vel == b.vel
                && p.mass == c.mass
                && p.radius == b.radius
        };
        let mut discs = self.order.iter().zip(self.bodies.iter().zip(&self.aux));
        same_geometry
            && !self.overlapping
            && particles.len() == self.bodies.len()
            && (turning || !Sim::is_rough(laws))
            && if turning {
                discs.zip(&self.spins).all(|((&i, (b, c)), s)| {
                    let p = &particles[i as usize];
                    unmoved(p, b, c) && p.spin == s.spin && p.angle == s.angle_at(self.finished_at)
                })
            } else {
                discs.all(|(&i, (b, c))| {
                    let p = &particles[i as usize];
                    unmoved(p, b, c) && p.spin == 0.0 && p.angle == 0.0
                })
            }
    }

    /// Starts a new step of `dt` from where the last one ended: every disc is
    /// at the end time, which becomes time zero.
    pub(super) fn restart(&mut self, laws: &Laws, dt: f64) {
        let shift = self.finished_at;
        for a in &mut self.aux {
            a.last_hit -= shift;
            a.guess.time -= shift;
        }
        for b in &mut self.bodies {
            b.time -= shift;
        }
        for s in &mut self.spins {
            s.since -= shift;
        }
        self.queue.shift_times(shift);
        self.laws = *laws; // restitutions may have changed
        self.rough = Sim::is_rough(laws);
        self.sleeping = Sim::may_sleep(laws);
        if !self.sleeping && self.sleepers > 0 {
            self.now = 0.0;
            self.wake_all();
            self.predict_all();
        }
        self.now = 0.0;
        self.end = dt;
        self.events = 0;
        self.collisions = 0;
        self.wall_hits = 0;
        self.resting = 0;
        self.step_id += 1;
        self.impact_speed = crate::impact::threshold(laws.gravity, dt);
        self.wall_impulse = 0.0;
        self.max_overlap = 0.0;
        self.separated = 0;
        self.separation_energy = 0.0;
        self.truncated = false;
    }
}
