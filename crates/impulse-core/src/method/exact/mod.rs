//! `exact`: event-driven hard discs.
//!
//! Discs fly on exact trajectories (straight lines, or parabolas under
//! gravity) between events. A calendar queue holds each disc's earliest
//! predicted event: a collision with a disc in its own or a neighbouring cell,
//! a wall hit, or a crossing into the next cell of a grid whose cells are at
//! least one diameter wide (so predicting an event costs O(1), and so does
//! queueing it). Each step takes the earliest event, advances the discs
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
//!   disc that already collided within the contact duration
//!   [`CONTACT_DURATION`] is elastic. It keeps the count of collisions per
//!   step finite while changing the dissipation only in those rare rapid
//!   sequences. Under gravity, slow discs that are held up fall asleep
//!   (see [`sleep`]), so a pile comes to rest instead. A hard cap of
//!   [`EVENTS_PER_DISC`]·n + [`EVENTS_BASE`] events per step bounds the work
//!   in any case; hitting it ends the step early and is reported
//!   (`StepStats::truncated`).
//! - Overlap present at the start (a scene may place discs that way) is
//!   pushed apart once, by inverse mass and positions only, so nothing
//!   starts moving and the centre of mass stays.
//! - Speed: the discs are copied into a local array sorted by cell, so
//!   neighbours sit close in memory; a cell's list runs through its discs,
//!   and what the pair scan reads of a disc fills one cache line; the
//!   results are written back in the caller's order. In large scenes each
//!   event prefetches what the events just after it will read, and each
//!   scan the first disc of every list it is about to walk. [`Exact`]
//!   keeps that array, the cells and the queue (with the events that lie past
//!   the step) from one step to the next; a step first checks that every
//!   disc is exactly where the last one left it, and only an edit (or a
//!   change of size, gravity or boundary) makes it start afresh.

use crate::boundary::Boundary;
use crate::clock::Instant;
use crate::laws::Laws;
use crate::ledger::{Impact, Ledger};
use crate::parallel::prefetch;
use crate::particle::Particle;
use crate::stats::StepStats;
use glam::DVec2;
use grid::Grid;

mod collide;
mod grid;
mod held;
mod kinematics;
mod plain;
mod predict;
mod queue;
mod setup;
mod simultaneous;
pub mod sleep;

pub use held::holds_discs;

use predict::PairGuess;
use queue::EventQueue;

/// The TC model's contact duration t_c (s): a disc that collided less than
/// this long ago collides elastically. About the contact time of two
/// billiard balls (200–300 µs); a physical time, so results do not depend
/// on the step.
pub const CONTACT_DURATION: f64 = 1e-4;
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
/// From this many discs, what the next events will read is prefetched while
/// the present one is carried out. The discs then take about 150 bytes each
/// in all, more than the 2 MB cache of a core, so a disc an event reads is
/// usually not in it. Measured on the gas at 30 %, 10⁵ discs, runs with and
/// without alternating, medians: 3.96 → 4.27 × 10⁵ collisions per second
/// (20 pairs of runs), 3.52 → 3.65 (16 pairs, a busier hour). Below, the
/// discs mostly fit the cache and the prefetches only cost instructions.
pub const PREFETCH_MIN_DISCS: usize = 30_000;
/// Sweeps of push-apart per set-up while they make little progress; what
/// is left waits for the next step, which starts afresh (see
/// `Sim::separate_overlaps`).
pub const SEPARATION_SWEEPS: usize = 100;
/// Most disc-visits of push-apart per set-up when sweeps keep making
/// progress (a sweep visits every disc): 10⁷, about half a second.
pub const SEPARATION_WORK: usize = 10_000_000;

/// Events this close after a stop's impact (s) belong to the same
/// instant: a step ended at an impact carries them out too.
pub const SAME_INSTANT: f64 = 1e-9;

/// The exact method's state between steps. While nobody edits the world,
/// the next step continues the event calendar where the last one stopped
/// instead of sorting the discs and predicting every event afresh.
#[derive(Default)]
pub struct Exact {
    sim: Option<Sim>,
    /// End a step at its first pair collision, at the instant of impact
    /// (after the other impacts of that instant, see [`SAME_INSTANT`]).
    pub stop_at_collision: bool,
    /// End a step at its first wall hit, likewise.
    pub stop_at_wall: bool,
    /// Run even a plain gas through the general loop (tests compare the
    /// two, see [`plain`]).
    #[cfg(test)]
    general_loop: bool,
}

impl Exact {
    /// Whether to keep to the general event loop.
    fn general_loop(&self) -> bool {
        #[cfg(test)]
        return self.general_loop;
        #[cfg(not(test))]
        false
    }

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
        sim.stop_at_wall = self.stop_at_wall;
        sim.stopped = false;
        sim.hold(dt);
        if sim.is_plain_gas() && !self.general_loop() {
            sim.run_plain();
        } else {
            sim.run();
        }
        sim.count_sleepers();
        // Recorded as they happened; the ledger takes the impacts, sorted
        // out with the threshold the counters use.
        let impact_speed = sim.impact_speed;
        for mut impact in sim.impacts.drain(..) {
            if crate::impact::is_impact(impact.closing_speed(), impact_speed) {
                match &mut impact {
                    Impact::Pair(c) => c.time += start,
                    Impact::Wall(w) => w.time += start,
                }
                ledger.push(impact);
            }
        }
        let end = if sim.truncated || sim.stopped {
            sim.now
        } else {
            sim.end
        };
        sim.pay_back(end);
        sim.finish(end, particles);
        stats.pair_collisions += sim.collisions;
        stats.wall_hits += sim.wall_hits;
        stats.resting_contacts += sim.resting;
        stats.wall_impulse += sim.wall_impulse;
        stats.events += sim.events;
        stats.truncated |= sim.truncated;
        stats.max_overlap = stats.max_overlap.max(sim.max_overlap);
        stats.separated_pairs += sim.separated;
        stats.separation_energy += sim.separation_energy;
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

#[derive(Clone, Copy, Debug, Default, PartialEq)]
enum Kind {
    /// Collision with `partner`, predicted when it had generation `gen`.
    Pair { partner: u32, gen: u32 },
    /// Hit on the wall of `axis` (upper or lower).
    Wall { axis: u8, upper: bool },
    /// Crossing into the next cell along `axis`.
    Cell { axis: u8, upper: bool },
    /// Open boundary: leaving the grid's region; the grid is rebuilt.
    #[default]
    Leave,
}

/// A disc during a step: its state at its own local time. What predicting
/// reads, and no more, in one cache line per disc; the rest is in [`Aux`].
#[derive(Clone, Copy, Debug)]
#[repr(align(64))]
struct Body {
    pos: DVec2,
    vel: DVec2,
    /// The time `pos` and `vel` refer to.
    time: f64,
    radius: f64,
    /// Bumped whenever its trajectory changes.
    gen: u32,
    /// Its grid cell.
    cell: [i32; 2],
    /// The next disc in its cell's list ([`grid::NIL`] at the end).
    next_in_cell: u32,
}

// Predicting reads one cache line per neighbour.
const _: () = assert!(std::mem::size_of::<Body>() == 64);

/// What a disc's collisions and predictions read besides its [`Body`],
/// together in half a cache line: a collision reads the masses, and the
/// predictions right after it the pair guesses, of the same two discs.
#[derive(Clone, Copy, Debug)]
#[repr(align(32))]
struct Aux {
    mass: f64,
    /// When it last collided (for the TC rule).
    last_hit: f64,
    /// Its earliest pair collision, as last predicted.
    guess: PairGuess,
}

const _: () = assert!(std::mem::size_of::<Aux>() == 32);

struct Sim {
    laws: Laws,
    end: f64,
    now: f64,
    /// The discs in cell order; `order[k]` is body k's index in the caller's slice.
    bodies: Vec<Body>,
    aux: Vec<Aux>,
    order: Vec<u32>,
    grid: Grid,
    queue: EventQueue<Kind>,
    /// Prefetch what coming events read ([`PREFETCH_MIN_DISCS`]).
    prefetching: bool,
    cap: usize,
    events: usize,
    collisions: usize,
    wall_hits: usize,
    /// Discs in a collision or wall hit slower than the impact speed this
    /// step (resting), each counted once.
    resting: usize,
    /// Per body: the step it was last counted resting in.
    rest_stamps: Vec<u64>,
    /// This step's number, for `rest_stamps`.
    step_id: u64,
    /// The closing speed above which a collision is an impact
    /// ([`crate::impact::threshold`] for a step of the step's length).
    impact_speed: f64,
    wall_impulse: f64,
    max_overlap: f64,
    /// Overlapping pairs the set-up pushed apart (0 on a continuing step).
    separated: usize,
    /// Potential energy the set-up's moves added (J; 0 on a continuing step).
    separation_energy: f64,
    truncated: bool,
    /// The time [`Sim::finish`] put every disc at.
    finished_at: f64,
    /// Overlaps were left after separating: start afresh next step.
    overlapping: bool,
    /// End the step at the first pair collision (run to the next collision).
    stop_at_collision: bool,
    /// End the step at the first wall hit (run to the next impact).
    stop_at_wall: bool,
    /// The step ended there.
    stopped: bool,
    /// Whether to keep this step's collisions and wall hits for the ledger
    /// (when it is on), in `impacts`.
    record: bool,
    impacts: Vec<Impact>,
    /// Whether discs may fall asleep under these laws ([`sleep`]).
    sleeping: bool,
    /// Per body: moving freely or asleep ([`sleep`]).
    rest: Vec<sleep::Rest>,
    /// How many are asleep or held.
    sleepers: usize,
    /// Per body: collisions in this step ([`held`]).
    hits: Vec<u32>,
    /// Total energy at the start of a step with held discs ([`held`]).
    energy_at_start: Option<f64>,
    /// Per body: steps in a row it has been held and barely moving
    /// ([`held`]).
    quiet: Vec<u32>,
    /// Per held body: the velocity its step's energy was paid for
    /// ([`held`]).
    paid: Vec<DVec2>,
    /// Per body: changes in the running [`held`] settle (zero between).
    fix_counts: Vec<u8>,
    /// Last step's contact impulses of held discs, by contact ([`held`]).
    warm: Vec<(u64, f64)>,
    /// Per body: its spin and how far it has turned ([`Spin`]); empty
    /// while nothing turns (smooth laws, no disc spinning or turned), so a
    /// smooth world reads and writes no more than before spins existed.
    spins: Vec<Spin>,
    /// Whether contacts are rough (between discs or at walls), so that
    /// collisions change spins.
    rough: bool,
}

/// A disc's rotation: read and written only at its collisions.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Spin {
    /// Angular velocity (rad/s, counter-clockwise).
    spin: f64,
    /// How far it had turned (rad) at time `since`.
    angle: f64,
    since: f64,
}

impl Spin {
    /// How far it has turned at time `t`.
    fn angle_at(&self, t: f64) -> f64 {
        self.angle + self.spin * (t - self.since)
    }
}

impl Sim {
    fn predict_all(&mut self) {
        self.queue.clear();
        for i in 0..self.bodies.len() as u32 {
            self.predict(i);
        }
        self.queue.retune();
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
            // The event stays queued while it is carried out: every branch
            // below re-predicts its owner, which replaces it.
            self.events += 1;
            if self.prefetching {
                self.prefetch_soon();
            }
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
                        self.tally(i);
                        self.tally(partner);
                        let gens = [i, partner].map(|k| self.bodies[k as usize].gen);
                        self.collide_pair(i, partner);
                        self.let_go_if_moved([i, partner], gens);
                        self.hold_if_busy([i, partner]);
                        if self.stop_at_collision && self.collisions > 0 {
                            self.stop_after_this_instant();
                        }
                    }
                }
                Kind::Wall { axis, upper } => {
                    self.tally(i);
                    let gen = self.bodies[i as usize].gen;
                    self.hit_wall(i, usize::from(axis), upper);
                    self.let_go_if_moved([i, i], [gen, gen]);
                    if self.stop_at_wall && self.wall_hits > 0 {
                        self.stop_after_this_instant();
                    }
                }
                Kind::Cell { axis, upper } => self.cross_cell(i, usize::from(axis), upper),
                Kind::Leave => self.rebuild_grid(),
            }
        }
    }

    /// Ends the step once the events of this instant (to [`SAME_INSTANT`])
    /// are carried out: two discs that hit two walls at once are one stop,
    /// not a stop between them with the momentum only half changed.
    fn stop_after_this_instant(&mut self) {
        self.stopped = true;
        self.end = self.end.min(self.now + SAME_INSTANT);
    }

    /// Asks the memory for what the events a bucket or three ahead will
    /// read, so that it arrives while this one is carried out. A bucket
    /// holds about two events, a list linked through the queue nodes, so
    /// each bucket is fetched one disc per event as it draws near, each
    /// found through the node fetched the event before: the first disc
    /// three buckets on (its body, the rest of it, its queue node), the
    /// second two buckets on, the third one bucket on; and for the first
    /// one bucket on, its partner and the cell lists around it.
    #[inline]
    fn prefetch_soon(&self) {
        let far = self.queue.soon(3);
        if far != queue::NIL {
            self.prefetch_disc(far);
        }
        let middle = self.queue.soon(2);
        if middle != queue::NIL {
            let its_second = self.queue.next_of(middle);
            if its_second != queue::NIL {
                self.prefetch_disc(its_second);
            }
        }
        let near = self.queue.soon(1);
        if near != queue::NIL {
            self.prefetch_surroundings(near);
            let its_second = self.queue.next_of(near);
            if its_second != queue::NIL {
                let its_third = self.queue.next_of(its_second);
                if its_third != queue::NIL {
                    self.prefetch_disc(its_third);
                }
            }
        }
    }

    /// Prefetches disc `k`'s body, the rest of it and its place in the queue.
    #[inline]
    fn prefetch_disc(&self, k: u32) {
        prefetch(&self.bodies[k as usize]);
        prefetch(&self.aux[k as usize]);
        self.queue.prefetch(k);
    }

    /// Prefetches the partner of disc `k`'s event and the cell lists
    /// around `k`.
    #[inline]
    fn prefetch_surroundings(&self, k: u32) {
        if let Some(Kind::Pair { partner, .. }) = self.queue.kind_of(k) {
            self.prefetch_disc(partner);
        }
        self.grid.prefetch_around(self.bodies[k as usize].cell);
    }

    /// Open space: a disc left the grid's region; grow the grid round all.
    fn rebuild_grid(&mut self) {
        for j in 0..self.bodies.len() as u32 {
            self.advance_to(j, self.now);
        }
        let as_particles: Vec<Particle> = self
            .bodies
            .iter()
            .zip(&self.aux)
            .map(|(b, c)| Particle::new(b.pos, b.vel, c.mass, b.radius, crate::Color::rgb(0, 0, 0)))
            .collect();
        self.grid = Grid::new(&as_particles, &self.laws);
        for k in 0..self.bodies.len() {
            let cell = self.grid.cell_of(self.bodies[k].pos);
            self.bodies[k].cell = cell;
            self.grid.insert(&mut self.bodies, k as u32, cell);
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
        for (s, &i) in self.spins.iter().zip(&self.order) {
            let p = &mut particles[i as usize];
            p.spin = s.spin;
            p.angle = s.angle_at(t);
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
        let g = self.accel(i);
        let b = &mut self.bodies[i as usize];
        let tau = t - b.time;
        if tau != 0.0 {
            b.pos += b.vel * tau + 0.5 * g * tau * tau;
            b.vel += g * tau;
            b.time = t;
        }
    }
}
