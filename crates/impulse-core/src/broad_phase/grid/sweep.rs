//! The grid's sweep (step 3 of [`super`]): every gridded disc of a band of
//! rows against the rest of its own cell and its forward neighbours, with
//! the candidate test chosen per boundary at compile time.

use super::super::{pair, touches, Disc, Pair, Space};
use glam::DVec2;
use std::ops::Range;

/// The filled grid, read-only.
pub(super) struct Cells<'a> {
    pub(super) starts: &'a [u32],
    pub(super) sorted: &'a [Disc],
    pub(super) nx: usize,
    pub(super) ny: usize,
}

// How the sweep compares two discs (`Cells::sweep`'s `MODE`).

/// Box or open: brute force's own test.
pub(super) const OPEN: u8 = 0;
/// Periodic with at least three cells along both axes: the shift that takes
/// a neighbour cell's disc to the minimum image is known per range (0, or ±
/// the box across the seam), so the raw difference is tested, widened by the
/// slack. Between adjacent cells, a pair that passes has |d| < a cell width
/// ≤ a third of the box, so it is the minimum image indeed.
pub(super) const SHIFTED: u8 = 1;
/// Periodic with an axis of a single cell: the minimum image by folding.
pub(super) const FOLDED: u8 = 2;

/// The candidate test in sweep mode `MODE`, `shift` added to `b`'s centre.
#[inline(always)]
fn test<const MODE: u8>(a: &Disc, b: &Disc, shift: DVec2, space: &Space) -> bool {
    match MODE {
        OPEN => touches::<false>(a, b, space),
        SHIFTED => {
            let reach = a.r + b.r + space.slack;
            let dx = (b.x + shift.x) - a.x;
            let dy = (b.y + shift.y) - a.y;
            (dx.abs() <= reach) & (dy.abs() <= reach)
        }
        _ => touches::<true>(a, b, space),
    }
}

impl Cells<'_> {
    /// Tests every gridded disc of rows `rows` against the rest of its own
    /// cell and the forward neighbours (right; up-left, up, up-right), row by
    /// row, writing the pairs to the start of `raw`; returns how many there
    /// are. What lies past them is scratch: `raw` keeps its length from
    /// sweep to sweep, so that it is not filled with zeros again before
    /// each sweep overwrites it. (Growing it from empty every time zeroed
    /// up to twice the pairs' bytes; keeping it took the broad phase at 10⁵
    /// discs from 53.4 to 51.6 ms per 200 steps on one thread, 30.6 to
    /// 29.4 on two.)
    #[inline(never)]
    pub(super) fn sweep<const MODE: u8>(
        &self,
        rows: Range<usize>,
        space: &Space,
        raw: &mut Vec<Pair>,
    ) -> usize {
        let (nx, ny, sorted) = (self.nx, self.ny, self.sorted);
        let start = |c: usize| self.starts[c] as usize;
        let periodic = MODE != OPEN;
        let period = space.period.unwrap_or(DVec2::ZERO);
        let wrap_x = periodic && nx >= 3;
        // Every candidate is written and the end moves on only if it passes:
        // no branch on the test's outcome, which is hard to predict.
        let mut found = 0;
        let mut scan = |a: &Disc, from: usize, to: usize, shift: DVec2, raw: &mut Vec<Pair>| {
            let need = found + (to - from);
            if raw.len() < need {
                raw.resize(need.max(2 * raw.len()), Pair::default());
            }
            for b in &sorted[from..to] {
                raw[found] = pair(a.i, b.i);
                found += usize::from(test::<MODE>(a, b, shift, space));
            }
        };
        for cy in rows {
            let row = cy * nx;
            let (up, up_y) = if cy + 1 < ny {
                (Some(row + nx), 0.0)
            } else if periodic && ny >= 3 {
                (Some(0), period.y)
            } else {
                (None, 0.0)
            };
            let here = DVec2::ZERO;
            let (left, right) = (DVec2::new(-period.x, 0.0), DVec2::new(period.x, 0.0));
            let first = start(row);
            for (k, a) in sorted[first..start(row + nx)].iter().enumerate() {
                let k = first + k;
                let c = a.tag as usize;
                let cx = c - row;
                // The rest of the own cell runs on into the right neighbour.
                if cx + 1 < nx {
                    scan(a, k + 1, start(c + 2), here, raw);
                } else {
                    scan(a, k + 1, start(c + 1), here, raw);
                    if wrap_x {
                        scan(a, start(row), start(row + 1), right, raw);
                    }
                }
                let Some(up) = up else {
                    continue;
                };
                let above = DVec2::new(0.0, up_y);
                if !wrap_x || (cx > 0 && cx + 1 < nx) {
                    // Up-left to up-right: one run of the array.
                    let (l, r) = (cx.saturating_sub(1), (cx + 1).min(nx - 1));
                    scan(a, start(up + l), start(up + r + 1), above, raw);
                } else if cx == 0 {
                    scan(a, start(up), start(up + 2), above, raw);
                    scan(a, start(up + nx - 1), start(up + nx), above + left, raw);
                } else {
                    scan(a, start(up + nx - 2), start(up + nx), above, raw);
                    scan(a, start(up), start(up + 1), above + right, raw);
                }
            }
        }
        found
    }
}
