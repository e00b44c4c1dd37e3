//! The mouse and a finger on the world, as commands in window pixels: a
//! press selects, grabs a disc, takes the selected disc's arrow tip or
//! starts a launch; a release finishes it. Only a release that changed the
//! discs (a launch, a fling, an aim) is remembered for undo and marks the
//! scene edited; a click only selects. Also the camera: zoom, fit, and
//! the world's rectangle from the layout.

use super::gesture::{Gesture, Released};
use super::overlays::ARROW_SECONDS;
use super::undo::Moment;
use super::Sandbox;
use glam::DVec2;

/// A press that moves less than this is a click, not a drag.
pub const CLICK_SLOP_PIXELS: f64 = 4.0;
/// A press this close (px) to the selected disc's velocity arrow tip drags the tip.
pub const ARROW_TIP_PIXELS: f64 = 10.0;

/// The gesture in progress and the scene when it began (for undo).
#[derive(Clone, Default)]
pub struct Pointer {
    pub gesture: Gesture,
    /// The scene when the button went down, remembered for undo if the
    /// gesture changes it.
    press: Option<Moment>,
    /// Where the pointer is (window px), for the launch preview.
    pub at: DVec2,
}

impl Pointer {
    /// Drops whatever was in progress.
    pub fn cancel(&mut self) {
        self.gesture = Gesture::Idle;
        self.press = None;
    }

    /// Keeps indices right after disc `removed` was deleted.
    pub fn on_removed(&mut self, removed: usize) {
        self.gesture.on_removed(removed);
    }

    /// Puts a held disc back under the cursor (after a physics step).
    pub fn pin_held(&self, world: &mut impulse::World) {
        self.gesture.pin_held(world);
    }
}

impl Sandbox {
    pub(super) fn pointer_down(&mut self, at: DVec2) {
        let world_at = self.view.camera.screen_to_world(at);
        self.pointer.at = at;
        self.pointer.press = Some(self.moment());
        let slop = CLICK_SLOP_PIXELS / self.view.camera.scale;
        let camera = &self.view.camera;
        // The tip is taken unless another disc lies under the pointer: a
        // click on that disc selects it.
        let under = self.world.particle_at(world_at);
        let tip = self
            .selected
            .filter(|&i| self.overlays.velocity && under.is_none_or(|j| j == i))
            .and_then(|i| {
                let p = self.world.particles.get(i)?;
                let centre = camera.world_to_screen(p.pos);
                let offset = camera.vector_to_screen(p.vel * ARROW_SECONDS);
                Gesture::near_tip(at, centre, offset, ARROW_TIP_PIXELS).then_some(i)
            });
        let now = self.session.now;
        match tip {
            Some(i) => {
                let press = (world_at, slop);
                self.pointer
                    .gesture
                    .press_arrow_tip(&self.world, i, ARROW_SECONDS, press)
            }
            None => {
                self.selected = self.pointer.gesture.press(&self.world, world_at, now, slop);
                if self.selected.is_some() {
                    self.panels.picks = self.panels.picks.wrapping_add(1);
                }
            }
        }
    }

    pub(super) fn pointer_move(&mut self, at: DVec2) {
        self.pointer.at = at;
        let world_at = self.view.camera.screen_to_world(at);
        let now = self.session.now;
        self.pointer.gesture.drag(&mut self.world, world_at, now);
    }

    pub(super) fn pointer_up(&mut self, at: DVec2) {
        // The cursor may have moved since the last frame: follow it first.
        self.pointer_move(at);
        let world_at = self.view.camera.screen_to_world(at);
        let before = self.pointer.press.take();
        let new_disc = self.new_disc_now();
        let released = self
            .pointer
            .gesture
            .release(&mut self.world, world_at, new_disc);
        let what = match released {
            Released::Launched(_) => Some("edit-launch"),
            Released::Flung(..) => Some("edit-fling"),
            Released::Aimed(..) => Some("edit-aim"),
            Released::Clicked(_) | Released::NoRoom | Released::Nothing => None,
        };
        if let (Some(what), Some(before)) = (what, before) {
            self.undo.remember(|| before, what, self.session.now);
            self.open.edited = true;
            self.open.unsaved = true;
            self.open.setup = Some(self.world.clone());
            // The totals the person changed: the Totals tab starts afresh
            // (as for the edits of `apply`).
            self.record.totals.restart(&self.world);
        }
        match released {
            Released::Launched(i) => self.selected = Some(i),
            Released::NoRoom => self.toast(crate::app::lang::tr!("no-room")),
            Released::Aimed(i, v) => {
                let velocity = crate::app::numbers::vector(v, 2, "m/s");
                self.toast(crate::app::lang::tr!(
                    "aimed",
                    disc = crate::app::numbers::disc_number(i),
                    velocity = velocity
                ));
            }
            Released::Flung(..) | Released::Clicked(_) | Released::Nothing => {}
        }
    }

    pub(super) fn zoom_at(&mut self, at: DVec2, factor: f64) {
        self.view.camera.zoom_at(at, factor);
        self.view.fitted = false;
    }

    /// Fits the box into the world's rectangle; in a box with open sides,
    /// the box and every disc that has left it.
    pub fn fit_camera(&mut self) {
        let margin = 24.0;
        let (mut lo, mut hi) = (DVec2::ZERO, self.world.laws.size);
        if self.follows_discs() {
            for p in self.world.particles.iter().filter(|p| p.pos.is_finite()) {
                lo = lo.min(p.pos - DVec2::splat(p.radius));
                hi = hi.max(p.pos + DVec2::splat(p.radius));
            }
        }
        if let Some((low, high)) = self.line_band() {
            (lo, hi) = (lo.max(low), hi.min(high));
        }
        let covered = self.view.covered;
        self.view.camera.fit_rect_beside(lo, hi, margin, covered);
        self.view.fitted = true;
    }

    /// In a one-dimensional world, the band along the discs' line that a
    /// fitted view shows, not the whole box (its walls along the line are
    /// not drawn and nothing reaches them): the line's length and, across
    /// it, every disc with room for its label (2 m, or three radii of the
    /// largest, each side). At 1366×768 at text size 2 the box's 10 m
    /// across had left the head-on discs 42 px wide in a world 348 px tall.
    fn line_band(&self) -> Option<(DVec2, DVec2)> {
        let along = self.world.laws.constrain?.index();
        let across = 1 - along;
        let discs = || self.world.particles.iter().filter(|p| p.pos.is_finite());
        let low = discs().map(|p| p.pos[across] - p.radius).reduce(f64::min)?;
        let high = discs().map(|p| p.pos[across] + p.radius).reduce(f64::max)?;
        let biggest = discs().map(|p| p.radius).fold(0.0, f64::max);
        let middle = 0.5 * (low + high);
        let half = (0.5 * (high - low)).max(2.0).max(3.0 * biggest);
        let (mut lo, mut hi) = (DVec2::splat(f64::NEG_INFINITY), DVec2::splat(f64::INFINITY));
        (lo[across], hi[across]) = (middle - half, middle + half);
        Some((lo, hi))
    }

    /// Whether a fitted view follows the discs out of the box: a box with
    /// open sides (the π blocks leave through theirs).
    pub fn follows_discs(&self) -> bool {
        self.world.laws.boundary == impulse::Boundary::Box && !self.world.laws.walls.all()
    }

    /// Gives the camera the world's rectangle [x, y, w, h] (window px),
    /// with `covered` px at its right under the open drawer; a view that
    /// was fitted stays fitted when either changes, in what is in sight
    /// (the drawer had hidden the right half of the box, and in Glancing
    /// the disc hit).
    pub fn place_world(&mut self, [x, y, w, h]: [f32; 4], covered: f32) {
        let origin = DVec2::new(f64::from(x), f64::from(y));
        let size = DVec2::new(f64::from(w), f64::from(h)).max(DVec2::ONE);
        let covered = f64::from(covered).max(0.0);
        let camera = &mut self.view.camera;
        if origin != camera.origin || size != camera.viewport || covered != self.view.covered {
            camera.set_rect(origin, size);
            self.view.covered = covered;
            if self.view.fitted {
                self.fit_camera();
            }
        }
    }
}
