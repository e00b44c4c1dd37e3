//! The world↔screen transform: pan, zoom at a point, fit the box.
//!
//! World coordinates are metres with y up; screen coordinates are pixels with
//! y down. Every hit test, arrow and label goes through this one transform,
//! so they stay right at every zoom (the seeds' grab areas did not).

use glam::DVec2;

/// Smallest and largest zoom, in pixels per metre.
pub const SCALE_LIMITS: (f64, f64) = (1e-3, 1e6);

/// Maps world points to screen pixels and back.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// World point shown at the centre of the viewport (m).
    pub center: DVec2,
    /// Zoom: pixels per metre.
    pub scale: f64,
    /// Size of the world's rectangle on screen (px): the part of the window
    /// the docked panels leave free.
    pub viewport: DVec2,
    /// Top-left corner of that rectangle in the window (px).
    pub origin: DVec2,
}

impl Camera {
    /// A camera showing the whole box `size` in `viewport`, leaving `margin`
    /// pixels free on every side.
    pub fn fitting(size: DVec2, viewport: DVec2, margin: f64) -> Self {
        let mut camera = Camera {
            center: DVec2::ZERO,
            scale: 1.0,
            viewport,
            origin: DVec2::ZERO,
        };
        camera.fit(size, margin);
        camera
    }

    /// Shows the whole box again.
    pub fn fit(&mut self, size: DVec2, margin: f64) {
        self.fit_rect(DVec2::ZERO, size, margin);
    }

    /// Shows the world rectangle `lo`–`hi` whole, centred.
    pub fn fit_rect(&mut self, lo: DVec2, hi: DVec2, margin: f64) {
        self.fit_rect_beside(lo, hi, margin, 0.0);
    }

    /// Shows the world rectangle `lo`–`hi` whole, centred in what is left
    /// of the viewport when `covered` pixels at its right are under
    /// something (a drawer open over the world).
    pub fn fit_rect_beside(&mut self, lo: DVec2, hi: DVec2, margin: f64, covered: f64) {
        let covered = covered.clamp(0.0, (self.viewport.x - 1.0).max(0.0));
        let clear = self.viewport - DVec2::new(covered, 0.0);
        let room = (clear - DVec2::splat(2.0 * margin)).max(DVec2::ONE);
        let size = (hi - lo).max(DVec2::splat(1e-9));
        self.scale = (room / size)
            .min_element()
            .clamp(SCALE_LIMITS.0, SCALE_LIMITS.1);
        // The box's middle at the clear part's middle, half the covered
        // width left of the viewport's.
        self.center = 0.5 * (lo + hi) + DVec2::new(0.5 * covered / self.scale, 0.0);
    }

    /// Moves the world's rectangle to `origin` with size `size` (px),
    /// keeping the world point at its centre.
    pub fn set_rect(&mut self, origin: DVec2, size: DVec2) {
        self.origin = origin;
        self.viewport = size.max(DVec2::ONE);
    }

    /// The world's rectangle on screen: top-left and bottom-right corners (px).
    pub fn screen_rect(&self) -> (DVec2, DVec2) {
        (self.origin, self.origin + self.viewport)
    }

    /// The centre of the world's rectangle on screen (px).
    pub fn screen_center(&self) -> DVec2 {
        self.origin + 0.5 * self.viewport
    }

    /// Screen pixel of a world point.
    pub fn world_to_screen(&self, world: DVec2) -> DVec2 {
        let d = (world - self.center) * self.scale;
        self.screen_center() + DVec2::new(d.x, -d.y)
    }

    /// World point under a screen pixel.
    pub fn screen_to_world(&self, screen: DVec2) -> DVec2 {
        let d = screen - self.screen_center();
        self.center + DVec2::new(d.x, -d.y) / self.scale
    }

    /// A world length in pixels.
    pub fn length_in_pixels(&self, metres: f64) -> f64 {
        metres * self.scale
    }

    /// A world vector (y up) as a screen vector (y down), in pixels.
    pub fn vector_to_screen(&self, world: DVec2) -> DVec2 {
        DVec2::new(world.x, -world.y) * self.scale
    }

    /// Multiplies the zoom by `factor`, keeping the world point under
    /// `screen_anchor` where it is on screen.
    pub fn zoom_at(&mut self, screen_anchor: DVec2, factor: f64) {
        let anchored = self.screen_to_world(screen_anchor);
        self.scale = (self.scale * factor).clamp(SCALE_LIMITS.0, SCALE_LIMITS.1);
        let drifted = self.screen_to_world(screen_anchor);
        self.center += anchored - drifted;
    }

    /// Moves the view so that the scene follows a drag of `pixels`.
    pub fn pan_pixels(&mut self, pixels: DVec2) {
        self.center -= DVec2::new(pixels.x, -pixels.y) / self.scale;
    }

    /// Two fingers moved from `before` to `after` (screen px): the scene
    /// follows their midpoint and scales with their distance, so the world
    /// point between them stays between them.
    pub fn pinch(&mut self, before: [DVec2; 2], after: [DVec2; 2]) {
        let (mid_before, mid_after) = ((before[0] + before[1]) / 2.0, (after[0] + after[1]) / 2.0);
        let (d_before, d_after) = (before[0].distance(before[1]), after[0].distance(after[1]));
        self.pan_pixels(mid_after - mid_before);
        if d_before > 1.0 && d_after > 1.0 {
            self.zoom_at(mid_after, d_after / d_before);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera::fitting(DVec2::new(16.0, 10.0), DVec2::new(1280.0, 800.0), 40.0)
    }

    #[test]
    fn a_pinch_keeps_the_point_between_the_fingers_and_scales_with_them() {
        let mut c = camera();
        let before = [DVec2::new(500.0, 400.0), DVec2::new(700.0, 400.0)];
        let held = c.screen_to_world(DVec2::new(600.0, 400.0));
        let scale = c.scale;
        // Apart to twice the distance, and the pair moved right and down.
        let after = [DVec2::new(450.0, 450.0), DVec2::new(850.0, 450.0)];
        c.pinch(before, after);
        assert!((c.scale - 2.0 * scale).abs() < 1e-9);
        let now = c.world_to_screen(held);
        assert!((now - DVec2::new(650.0, 450.0)).length() < 1e-9, "{now}");
        // Fingers on one spot change nothing but the pan.
        let spot = [DVec2::new(10.0, 10.0); 2];
        let s = c.scale;
        c.pinch(spot, spot);
        assert_eq!(c.scale, s);
    }

    #[test]
    fn screen_and_world_round_trip_with_y_flipped() {
        let c = camera();
        let w = DVec2::new(3.0, 7.5);
        let s = c.world_to_screen(w);
        assert!((c.screen_to_world(s) - w).length() < 1e-12);
        let higher = c.world_to_screen(w + DVec2::Y);
        assert!(higher.y < s.y, "world up is screen up");
    }

    #[test]
    fn fit_shows_the_whole_box_inside_the_margin() {
        let c = camera();
        for corner in [DVec2::ZERO, DVec2::new(16.0, 10.0)] {
            let s = c.world_to_screen(corner);
            assert!(s.x >= 40.0 - 1e-9 && s.x <= 1240.0 + 1e-9, "{s}");
            assert!(s.y >= 40.0 - 1e-9 && s.y <= 760.0 + 1e-9, "{s}");
        }
    }

    #[test]
    fn a_world_rectangle_inside_the_window_is_fitted_and_mapped() {
        let mut c = camera();
        c.set_rect(DVec2::new(0.0, 40.0), DVec2::new(960.0, 560.0));
        c.fit(DVec2::new(16.0, 10.0), 30.0);
        let (a, b) = (
            c.world_to_screen(DVec2::new(0.0, 10.0)),
            c.world_to_screen(DVec2::new(16.0, 0.0)),
        );
        // 500 px of height for 10 m: 50 px/m, so 800 px for 16 m, centred.
        assert!((c.scale - 50.0).abs() < 1e-9, "{}", c.scale);
        assert!(
            (a.y - 70.0).abs() < 1e-9 && (b.y - 570.0).abs() < 1e-9,
            "{a} {b}"
        );
        assert!(
            (a.x - 80.0).abs() < 1e-9 && (b.x - 880.0).abs() < 1e-9,
            "{a} {b}"
        );
        let p = DVec2::new(123.0, 456.0);
        assert!((c.world_to_screen(c.screen_to_world(p)) - p).length() < 1e-9);
        assert_eq!(
            c.screen_rect(),
            (DVec2::new(0.0, 40.0), DVec2::new(960.0, 600.0))
        );
    }

    #[test]
    fn zoom_keeps_the_point_under_the_cursor() {
        let mut c = camera();
        let cursor = DVec2::new(900.0, 200.0);
        let before = c.screen_to_world(cursor);
        for factor in [1.1, 1.1, 3.0, 0.2, 1e9, 1e-12] {
            c.zoom_at(cursor, factor);
            assert!((c.screen_to_world(cursor) - before).length() < 1e-9 * (1.0 + before.length()));
        }
        assert_eq!(c.scale, SCALE_LIMITS.0, "zoom is clamped");
    }

    #[test]
    fn pan_moves_the_scene_with_the_drag() {
        let mut c = camera();
        let w = DVec2::new(5.0, 5.0);
        let s0 = c.world_to_screen(w);
        c.pan_pixels(DVec2::new(30.0, -12.0));
        assert!((c.world_to_screen(w) - (s0 + DVec2::new(30.0, -12.0))).length() < 1e-9);
    }

    /// Beside a drawer over its right part, the box is fitted whole into
    /// the rest, centred there; with nothing over it, as before.
    #[test]
    fn a_box_fitted_beside_a_drawer_lies_wholly_left_of_it() {
        let mut c = Camera::fitting(DVec2::new(20.0, 10.0), DVec2::new(1000.0, 400.0), 24.0);
        let plain = c;
        c.fit_rect_beside(DVec2::ZERO, DVec2::new(20.0, 10.0), 24.0, 420.0);
        let (left, right) = (
            c.world_to_screen(DVec2::ZERO),
            c.world_to_screen(DVec2::new(20.0, 10.0)),
        );
        assert!((left.x - 24.0).abs() < 1e-9, "{left}");
        assert!((right.x - (1000.0 - 420.0 - 24.0)).abs() < 1e-9, "{right}");
        assert!(right.y >= 24.0 - 1e-9 && left.y <= 400.0 - 24.0 + 1e-9);
        c.fit_rect_beside(DVec2::ZERO, DVec2::new(20.0, 10.0), 24.0, 0.0);
        assert_eq!(c, plain);
    }
}
