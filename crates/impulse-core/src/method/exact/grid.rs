//! The exact method's cell grid: cells at least one diameter wide, so a
//! disc can only touch discs in its own and the eight neighbouring cells.

use super::Body;
use crate::boundary::Boundary;
use crate::laws::Laws;
use crate::particle::Particle;
use glam::DVec2;

/// Cell width in largest diameters.
const CELL_DIAMETERS: f64 = 1.0;
/// Cap on grid cells, per disc.
const CELLS_PER_DISC: usize = 4;

/// End of a cell's list.
pub(super) const NIL: u32 = u32::MAX;

/// A grid over the world (or, for open space, over where the discs are),
/// with cells at least one diameter wide.
pub(super) struct Grid {
    origin: DVec2,
    /// Size of the gridded region.
    extent: DVec2,
    cell: DVec2,
    pub(super) dims: [i32; 2],
    pub(super) periodic: bool,
    /// Each cell's discs as a singly linked list: its first disc here, and
    /// each disc's next in the disc itself ([`Body::next_in_cell`]), so that
    /// walking a cell reads nothing but the discs it visits anyway. Cells
    /// hold less than one disc on average.
    heads: Vec<u32>,
}

impl Grid {
    pub(super) fn new(particles: &[Particle], laws: &Laws) -> Grid {
        let n = particles.len();
        let max_d = particles
            .iter()
            .map(|p| 2.0 * p.radius)
            .fold(0.0, f64::max)
            .max(1e-12);
        let (origin, extent) = match laws.boundary {
            Boundary::Box if laws.walls.all() => (DVec2::ZERO, laws.size),
            Boundary::Periodic => (DVec2::ZERO, laws.size),
            // A box with open sides: the box, and beyond each open side as far
            // as the discs reach, with the open world's margin; a walled
            // side stays the grid's edge, so its wall is met in an edge cell.
            Boundary::Box => {
                let (mut lo, mut hi) = (DVec2::ZERO, laws.size);
                for p in particles.iter().filter(|p| p.pos.is_finite()) {
                    lo = lo.min(p.pos);
                    hi = hi.max(p.pos);
                }
                let margin = (hi - lo).max(DVec2::splat(4.0 * max_d));
                let w = laws.walls;
                let lo = DVec2::new(
                    if w.left { 0.0 } else { lo.x - margin.x },
                    if w.bottom { 0.0 } else { lo.y - margin.y },
                );
                let hi = DVec2::new(
                    if w.right {
                        laws.size.x
                    } else {
                        hi.x + margin.x
                    },
                    if w.top { laws.size.y } else { hi.y + margin.y },
                );
                (lo, hi - lo)
            }
            Boundary::Open => {
                let (mut lo, mut hi) =
                    (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
                for p in particles {
                    lo = lo.min(p.pos);
                    hi = hi.max(p.pos);
                }
                if n == 0 || !lo.is_finite() || !hi.is_finite() {
                    (DVec2::ZERO, DVec2::ONE)
                } else {
                    let margin = (hi - lo).max(DVec2::splat(4.0 * max_d));
                    (lo - margin, (hi - lo) + 2.0 * margin)
                }
            }
        };
        let cap = (CELLS_PER_DISC * n).max(16) as f64;
        let mut dims = (extent / (CELL_DIAMETERS * max_d))
            .floor()
            .max(DVec2::ONE)
            .min(DVec2::splat(1e6));
        while dims.x * dims.y > cap {
            dims = (dims * 0.5).floor().max(DVec2::ONE);
        }
        let dims = [dims.x as i32, dims.y as i32];
        Grid {
            origin,
            extent,
            cell: extent / DVec2::new(f64::from(dims[0]), f64::from(dims[1])),
            dims,
            periodic: laws.boundary == Boundary::Periodic,
            heads: vec![NIL; (dims[0] as usize) * (dims[1] as usize)],
        }
    }

    pub(super) fn cell_of(&self, pos: DVec2) -> [i32; 2] {
        let rel = (pos - self.origin) / self.cell;
        let clamp = |v: f64, n: i32| {
            if v.is_finite() {
                (v.floor().clamp(0.0, f64::from(n - 1))) as i32
            } else {
                0
            }
        };
        [clamp(rel.x, self.dims[0]), clamp(rel.y, self.dims[1])]
    }

    /// Prefetches the list heads of the cells around cell `c` (three rows,
    /// one cache line each, mostly).
    pub(super) fn prefetch_around(&self, c: [i32; 2]) {
        for dy in -1..=1 {
            let row = c[1] + dy;
            if row >= 0 && row < self.dims[1] && c[0] >= 0 && c[0] < self.dims[0] {
                super::prefetch(&self.heads[self.index([c[0], row])]);
            }
        }
    }

    /// Whether cell `c` has neighbours on all sides without wrapping.
    #[inline]
    pub(super) fn is_inner(&self, c: [i32; 2]) -> bool {
        c[0] > 0 && c[0] < self.dims[0] - 1 && c[1] > 0 && c[1] < self.dims[1] - 1
    }

    /// The nine cells around inner cell `c` ([`Grid::is_inner`]), as grid
    /// indices, row by row: what [`Grid::for_each_neighbour`] visits there,
    /// in the same order, with no shift.
    #[inline]
    pub(super) fn around_inner(&self, c: [i32; 2]) -> [usize; 9] {
        let (row, k) = (self.dims[0] as usize, self.index(c));
        [
            k - row - 1,
            k - row,
            k - row + 1,
            k - 1,
            k,
            k + 1,
            k + row - 1,
            k + row,
            k + row + 1,
        ]
    }

    /// The three cells a disc in inner cell `c` has newly in reach after
    /// crossing into it along `axis`: what [`Grid::for_each_new_in_reach`]
    /// visits there, in the same order, with no shift.
    #[inline]
    pub(super) fn beyond_inner(&self, c: [i32; 2], axis: usize, upper: bool) -> [usize; 3] {
        let mut ahead = c;
        ahead[axis] += if upper { 1 } else { -1 };
        let k = self.index(ahead);
        let step = if axis == 0 { self.dims[0] as usize } else { 1 };
        [k - step, k, k + step]
    }

    #[inline]
    pub(super) fn index(&self, c: [i32; 2]) -> usize {
        (c[1] as usize) * (self.dims[0] as usize) + c[0] as usize
    }

    /// Whether a neighbour's image is fixed by its cell: true unless the
    /// grid wraps with fewer than three cells along an axis, where one cell
    /// can be a neighbour on both sides and the nearest image must be found
    /// per pair.
    pub(super) fn images_by_cell(&self) -> bool {
        !self.periodic || (self.dims[0] >= 3 && self.dims[1] >= 3)
    }

    /// The up to three distinct cell coordinates around `v` along an axis
    /// of `n` cells (wrapped when periodic), how many there are, and for
    /// each the wrap it took (−1, 0 or +1 world lengths): a disc in that
    /// cell is nearest at its position plus that many lengths.
    #[inline]
    fn around(&self, v: i32, n: i32) -> ([i32; 3], [f64; 3], usize) {
        if v > 0 && v < n - 1 {
            // The common case: an inner cell.
            return ([v - 1, v, v + 1], [0.0; 3], 3);
        }
        let mut out = [0; 3];
        let mut wraps = [0.0; 3];
        let mut count = 0;
        for d in [v - 1, v, v + 1] {
            let (w, wrap) = if !self.periodic {
                (d, 0.0)
            } else if d < 0 {
                (d + n, -1.0)
            } else if d >= n {
                (d - n, 1.0)
            } else {
                (d, 0.0)
            };
            if (0..n).contains(&w) && !out[..count].contains(&w) {
                out[count] = w;
                wraps[count] = wrap;
                count += 1;
            }
        }
        (out, wraps, count)
    }

    /// Calls `visit` with the index of each of the up to nine cells around
    /// `c`, each once, and the shift that puts its discs at their nearest
    /// periodic image (zero unless the grid wraps there; meaningful only
    /// when [`Grid::images_by_cell`]).
    #[inline]
    pub(super) fn for_each_neighbour(&self, c: [i32; 2], mut visit: impl FnMut(usize, DVec2)) {
        if !self.is_inner(c) {
            return self.for_each_neighbour_at_edge(c, visit);
        }
        // The common case: nine cells in three runs of three, unwrapped.
        let row = self.dims[0] as usize;
        let centre = self.index(c);
        for middle in [centre - row, centre, centre + row] {
            visit(middle - 1, DVec2::ZERO);
            visit(middle, DVec2::ZERO);
            visit(middle + 1, DVec2::ZERO);
        }
    }

    /// [`Grid::for_each_neighbour`] for any cell, wrapping or clipping at
    /// the grid's edges.
    fn for_each_neighbour_at_edge(&self, c: [i32; 2], mut visit: impl FnMut(usize, DVec2)) {
        let (xs, x_wraps, nx) = self.around(c[0], self.dims[0]);
        let (ys, y_wraps, ny) = self.around(c[1], self.dims[1]);
        let row = self.dims[0] as usize;
        for (&y, &y_wrap) in ys[..ny].iter().zip(&y_wraps) {
            for (&x, &x_wrap) in xs[..nx].iter().zip(&x_wraps) {
                let shift = DVec2::new(x_wrap * self.extent.x, y_wrap * self.extent.y);
                visit(y as usize * row + x as usize, shift);
            }
        }
    }

    /// Calls `visit` like [`Grid::for_each_neighbour`] for the cells that
    /// came into reach of a disc that has just crossed into cell `c` along
    /// `axis` (upwards if `upper`): the row or column beyond `c`, up to three
    /// cells. Only meaningful when [`Grid::images_by_cell`].
    #[inline]
    pub(super) fn for_each_new_in_reach(
        &self,
        c: [i32; 2],
        axis: usize,
        upper: bool,
        mut visit: impl FnMut(usize, DVec2),
    ) {
        let ahead = c[axis] + if upper { 1 } else { -1 };
        let across = 1 - axis;
        // The row (or column) ahead exists without wrapping, and has a
        // cell on each side of the one ahead.
        let unwrapped_ahead = (0..self.dims[axis]).contains(&ahead)
            && c[across] > 0
            && c[across] < self.dims[across] - 1;
        if !unwrapped_ahead {
            return self.for_each_new_in_reach_at_edge(c, axis, upper, visit);
        }
        // The common case: three neighbouring cells, unwrapped.
        let mut cell = c;
        cell[axis] = ahead;
        let middle = self.index(cell);
        let step = if across == 0 {
            1
        } else {
            self.dims[0] as usize
        };
        for k in [middle - step, middle, middle + step] {
            visit(k, DVec2::ZERO);
        }
    }

    /// [`Grid::for_each_new_in_reach`] for any cell, wrapping or clipping
    /// at the grid's edges.
    fn for_each_new_in_reach_at_edge(
        &self,
        c: [i32; 2],
        axis: usize,
        upper: bool,
        mut visit: impl FnMut(usize, DVec2),
    ) {
        let n = self.dims[axis];
        let mut ahead = c[axis] + if upper { 1 } else { -1 };
        let mut wrap = 0.0;
        if !(0..n).contains(&ahead) {
            if !self.periodic {
                return;
            }
            wrap = if upper { 1.0 } else { -1.0 };
            ahead = ahead.rem_euclid(n);
        }
        let across = 1 - axis;
        let (others, other_wraps, count) = self.around(c[across], self.dims[across]);
        for (&other, &other_wrap) in others[..count].iter().zip(&other_wraps) {
            let mut cell = [0; 2];
            cell[axis] = ahead;
            cell[across] = other;
            let mut shift = DVec2::ZERO;
            shift[axis] = wrap * self.extent[axis];
            shift[across] = other_wrap * self.extent[across];
            visit(self.index(cell), shift);
        }
    }

    /// The lower or upper border along `axis` of cells at `along` on it.
    #[inline]
    pub(super) fn border(&self, along: i32, axis: usize, upper: bool) -> f64 {
        let (origin, width) = if axis == 0 {
            (self.origin.x, self.cell.x)
        } else {
            (self.origin.y, self.cell.y)
        };
        origin + f64::from(along + i32::from(upper)) * width
    }

    pub(super) fn bounds(&self, c: [i32; 2], axis: usize) -> (f64, f64) {
        let lo = self.origin[axis] + f64::from(c[axis]) * self.cell[axis];
        (lo, lo + self.cell[axis])
    }

    /// The first disc of cell `k` (index), or [`NIL`].
    #[inline]
    pub(super) fn first(&self, k: usize) -> u32 {
        self.heads[k]
    }

    /// The discs of cell `k` (index).
    pub(super) fn members<'a>(
        &'a self,
        bodies: &'a [Body],
        k: usize,
    ) -> impl Iterator<Item = u32> + 'a {
        std::iter::successors(Some(self.heads[k]).filter(|&i| i != NIL), |&i| {
            Some(bodies[i as usize].next_in_cell).filter(|&j| j != NIL)
        })
    }

    /// Puts disc `i` into cell `c`.
    pub(super) fn insert(&mut self, bodies: &mut [Body], i: u32, c: [i32; 2]) {
        let k = self.index(c);
        bodies[i as usize].next_in_cell = self.heads[k];
        self.heads[k] = i;
    }

    /// Takes disc `i` out of cell `c`.
    pub(super) fn remove(&mut self, bodies: &mut [Body], i: u32, c: [i32; 2]) {
        let k = self.index(c);
        let after = bodies[i as usize].next_in_cell;
        if self.heads[k] == i {
            self.heads[k] = after;
            return;
        }
        let mut j = self.heads[k];
        while j != NIL {
            if bodies[j as usize].next_in_cell == i {
                bodies[j as usize].next_in_cell = after;
                return;
            }
            j = bodies[j as usize].next_in_cell;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::particle::Color;

    /// A grid of `dims` cells one metre wide (discs of radius 0.5).
    fn grid(dims: [i32; 2], boundary: Boundary) -> Grid {
        let size = DVec2::new(f64::from(dims[0]), f64::from(dims[1]));
        let disc = Particle::new(
            DVec2::splat(0.5),
            DVec2::ZERO,
            1.0,
            0.5,
            Color::rgb(0, 0, 0),
        );
        let laws = Laws {
            boundary,
            ..Laws::new(size)
        };
        let g = Grid::new(&vec![disc; (dims[0] * dims[1]) as usize], &laws);
        assert_eq!(g.dims, dims);
        g
    }

    fn cells(g: &Grid) -> impl Iterator<Item = [i32; 2]> + '_ {
        (0..g.dims[1]).flat_map(move |y| (0..g.dims[0]).map(move |x| [x, y]))
    }

    #[test]
    fn inner_cells_visit_what_the_edge_walk_visits_in_its_order() {
        let mut inner = 0;
        for boundary in [Boundary::Box, Boundary::Periodic] {
            for dims in [[3, 3], [4, 3], [5, 6], [7, 4]] {
                let g = grid(dims, boundary);
                for c in cells(&g) {
                    let (mut fast, mut general) = (Vec::new(), Vec::new());
                    g.for_each_neighbour(c, |k, s| fast.push((k, s)));
                    g.for_each_neighbour_at_edge(c, |k, s| general.push((k, s)));
                    assert_eq!(fast, general, "{boundary:?} {dims:?} cell {c:?}");
                    inner += usize::from(g.is_inner(c));
                    for axis in 0..2 {
                        for upper in [false, true] {
                            let (mut fast, mut general) = (Vec::new(), Vec::new());
                            g.for_each_new_in_reach(c, axis, upper, |k, s| fast.push((k, s)));
                            g.for_each_new_in_reach_at_edge(c, axis, upper, |k, s| {
                                general.push((k, s))
                            });
                            assert_eq!(fast, general, "{boundary:?} {dims:?} {c:?} {axis} {upper}");
                        }
                    }
                }
            }
        }
        assert!(inner > 20, "the inner path ran {inner} times");
    }

    #[test]
    fn an_inner_cell_has_its_nine_neighbours_unshifted() {
        let g = grid([5, 6], Boundary::Periodic);
        let mut seen = Vec::new();
        g.for_each_neighbour([2, 3], |k, s| {
            assert_eq!(s, DVec2::ZERO);
            seen.push(k);
        });
        let expected: Vec<usize> = (2..=4)
            .flat_map(|y| (1..=3).map(move |x| y * 5 + x))
            .collect();
        assert_eq!(seen, expected);
    }

    #[test]
    fn the_inner_lists_are_what_the_walks_visit_there() {
        for boundary in [Boundary::Box, Boundary::Periodic] {
            let g = grid([7, 5], boundary);
            for c in cells(&g).filter(|&c| g.is_inner(c)) {
                let mut walked = Vec::new();
                g.for_each_neighbour(c, |k, s| walked.push((k, s)));
                let listed: Vec<_> = g.around_inner(c).map(|k| (k, DVec2::ZERO)).into();
                assert_eq!(walked, listed, "{boundary:?} {c:?}");
                for axis in 0..2 {
                    for upper in [false, true] {
                        let mut walked = Vec::new();
                        g.for_each_new_in_reach(c, axis, upper, |k, s| walked.push((k, s)));
                        let listed: Vec<_> = g
                            .beyond_inner(c, axis, upper)
                            .map(|k| (k, DVec2::ZERO))
                            .into();
                        assert_eq!(walked, listed, "{boundary:?} {c:?} {axis} {upper}");
                    }
                }
            }
        }
    }
}
