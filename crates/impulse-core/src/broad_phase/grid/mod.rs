//! Uniform grid (cell list), rebuilt every step.
//!
//! The plane is cut into square cells at least as wide as the largest disc's
//! diameter, so two discs can only overlap if their cells are the same or
//! neighbours. Each step:
//!
//! 1. one pass over the particles collects the candidate discs (struct of
//!    centre, radius, index: 32 bytes) and their largest radius and extent,
//!    which fix the cells;
//! 2. a counting sort (count, prefix sum, scatter) lays the discs out cell
//!    by cell in one array, `starts[c]..starts[c + 1]` being cell `c`. It
//!    runs in two passes, by row and then each row by column, because the
//!    particles come in no spatial order and a single scatter into
//!    ~2n cells would touch memory at random (about 25 % slower at 10⁶ discs)
//!    (`cells.rs`);
//! 3. each disc, row by row, is tested against the rest of its own cell and
//!    the four "forward" neighbours (right, and the three cells of the row
//!    above), so every pair of neighbouring cells is seen once. In row-major
//!    order the own cell and its right neighbour, and the three cells above,
//!    are each one contiguous run of the array, so a disc costs two short
//!    loops; a candidate is written unconditionally and kept by advancing
//!    the end, with no branch on the test's outcome;
//! 4. the pairs found are put in `(i, j)` order by a counting sort on `i`.
//!
//! Cost: O(n + cells + pairs) time per step, and no allocation once the
//! buffers have grown. The number of cells is capped at about 2n: when the
//! discs are spread thinly the cells grow instead (more discs per cell, still
//! correct). For a gas of equal discs at 30 % area fraction this is about
//! 25–45 ns per disc for n = 10³–10⁵.
//!
//! - **Periodic**: the grid covers the box and wraps, so the last column's
//!   right neighbour is the first column; a neighbour across the seam is
//!   compared with its centre shifted by the box size, so no minimum-image
//!   arithmetic is needed per pair. An axis with fewer than three cells is
//!   made a single cell (with two, the left and right neighbours would be
//!   the same cell and pairs would be reported twice) and then the minimum
//!   image is taken by folding.
//! - **Box and open**: the grid covers the bounding box of the centres. If a
//!   few discs have flown far away, that box would need huge cells; the grid
//!   then covers the bulk (2–98 % quantiles of a sample of the discs, padded)
//!   and the stragglers are clamped into the border cells, which stays
//!   correct because clamping keeps neighbours neighbours.
//! - **Mixed radii**: the cell size follows the largest disc. A few discs
//!   (at most 32) much larger than the mean are taken out of the grid and
//!   tested against every disc, so one huge disc does not make every cell
//!   huge. Many large discs among small ones still make big cells; the
//!   quadtree is the better choice there.
//!
//! **In parallel** ([`BroadPhase::set_parallel`], for large scenes) step 1
//! runs per chunk of [`CHUNK`] particles, each chunk's discs and extent kept
//! apart and joined in chunk order; the row scatter of step 2 runs per run of
//! discs (each row's discs placed run by run, as serially); the column sort
//! of step 2 and the sweep of step 3 run per band of at most
//! [`BAND_ROWS`](crate::parallel::BAND_ROWS) rows, thread k taking the same
//! run of bands for both, the runs cut where each holds about as many discs
//! (a pile at the bottom is shared out like an even gas); the pair sort of
//! step 4 runs per range of first indices, each sorted on its own thread.
//! The pairs' order is total, so the pairs are the same on any number of
//! threads and whatever the bands, and the same as serially
//! (which gathers by the same chunks, so even the mean radius is summed
//! alike).

use super::{pair, sort_pairs, touches, BroadPhase, BruteForce, Disc, Pair, Space};
use crate::boundary::Boundary;
use crate::parallel::CHUNK;
use crate::particle::Particle;
use glam::DVec2;
use std::ops::Range;

mod cells;
mod sweep;
use sweep::{Cells, FOLDED, OPEN, SHIFTED};

/// Cells per gridded disc, at most (plus a few).
const CELLS_PER_DISC: usize = 2;
/// A disc is "big" when its radius exceeds this many times the mean radius…
const BIG_FACTOR: f64 = 4.0;
/// …and there are at most this many such discs.
const MAX_BIG: usize = 32;
/// Marks a big disc in its `tag`.
const BIG: u32 = u32::MAX;

/// Uniform grid broad phase: O(n) for discs of similar size.
#[derive(Clone, Debug, Default)]
pub struct Grid {
    /// Candidate discs, in index order; `tag` is the cell, or [`BIG`].
    discs: Vec<Disc>,
    /// Positions in `discs` of the big discs, ascending.
    big: Vec<u32>,
    /// Row `r` begins at `sorted[row_starts[r]]` (during the sort).
    row_starts: Vec<u32>,
    /// Scratch per band of rows (one band when serial).
    bands: Vec<Band>,
    /// Band `b` covers rows `band_rows[b]..band_rows[b + 1]`.
    band_rows: Vec<usize>,
    /// Scratch: per chunk of particles, the discs kept and what they showed.
    gathered: Vec<(usize, Gathered, f64)>,
    /// Run the order-free work on rayon's pool.
    parallel: bool,
    /// Cell `c` holds `sorted[starts[c]..starts[c + 1]]`.
    starts: Vec<u32>,
    /// The gridded discs, cell by cell.
    sorted: Vec<Disc>,
    /// Scratch for the quantiles of a sample of positions.
    sample: Vec<f64>,
    /// Pairs as found, before sorting: the first `found` of them in
    /// `candidate_pairs_inflated`, the rest scratch (see `Cells::sweep`).
    raw: Vec<Pair>,
    /// Scratch for the pair sort.
    ends: Vec<u32>,
    /// Scratch for the pair sort on the pool, one per range of first index.
    #[cfg_attr(not(feature = "parallel"), allow(dead_code))]
    part_ends: Vec<Vec<u32>>,
}

/// Scratch for one band of at most [`BAND_ROWS`](crate::parallel::BAND_ROWS) grid rows.
#[derive(Clone, Debug, Default)]
struct Band {
    /// One row of discs, sorted by column.
    row_buf: Vec<Disc>,
    /// Where the next disc of each column of a row goes.
    cursor: Vec<u32>,
    /// Pairs the band's sweep found (on the pool): `raw[..found]`, the
    /// rest scratch (see `Cells::sweep`).
    #[cfg_attr(not(feature = "parallel"), allow(dead_code))]
    raw: Vec<Pair>,
    /// How many of `raw` are this rebuild's pairs.
    #[cfg_attr(not(feature = "parallel"), allow(dead_code))]
    found: usize,
    /// The same, split by range of first index for the sort (on the pool;
    /// see `sort_pairs_in_parts`).
    #[cfg_attr(not(feature = "parallel"), allow(dead_code))]
    by_part: Vec<Vec<Pair>>,
}

/// Where the cells are: cell (cx, cy) covers
/// `origin + [cx, cx + 1) / inv_width.x` along x, likewise y.
#[derive(Clone, Copy, Debug)]
struct Layout {
    origin: DVec2,
    inv_width: DVec2,
    nx: usize,
    ny: usize,
}

impl Layout {
    /// The disc's column.
    #[inline(always)]
    fn column(&self, d: &Disc) -> usize {
        axis(d.x, self.origin.x, self.inv_width.x, self.nx)
    }

    /// The disc's row.
    #[inline(always)]
    fn row(&self, d: &Disc) -> usize {
        axis(d.y, self.origin.y, self.inv_width.y, self.ny)
    }
}

/// The cell index along one axis.
#[inline(always)]
fn axis(v: f64, origin: f64, inv_width: f64, n: usize) -> usize {
    // `as` saturates (and maps NaN to 0); clamping keeps neighbours
    // neighbours for discs outside the covered region.
    let c = ((v - origin) * inv_width) as i64;
    c.clamp(0, n as i64 - 1) as usize
}

impl BroadPhase for Grid {
    fn candidate_pairs(
        &mut self,
        particles: &[Particle],
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    ) {
        self.candidate_pairs_inflated(particles, 0.0, boundary, size, out);
    }

    fn candidate_pairs_inflated(
        &mut self,
        particles: &[Particle],
        inflate: f64,
        boundary: Boundary,
        size: DVec2,
        out: &mut Vec<Pair>,
    ) {
        // `out` keeps its length until the sort: it is overwritten whole,
        // and resizing it from empty would zero it all first. So does
        // `raw`, whose pairs are `raw[..found]` (see `Cells::sweep`).
        let mut found = 0;
        let Some(mut space) = Space::new(boundary, size) else {
            let inflated = super::inflated(particles, inflate);
            BruteForce.candidate_pairs(&inflated, boundary, size, out);
            return;
        };
        space.inflate = inflate;
        // One pass: the candidate discs, their radii, and their extent.
        let stats = self.gather(particles, &mut space);
        space.finish();
        if self.discs.len() < 2 {
            out.clear();
            return;
        }

        let (grid_radius, lo, hi) = self.split_off_big_discs(&stats);
        let gridded = self.discs.len() - self.big.len();
        if gridded > 0 {
            let layout = match space.period {
                Some(period) => periodic_layout(period, grid_radius, gridded, &space),
                None => self.open_layout(grid_radius, lo, hi, gridded),
            };
            self.sort_into_cells(&layout);
            let cells = Cells {
                starts: &self.starts,
                sorted: &self.sorted,
                nx: layout.nx,
                ny: layout.ny,
            };
            let mode = match space.period {
                None => OPEN,
                Some(_) if layout.nx >= 3 && layout.ny >= 3 => SHIFTED,
                Some(_) => FOLDED,
            };
            let sweep = |rows: Range<usize>, raw: &mut Vec<Pair>| match mode {
                OPEN => cells.sweep::<OPEN>(rows, &space, raw),
                SHIFTED => cells.sweep::<SHIFTED>(rows, &space, raw),
                _ => cells.sweep::<FOLDED>(rows, &space, raw),
            };
            crate::parallel::pool_or_here!(
                self.parallel,
                {
                    // Band b is rows band_rows[b]..band_rows[b + 1] (sort_into_cells).
                    let band_rows = &self.band_rows;
                    let n = particles.len();
                    let parts = crate::parallel::threads().max(1);
                    let starts = super::key_part_starts(parts, n);
                    // Thread k sweeps the bands whose rows it sorted.
                    crate::parallel::on_each_part(&mut self.bands, 1, |first, bands| {
                        for (b, band) in (first..).zip(bands) {
                            let rows = band_rows[b]..band_rows[b + 1];
                            band.found = sweep(rows, &mut band.raw);
                            let pairs = &band.raw[..band.found];
                            super::split_by_key_part(pairs, &starts, &mut band.by_part);
                        }
                    });
                    if self.big.is_empty() {
                        // Each range of first indices sorted on its own thread.
                        let by_part: Vec<&[Vec<Pair>]> =
                            self.bands.iter().map(|band| &band.by_part[..]).collect();
                        super::sort_pairs_in_parts(&by_part, parts, n, &mut self.part_ends, out);
                        return;
                    }
                    self.raw.clear();
                    for band in &self.bands {
                        self.raw.extend_from_slice(&band.raw[..band.found]);
                    }
                    found = self.raw.len();
                },
                {
                    found = sweep(0..layout.ny, &mut self.raw);
                }
            );
        }
        if !self.big.is_empty() {
            self.raw.truncate(found);
            if space.period.is_some() {
                self.big_discs::<true>(&space);
            } else {
                self.big_discs::<false>(&space);
            }
            found = self.raw.len();
        }
        sort_pairs(&self.raw[..found], particles.len(), &mut self.ends, out);
    }

    fn set_parallel(&mut self, parallel: bool) {
        self.parallel = parallel;
    }
}

/// What one pass over the discs learns.
#[derive(Clone, Copy, Debug)]
struct Gathered {
    /// Sum, count and maximum of the finite radii (negative ones as 0).
    r_sum: f64,
    r_count: usize,
    r_max: f64,
    /// Whether some radius is +∞.
    infinite: bool,
    /// Bounding box of the centres.
    lo: DVec2,
    hi: DVec2,
}

impl Default for Gathered {
    fn default() -> Self {
        Gathered {
            r_sum: 0.0,
            r_count: 0,
            r_max: 0.0,
            infinite: false,
            lo: DVec2::INFINITY,
            hi: DVec2::NEG_INFINITY,
        }
    }
}

impl Gathered {
    /// Adds what another chunk of discs showed (sums in call order).
    fn merge(&mut self, o: &Gathered) {
        self.r_sum += o.r_sum;
        self.r_count += o.r_count;
        self.r_max = self.r_max.max(o.r_max);
        self.infinite |= o.infinite;
        self.lo = self.lo.min(o.lo);
        self.hi = self.hi.max(o.hi);
    }

    /// Adds a disc (finite centre, radius not NaN). Plain selects (one
    /// `minsd`/`maxsd` each) rather than `f64::max`, which pays for NaN
    /// handling not needed here.
    #[inline(always)]
    fn add(&mut self, d: &Disc) {
        if d.r < f64::INFINITY {
            let r = if d.r > 0.0 { d.r } else { 0.0 };
            self.r_sum += r;
            self.r_count += 1;
            self.r_max = if r > self.r_max { r } else { self.r_max };
        } else {
            self.infinite = true;
        }
        self.lo.x = if d.x < self.lo.x { d.x } else { self.lo.x };
        self.lo.y = if d.y < self.lo.y { d.y } else { self.lo.y };
        self.hi.x = if d.x > self.hi.x { d.x } else { self.hi.x };
        self.hi.y = if d.y > self.hi.y { d.y } else { self.hi.y };
    }
}

impl Grid {
    /// Fills `discs` with the candidate discs in index order, chunk by chunk
    /// of [`CHUNK`] particles (on the pool when parallel), and returns what
    /// they showed, the chunks' sums added in chunk order.
    fn gather(&mut self, particles: &[Particle], space: &mut Space) -> Gathered {
        let base = *space;
        let chunk = |(c, (ps, ds)): (usize, (&[Particle], &mut [Disc]))| {
            let (mut space, mut seen, mut kept) = (base, Gathered::default(), 0);
            for (k, p) in ps.iter().enumerate() {
                if let Some(d) = space.disc(c * CHUNK + k, p) {
                    seen.add(&d);
                    ds[kept] = d;
                    kept += 1;
                }
            }
            (kept, seen, space.outside)
        };
        // Every slot is written before it is read: no need to clear.
        self.discs.resize(particles.len(), Disc::default());
        self.gathered.clear();
        crate::parallel::pool_or_here!(
            self.parallel,
            {
                // Thread k gathers the run of chunks it integrates and checks
                // (`parallel::on_each_part`): those particles are in its caches.
                let per_thread =
                    crate::parallel::on_each_part(&mut self.discs, CHUNK, |first, ds| {
                        let n = particles.len();
                        let ps =
                            &particles[(first * CHUNK).min(n)..(first * CHUNK + ds.len()).min(n)];
                        let chunks = ps.chunks(CHUNK).zip(ds.chunks_mut(CHUNK));
                        let chunks = (first..).zip(chunks);
                        chunks.map(chunk).collect::<Vec<_>>()
                    });
                self.gathered.extend(per_thread.into_iter().flatten());
            },
            {
                let chunks = particles.chunks(CHUNK).zip(self.discs.chunks_mut(CHUNK));
                self.gathered.extend(chunks.enumerate().map(chunk));
            }
        );
        // Close the gaps left by skipped discs (rare: non-finite input).
        let (mut stats, mut end) = (Gathered::default(), 0);
        for (c, (kept, seen, outside)) in self.gathered.iter().enumerate() {
            let start = c * CHUNK;
            if start != end {
                self.discs.copy_within(start..start + kept, end);
            }
            end += kept;
            stats.merge(seen);
            space.outside = space.outside.max(*outside);
        }
        self.discs.truncate(end);
        stats
    }

    /// Lists the big discs in `big` (ascending) and returns the largest
    /// radius of the others and the bounding box of their centres.
    fn split_off_big_discs(&mut self, stats: &Gathered) -> (f64, DVec2, DVec2) {
        self.big.clear();
        let mean = stats.r_sum / stats.r_count.max(1) as f64;
        let mut cut = f64::INFINITY;
        if stats.r_max > BIG_FACTOR * mean {
            let candidate = BIG_FACTOR * mean;
            if self.discs.iter().filter(|d| d.r > candidate).count() <= MAX_BIG {
                cut = candidate;
            }
        }
        if cut == f64::INFINITY && !stats.infinite {
            return (stats.r_max, stats.lo, stats.hi); // the common case
        }
        let (mut grid_radius, mut lo, mut hi) = (0.0f64, DVec2::INFINITY, DVec2::NEG_INFINITY);
        for (k, d) in self.discs.iter().enumerate() {
            if d.r > cut || d.r == f64::INFINITY {
                self.big.push(k as u32);
            } else {
                grid_radius = grid_radius.max(d.r);
                let c = DVec2::new(d.x, d.y);
                lo = lo.min(c);
                hi = hi.max(c);
            }
        }
        (grid_radius, lo, hi)
    }

    /// Cells for a closed or open world: over the bounding box of the
    /// centres `lo..hi`, or over the bulk of the discs if that box is far too
    /// big for the cell cap.
    fn open_layout(
        &mut self,
        grid_radius: f64,
        mut lo: DVec2,
        mut hi: DVec2,
        gridded: usize,
    ) -> Layout {
        let cap = CELLS_PER_DISC * gridded + 8;
        let diameter = 2.0 * grid_radius * (1.0 + 1e-5);
        let needed = |lo: DVec2, hi: DVec2, w: f64| {
            let ext = hi - lo;
            ((ext.x / w).floor() + 1.0) * ((ext.y / w).floor() + 1.0)
        };
        // (An extent too large for f64 gives NaN here: not a fit either.)
        let fits = needed(lo, hi, diameter.max(f64::MIN_POSITIVE)) <= 4.0 * cap as f64;
        if !fits {
            (lo, hi) = self.bulk(lo, hi, diameter);
        }
        // Widen the cells by the rounding error of (x − origin)/w, so that two
        // centres closer than a diameter never land two cells apart.
        let scale = lo.abs().max(hi.abs()).max_element() + 2.0 * grid_radius;
        let h = (diameter + 64.0 * f64::EPSILON * scale).max(f64::MIN_POSITIVE);
        let mut w = h;
        for _ in 0..100 {
            let cells = needed(lo, hi, w);
            if cells <= cap as f64 {
                let ext = hi - lo;
                return Layout {
                    origin: lo,
                    inv_width: DVec2::splat(1.0 / w),
                    nx: (ext.x / w) as usize + 1,
                    ny: (ext.y / w) as usize + 1,
                };
            }
            w *= (cells / cap as f64).sqrt().max(1.001);
        }
        Layout {
            origin: lo,
            inv_width: DVec2::ZERO,
            nx: 1,
            ny: 1,
        }
    }

    /// The region holding the bulk of the gridded discs: the 2–98 %
    /// quantiles of a sample of at most 256 of them, padded, within `lo..hi`.
    fn bulk(&mut self, lo: DVec2, hi: DVec2, diameter: f64) -> (DVec2, DVec2) {
        let gridded = self.discs.len() - self.big.len();
        let stride = (gridded / 256).max(1);
        let mut range = |coord: fn(&Disc) -> f64, lo: f64, hi: f64| {
            self.sample.clear();
            let mut big = self.big.iter().peekable();
            let in_grid = self.discs.iter().enumerate().filter_map(|(k, d)| {
                if big.peek() == Some(&&(k as u32)) {
                    big.next();
                    None
                } else {
                    Some(coord(d))
                }
            });
            self.sample.extend(in_grid.step_by(stride));
            self.sample.sort_unstable_by(f64::total_cmp);
            let m = self.sample.len();
            let skip = m * 2 / 100;
            let (q_lo, q_hi) = (self.sample[skip], self.sample[m - 1 - skip]);
            let pad = 0.25 * (q_hi - q_lo) + diameter;
            ((q_lo - pad).max(lo), (q_hi + pad).min(hi))
        };
        let (x0, x1) = range(|d| d.x, lo.x, hi.x);
        let (y0, y1) = range(|d| d.y, lo.y, hi.y);
        (DVec2::new(x0, y0), DVec2::new(x1, y1))
    }

    /// Tests each big disc against every other disc.
    fn big_discs<const PERIODIC: bool>(&mut self, space: &Space) {
        for &k in &self.big {
            let a = self.discs[k as usize];
            for (m, b) in self.discs.iter().enumerate() {
                // A pair of big discs is tested from the first of them.
                let other_big_first = b.tag == BIG && m <= k as usize;
                if !other_big_first && touches::<PERIODIC>(&a, b, space) {
                    self.raw.push(pair(a.i, b.i));
                }
            }
        }
    }
}

/// Cells for a periodic box of size `period`, at least `2·radius` wide.
fn periodic_layout(period: DVec2, radius: f64, gridded: usize, space: &Space) -> Layout {
    let cap = CELLS_PER_DISC * gridded + 8;
    let h =
        (2.0 * radius + space.slack) * (1.0 + 1e-5) + 64.0 * f64::EPSILON * period.max_element();
    let along = |side: f64| (side / h).floor().clamp(1.0, cap as f64) as usize;
    let (mut nx, mut ny) = (along(period.x), along(period.y));
    if nx * ny > cap {
        let f = ((nx * ny) as f64 / cap as f64).sqrt();
        nx = ((nx as f64 / f) as usize).max(1);
        ny = ((ny as f64 / f) as usize).max(1);
        if nx * ny > cap {
            if nx == 1 {
                ny = cap;
            } else {
                nx = cap;
            }
        }
    }
    // With two cells along an axis, left and right neighbours coincide.
    if nx < 3 {
        nx = 1;
    }
    if ny < 3 {
        ny = 1;
    }
    Layout {
        origin: DVec2::ZERO,
        inv_width: DVec2::new(nx as f64 / period.x, ny as f64 / period.y),
        nx,
        ny,
    }
}
