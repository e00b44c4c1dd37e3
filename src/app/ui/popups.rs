//! What the user opens and closes, the only things allowed over the world:
//! the key list (H), the preset menu (P), and the question whether to
//! restore a session that did not close normally.

use super::Action;
use crate::app::{scenes, App};
use egui::{Align2, RichText};

/// Every key, as the help lists it, with the on-screen control that does
/// the same.
pub const HELP: &[(&str, &str)] = &[
    (
        "Left drag on empty space",
        "launch a new disc along the drag",
    ),
    (
        "Left drag on a disc",
        "grab and fling it (it keeps the mouse's velocity)",
    ),
    ("Drag the selected disc's arrow tip", "set its velocity"),
    ("Left click", "select a disc; on empty space, deselect"),
    ("Right or middle drag, arrow keys", "pan"),
    (
        "Wheel, + / −",
        "zoom at the cursor / at the centre (View: Zoom + / −)",
    ),
    ("F", "fit the box to the window (Fit view)"),
    ("Space", "pause / resume (Play / Pause)"),
    ("N", "one step, paused (Step)"),
    ("[ / ]", "slower / faster (« Slower, Faster »)"),
    ("V / M", "velocity / momentum arrows (Show)"),
    (
        "I",
        "values beside: none / the selected disc / every disc (Show)",
    ),
    ("O", "centre of mass and its velocity (Show)"),
    ("A", "path traces, a dot every 0.1 s (Show)"),
    ("F3", "colour-blind-safe colours (Show)"),
    (
        "Z",
        "centre-of-mass view on or off: the view moves with it (Show)",
    ),
    (
        "J",
        "run to the next collision and pause at impact (Show, Collisions tab)",
    ),
    (
        ", / .",
        "back / forward through the recorded past; Shift: ×10 (◀ Back, Forward ▶)",
    ),
    ("E / Shift+E", "restitution between discs ±0.1 (Collisions)"),
    ("W / Shift+W", "restitution at the walls ±0.1 (Collisions)"),
    ("G", "gravity on / off (Collisions)"),
    (
        "PgUp / PgDn, Home / End",
        "radius / mass of new discs (New discs)",
    ),
    (
        "Delete / Backspace",
        "delete the selected disc (Selected disc)",
    ),
    ("C", "clear all discs (Scene)"),
    ("R", "reset the scene (⟲ Reset)"),
    (
        "1 … 9, 0, P",
        "open a classroom preset / the preset menu (Presets…)",
    ),
    ("Ctrl+N", "a new empty box (Presets…: the last one)"),
    ("Ctrl+Z", "undo the last change to the scene (Undo)"),
    ("Ctrl+Shift+Z, Ctrl+Y", "redo it (Redo)"),
    (
        "Esc",
        "after Enter in a field: keys act on the world again (or click it)",
    ),
    ("Ctrl+S", "save the scene; it reopens exactly (Scene: Save)"),
    ("X", "export totals, discs and collisions as CSV (Scene)"),
    ("F12", "screenshot into the output folder (Scene)"),
    (
        "T / U / D / F4",
        "bottom dock: Totals / Collisions / Momenta / Speeds",
    ),
    (
        "Tab",
        "hide or show the panels; the top bar stays (View: Hide panels)",
    ),
    ("L", "hide or show the controls at the side"),
    ("F2", "text size 1.0 / 1.5 / 2.0 for a projector (View)"),
    ("Y / B / K", "method / broad phase / substeps (Details)"),
    ("F11", "full screen (View)"),
    ("H or F1, Esc", "this list; Esc closes it or deselects"),
    ("Ctrl+Q", "quit"),
];

impl App {
    /// The popups that are open.
    pub(super) fn popups(&mut self, ctx: &egui::Context, actions: &mut Vec<Action>) {
        let ppp = super::px_per_point(ctx);
        let screen = ctx.screen_rect();
        if self.ui.help_open {
            let mut open = true;
            egui::Window::new("Keys and mouse")
                .open(&mut open)
                .anchor(Align2::CENTER_CENTER, egui::Vec2::ZERO)
                .max_height(screen.height() * 0.8)
                .max_width(screen.width() * 0.9)
                .collapsible(false)
                .show(ctx, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        egui::Grid::new("help_grid")
                            .striped(true)
                            .num_columns(2)
                            .show(ui, |ui| {
                                for (keys, what) in HELP {
                                    // The browser keeps these keys for itself
                                    // (and has its own full-screen key).
                                    if cfg!(target_arch = "wasm32")
                                        && ["Ctrl+Q", "F11"].contains(keys)
                                    {
                                        continue;
                                    }
                                    ui.label(RichText::new(*keys).strong());
                                    ui.label(*what);
                                    ui.end_row();
                                }
                            });
                    });
                });
            self.ui.help_open = open;
        }
        if self.ui.presets_open {
            let mut open = true;
            let response = egui::Window::new("Presets")
                .open(&mut open)
                .anchor(Align2::CENTER_CENTER, egui::Vec2::ZERO)
                .max_height(screen.height() * 0.8)
                .collapsible(false)
                .show(ctx, |ui| {
                    ui.label("Press the key, or click:");
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        for (k, (preset, label)) in scenes::PRESETS
                            .iter()
                            .zip(scenes::preset_labels())
                            .enumerate()
                        {
                            let description = scenes::preset_description(k);
                            let r = ui.button(RichText::new(label.as_str()).strong());
                            self.ui.note_widget(format!("preset_{k}"), r.rect, ppp);
                            if r.clicked() {
                                actions.push(Action::OpenPreset(k));
                            }
                            let _ = preset;
                            if let Some(d) = description {
                                ui.label(d);
                            }
                            ui.add_space(4.0);
                        }
                    });
                });
            if let Some(r) = response {
                self.ui.note_widget("preset_menu", r.response.rect, ppp);
            }
            self.ui.presets_open = open;
        }
        if let Some(question) = self.recovery_prompt() {
            egui::Window::new("Restore the last session?")
                .anchor(Align2::CENTER_CENTER, egui::Vec2::ZERO)
                .collapsible(false)
                .resizable(false)
                .show(ctx, |ui| {
                    ui.add(egui::Label::new(question).wrap());
                    ui.horizontal(|ui| {
                        if ui.button("Restore (R)").clicked() {
                            actions.push(Action::RecoveryRestore);
                        }
                        if ui.button("Set it aside (Esc)").clicked() {
                            actions.push(Action::RecoverySetAside);
                        }
                    });
                });
        }
    }
}
