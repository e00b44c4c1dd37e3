//! Broad phase, the first stage of a step: list the pairs that *might* touch.
//!
//! Every broad phase answers the same question through [`BroadPhase`], so one
//! test can hold each to the brute-force answer:
//!
//! | Kind | Type | Cost per step | Good for |
//! |---|---|---|---|
//! | `brute` | [`BruteForce`] | O(n²) | a handful of discs; the reference |
//! | `grid` | [`Grid`] | O(n) | many discs of similar size |
//! | `sap` | [`SweepAndPrune`] | O(n) sort (warm) + O(n·k) sweep | discs spread along one axis |
//! | `quadtree` | [`Quadtree`] | O(n log n) | radii that differ by orders of magnitude |
//!
//! Each file's documentation explains its algorithm and cost;
//! `tests/broad_phase.rs` has an ignored test that measures them in a world.
//!
//! ## The contract
//!
//! [`BroadPhase::candidate_pairs`] replaces `out` with pairs `i < j`, each
//! once, sorted ascending by `(i, j)`. It includes every pair whose discs
//! overlap (distance < rᵢ + rⱼ, measured by [`Boundary::separation`], so
//! across the seam for [`Boundary::Periodic`]); it may include a few pairs
//! that do not. Resolution runs in this order, so a world steps bit for bit
//! the same whatever the broad phase.
//!
//! No input makes a broad phase panic or run away: discs far outside the box,
//! coincident discs, one huge disc among tiny ones, zero or one disc. Discs
//! with a non-finite position or a NaN radius can never be a candidate (their
//! separation test is never true) and are skipped; a disc of infinite radius
//! pairs with every other. A periodic world with a zero or non-finite side
//! has no meaningful minimum image; there the accelerated phases hand over
//! to brute force.
//!
//! The accelerated phases keep their buffers between steps, so once warmed up
//! a step allocates nothing. They share two helpers from this module: the
//! exact candidate test (bit-identical to brute force's for closed and open
//! worlds; with a rounding slack of a few ulps for periodic ones) and a
//! counting sort that puts the pairs they find in `(i, j)` order.

mod brute;
mod grid;
mod quadtree;
mod sap;
mod skin;

pub use brute::BruteForce;
pub use grid::Grid;
pub use quadtree::Quadtree;
pub use sap::SweepAndPrune;
pub use skin::Skinned;

use crate::boundary::Boundary;
use crate::particle::Particle;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// A candidate pair of particle indices, always with `i < j`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Pair {
    /// Lower index.
    pub i: u32,
    /// Higher index.
    pub j: u32,
}

/// Finds candidate pairs: a superset of the overlapping pairs.
pub trait BroadPhase {
    /// Replaces `out` with the candidate pairs, each once, `i < j`, in
    /// ascending order (so that resolution order, and hence results, do not
    /// depend on the broad phase). Every overlapping pair is included.
    fn candidate_pairs(
        &mut self,
        particles: &[Particle],
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    );

    /// [`BroadPhase::candidate_pairs`] for the discs with `inflate` added to
    /// every radius (a Verlet list's skin), without a copy of them where
    /// the phase can do that as it reads them (the grid: a million discs
    /// would be 72 MB).
    fn candidate_pairs_inflated(
        &mut self,
        particles: &[Particle],
        inflate: f64,
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    ) {
        self.candidate_pairs(&inflated(particles, inflate), boundary, size, out);
    }

    /// Lets the phase run its order-free work on rayon's pool (see
    /// [`crate::parallel`]). The pairs it returns must not change with this
    /// or with the number of threads. Phases that stay serial ignore it.
    fn set_parallel(&mut self, _parallel: bool) {}

    /// For a phase that keeps its list from step to step (a Verlet list):
    /// brings it up to date for `particles` and returns true; the pairs,
    /// the same [`BroadPhase::candidate_pairs`] would give, are then read
    /// in place through [`BroadPhase::kept_pairs`] instead of copied (a
    /// million discs: about 10 MB a step). Others return false.
    fn refresh_kept(&mut self, _particles: &[Particle], _boundary: Boundary, _size: DVec2) -> bool {
        false
    }

    /// The list the last [`BroadPhase::refresh_kept`] that returned true
    /// brought up to date (empty for phases that keep none).
    fn kept_pairs(&self) -> &[Pair] {
        &[]
    }

    /// For a phase that keeps its list: the list as it stands, if it was
    /// built for this boundary, box and disc count, with what must hold of
    /// every disc for it to be what [`BroadPhase::refresh_kept`] would give
    /// ([`KeptCheck`]). The narrow phase checks that as it reads the discs
    /// anyway, instead of a pass of its own; where it fails, it calls
    /// `refresh_kept`. `None`: call `refresh_kept`.
    fn kept_unchecked(
        &self,
        _count: usize,
        _boundary: Boundary,
        _size: DVec2,
    ) -> Option<(&[Pair], KeptCheck<'_>)> {
        None
    }
}

/// A copy of `particles` with `inflate` added to every radius.
fn inflated(particles: &[Particle], inflate: f64) -> Vec<Particle> {
    let inflate = |p: &Particle| Particle {
        radius: p.radius + inflate,
        ..*p
    };
    particles.iter().map(inflate).collect()
}

/// What every disc must satisfy for a kept list to hold: it is within
/// `limit` of where it was when the list was built (its anchor), and its
/// radius has not changed.
#[derive(Clone, Copy, Debug)]
pub struct KeptCheck<'a> {
    /// Each disc's position when the list was built.
    pub anchors: &'a [DVec2],
    /// Each disc's radius then.
    pub radii: &'a [f64],
    /// The square of the farthest a disc may have moved.
    pub limit_sq: f64,
    /// The boundary the list was built for (how far "moved" is measured).
    pub boundary: Boundary,
    /// The box it was built for.
    pub size: DVec2,
}

impl KeptCheck<'_> {
    /// Whether disc `k`, now `p`, still satisfies it.
    #[inline]
    pub fn holds(&self, k: usize, p: &Particle) -> bool {
        p.radius == self.radii[k]
            && self
                .boundary
                .separation(self.anchors[k], p.pos, self.size)
                .length_squared()
                <= self.limit_sq
    }
}

/// The broad phases a world can use; scene files and the CLI name them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum BroadPhaseKind {
    /// Every pair i < j: O(n²).
    #[default]
    Brute,
    /// Uniform grid of cells as wide as the largest disc: O(n).
    Grid,
    /// Sort and sweep along one axis, warm-started from the last step.
    Sap,
    /// Loose quadtree: for radii that differ by orders of magnitude.
    Quadtree,
}

impl BroadPhaseKind {
    /// Every kind, in the order the UI cycles through them.
    pub const ALL: [BroadPhaseKind; 4] = [
        BroadPhaseKind::Brute,
        BroadPhaseKind::Grid,
        BroadPhaseKind::Sap,
        BroadPhaseKind::Quadtree,
    ];

    /// A fresh broad phase of this kind.
    pub fn build(self) -> Box<dyn BroadPhase + Send> {
        match self {
            BroadPhaseKind::Brute => Box::new(BruteForce),
            BroadPhaseKind::Grid => Box::<Skinned<Grid>>::default(),
            BroadPhaseKind::Sap => Box::<SweepAndPrune>::default(),
            BroadPhaseKind::Quadtree => Box::<Quadtree>::default(),
        }
    }

    /// The lowercase name used in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            BroadPhaseKind::Brute => "brute",
            BroadPhaseKind::Grid => "grid",
            BroadPhaseKind::Sap => "sap",
            BroadPhaseKind::Quadtree => "quadtree",
        }
    }
}

impl fmt::Display for BroadPhaseKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for BroadPhaseKind {
    type Err = String;

    /// Parses a name as written by [`BroadPhaseKind::name`].
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        BroadPhaseKind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = BroadPhaseKind::ALL.iter().map(|k| k.name()).collect();
                format!(
                    "unknown broad phase {s:?}: expected one of {}",
                    names.join(", ")
                )
            })
    }
}

/// One disc as the accelerated phases store it: centre (wrapped into the box
/// when periodic), radius, and index into the particle slice.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Disc {
    x: f64,
    y: f64,
    r: f64,
    i: u32,
    /// Free for the phase's own use (the grid keeps the cell here); it fits
    /// in what would otherwise be padding.
    tag: u32,
}

/// The geometry of one call: open space or a torus, and the rounding slack.
#[derive(Clone, Copy, Debug)]
struct Space {
    /// Box size when periodic (both components positive and finite).
    period: Option<DVec2>,
    /// Added to the reach in the periodic candidate test, to cover the
    /// difference between wrapping here and [`Boundary::separation`]'s
    /// minimum image (a few ulps of the largest coordinate).
    slack: f64,
    /// Largest |coordinate| of a periodic disc found outside the box.
    outside: f64,
    /// Added to every radius ([`BroadPhase::candidate_pairs_inflated`]).
    inflate: f64,
}

impl Space {
    /// The space for `boundary`, or `None` when a periodic `size` has a zero
    /// or non-finite side. Such a torus is meaningless and its separations are
    /// degenerate (NaN, or unwrapped), so the caller defers to brute force,
    /// which follows [`Boundary::separation`] whatever it does there.
    fn new(boundary: Boundary, size: DVec2) -> Option<Space> {
        let period = match boundary {
            Boundary::Periodic => {
                // A negative side gives the same minimum image as its absolute value.
                let period = size.abs();
                if !(period.x > 0.0 && period.y > 0.0 && period.is_finite()) {
                    return None;
                }
                Some(period)
            }
            Boundary::Box | Boundary::Open => None,
        };
        Some(Space {
            period,
            slack: 0.0,
            outside: 0.0,
            inflate: 0.0,
        })
    }

    /// The disc as stored, or `None` if it can never be a candidate.
    #[inline(always)]
    fn disc(&mut self, i: usize, p: &Particle) -> Option<Disc> {
        let r = p.radius + self.inflate;
        if !(p.pos.is_finite() && r > f64::NEG_INFINITY) {
            return None; // non-finite centre, NaN or −∞ radius
        }
        let mut pos = p.pos;
        if let Some(period) = self.period {
            // After a periodic step every centre is inside already.
            if !((0.0..period.x).contains(&pos.x) && (0.0..period.y).contains(&pos.y)) {
                pos = self.wrap(pos, period);
            }
        }
        Some(Disc {
            x: pos.x,
            y: pos.y,
            r,
            i: i as u32,
            tag: 0,
        })
    }

    /// A centre outside the periodic box, wrapped into `[0, period]`
    /// (`rem_euclid` is a software division: kept off the common path).
    #[cold]
    #[inline(never)]
    fn wrap(&mut self, pos: DVec2, period: DVec2) -> DVec2 {
        self.outside = self.outside.max(pos.abs().max_element());
        pos.rem_euclid(period)
    }

    /// Sets the periodic slack once every disc has been seen.
    fn finish(&mut self) {
        if let Some(period) = self.period {
            let scale = period.max_element().max(self.outside);
            self.slack = 8.0 * f64::EPSILON * scale;
        }
    }
}

/// The shorter way round a circle of length `period` (`d` within ±`period`).
#[inline(always)]
fn fold(d: f64, period: f64) -> f64 {
    if d > 0.5 * period {
        d - period
    } else if d < -0.5 * period {
        d + period
    } else {
        d
    }
}

/// The candidate test: do the discs' bounding boxes touch?
///
/// With `PERIODIC = false` this is exactly brute force's test (same floating
/// point operations on the same numbers). With `PERIODIC = true` the discs
/// hold wrapped centres; the minimum image is taken by folding and the reach
/// is widened by `space.slack`, so the result is a superset of brute force's
/// overlapping pairs.
#[inline(always)]
fn touches<const PERIODIC: bool>(a: &Disc, b: &Disc, space: &Space) -> bool {
    let reach = a.r + b.r;
    if PERIODIC {
        let period = space.period.unwrap_or(DVec2::ONE);
        let dx = fold(b.x - a.x, period.x);
        let dy = fold(b.y - a.y, period.y);
        let reach = reach + space.slack;
        // `&`, not `&&`: the x test alone is a coin flip for neighbours, and
        // a mispredicted branch costs more than the y test.
        (dx.abs() <= reach) & (dy.abs() <= reach)
    } else {
        let dx = b.x - a.x;
        let dy = b.y - a.y;
        (dx.abs() <= reach) & (dy.abs() <= reach)
    }
}

/// The pair of two distinct particle indices, lower first.
#[inline(always)]
fn pair(a: u32, b: u32) -> Pair {
    if a < b {
        Pair { i: a, j: b }
    } else {
        Pair { i: b, j: a }
    }
}

/// Replaces `out` with `raw` (distinct pairs with `i < j < n`) sorted by
/// `(i, j)`: a counting sort on `i`, then each particle's few partners sorted.
fn sort_pairs(raw: &[Pair], n: usize, ends: &mut Vec<u32>, out: &mut Vec<Pair>) {
    if raw.len() <= 32 {
        out.clear();
        out.extend_from_slice(raw);
        out.sort_unstable();
        return;
    }
    // Every slot is written: no need to clear (and zero) `out` first.
    out.resize(raw.len(), Pair::default());
    sort_pairs_into(&[raw], 0, n, ends, out);
}

/// Fills `out` (exactly as long as all of them) with the pairs of
/// `sources`, whose first indices lie in `lo..lo + keys`, sorted by
/// `(i, j)`: [`sort_pairs`]'s work, for one range of first indices.
fn sort_pairs_into(
    sources: &[&[Pair]],
    lo: usize,
    keys: usize,
    ends: &mut Vec<u32>,
    out: &mut [Pair],
) {
    let lo = lo as u32;
    // ends[k + 1] counts pairs with first index lo + k; after the prefix
    // sum, ends[k] is where they start; after scattering, where they end.
    ends.clear();
    ends.resize(keys + 1, 0);
    for p in sources.iter().flat_map(|s| s.iter()) {
        ends[(p.i - lo) as usize + 1] += 1;
    }
    let mut total = 0;
    for e in ends.iter_mut() {
        total += *e;
        *e = total;
    }
    for &p in sources.iter().flat_map(|s| s.iter()) {
        let slot = &mut ends[(p.i - lo) as usize];
        out[*slot as usize] = p;
        *slot += 1;
    }
    // Now index lo + k's pairs are out[ends[k-1]..ends[k]]: sort each by j.
    let mut start = 0;
    for &end in &ends[..keys] {
        let group = &mut out[start..end as usize];
        match group.len() {
            0 | 1 => {}
            2..=16 => insertion_sort(group),
            _ => group.sort_unstable(),
        }
        start = end as usize;
    }
}

/// Where ranges 1.. of `parts` equal ranges of first indices over `0..n`
/// begin ([`key_part_start`]), for [`split_by_key_part`].
#[cfg(feature = "parallel")]
fn key_part_starts(parts: usize, n: usize) -> Vec<u32> {
    (1..parts)
        .map(|t| key_part_start(t, parts, n) as u32)
        .collect()
}

/// Appends `pairs` to `by_part` (cleared first, one list per range after),
/// each to the list of the range of first indices it falls in, the ranges
/// beginning at `starts` ([`key_part_starts`]). The range is found by
/// comparing with their starts, without a division or a branch per pair.
#[cfg(feature = "parallel")]
fn split_by_key_part(pairs: &[Pair], starts: &[u32], by_part: &mut Vec<Vec<Pair>>) {
    let parts = starts.len() + 1;
    by_part.resize_with(parts, Vec::new);
    by_part.truncate(parts);
    by_part.iter_mut().for_each(Vec::clear);
    for &p in pairs {
        let part: usize = starts.iter().map(|&s| usize::from(p.i >= s)).sum();
        by_part[part].push(p);
    }
}

/// The first index of key range `part` of `parts` equal ranges over `0..n`.
#[cfg(feature = "parallel")]
fn key_part_start(part: usize, parts: usize, n: usize) -> usize {
    (part * n).div_ceil(parts)
}

/// [`sort_pairs`] on rayon's pool: `by_part` holds, per source, its pairs
/// already split by [`split_by_key_part`] into `parts` ranges, one per pool thread;
/// each range is sorted on its own thread into its own stretch of `out`. Since the pairs are
/// distinct and the order `(i, j)` total, the list is the one
/// [`sort_pairs`] makes of the same pairs.
#[cfg(feature = "parallel")]
fn sort_pairs_in_parts(
    by_part: &[&[Vec<Pair>]],
    parts: usize,
    n: usize,
    scratch: &mut Vec<Vec<u32>>,
    out: &mut Vec<Pair>,
) {
    let lengths: Vec<usize> = (0..parts)
        .map(|t| by_part.iter().map(|source| source[t].len()).sum())
        .collect();
    // Every slot is written: no need to clear (and zero) `out` first.
    out.resize(lengths.iter().sum(), Pair::default());
    let mut stretches = Vec::with_capacity(parts);
    let mut rest = &mut out[..];
    for &len in &lengths {
        let (stretch, after) = rest.split_at_mut(len);
        stretches.push(stretch);
        rest = after;
    }
    scratch.resize_with(parts, Vec::new);
    let work: Vec<_> = stretches
        .into_iter()
        .zip(scratch.iter_mut())
        .enumerate()
        .collect();
    // Range t on thread t: the stretch of the list the narrow phase's
    // thread t reads first (see `crate::parallel::on_each_run`).
    crate::parallel::on_each_thread(work, |(t, (stretch, ends))| {
        let sources: Vec<&[Pair]> = by_part.iter().map(|source| &source[t][..]).collect();
        let lo = key_part_start(t, parts, n);
        let keys = key_part_start(t + 1, parts, n) - lo;
        sort_pairs_into(&sources, lo, keys, ends, stretch);
    });
}

/// Sorts a short slice of pairs that share `i` by `j`.
#[inline]
fn insertion_sort(group: &mut [Pair]) {
    for k in 1..group.len() {
        let cur = group[k];
        let mut m = k;
        while m > 0 && group[m - 1].j > cur.j {
            group[m] = group[m - 1];
            m -= 1;
        }
        group[m] = cur;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_errors_list_the_choices() {
        for k in BroadPhaseKind::ALL {
            assert_eq!(k.name().parse::<BroadPhaseKind>(), Ok(k));
            assert_eq!(k.to_string(), k.name());
        }
        let err = "octree".parse::<BroadPhaseKind>().unwrap_err();
        for k in BroadPhaseKind::ALL {
            assert!(err.contains(k.name()), "{err}");
        }
        assert!(err.contains("octree"));
    }

    #[test]
    fn counting_sort_orders_pairs() {
        let mut raw = Vec::new();
        for i in 0..50u32 {
            for j in (i + 1..60).rev().step_by(7) {
                raw.push(Pair { i, j });
            }
        }
        raw.reverse();
        let mut expected = raw.clone();
        expected.sort_unstable();
        let (mut ends, mut out) = (Vec::new(), Vec::new());
        sort_pairs(&raw, 60, &mut ends, &mut out);
        assert_eq!(out, expected);
    }

    #[cfg(feature = "parallel")]
    #[test]
    fn the_sort_in_ranges_of_first_index_gives_the_serial_order() {
        // Pairs from several sources (like the grid's bands), some with
        // many partners, in no order; split by range of first index for 1
        // to 5 threads' ranges (some empty when there are more ranges than
        // indices) and sorted range by range on a pool.
        for (n, count) in [(3u32, 3usize), (60, 700), (1000, 5000)] {
            let mut x: u64 = 0x9e37_79b9_7f4a_7c15 ^ u64::from(n);
            let mut next = || {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x
            };
            let mut all = std::collections::BTreeSet::new();
            while all.len() < count {
                let (a, b) = (
                    (next() % u64::from(n)) as u32,
                    (next() % u64::from(n)) as u32,
                );
                if a != b {
                    all.insert(pair(a, b));
                }
            }
            let mut raw: Vec<Pair> = all.iter().copied().collect();
            for k in (1..raw.len()).rev() {
                raw.swap(k, (next() % (k as u64 + 1)) as usize);
            }
            let (mut ends, mut serial) = (Vec::new(), Vec::new());
            sort_pairs(&raw, n as usize, &mut ends, &mut serial);
            assert_eq!(serial, all.iter().copied().collect::<Vec<_>>());
            for parts in 1..=5 {
                let sources: Vec<Vec<Vec<Pair>>> = raw
                    .chunks(raw.len().div_ceil(3))
                    .map(|chunk| {
                        let mut split = Vec::new();
                        let starts = key_part_starts(parts, n as usize);
                        split_by_key_part(chunk, &starts, &mut split);
                        for (t, list) in split.iter().enumerate() {
                            let range = key_part_start(t, parts, n as usize)
                                ..key_part_start(t + 1, parts, n as usize);
                            assert!(list.iter().all(|p| range.contains(&(p.i as usize))));
                        }
                        split
                    })
                    .collect();
                let by_part: Vec<&[Vec<Pair>]> = sources.iter().map(|s| &s[..]).collect();
                let (mut scratch, mut out) = (Vec::new(), vec![Pair { i: 7, j: 9 }]);
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(parts)
                    .build()
                    .unwrap();
                pool.install(|| {
                    sort_pairs_in_parts(&by_part, parts, n as usize, &mut scratch, &mut out)
                });
                assert_eq!(out, serial, "{n} discs, {parts} ranges");
            }
        }
    }

    #[test]
    fn fold_takes_the_short_way() {
        assert_eq!(fold(9.0, 10.0), -1.0);
        assert_eq!(fold(-9.0, 10.0), 1.0);
        assert_eq!(fold(4.0, 10.0), 4.0);
    }
}
