//! Sort and sweep (sweep and prune) along one axis, warm-started.
//!
//! Each disc projects onto the sweep axis as the interval [u − r, u + r].
//! With the intervals sorted by their lower end, a sweep from left to right
//! meets, for each disc, exactly the discs whose intervals start before its
//! own ends: those are tested on the other axis, the rest are never looked
//! at.
//!
//! Discs move little from one step to the next, so the order of the last step
//! is kept and repaired with an insertion sort: O(n + swaps), about O(n) for
//! a gas. (If the order is far off, e.g. after the discs were replaced, the
//! insertion sort gives up after a budget of moves and a full O(n log n) sort
//! takes over, so a shuffled scene costs no more than a cold start.)
//!
//! Cost: O(n + swaps) sort plus O(n·k) sweep, where k is the number of discs
//! whose intervals overlap a given one on the sweep axis. For a uniform gas in
//! a square of side L, k grows like L, so a sweep is O(n^1.5) (about 100, 300
//! and 700 ns per disc for n = 10³, 10⁴, 10⁵ at 30 % area fraction); the
//! axis with the larger spread of centres is used (with some hysteresis,
//! since changing axis costs a full sort), which helps in long, thin worlds.
//! The sweep streams through columns of the interval starts and of the
//! cross-axis coordinates and radii, and looks at a whole disc only when the
//! cross axis overlaps too.
//!
//! - **Periodic**: centres are wrapped into the box. An interval that sticks
//!   out past the far end of the sweep axis also meets the intervals at the
//!   start of the sorted list, shifted by the box length: each disc also
//!   sweeps the start of the list up to its upper end minus the box length,
//!   skipping pairs the direct sweep has already met.
//! - **Box and open**: no special case; far-away discs simply sort to the
//!   ends.

use super::{fold, pair, sort_pairs, touches, BroadPhase, BruteForce, Disc, Pair, Space};
use crate::boundary::Boundary;
use crate::particle::Particle;
use glam::DVec2;

/// Insertion sort gives up after this many moves per disc (plus a constant).
const MOVES_PER_DISC: usize = 8;
/// The other axis is taken when its spread is this many times larger.
const SWITCH_AXIS: f64 = 1.5;

/// Sort-and-sweep broad phase along the axis of larger spread.
#[derive(Clone, Debug, Default)]
pub struct SweepAndPrune {
    /// Particle indices in the order of the last sort.
    order: Vec<u32>,
    /// Whether the sweep axis is y (else x).
    along_y: bool,
    /// The discs in sweep order.
    recs: Vec<Rec>,
    /// `recs[k].lo`, as a column.
    lo: Vec<f64>,
    /// `recs[k]`'s coordinate across the sweep axis and radius.
    cross: Vec<(f64, f64)>,
    /// Scratch: which particles `order` already covers.
    seen: Vec<bool>,
    /// Pairs as found, before sorting.
    raw: Vec<Pair>,
    /// Scratch for the pair sort.
    ends: Vec<u32>,
}

/// A disc in sweep coordinates: `disc` has the sweep axis as x.
#[derive(Clone, Copy, Debug, Default)]
struct Rec {
    lo: f64,
    hi: f64,
    disc: Disc,
}

impl Rec {
    fn new(d: Disc, along_y: bool) -> Rec {
        let disc = if along_y {
            Disc {
                x: d.y,
                y: d.x,
                ..d
            }
        } else {
            d
        };
        Rec {
            lo: disc.x - disc.r,
            hi: disc.x + disc.r,
            disc,
        }
    }
}

impl BroadPhase for SweepAndPrune {
    fn candidate_pairs(
        &mut self,
        particles: &[Particle],
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    ) {
        out.clear();
        self.raw.clear();
        self.recs.clear();
        let Some(mut space) = Space::new(boundary, size) else {
            BruteForce.candidate_pairs(particles, boundary, size, out);
            return;
        };

        // Gather in last step's order, then append discs it did not cover.
        let n = particles.len();
        self.seen.clear();
        self.seen.resize(n, false);
        let (mut lo, mut hi) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        let mut r_max = 0.0f64;
        let along_y = self.along_y;
        let mut take = |i: usize, recs: &mut Vec<Rec>| {
            let p = &particles[i];
            if let Some(d) = space.disc(i, p) {
                if d.r.is_finite() {
                    r_max = r_max.max(d.r.abs());
                }
                let c = DVec2::new(d.x, d.y);
                lo = lo.min(c);
                hi = hi.max(c);
                recs.push(Rec::new(d, along_y));
            }
        };
        for &i in &self.order {
            let i = i as usize;
            if i < n && !self.seen[i] {
                self.seen[i] = true;
                take(i, &mut self.recs);
            }
        }
        for (i, seen) in self.seen.iter().enumerate() {
            if !seen {
                take(i, &mut self.recs);
            }
        }
        space.finish();

        // Sweep along the axis where the discs spread more.
        let spread = match space.period {
            Some(period) => period,
            None => hi - lo,
        };
        let switch = if self.along_y {
            spread.x > SWITCH_AXIS * spread.y
        } else {
            spread.y > SWITCH_AXIS * spread.x
        };
        if switch {
            self.along_y = !self.along_y;
            for rec in &mut self.recs {
                let d = rec.disc;
                *rec = Rec::new(
                    Disc {
                        x: d.y,
                        y: d.x,
                        ..d
                    },
                    false,
                );
            }
        }
        if switch || !insertion_sort(&mut self.recs) {
            self.recs.sort_unstable_by(|a, b| a.lo.total_cmp(&b.lo));
        }
        self.order.clear();
        self.order.extend(self.recs.iter().map(|r| r.disc.i));

        // The sweep sees the world with the sweep axis as x.
        let period = space.period.map(|p| {
            if self.along_y {
                DVec2::new(p.y, p.x)
            } else {
                p
            }
        });
        let space = Space { period, ..space };
        // The direct sweep streams through these three columns only.
        self.lo.clear();
        self.lo.extend(self.recs.iter().map(|r| r.lo));
        self.cross.clear();
        self.cross
            .extend(self.recs.iter().map(|r| (r.disc.y, r.disc.r)));
        let sweep = Sweep {
            recs: &self.recs,
            lo: &self.lo,
            cross: &self.cross,
            space,
            r_max,
        };
        if period.is_some() {
            sweep.run::<true>(&mut self.raw);
        } else {
            sweep.run::<false>(&mut self.raw);
        }
        sort_pairs(&self.raw, n, &mut self.ends, out);
    }
}

/// Sorts nearly sorted records by `lo`; gives up (returning false, the slice
/// partly sorted) after a budget of moves.
fn insertion_sort(recs: &mut [Rec]) -> bool {
    let mut budget = MOVES_PER_DISC * recs.len() + 1024;
    for k in 1..recs.len() {
        let cur = recs[k];
        let mut m = k;
        while m > 0 && recs[m - 1].lo > cur.lo {
            recs[m] = recs[m - 1];
            m -= 1;
        }
        recs[m] = cur;
        let moves = k - m;
        if moves > budget {
            return false;
        }
        budget -= moves;
    }
    true
}

/// One sweep over sorted records.
struct Sweep<'a> {
    recs: &'a [Rec],
    lo: &'a [f64],
    cross: &'a [(f64, f64)],
    space: Space,
    /// Largest finite |radius|.
    r_max: f64,
}

impl Sweep<'_> {
    /// How far past `hi` the sweep of a record looks: the periodic slack plus
    /// the rounding of the interval ends.
    #[inline(always)]
    fn reach(&self, rec: &Rec) -> f64 {
        rec.hi + (self.space.slack + 8.0 * f64::EPSILON * (rec.hi.abs() + self.r_max))
    }

    fn run<const PERIODIC: bool>(&self, raw: &mut Vec<Pair>) {
        let recs = self.recs;
        let (length, width) = self.space.period.map_or((0.0, 0.0), |p| (p.x, p.y));
        // Record k's sweep meets records k+1.. up to the first whose lo
        // passes this bound.
        let direct = |k: usize| self.reach(&recs[k]);
        for (k, a) in recs.iter().enumerate() {
            let bound = direct(k);
            for (m, (&lo, &(v, r))) in self.lo[k + 1..]
                .iter()
                .zip(&self.cross[k + 1..])
                .enumerate()
            {
                if lo > bound {
                    break;
                }
                // Across the sweep axis first (the part of the test that
                // usually fails), then the whole test.
                let dv = v - a.disc.y;
                let dv = if PERIODIC { fold(dv, width) } else { dv };
                if dv.abs() <= a.disc.r + r + self.space.slack {
                    let b = &recs[k + 1 + m];
                    if touches::<PERIODIC>(&a.disc, &b.disc, &self.space) {
                        raw.push(pair(a.disc.i, b.disc.i));
                    }
                }
            }
            if PERIODIC {
                // Across the seam, record k meets the records at the start
                // of the list up to this bound (their intervals shifted by
                // the box length). A record after k within it has
                // lo ≤ bound ≤ direct(k): the direct sweep met it already. A
                // record m before k was met directly if k's lo ≤ direct(m);
                // m's own seam sweep looks only before m. So each pair is
                // tested once.
                let bound = direct(k) - length;
                for (m, b) in recs[..k].iter().enumerate() {
                    if b.lo > bound {
                        break;
                    }
                    if a.lo > direct(m) && touches::<PERIODIC>(&a.disc, &b.disc, &self.space) {
                        raw.push(pair(a.disc.i, b.disc.i));
                    }
                }
            }
        }
    }
}
