//! Predicting a disc's next event: the earliest of its collisions with the
//! discs in the 3×3 cells around it, its wall hits, and its crossing into
//! the next cell.
//!
//! The earliest pair collision found is kept per disc ([`PairGuess`]). A
//! cell crossing leaves the disc's trajectory as it was, so after one the
//! guess still holds unless its partner has changed course since, and only
//! the three cells that have just come into reach need scanning: a third of
//! a full prediction, for the commonest event of a gas.

use super::grid::NIL;
use super::kinematics::{accelerating_pair_time, first_crossing, pair_time, PairTerms};
use super::queue::Event;
use super::sleep::Rest;
use super::{Body, Kind, Sim};
use crate::boundary::Boundary;
use glam::DVec2;

/// No partner.
const NOBODY: u32 = NIL;

/// Slots of the scan's ring of discs to visit: never more than the nine
/// cells' lists are waiting, one disc each.
const RING: usize = 16;
/// Where [`Sim::scan_for`] keeps, in a rank, which of its discs the
/// neighbour is measured against (above a slot's bits and a list's place).
const WHOSE_SHIFT: u32 = 28;

/// A disc's earliest pair collision, as last predicted.
#[derive(Clone, Copy, Debug)]
pub(super) struct PairGuess {
    /// When, on the step's clock; infinite when there is none.
    pub time: f64,
    /// With whom ([`NOBODY`] when there is none).
    pub partner: u32,
    /// The partner's generation when it was predicted.
    pub gen: u32,
}

impl PairGuess {
    pub const NONE: PairGuess = PairGuess {
        time: f64::INFINITY,
        partner: NOBODY,
        gen: 0,
    };
}

/// How a scan finds a neighbour's nearest periodic image
/// ([`Sim::scan_cells`]).
pub(super) mod images {
    /// No cell scanned wraps: the neighbour where it is.
    pub const NONE: u8 = 0;
    /// Shifted by its cell's shift.
    pub const BY_CELL: u8 = 1;
    /// Pair by pair, from the boundary (a periodic grid less than three
    /// cells wide, where one cell can be a neighbour on both sides).
    pub const PER_PAIR: u8 = 2;
}

/// Which cells a pair scan visits.
#[derive(Clone, Copy)]
enum Reach {
    /// All nine around the disc.
    Around,
    /// The three that came into reach with a crossing along `axis`.
    New { axis: usize, upper: bool },
}

impl Sim {
    /// Queues disc `i`'s earliest event after scanning all nine cells
    /// around it (`i` must be at the current time). Events past the step
    /// stay queued for the steps after.
    pub(super) fn predict(&mut self, i: u32) {
        self.aux[i as usize].guess = self.scan(i, PairGuess::NONE, Reach::Around);
        self.schedule(i);
    }

    /// Queues disc `i`'s earliest event after it crossed into its present
    /// cell along `axis`: its pair guess holds if its partner kept its
    /// course, and then only the cells new in reach are scanned.
    pub(super) fn predict_after_crossing(&mut self, i: u32, axis: usize, upper: bool) {
        let guess = match self.guess_that_holds(i) {
            Some(guess) if self.grid.images_by_cell() => guess,
            _ => return self.predict(i),
        };
        self.aux[i as usize].guess = self.scan(i, guess, Reach::New { axis, upper });
        self.schedule(i);
    }

    /// Disc `i`'s pair guess, if it still holds: it has no partner, or its
    /// partner has kept its course since.
    #[inline]
    pub(super) fn guess_that_holds(&self, i: u32) -> Option<PairGuess> {
        let guess = self.aux[i as usize].guess;
        let holds = guess.partner == NOBODY || self.bodies[guess.partner as usize].gen == guess.gen;
        holds.then_some(guess)
    }

    /// Queues the earliest of disc `i`'s pair guess, wall hits and cell
    /// crossings.
    fn schedule(&mut self, i: u32) {
        let me = &self.bodies[i as usize];
        let guess = self.aux[i as usize].guess;
        let mut best = (
            guess.time,
            Kind::Pair {
                partner: guess.partner,
                gen: guess.gen,
            },
        );
        let g = self.accel(i);
        let exit = if self.asleep(i) {
            None // still: no walls, no crossings
        } else if g == DVec2::ZERO {
            self.straight_exit(me)
        } else {
            self.curved_exit(me, g)
        };
        if let Some((tau, kind)) = exit {
            if self.now + tau < best.0 {
                best = (self.now + tau, kind);
            }
        }
        let event = best.0.is_finite().then_some(Event {
            time: best.0,
            owner: i,
            kind: best.1,
        });
        self.queue.set(i, event);
    }

    /// `guess` improved by the discs in the cells of `reach`, specialised
    /// on whether there is gravity and whether a neighbour's periodic image
    /// follows from its cell, since this loop is where the method spends
    /// its time.
    fn scan(&self, i: u32, guess: PairGuess, reach: Reach) -> PairGuess {
        let me = &self.bodies[i as usize];
        match (self.laws.gravity == DVec2::ZERO, self.grid.images_by_cell()) {
            (true, true) => self.scan_with::<false, true>(i, me, guess, reach),
            (false, true) => self.scan_with::<true, true>(i, me, guess, reach),
            (true, false) => self.scan_with::<false, false>(i, me, guess, reach),
            (false, false) => self.scan_with::<true, false>(i, me, guess, reach),
        }
    }

    #[inline]
    fn scan_with<const GRAVITY: bool, const IMAGES_BY_CELL: bool>(
        &self,
        i: u32,
        me: &Body,
        guess: PairGuess,
        reach: Reach,
    ) -> PairGuess {
        // Sleepers lie still: a moving disc meets one on a parabola.
        if GRAVITY && self.sleepers > 0 {
            return self.scan_among_sleepers::<IMAGES_BY_CELL>(i, me, guess, reach);
        }
        // The cells first, then one loop over their discs: the loop is
        // where the method spends its time, and a closure per cell kept
        // it from being compiled as one.
        let (mut cells, mut shifts, mut count) = ([0; 9], [DVec2::ZERO; 9], 0);
        let gather = |cell: usize, shift: DVec2| {
            (cells[count], shifts[count]) = (cell, shift);
            count += 1;
        };
        match reach {
            Reach::Around => self.grid.for_each_neighbour(me.cell, gather),
            Reach::New { axis, upper } => self
                .grid
                .for_each_new_in_reach(me.cell, axis, upper, gather),
        }
        if IMAGES_BY_CELL {
            self.scan_cells::<GRAVITY, { images::BY_CELL }>(i, &cells[..count], &shifts, guess)
        } else {
            self.scan_cells::<GRAVITY, { images::PER_PAIR }>(i, &cells[..count], &shifts, guess)
        }
    }

    /// `guess` improved by the discs in `cells` (grid indices); `IMAGES`
    /// says how a neighbour's nearest periodic image is found ([`images`]),
    /// from `shifts` (one per cell) for [`images::BY_CELL`].
    #[inline(always)]
    pub(super) fn scan_cells<const GRAVITY: bool, const IMAGES: u8>(
        &self,
        i: u32,
        cells: &[usize],
        shifts: &[DVec2],
        guess: PairGuess,
    ) -> PairGuess {
        let [guess] = self.scan_for::<GRAVITY, IMAGES, 1, RING>([i], [cells], shifts, [guess]);
        guess
    }

    /// [`Sim::scan_cells`] for the two discs of a collision at once, each
    /// with its nine cells, none wrapped, no gravity: one ring over all
    /// eighteen lists, so that the loads of both scans are on their way
    /// together.
    #[inline(always)]
    pub(super) fn scan_two(&self, discs: [u32; 2], cells: [[usize; 9]; 2]) -> [PairGuess; 2] {
        let cells = [&cells[0][..], &cells[1][..]];
        let none = [PairGuess::NONE; 2];
        self.scan_for::<false, { images::NONE }, 2, { 2 * RING }>(discs, cells, &[], none)
    }

    /// The `N` discs' `guesses` improved by the discs in their `cells`.
    ///
    /// The discs are visited from a ring of `R` lists (at least as many as
    /// there are cells): each cell's first disc, then each visited disc's
    /// follower. One loop, whose only hard-to-guess branch is its end, and
    /// the next lists' loads start while this one's arrive. Each neighbour
    /// carries whose cell it was found in and its place in the order of a
    /// walk cell by cell, list by list (`rank`), so that it is measured
    /// against that disc with the same arithmetic as a scan of its own, and
    /// a tie goes to the neighbour that walk would have met first, as it
    /// always did.
    #[inline(always)]
    fn scan_for<const GRAVITY: bool, const IMAGES: u8, const N: usize, const R: usize>(
        &self,
        discs: [u32; N],
        cells: [&[usize]; N],
        shifts: &[DVec2],
        mut guesses: [PairGuess; N],
    ) -> [PairGuess; N] {
        let (bodies, laws, now) = (&self.bodies, &self.laws, self.now);
        let mine = discs.map(|i| &bodies[i as usize]);
        let g = laws.gravity;
        let mut ring = [(NIL, 0u32); R];
        let (mut head, mut tail) = (0usize, 0usize);
        for (whose, cells) in cells.iter().enumerate() {
            for (slot, &cell) in cells.iter().enumerate() {
                let first = self.grid.first(cell);
                let rank = ((whose as u32) << WHOSE_SHIFT) + ((slot as u32) << 24) + 1;
                ring[tail % R] = (first, rank);
                tail += usize::from(first != NIL);
            }
        }
        // Ask for every list's first disc at once. The loop below reads them
        // one per turn, and a turn is long enough that the processor looks
        // only two or three turns ahead; a prefetch waits for nothing. At 10⁵
        // discs these bodies are mostly outside the core's caches (the
        // eleventh look at issue 30: 1.06–1.08× there, nothing at 10⁴).
        if self.prefetching {
            for &(first, _) in &ring[..tail] {
                super::prefetch(&bodies[first as usize]);
            }
        }
        // The guesses brought in win ties (rank 0).
        let mut best_ranks = [0u32; N];
        while head != tail {
            let (j, rank) = ring[head % R];
            head += 1;
            let other = &bodies[j as usize];
            let next = other.next_in_cell;
            ring[tail % R] = (next, rank + 1);
            tail += usize::from(next != NIL);
            let whose = if N == 1 {
                0
            } else {
                (rank >> WHOSE_SHIFT) as usize
            };
            let me = mine[whose];
            let tau = now - other.time;
            let (pj, vj) = if GRAVITY {
                (
                    other.pos + other.vel * tau + 0.5 * g * tau * tau,
                    other.vel + g * tau,
                )
            } else {
                (other.pos + other.vel * tau, other.vel)
            };
            let d = match IMAGES {
                images::NONE => pj - me.pos,
                images::BY_CELL => pj + shifts[((rank >> 24) & 0xf) as usize] - me.pos,
                _ => laws.boundary.separation(me.pos, pj, laws.size),
            };
            let terms = PairTerms::of(d, vj - me.vel, me.radius + other.radius);
            // Most neighbours never meet it: no root to take. (The disc
            // itself, met in its own cell, is one of them.)
            if !terms.meets() || j == discs[whose] {
                continue;
            }
            let t = now + terms.time();
            let (guess, best_rank) = (&mut guesses[whose], &mut best_ranks[whose]);
            if t < guess.time || (t == guess.time && rank < *best_rank) {
                *guess = PairGuess {
                    time: t,
                    partner: j,
                    gen: other.gen,
                };
                *best_rank = rank;
            }
        }
        guesses
    }

    /// [`Sim::scan_with`] under gravity while some discs sleep or are
    /// held: a free disc meets a still one on a parabola, and held discs
    /// meet each other through the contact solve.
    #[cold]
    #[inline(never)]
    fn scan_among_sleepers<const IMAGES_BY_CELL: bool>(
        &self,
        i: u32,
        me: &Body,
        mut guess: PairGuess,
        reach: Reach,
    ) -> PairGuess {
        let (bodies, laws, now) = (&self.bodies, &self.laws, self.now);
        let my_rest = self.rest[i as usize];
        let mine = self.accel(i);
        let visit = |cell: usize, shift: DVec2| {
            let mut next = self.grid.first(cell);
            while next != NIL {
                let j = next;
                let other = &bodies[j as usize];
                next = other.next_in_cell;
                if j == i {
                    continue;
                }
                let its_rest = self.rest[j as usize];
                if my_rest == its_rest && my_rest != Rest::Free {
                    // Neither moves, or both are held: held discs meet
                    // through the contact solve ([`super::held`]).
                    continue;
                }
                let its = self.accel(j);
                let tau = now - other.time;
                let pj = other.pos + other.vel * tau + 0.5 * its * tau * tau;
                let vj = other.vel + its * tau;
                let sigma = me.radius + other.radius;
                let t = if my_rest == Rest::Free && its_rest == Rest::Free {
                    // Both fall alike: as in the plain scan.
                    let d = if IMAGES_BY_CELL {
                        pj + shift - me.pos
                    } else {
                        laws.boundary.separation(me.pos, pj, laws.size)
                    };
                    now + pair_time(d, vj - me.vel, sigma)
                } else {
                    let d = laws.boundary.separation(me.pos, pj, laws.size);
                    now + accelerating_pair_time(d, vj - me.vel, its - mine, sigma)
                };
                if t < guess.time {
                    guess = PairGuess {
                        time: t,
                        partner: j,
                        gen: other.gen,
                    };
                }
            }
        };
        match reach {
            Reach::Around => self.grid.for_each_neighbour(me.cell, visit),
            Reach::New { axis, upper } => {
                self.grid.for_each_new_in_reach(me.cell, axis, upper, visit)
            }
        }
        guess
    }

    /// Without gravity: the first wall hit or cell crossing (time from now
    /// and kind). Along each axis only the side the disc moves towards can
    /// come, and in a box the wall comes first only from the edge cell
    /// (cells are at least a diameter wide).
    fn straight_exit(&self, me: &Body) -> Option<(f64, Kind)> {
        if self.grid.periodic || self.grid.is_inner(me.cell) {
            return Some(self.next_crossing(me));
        }
        let x = self.straight_exit_along(me, 0, me.pos.x, me.vel.x);
        let y = self.straight_exit_along(me, 1, me.pos.y, me.vel.y);
        match (x, y) {
            (Some(a), Some(b)) => Some(if b.0 < a.0 { b } else { a }),
            (a, b) => a.or(b),
        }
    }

    /// [`Sim::straight_exit`] where no wall and no edge of the grid is in
    /// the way (the commonest case, and a coin toss for a branch predictor
    /// which way it goes): the earlier crossing of the two axes, chosen
    /// without branches. An axis the disc does not move along never comes
    /// (infinite time), and neither does anything if it is still.
    #[inline]
    pub(super) fn next_crossing(&self, me: &Body) -> (f64, Kind) {
        let along = |axis: usize| {
            let v = me.vel[axis];
            let upper = v > 0.0;
            let border = self.grid.border(me.cell[axis], axis, upper);
            let tau = ((border - me.pos[axis]) / v).max(0.0);
            (if v == 0.0 { f64::INFINITY } else { tau }, upper)
        };
        let ((tx, ux), (ty, uy)) = (along(0), along(1));
        // Along x on a tie, as the general case has it.
        let y_first = ty < tx;
        (
            if y_first { ty } else { tx },
            Kind::Cell {
                axis: u8::from(y_first),
                upper: if y_first { uy } else { ux },
            },
        )
    }

    #[inline]
    fn straight_exit_along(&self, me: &Body, axis: usize, p: f64, v: f64) -> Option<(f64, Kind)> {
        if v == 0.0 {
            return None;
        }
        let upper = v > 0.0;
        let a = axis as u8;
        let cell = me.cell[axis];
        let edge = if upper { self.grid.dims[axis] - 1 } else { 0 };
        let walled = self.laws.walls.at(axis, upper);
        let (target, kind) = match (cell == edge, self.laws.boundary) {
            (true, Boundary::Box) if walled => {
                let wall = if upper {
                    self.laws.size[axis] - me.radius
                } else {
                    me.radius
                };
                (wall, Kind::Wall { axis: a, upper })
            }
            (true, Boundary::Open | Boundary::Box) => {
                (self.grid.border(cell, axis, upper), Kind::Leave)
            }
            _ => (
                self.grid.border(cell, axis, upper),
                Kind::Cell { axis: a, upper },
            ),
        };
        Some((((target - p) / v).max(0.0), kind))
    }

    /// Under gravity: the first wall hit or cell crossing along parabolas.
    fn curved_exit(&self, me: &Body, g: DVec2) -> Option<(f64, Kind)> {
        let mut best: Option<(f64, Kind)> = None;
        let mut consider = |tau: Option<f64>, kind: Kind| {
            if let Some(tau) = tau {
                if best.is_none_or(|(b, _)| tau < b) {
                    best = Some((tau, kind));
                }
            }
        };
        for axis in 0..2 {
            let (p, v, ga) = (me.pos[axis], me.vel[axis], g[axis]);
            let a = axis as u8;
            if self.laws.boundary == Boundary::Box {
                let hi = self.laws.size[axis] - me.radius;
                let lower = Kind::Wall {
                    axis: a,
                    upper: false,
                };
                let upper = Kind::Wall {
                    axis: a,
                    upper: true,
                };
                if self.laws.walls.at(axis, false) {
                    consider(first_crossing(p, v, ga, me.radius, -1.0), lower);
                }
                if self.laws.walls.at(axis, true) {
                    consider(first_crossing(p, v, ga, hi, 1.0), upper);
                }
            }
            let (lo, hi) = self.grid.bounds(me.cell, axis);
            let last = self.grid.dims[axis] - 1;
            for (upper, bound, sign) in [(false, lo, -1.0), (true, hi, 1.0)] {
                let at_edge = if upper {
                    me.cell[axis] == last
                } else {
                    me.cell[axis] == 0
                };
                let walled = self.laws.walls.at(axis, upper);
                let kind = match (at_edge, self.laws.boundary) {
                    (true, Boundary::Box) if walled => continue, // the wall comes first
                    (true, Boundary::Open | Boundary::Box) => Kind::Leave,
                    _ => Kind::Cell { axis: a, upper },
                };
                consider(first_crossing(p, v, ga, bound, sign), kind);
            }
        }
        best
    }
}
