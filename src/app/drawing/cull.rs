//! What is worth drawing and where: discs on screen, arrows long enough to
//! read, and labels beside discs big enough to point at, placed where they
//! cover no disc, no arrow and no other label (the free side first, farther
//! out with a leader line when the near sides are taken). Pure screen
//! geometry (pixels, y down), so it is tested without a window.

use glam::DVec2;

/// Arrows shorter than this (px) are not drawn: a head alone says nothing.
pub const MIN_ARROW_PIXELS: f64 = 4.0;
/// Readouts of "all discs" are shown only beside discs at least this big
/// (radius, px); the selected disc's readout is always shown.
pub const MIN_LABEL_DISC_PIXELS: f64 = 4.0;
/// Discs are drawn at least this big (radius, px), so none vanishes.
pub const MIN_DISC_PIXELS: f64 = 1.0;

/// A rectangle on screen: top-left and bottom-right corners (px).
pub type ScreenRect = (DVec2, DVec2);

/// Whether a circle (centre and radius in px) touches the rectangle.
pub fn circle_on_screen(center: DVec2, radius: f64, (lo, hi): ScreenRect) -> bool {
    center.x + radius >= lo.x
        && center.y + radius >= lo.y
        && center.x - radius <= hi.x
        && center.y - radius <= hi.y
}

/// Whether an arrow from `from` to `to` (px) is long enough to read and
/// crosses the rectangle (its bounding box touches it).
pub fn arrow_readable(from: DVec2, to: DVec2, (rect_lo, rect_hi): ScreenRect) -> bool {
    let long_enough = from.distance(to) >= MIN_ARROW_PIXELS; // false for NaN
    if !long_enough {
        return false;
    }
    let (lo, hi) = (from.min(to), from.max(to));
    hi.x >= rect_lo.x && hi.y >= rect_lo.y && lo.x <= rect_hi.x && lo.y <= rect_hi.y
}

/// Where readouts have gone this frame: a label is placed only where it
/// overlaps none placed before, so text stays readable however many discs
/// there are. Placed rectangles are kept in cells of a coarse grid.
#[derive(Debug)]
pub struct LabelPlacer {
    cell: DVec2,
    placed: std::collections::HashMap<(i64, i64), Vec<[f64; 4]>>,
    /// Labels placed so far.
    pub count: usize,
}

impl LabelPlacer {
    /// A placer for labels of about `typical` size (px).
    pub fn new(typical: DVec2) -> Self {
        LabelPlacer {
            cell: typical.max(DVec2::splat(8.0)),
            placed: Default::default(),
            count: 0,
        }
    }

    fn cells(&self, r: [f64; 4]) -> impl Iterator<Item = (i64, i64)> {
        let lo = (DVec2::new(r[0], r[1]) / self.cell).floor();
        let hi = (DVec2::new(r[0] + r[2], r[1] + r[3]) / self.cell).floor();
        let (x0, y0, x1, y1) = (lo.x as i64, lo.y as i64, hi.x as i64, hi.y as i64);
        (x0..=x1).flat_map(move |x| (y0..=y1).map(move |y| (x, y)))
    }

    /// Whether the rectangle [x, y, width, height] overlaps nothing placed.
    pub fn is_free(&self, r: [f64; 4]) -> bool {
        let overlaps = |q: &[f64; 4]| {
            r[0] < q[0] + q[2] && q[0] < r[0] + r[2] && r[1] < q[1] + q[3] && q[1] < r[1] + r[3]
        };
        self.cells(r).all(|c| {
            self.placed
                .get(&c)
                .is_none_or(|list| !list.iter().any(overlaps))
        })
    }

    /// Places the rectangle [x, y, width, height] if it overlaps nothing
    /// placed, and says whether it did.
    pub fn try_place(&mut self, r: [f64; 4]) -> bool {
        let overlaps = |q: &[f64; 4]| {
            r[0] < q[0] + q[2] && q[0] < r[0] + r[2] && r[1] < q[1] + q[3] && q[1] < r[1] + r[3]
        };
        let free = self.cells(r).all(|c| {
            self.placed
                .get(&c)
                .is_none_or(|list| !list.iter().any(overlaps))
        });
        if free {
            let cells: Vec<_> = self.cells(r).collect();
            for c in cells {
                self.placed.entry(c).or_default().push(r);
            }
            self.count += 1;
        }
        free
    }
}

/// Things a label must not cover: discs (circles) and arrows (segments
/// with a half-width), kept in the cells of a coarse grid so that a query
/// looks only near the label.
#[derive(Debug)]
pub struct Obstacles {
    cell: f64,
    circles: std::collections::HashMap<(i64, i64), Vec<(DVec2, f64)>>,
    segments: std::collections::HashMap<(i64, i64), Vec<Segment>>,
    /// Obstacles too big for the grid (a disc zoomed to fill the screen).
    big_circles: Vec<(DVec2, f64)>,
    big_segments: Vec<Segment>,
}

/// An arrow as an obstacle: its ends and half its width (px).
type Segment = (DVec2, DVec2, f64);

/// An obstacle covering more cells than this is checked against every label.
const MAX_OBSTACLE_CELLS: i64 = 64;

fn cells_of(cell: f64, lo: DVec2, hi: DVec2) -> Option<Vec<(i64, i64)>> {
    let (a, b) = ((lo / cell).floor(), (hi / cell).floor());
    if !(a.is_finite() && b.is_finite()) {
        return None;
    }
    let (x0, y0, x1, y1) = (a.x as i64, a.y as i64, b.x as i64, b.y as i64);
    if (x1 - x0 + 1) * (y1 - y0 + 1) > MAX_OBSTACLE_CELLS {
        return None;
    }
    Some(
        (x0..=x1)
            .flat_map(|x| (y0..=y1).map(move |y| (x, y)))
            .collect(),
    )
}

/// Whether the rectangle [x, y, w, h] and the circle overlap.
pub fn rect_hits_circle(r: [f64; 4], center: DVec2, radius: f64) -> bool {
    let nearest = DVec2::new(
        center.x.clamp(r[0], r[0] + r[2]),
        center.y.clamp(r[1], r[1] + r[3]),
    );
    nearest.distance_squared(center) < radius * radius
}

/// Whether the rectangle [x, y, w, h] comes within `pad` of the segment a–b.
pub fn rect_hits_segment(r: [f64; 4], a: DVec2, b: DVec2, pad: f64) -> bool {
    let (lo, hi) = (
        DVec2::new(r[0] - pad, r[1] - pad),
        DVec2::new(r[0] + r[2] + pad, r[1] + r[3] + pad),
    );
    super::clip::clip_segment(a, b, lo, hi).is_some()
}

impl Obstacles {
    /// An empty set, with grid cells of `cell` pixels.
    pub fn new(cell: f64) -> Self {
        Obstacles {
            cell: cell.max(8.0),
            circles: Default::default(),
            segments: Default::default(),
            big_circles: Vec::new(),
            big_segments: Vec::new(),
        }
    }

    /// A disc on screen.
    pub fn add_circle(&mut self, center: DVec2, radius: f64) {
        let reach = DVec2::splat(radius);
        match cells_of(self.cell, center - reach, center + reach) {
            Some(cells) => cells
                .into_iter()
                .for_each(|c| self.circles.entry(c).or_default().push((center, radius))),
            None => self.big_circles.push((center, radius)),
        }
    }

    /// An arrow from `a` to `b`, `half_width` pixels to each side.
    pub fn add_segment(&mut self, a: DVec2, b: DVec2, half_width: f64) {
        let pad = DVec2::splat(half_width);
        match cells_of(self.cell, a.min(b) - pad, a.max(b) + pad) {
            Some(cells) => cells
                .into_iter()
                .for_each(|c| self.segments.entry(c).or_default().push((a, b, half_width))),
            None => self.big_segments.push((a, b, half_width)),
        }
    }

    /// Whether the rectangle [x, y, w, h] covers any obstacle.
    pub fn hits(&self, r: [f64; 4]) -> bool {
        let circle = |&(c, radius): &(DVec2, f64)| rect_hits_circle(r, c, radius);
        let segment = |&(a, b, pad): &Segment| rect_hits_segment(r, a, b, pad);
        if self.big_circles.iter().any(circle) || self.big_segments.iter().any(segment) {
            return true;
        }
        let lo = (DVec2::new(r[0], r[1]) / self.cell).floor();
        let hi = (DVec2::new(r[0] + r[2], r[1] + r[3]) / self.cell).floor();
        if !(lo.is_finite() && hi.is_finite()) {
            return true;
        }
        for x in lo.x as i64..=hi.x as i64 {
            for y in lo.y as i64..=hi.y as i64 {
                let c = (x, y);
                if self.circles.get(&c).is_some_and(|l| l.iter().any(circle))
                    || self.segments.get(&c).is_some_and(|l| l.iter().any(segment))
                {
                    return true;
                }
            }
        }
        false
    }
}

/// Where a label went: its rectangle [x, y, w, h], and the leader line from
/// the disc's edge to the label when it sits away from the disc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub rect: [f64; 4],
    pub leader: Option<(DVec2, DVec2)>,
}

/// The diagonal's component, 1/√2.
const D: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// The directions a label is tried in, the free side first: right, left,
/// above, below, then the diagonals (screen y down).
const DIRECTIONS: [(f64, f64); 8] = [
    (1.0, 0.0),
    (-1.0, 0.0),
    (0.0, -1.0),
    (0.0, 1.0),
    (D, -D),
    (-D, -D),
    (D, D),
    (-D, D),
];

/// Places a label of `size` beside the disc at `center` (radius `radius`),
/// wholly inside `inside`, over no obstacle and no label placed before:
/// each direction close to the disc first, then farther out (`gaps`, px)
/// with a leader line. Where none of those fits (a disc near the edge of a
/// world narrower than its label, beside a projector's drawer), the same
/// places slid back inside, with a leader line. Returns `None` when every
/// place is taken.
pub fn place_label(
    center: DVec2,
    radius: f64,
    size: DVec2,
    gaps: &[f64],
    inside: ScreenRect,
    obstacles: &Obstacles,
    placed: &LabelPlacer,
) -> Option<Placement> {
    let (lo, hi) = inside;
    for slid in [false, true] {
        for (k, &gap) in gaps.iter().enumerate() {
            for (ux, uy) in DIRECTIONS {
                let [mut x, mut y] = beside(center, radius + gap, (ux, uy), size);
                if slid {
                    x = x.min(hi.x - size.x).max(lo.x);
                    y = y.min(hi.y - size.y).max(lo.y);
                }
                let rect = [x, y, size.x, size.y];
                let within = x >= lo.x && y >= lo.y && x + size.x <= hi.x && y + size.y <= hi.y;
                if !within || obstacles.hits(rect) || !placed.is_free(rect) {
                    continue;
                }
                let leader = (k > 0 || slid).then(|| {
                    let nearest =
                        DVec2::new(center.x.clamp(x, x + size.x), center.y.clamp(y, y + size.y));
                    let dir = (nearest - center).normalize_or_zero();
                    (center + dir * radius, nearest)
                });
                return Some(Placement { rect, leader });
            }
        }
    }
    None
}

/// The top left corner of a label of `size` whose near side touches the
/// point `away` px from `center` in the direction `(ux, uy)`: beside it on
/// that side, centred across it.
fn beside(center: DVec2, away: f64, (ux, uy): (f64, f64), size: DVec2) -> [f64; 2] {
    let anchor = center + DVec2::new(ux, uy) * away;
    // Along one axis: past the anchor, before it, or centred on it.
    let start = |anchor: f64, u: f64, length: f64| {
        if u > 0.3 {
            anchor
        } else if u < -0.3 {
            anchor - length
        } else {
            anchor - 0.5 * length
        }
    };
    [start(anchor.x, ux, size.x), start(anchor.y, uy, size.y)]
}

#[cfg(test)]
mod tests {
    use super::*;

    const VIEW: ScreenRect = (DVec2::ZERO, DVec2::new(1280.0, 800.0));

    #[test]
    fn a_rectangle_away_from_the_corner_counts_only_inside() {
        let rect = (DVec2::new(100.0, 50.0), DVec2::new(500.0, 450.0));
        assert!(!circle_on_screen(DVec2::new(90.0, 200.0), 5.0, rect));
        assert!(circle_on_screen(DVec2::new(96.0, 200.0), 5.0, rect));
        assert!(!arrow_readable(
            DVec2::new(10.0, 10.0),
            DVec2::new(60.0, 40.0),
            rect
        ));
    }

    #[test]
    fn circles_count_while_any_part_is_on_screen() {
        assert!(circle_on_screen(DVec2::new(640.0, 400.0), 1.0, VIEW));
        assert!(circle_on_screen(DVec2::new(-4.0, 400.0), 5.0, VIEW));
        assert!(!circle_on_screen(DVec2::new(-6.0, 400.0), 5.0, VIEW));
        assert!(!circle_on_screen(DVec2::new(640.0, 806.0), 5.0, VIEW));
        assert!(circle_on_screen(DVec2::new(1284.0, 804.0), 5.0, VIEW));
    }

    #[test]
    fn short_or_off_screen_arrows_are_not_drawn() {
        let at = DVec2::new(100.0, 100.0);
        assert!(!arrow_readable(at, at + DVec2::new(3.0, 0.0), VIEW));
        assert!(arrow_readable(at, at + DVec2::new(3.0, 3.0), VIEW));
        assert!(!arrow_readable(at, DVec2::new(f64::NAN, 0.0), VIEW));
        // Off screen entirely, or crossing the screen from outside.
        let left = DVec2::new(-50.0, 100.0);
        assert!(!arrow_readable(left, left + DVec2::new(-30.0, 0.0), VIEW));
        assert!(arrow_readable(left, left + DVec2::new(80.0, 0.0), VIEW));
    }

    fn rect_of(p: &Placement) -> [f64; 4] {
        p.rect
    }

    #[test]
    fn segments_and_circles_against_rectangles() {
        let r = [10.0, 10.0, 20.0, 10.0];
        assert!(rect_hits_circle(r, DVec2::new(5.0, 15.0), 6.0));
        assert!(!rect_hits_circle(r, DVec2::new(5.0, 15.0), 4.0));
        assert!(
            rect_hits_segment(r, DVec2::new(0.0, 0.0), DVec2::new(40.0, 40.0), 0.0),
            "crosses"
        );
        assert!(
            !rect_hits_segment(r, DVec2::new(0.0, 0.0), DVec2::new(40.0, 0.0), 0.0),
            "above"
        );
        assert!(
            rect_hits_segment(r, DVec2::new(0.0, 8.0), DVec2::new(40.0, 8.0), 3.0),
            "within the width"
        );
        assert!(
            rect_hits_segment(r, DVec2::new(15.0, 12.0), DVec2::new(16.0, 13.0), 0.0),
            "inside"
        );
    }

    #[test]
    fn a_label_covers_neither_its_arrow_nor_the_disc_it_touches() {
        // Two discs touching at the instant of impact, the selected one on
        // the left with its velocity arrow pointing right, through the other.
        let world = (DVec2::ZERO, DVec2::new(1000.0, 700.0));
        let (a, b, r) = (DVec2::new(400.0, 350.0), DVec2::new(480.0, 350.0), 40.0);
        let mut obstacles = Obstacles::new(100.0);
        obstacles.add_circle(a, r);
        obstacles.add_circle(b, r);
        obstacles.add_segment(a, a + DVec2::new(200.0, 0.0), 4.0);
        obstacles.add_segment(b, b + DVec2::new(-100.0, 0.0), 4.0);
        let size = DVec2::new(220.0, 60.0);
        let placed = LabelPlacer::new(size);
        let p = place_label(a, r, size, &[6.0, 40.0], world, &obstacles, &placed).unwrap();
        assert!(!obstacles.hits(rect_of(&p)));
        assert!(
            !rect_hits_circle(p.rect, b, r),
            "{p:?} covers the other disc"
        );
        assert!(
            !rect_hits_segment(p.rect, a, a + DVec2::new(200.0, 0.0), 4.0),
            "{p:?} covers its arrow"
        );
        assert_eq!(p.leader, None, "room right beside the disc: no leader line");
        // With the sides above and below taken too, the left is what is free.
        let mut crowded = obstacles;
        crowded.add_circle(a + DVec2::new(0.0, -100.0), 60.0);
        crowded.add_circle(a + DVec2::new(0.0, 100.0), 60.0);
        let p = place_label(a, r, size, &[6.0, 40.0], world, &crowded, &placed).unwrap();
        assert!(p.rect[0] + p.rect[2] <= a.x - r, "{p:?}");
    }

    #[test]
    fn a_crowded_label_moves_out_on_a_leader_line_or_gives_up() {
        let world = (DVec2::ZERO, DVec2::new(400.0, 400.0));
        let c = DVec2::new(200.0, 200.0);
        let mut obstacles = Obstacles::new(50.0);
        // A ring of discs right round the disc.
        for k in 0..16 {
            let t = k as f64 / 16.0 * std::f64::consts::TAU;
            obstacles.add_circle(c + DVec2::new(t.cos(), t.sin()) * 40.0, 16.0);
        }
        let size = DVec2::new(60.0, 20.0);
        let placed = LabelPlacer::new(size);
        let p = place_label(c, 20.0, size, &[6.0, 60.0], world, &obstacles, &placed).unwrap();
        let (from, to) = p.leader.expect("away from the disc: a leader line");
        assert!(
            (from.distance(c) - 20.0).abs() < 1e-9,
            "starts at the disc's edge"
        );
        assert!(to.x >= p.rect[0] - 1e-9 && to.x <= p.rect[0] + p.rect[2] + 1e-9);
        assert!(place_label(c, 20.0, size, &[6.0], world, &obstacles, &placed).is_none());
        let tiny = (DVec2::new(150.0, 150.0), DVec2::new(250.0, 250.0));
        assert!(
            place_label(c, 20.0, size, &[6.0, 60.0], tiny, &obstacles, &placed).is_none(),
            "outside the world"
        );
    }

    /// Beside a projector's drawer the world is little wider than a label:
    /// with no room right of the disc nor centred over it, the label slides
    /// along above it, inside, on a leader line (it went under the drawer).
    #[test]
    fn a_label_with_no_room_beside_its_disc_slides_back_inside() {
        let world = (DVec2::new(0.0, 60.0), DVec2::new(862.0, 440.0));
        let (c, r) = (DVec2::new(247.0, 240.0), 25.0);
        let mut obstacles = Obstacles::new(142.0);
        obstacles.add_circle(c, r);
        let size = DVec2::new(615.0, 142.0);
        let placed = LabelPlacer::new(size);
        let gaps = [6.0, 30.0];
        let p = place_label(c, r, size, &gaps, world, &obstacles, &placed).expect("a place");
        let [x, y, w, h] = p.rect;
        let (lo, hi) = world;
        assert!(
            x >= lo.x && y >= lo.y && x + w <= hi.x && y + h <= hi.y,
            "{p:?}"
        );
        assert!(!rect_hits_circle(p.rect, c, r), "{p:?} covers its disc");
        assert!(p.leader.is_some(), "slid along: a leader line");
        // Where it fits as it is, it is not slid.
        let wide = (lo, DVec2::new(1280.0, 440.0));
        let p = place_label(c, r, size, &gaps, wide, &obstacles, &placed).unwrap();
        assert_eq!(p.rect[0], c.x + r + 6.0, "right beside the disc");
        assert_eq!(p.leader, None);
    }

    #[test]
    fn labels_never_overlap() {
        let mut placer = LabelPlacer::new(DVec2::new(100.0, 40.0));
        assert!(placer.try_place([0.0, 0.0, 100.0, 40.0]));
        assert!(
            !placer.try_place([99.0, 39.0, 100.0, 40.0]),
            "one pixel over"
        );
        assert!(placer.try_place([100.0, 0.0, 100.0, 40.0]), "side by side");
        assert!(placer.try_place([0.0, 40.0, 250.0, 40.0]), "below, wider");
        assert!(
            !placer.try_place([150.0, 60.0, 10.0, 10.0]),
            "inside the wide one"
        );
        assert!(
            placer.try_place([-500.0, -500.0, 10.0, 10.0]),
            "negative cells"
        );
        assert_eq!(placer.count, 4);
    }
}
