//! What is worth drawing: discs on screen, arrows long enough to read, and
//! readouts beside discs big enough to point at, never on top of each other.
//! Pure screen geometry (pixels, y down), so it is tested without a window.

use glam::DVec2;

/// Arrows shorter than this (px) are not drawn: a head alone says nothing.
pub const MIN_ARROW_PIXELS: f64 = 4.0;
/// Readouts of "all discs" are shown only beside discs at least this big
/// (radius, px); the selected disc's readout is always shown.
pub const MIN_LABEL_DISC_PIXELS: f64 = 4.0;
/// Discs are drawn at least this big (radius, px), so none vanishes.
pub const MIN_DISC_PIXELS: f64 = 1.0;

/// Whether a circle (centre and radius in px) touches the viewport.
pub fn circle_on_screen(center: DVec2, radius: f64, viewport: DVec2) -> bool {
    center.x + radius >= 0.0
        && center.y + radius >= 0.0
        && center.x - radius <= viewport.x
        && center.y - radius <= viewport.y
}

/// Whether an arrow from `from` to `to` (px) is long enough to read and
/// crosses the viewport (its bounding box touches it).
pub fn arrow_readable(from: DVec2, to: DVec2, viewport: DVec2) -> bool {
    let long_enough = from.distance(to) >= MIN_ARROW_PIXELS; // false for NaN
    if !long_enough {
        return false;
    }
    let (lo, hi) = (from.min(to), from.max(to));
    hi.x >= 0.0 && hi.y >= 0.0 && lo.x <= viewport.x && lo.y <= viewport.y
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

#[cfg(test)]
mod tests {
    use super::*;

    const VIEW: DVec2 = DVec2::new(1280.0, 800.0);

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
