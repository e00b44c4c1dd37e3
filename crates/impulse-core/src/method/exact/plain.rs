//! The event loop of a plain gas: no gravity, a periodic world, smooth discs
//! that do not turn, nothing asleep or held, no stop at the first impact.
//! The lab's gas and the bench are such scenes, and most of `exact`'s time
//! goes to them.
//!
//! It carries out the same events in the same order as [`Sim::run`], with
//! the same arithmetic, so it leaves the same state bit for bit (the tests
//! below step gases both ways and compare). What it leaves out is only what
//! such a scene cannot need: the checks for sleeping and held discs, walls,
//! gravity's parabolas and spins, at every event and every prediction. Where
//! no cell around a disc wraps, the cells to scan are listed straight from
//! the grid and no periodic shift is added; after a collision, the two
//! discs' scans are one walk over both their cells ([`Sim::scan_two`]), so
//! that both scans' loads are on their way together. The pair scan
//! ([`Sim::scan_cells`]), the move into the next cell and the bounce are the
//! general loop's own. Measured on the bench's gas against the general loop
//! when it was written (c2152a4; 5 alternating rounds, medians, the same
//! state hash): 154 against 186 ns per event at 10⁴ discs, 204 against 235
//! at 10⁵ (docs/lab/NOTES.md, issue 30, the eighth look).
//!
//! An event the loop has no case for (a wall, leaving the grid: neither
//! happens in a periodic world) hands the rest of the step to the general
//! loop, which takes it from the same state.

use super::predict::{images, PairGuess};
use super::queue::Event;
use super::{Kind, Sim};
use glam::DVec2;

impl Sim {
    /// Whether this step can run [`Sim::run_plain`].
    pub(super) fn is_plain_gas(&self) -> bool {
        self.laws.gravity == DVec2::ZERO
            && self.grid.periodic
            && self.grid.images_by_cell()
            && !self.rough
            && self.spins.is_empty()
            && !self.sleeping
            && self.sleepers == 0
            && !self.stop_at_collision
            && !self.stop_at_wall
    }

    /// [`Sim::run`] for a plain gas ([`Sim::is_plain_gas`]). The head of
    /// the loop is [`Sim::run`]'s, written out again: taken from one
    /// function both share, this loop ran 6–8 % slower (10⁴ discs, 164–170
    /// against 153–159 ns per event, the same events).
    pub(super) fn run_plain(&mut self) {
        while let Some(ev) = self.queue.peek() {
            if ev.time > self.end {
                break;
            }
            if matches!(ev.kind, Kind::Wall { .. } | Kind::Leave) {
                return self.run();
            }
            if self.events >= self.cap {
                self.truncated = true;
                break;
            }
            self.events += 1;
            if self.prefetching {
                self.prefetch_soon();
            }
            let i = ev.owner;
            self.now = ev.time;
            match ev.kind {
                Kind::Pair { partner, gen } if self.bodies[partner as usize].gen != gen => {
                    // Only the partner changed: re-predict the owner.
                    self.advance_plain(i);
                    self.predict_plain(i);
                }
                Kind::Pair { partner, .. } => self.collide_plain(i, partner),
                Kind::Cell { axis, upper } => self.cross_plain(i, usize::from(axis), upper),
                Kind::Wall { .. } | Kind::Leave => {} // handed over above
            }
        }
    }

    /// Moves disc `i` to now along its straight line.
    #[inline]
    fn advance_plain(&mut self, i: u32) {
        let now = self.now;
        let b = &mut self.bodies[i as usize];
        let tau = now - b.time;
        if tau != 0.0 {
            b.pos += b.vel * tau;
            b.time = now;
        }
    }

    /// [`Sim::collide_pair`] for a plain gas.
    fn collide_plain(&mut self, i: u32, j: u32) {
        self.advance_plain(i);
        self.advance_plain(j);
        if self.queue.another_by(i, self.now) {
            // Maybe a disc meeting two others at once: the general case.
            return self.collide_pair(i, j);
        }
        let (a, b) = (self.bodies[i as usize], self.bodies[j as usize]);
        let (normal, dist) = self.contact_normal(&a, &b);
        self.bounce([i, j], [a, b], normal, dist);
        let (ci, cj) = (self.bodies[i as usize].cell, self.bodies[j as usize].cell);
        if self.grid.is_inner(ci) && self.grid.is_inner(cj) {
            // Both scans in one walk (the same guesses as two).
            let cells = [ci, cj].map(|c| self.grid.around_inner(c));
            let [gi, gj] = self.scan_two([i, j], cells);
            self.aux[i as usize].guess = gi;
            self.schedule_plain(i);
            self.aux[j as usize].guess = gj;
            self.schedule_plain(j);
        } else {
            self.predict_plain(i);
            self.predict_plain(j);
        }
    }

    /// [`Sim::cross_cell`] for a plain gas.
    fn cross_plain(&mut self, i: u32, axis: usize, upper: bool) {
        self.advance_plain(i);
        self.move_to_next_cell(i, axis, upper);
        self.predict_after_crossing_plain(i, axis, upper);
    }

    /// [`Sim::predict`] for a plain gas.
    fn predict_plain(&mut self, i: u32) {
        let c = self.bodies[i as usize].cell;
        let guess = if self.grid.is_inner(c) {
            // Nine cells in three runs of three, none wrapped.
            let cells = self.grid.around_inner(c);
            self.scan_cells::<false, { images::NONE }>(i, &cells, &[], PairGuess::NONE)
        } else {
            let (mut cells, mut shifts, mut count) = ([0; 9], [DVec2::ZERO; 9], 0);
            self.grid.for_each_neighbour(c, |cell, shift| {
                (cells[count], shifts[count]) = (cell, shift);
                count += 1;
            });
            self.scan_cells::<false, { images::BY_CELL }>(
                i,
                &cells[..count],
                &shifts,
                PairGuess::NONE,
            )
        };
        self.aux[i as usize].guess = guess;
        self.schedule_plain(i);
    }

    /// [`Sim::predict_after_crossing`] for a plain gas.
    fn predict_after_crossing_plain(&mut self, i: u32, axis: usize, upper: bool) {
        let Some(guess) = self.guess_that_holds(i) else {
            return self.predict_plain(i);
        };
        let c = self.bodies[i as usize].cell;
        let guess = if self.grid.is_inner(c) {
            // The three cells beyond, none wrapped.
            let cells = self.grid.beyond_inner(c, axis, upper);
            self.scan_cells::<false, { images::NONE }>(i, &cells, &[], guess)
        } else {
            let (mut cells, mut shifts, mut count) = ([0; 3], [DVec2::ZERO; 3], 0);
            self.grid
                .for_each_new_in_reach(c, axis, upper, |cell, shift| {
                    (cells[count], shifts[count]) = (cell, shift);
                    count += 1;
                });
            self.scan_cells::<false, { images::BY_CELL }>(i, &cells[..count], &shifts, guess)
        };
        self.aux[i as usize].guess = guess;
        self.schedule_plain(i);
    }

    /// [`Sim::schedule`] for a plain gas: the pair guess or the next cell
    /// crossing, whichever comes first (the guess on a tie).
    #[inline]
    fn schedule_plain(&mut self, i: u32) {
        let me = &self.bodies[i as usize];
        let guess = self.aux[i as usize].guess;
        let (tau, kind) = self.next_crossing(me);
        let tc = self.now + tau;
        let event = if tc < guess.time {
            Event {
                time: tc,
                owner: i,
                kind,
            }
        } else {
            Event {
                time: guess.time,
                owner: i,
                kind: Kind::Pair {
                    partner: guess.partner,
                    gen: guess.gen,
                },
            }
        };
        self.queue.set(i, event.time.is_finite().then_some(event));
    }
}

#[cfg(test)]
mod tests {
    use super::super::Exact;
    use crate::boundary::Boundary;
    use crate::laws::Laws;
    use crate::ledger::Ledger;
    use crate::particle::{Color, Particle};
    use crate::stats::StepStats;
    use glam::DVec2;

    /// A gas of `n` discs covering about `fraction` of a periodic square, on
    /// a jittered lattice (no two overlap), radii from 0.5 m down to
    /// 0.5 / `ratio` m, speeds up to 1 m/s in every direction; numbers from
    /// a xorshift seeded with `seed`.
    fn gas(n: usize, fraction: f64, ratio: f64, seed: u64) -> (Vec<Particle>, Laws) {
        let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        let mut random = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        let spacing = 0.5 * (std::f64::consts::PI / fraction).sqrt();
        let per_row = (n as f64).sqrt().ceil() as usize;
        let mut laws = Laws::new(DVec2::splat(per_row as f64 * spacing));
        laws.boundary = Boundary::Periodic;
        let discs = (0..n)
            .map(|k| {
                let radius = 0.5 / ratio.powf(random());
                let room = 0.5 * spacing - radius;
                let jitter = DVec2::new(random() - 0.5, random() - 0.5) * room;
                let cell = DVec2::new((k % per_row) as f64 + 0.5, (k / per_row) as f64 + 0.5);
                let vel = DVec2::new(random() - 0.5, random() - 0.5) * 2.0;
                let mass = 4.0 * radius * radius;
                Particle::new(
                    cell * spacing + jitter,
                    vel,
                    mass,
                    radius,
                    Color::rgb(0, 0, 0),
                )
            })
            .collect();
        (discs, laws)
    }

    /// Steps `discs` under `laws` with `exact` for `steps` steps of `dt`,
    /// through the plain loop or the general one; returns the discs, each
    /// step's counts and the ledger (on, so that impacts are recorded too).
    fn stepped(
        (mut discs, laws): (Vec<Particle>, Laws),
        steps: usize,
        dt: f64,
        general_loop: bool,
    ) -> (Vec<Particle>, Vec<StepStats>, Ledger) {
        let mut exact = Exact {
            general_loop,
            ..Exact::default()
        };
        let mut ledger = Ledger::default();
        ledger.keep(1_000_000);
        let mut all = Vec::new();
        for k in 0..steps {
            let mut stats = StepStats::default();
            exact.advance(
                &mut discs,
                &laws,
                dt,
                &mut stats,
                (&mut ledger, k as f64 * dt),
            );
            stats.timings = Default::default();
            all.push(stats);
        }
        (discs, all, ledger)
    }

    #[test]
    fn a_plain_gas_steps_as_the_general_loop_does_bit_for_bit() {
        // (discs, fraction of the area, largest over smallest radius, seed, e)
        let gases = [
            (1500, 0.3, 1.0, 1, 1.0),
            (1200, 0.3, 3.0, 7, 1.0),
            (1000, 0.5, 1.0, 3, 1.0),
            // Inelastic: the contact-duration rule decides some collisions.
            (800, 0.3, 1.0, 11, 0.6),
        ];
        for (n, fraction, ratio, seed, e) in gases {
            let case = format!("{n} discs, {fraction} of the area, radii ×{ratio}, e = {e}");
            let start = || {
                let (discs, mut laws) = gas(n, fraction, ratio, seed);
                laws.restitution = e;
                (discs, laws)
            };
            assert!(!Exact::default().general_loop);
            let (plain, plain_stats, plain_ledger) = stepped(start(), 4, 0.5, false);
            let (general, general_stats, general_ledger) = stepped(start(), 4, 0.5, true);
            assert!(plain_stats.iter().all(|s| s.pair_collisions > 0), "{case}");
            assert_eq!(plain_stats, general_stats, "{case}");
            assert_eq!(plain_ledger, general_ledger, "{case}");
            for (a, b) in plain.iter().zip(&general) {
                assert_eq!(
                    (
                        a.pos.to_array().map(f64::to_bits),
                        a.vel.to_array().map(f64::to_bits)
                    ),
                    (
                        b.pos.to_array().map(f64::to_bits),
                        b.vel.to_array().map(f64::to_bits)
                    ),
                    "{case}"
                );
            }
        }
    }

    #[test]
    fn only_a_plain_gas_takes_the_plain_loop() {
        let check = |change: &dyn Fn(&mut Laws), plain: bool| {
            let (discs, mut laws) = gas(300, 0.3, 1.0, 5);
            change(&mut laws);
            let sim = super::Sim::new(&discs, &laws, 0.1);
            assert_eq!(sim.is_plain_gas(), plain, "{laws:?}");
        };
        check(&|_| {}, true);
        check(&|l| l.gravity = DVec2::new(0.0, -9.81), false);
        check(&|l| l.tangential_restitution = 0.5, false);
        check(&|l| l.boundary = Boundary::Box, false);
    }
}
