//! Keyboard and mouse: every binding the help overlay lists lives here.

use super::interaction::{Gesture, Released};
use super::{draw, scenes, App};
use glam::DVec2;
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::{Method, Setting};
use macroquad::prelude::*;

/// Zoom factor per wheel notch or key press.
const ZOOM_STEP: f64 = 1.15;
/// Keyboard pan speed, pixels per frame.
const PAN_PIXELS: f64 = 12.0;
/// A press that moves less than this is a click, not a drag.
const CLICK_SLOP_PIXELS: f64 = 4.0;
/// A press this close (px) to the selected disc's velocity arrow tip drags the tip.
const ARROW_TIP_PIXELS: f64 = 10.0;
/// Gravity G switches on (m/s², downwards).
const EARTH_GRAVITY: f64 = 9.81;

/// Whether a modifier was down at any moment of this frame: held, pressed
/// or released. At a low frame rate a quick Ctrl+Q can press and release
/// Ctrl, or release it together with Q, within one frame.
fn held_or_pressed(keys: [KeyCode; 2]) -> bool {
    keys.into_iter()
        .any(|k| is_key_down(k) || is_key_pressed(k) || is_key_released(k))
}

fn shift() -> bool {
    held_or_pressed([KeyCode::LeftShift, KeyCode::RightShift])
}

fn ctrl() -> bool {
    held_or_pressed([KeyCode::LeftControl, KeyCode::RightControl])
}

/// `e` moved by one tenth up or down, kept in [0, 1].
fn nudge_restitution(e: f64, up: bool) -> f64 {
    let tenths = (e * 10.0).round() + if up { 1.0 } else { -1.0 };
    (tenths / 10.0).clamp(0.0, 1.0)
}

pub(super) const METHODS: [Setting<Method>; 5] = [
    Setting::Auto,
    Setting::Fixed(Method::Seed),
    Setting::Fixed(Method::Impulse),
    Setting::Fixed(Method::Verlet),
    Setting::Fixed(Method::Exact),
];
pub(super) const BROAD_PHASES: [Setting<BroadPhaseKind>; 5] = [
    Setting::Auto,
    Setting::Fixed(BroadPhaseKind::Brute),
    Setting::Fixed(BroadPhaseKind::Grid),
    Setting::Fixed(BroadPhaseKind::Sap),
    Setting::Fixed(BroadPhaseKind::Quadtree),
];
pub(super) const SUBSTEPS: [Setting<u32>; 6] = [
    Setting::Auto,
    Setting::Fixed(1),
    Setting::Fixed(2),
    Setting::Fixed(4),
    Setting::Fixed(8),
    Setting::Fixed(16),
];

/// The entry after `current` in `list` (the first if `current` is not in it).
fn cycle<T: PartialEq + Copy>(list: &[T], current: T) -> T {
    let next = list.iter().position(|&x| x == current).map_or(0, |k| k + 1);
    list[next % list.len()]
}

impl App {
    pub(super) fn handle_keys(&mut self) {
        if ctrl() && is_key_pressed(KeyCode::Q) {
            self.quit = true;
            return;
        }
        if self.ui.typing {
            return; // the keys went into a text field (Ctrl+Z too: its own undo)
        }
        if ctrl() {
            // Letter and digit shortcuts act only while Ctrl is up.
            self.handle_ctrl_keys();
            return;
        }
        if self.ui.panel_keyboard {
            // After Enter in a field the keyboard stays with the panel until
            // a click in the world or Esc.
            if is_key_pressed(KeyCode::Escape) {
                self.ui.panel_keyboard = false;
                self.toast("Keys act on the world again");
            }
            return;
        }
        if self.answer_recovery_offer() {
            return;
        }
        if is_key_pressed(KeyCode::Space) {
            self.clock.paused = !self.clock.paused;
        }
        if is_key_pressed(KeyCode::N) && !ctrl() {
            self.clock.single_step();
        }
        if is_key_pressed(KeyCode::LeftBracket) {
            self.clock.change_time_scale(-1);
            self.toast(format!("Time scale x{}", self.clock.time_scale()));
        }
        if is_key_pressed(KeyCode::RightBracket) {
            self.clock.change_time_scale(1);
            self.toast(format!("Time scale x{}", self.clock.time_scale()));
        }
        self.handle_view_keys();
        self.handle_overlay_keys();
        self.handle_world_keys();
        self.handle_scene_keys();
        self.handle_lesson_keys();
    }

    /// Ctrl+Z undo, Ctrl+Shift+Z and Ctrl+Y redo, Ctrl+S save, Ctrl+N the
    /// empty box.
    fn handle_ctrl_keys(&mut self) {
        if is_key_pressed(KeyCode::Z) {
            if shift() {
                self.redo_change();
            } else {
                self.undo_change();
            }
        }
        if is_key_pressed(KeyCode::Y) {
            self.redo_change();
        }
        if is_key_pressed(KeyCode::S) {
            let _ = self.save_scene(); // reported in the window and on the terminal
        }
        if is_key_pressed(KeyCode::N) {
            self.open_preset(scenes::PRESETS.len() - 1);
        }
    }

    fn handle_scene_keys(&mut self) {
        const DIGITS: [KeyCode; 10] = [
            KeyCode::Key1,
            KeyCode::Key2,
            KeyCode::Key3,
            KeyCode::Key4,
            KeyCode::Key5,
            KeyCode::Key6,
            KeyCode::Key7,
            KeyCode::Key8,
            KeyCode::Key9,
            KeyCode::Key0,
        ];
        if let Some(k) = DIGITS.iter().position(|&key| is_key_pressed(key)) {
            self.ui.presets_open = false;
            self.open_preset(k);
        }
        if is_key_pressed(KeyCode::P) {
            self.ui.presets_open = !self.ui.presets_open;
        }
    }

    fn handle_view_keys(&mut self) {
        let centre = self.camera.screen_center();
        if is_key_pressed(KeyCode::Equal) || is_key_pressed(KeyCode::KpAdd) {
            self.camera.zoom_at(centre, ZOOM_STEP);
            self.camera_fitted = false;
        }
        if is_key_pressed(KeyCode::Minus) || is_key_pressed(KeyCode::KpSubtract) {
            self.camera.zoom_at(centre, 1.0 / ZOOM_STEP);
            self.camera_fitted = false;
        }
        if is_key_pressed(KeyCode::F) {
            self.fit_camera();
        }
        let mut pan = DVec2::ZERO;
        for (key, dir) in [
            (KeyCode::Left, DVec2::X),
            (KeyCode::Right, -DVec2::X),
            (KeyCode::Up, DVec2::Y),
            (KeyCode::Down, -DVec2::Y),
        ] {
            if is_key_down(key) {
                pan += dir * PAN_PIXELS;
            }
        }
        if pan != DVec2::ZERO {
            self.camera.pan_pixels(pan);
            self.camera_fitted = false;
        }
        if is_key_pressed(KeyCode::F11) {
            self.toggle_fullscreen();
        }
    }

    pub(super) fn toggle_fullscreen(&mut self) {
        self.fullscreen = !self.fullscreen;
        set_fullscreen(self.fullscreen);
    }

    fn handle_overlay_keys(&mut self) {
        let o = &mut self.overlays;
        if is_key_pressed(KeyCode::V) {
            o.velocity = !o.velocity;
        }
        if is_key_pressed(KeyCode::M) {
            o.momentum = !o.momentum;
        }
        if is_key_pressed(KeyCode::I) {
            o.readouts = o.readouts.next();
        }
        let ui = &mut self.ui;
        if is_key_pressed(KeyCode::Tab) {
            ui.docks_open = !ui.docks_open;
        }
        if is_key_pressed(KeyCode::H) || is_key_pressed(KeyCode::F1) {
            ui.help_open = !ui.help_open;
        }
        if is_key_pressed(KeyCode::L) {
            ui.side_open = !ui.side_open;
        }
        if is_key_pressed(KeyCode::Escape) {
            if ui.presets_open {
                ui.presets_open = false;
            } else if ui.help_open {
                ui.help_open = false;
            } else {
                self.selected = None;
                self.gesture = Default::default();
            }
        }
    }

    fn handle_world_keys(&mut self) {
        if is_key_pressed(KeyCode::E) {
            self.remember("restitution");
            self.world.laws.restitution = nudge_restitution(self.world.laws.restitution, !shift());
            self.toast(format!(
                "Restitution e = {:.1}",
                self.world.laws.restitution
            ));
        }
        if is_key_pressed(KeyCode::W) {
            self.remember("wall restitution");
            self.world.laws.wall_restitution =
                nudge_restitution(self.world.laws.wall_restitution, !shift());
            self.toast(format!(
                "Wall restitution = {:.1}",
                self.world.laws.wall_restitution
            ));
        }
        if is_key_pressed(KeyCode::Y) {
            self.remember("method");
            self.world.method = cycle(&METHODS, self.world.method);
            self.toast(format!("Method: {}", self.world.method));
        }
        if is_key_pressed(KeyCode::B) {
            self.remember("broad phase");
            self.world.broad_phase = cycle(&BROAD_PHASES, self.world.broad_phase);
            self.toast(format!("Broad phase: {}", self.world.broad_phase));
        }
        if is_key_pressed(KeyCode::K) {
            self.remember("substeps");
            self.world.substeps = cycle(&SUBSTEPS, self.world.substeps);
            self.toast(format!("Substeps: {}", self.world.substeps));
        }
        if is_key_pressed(KeyCode::G) {
            self.remember("gravity");
            self.world.laws.gravity = if self.world.laws.gravity == DVec2::ZERO {
                DVec2::new(0.0, -EARTH_GRAVITY)
            } else {
                DVec2::ZERO
            };
            self.toast(format!(
                "Gravity {:.2} m/s²",
                self.world.laws.gravity.length()
            ));
        }
        if is_key_pressed(KeyCode::PageUp) || is_key_pressed(KeyCode::PageDown) {
            let factor = if is_key_pressed(KeyCode::PageUp) {
                1.25
            } else {
                0.8
            };
            let biggest = 0.45 * self.world.laws.size.min_element();
            self.new_disc.radius = (self.new_disc.radius * factor).clamp(0.01, biggest);
            self.toast(format!("New discs: radius {:.2} m", self.new_disc.radius));
        }
        if is_key_pressed(KeyCode::Home) || is_key_pressed(KeyCode::End) {
            let factor = if is_key_pressed(KeyCode::Home) {
                2.0
            } else {
                0.5
            };
            self.new_disc.mass = (self.new_disc.mass * factor).clamp(1e-3, 1e6);
            self.toast(format!("New discs: mass {:.3} kg", self.new_disc.mass));
        }
        if is_key_pressed(KeyCode::Delete) || is_key_pressed(KeyCode::Backspace) {
            self.delete_selected();
        }
        if is_key_pressed(KeyCode::C) && !ctrl() {
            self.clear_discs();
        }
        if is_key_pressed(KeyCode::R) {
            self.reset_scene();
        }
    }

    /// The disc a launch makes now: with "size follows mass", its radius
    /// from its mass.
    pub(super) fn new_disc_now(&self) -> super::interaction::NewDisc {
        let mut d = self.new_disc;
        if self.size_follows_mass {
            let biggest = 0.45 * self.world.laws.size.min_element();
            d.radius = super::interaction::radius_for_mass(d.mass).min(biggest);
        }
        d
    }

    /// Removes every disc.
    pub(super) fn clear_discs(&mut self) {
        self.remember("clear");
        self.world.particles.clear();
        self.forget_past();
        self.selected = None;
        self.gesture = Default::default();
        self.toast("Cleared: drag on empty space to launch discs");
    }

    /// Two or more fingers on a touch screen pan and zoom (the first
    /// finger alone is a mouse: a drag launches a disc). While they are
    /// down, whatever the first finger began is dropped.
    pub(super) fn handle_touches(&mut self) {
        let fingers: Vec<DVec2> = touches()
            .iter()
            .filter(|t| {
                matches!(
                    t.phase,
                    TouchPhase::Started | TouchPhase::Moved | TouchPhase::Stationary
                )
            })
            .map(|t| DVec2::new(f64::from(t.position.x), f64::from(t.position.y)))
            .collect();
        if fingers.len() >= 2 {
            let now = [fingers[0], fingers[1]];
            if let Some(before) = self.pinch {
                self.camera.pinch(before, now);
                self.camera_fitted = false;
            }
            self.pinch = Some(now);
            self.gesture = Gesture::Idle;
            self.press_moment = None;
        } else if self.pinch.is_some() && fingers.is_empty() {
            self.pinch = None;
        }
    }

    /// Whether two fingers are panning and zooming (mouse gestures wait).
    pub(super) fn pinching(&self) -> bool {
        self.pinch.is_some()
    }

    pub(super) fn handle_mouse(&mut self, mouse: DVec2) {
        let at = self.camera.screen_to_world(mouse);
        let now = get_time();
        // Over a panel or popup the mouse belongs to its widgets: no zoom,
        // pan or new gesture there (one begun in the world finishes).
        let on_panel = self.ui.pointer_on_ui;

        let (_, wheel) = mouse_wheel();
        if wheel != 0.0 && !on_panel {
            let notches = f64::from(wheel.clamp(-5.0, 5.0)).signum();
            self.camera.zoom_at(mouse, ZOOM_STEP.powf(notches));
            self.camera_fitted = false;
        }
        let panning =
            is_mouse_button_down(MouseButton::Right) || is_mouse_button_down(MouseButton::Middle);
        let just_started = is_mouse_button_pressed(MouseButton::Right)
            || is_mouse_button_pressed(MouseButton::Middle);
        if panning && !just_started && !on_panel {
            self.camera.pan_pixels(mouse - self.last_mouse);
            self.camera_fitted = false;
        }

        if is_mouse_button_pressed(MouseButton::Left) {
            if !on_panel {
                // A click in the world takes the keyboard back from a panel,
                // and what the press may change can be undone.
                self.ui.panel_keyboard = false;
                self.press_moment = Some(self.moment());
                let slop = CLICK_SLOP_PIXELS / self.camera.scale;
                let tip = self
                    .selected
                    .filter(|_| self.overlays.velocity)
                    .and_then(|i| {
                        let p = self.world.particles.get(i)?;
                        let centre = self.camera.world_to_screen(p.pos);
                        let offset = self.camera.vector_to_screen(p.vel * draw::ARROW_SECONDS);
                        Gesture::near_tip(mouse, centre, offset, ARROW_TIP_PIXELS).then_some(i)
                    });
                match tip {
                    Some(i) => self.gesture.press_arrow_tip(i, draw::ARROW_SECONDS),
                    None => self.selected = self.gesture.press(&self.world, at, now, slop),
                }
            }
        } else if is_mouse_button_down(MouseButton::Left) {
            self.gesture.drag(&mut self.world, at, now);
        }
        if is_mouse_button_released(MouseButton::Left) {
            // The cursor may have moved since the last frame: follow it first.
            self.gesture.drag(&mut self.world, at, now);
            let before = self.press_moment.take();
            let new_disc = self.new_disc_now();
            let released = self.gesture.release(&mut self.world, at, new_disc);
            let what = match released {
                Released::Launched(_) => Some("launch"),
                Released::Flung(..) => Some("fling"),
                Released::Aimed(..) => Some("set a velocity"),
                Released::NoRoom | Released::Nothing => None,
            };
            if let (Some(what), Some(before)) = (what, before) {
                self.undo.remember(|| before, what, get_time());
                self.scene_edited = true;
            }
            match released {
                Released::Launched(i) => self.selected = Some(i),
                Released::NoRoom => self.toast("No room for a new disc here"),
                Released::Aimed(i, v) => {
                    self.toast(format!(
                        "Disc {i}: velocity set to ({:+.2}, {:+.2}) m/s",
                        v.x, v.y
                    ));
                }
                Released::Flung(..) | Released::Nothing => {}
            }
        }
        self.last_mouse = mouse;
    }
}

#[cfg(test)]
mod tests {
    use super::nudge_restitution;

    #[test]
    fn restitution_moves_in_tenths_within_bounds() {
        assert_eq!(nudge_restitution(0.5, true), 0.6);
        assert_eq!(nudge_restitution(1.0, true), 1.0);
        assert_eq!(nudge_restitution(0.0, false), 0.0);
        assert_eq!(nudge_restitution(0.33, false), 0.2);
    }
}
