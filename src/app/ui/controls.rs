//! The side dock: the transport buttons (play, step, slower, faster, reset,
//! presets, help, fit) and, in collapsible sections that scroll when the
//! window is short, what the simulation does (Collisions), what is drawn
//! (Show), new discs, the selected disc, scene files, the view (UI scale,
//! theme) and the solver's Details, collapsed by default. Every keyboard
//! shortcut has a control here, its key in the tooltip.

use super::discs_table::{parse_disc_edit, FIELDS};
use super::numbers::{field, plain, with_unit};
use super::theme::{next_scale, Theme, UI_SCALE_RANGE};
use super::{show_note, Action, Note};
use crate::app::draw::ReadoutScope;
use crate::app::input::{BROAD_PHASES, METHODS, SUBSTEPS};
use crate::app::{scenes, App};
use egui::{CollapsingHeader, ComboBox, Slider, Ui};
use std::fmt::Display;

/// Earth's gravity, where the gravity slider sticks (m/s²).
pub const EARTH_GRAVITY: f64 = 9.81;

/// The gravity slider's value: tenths, sticking to 9.81 within 0.15.
pub fn snap_gravity(g: f64) -> f64 {
    if (g - EARTH_GRAVITY).abs() < 0.15 {
        EARTH_GRAVITY
    } else {
        (g * 10.0).round() / 10.0
    }
}

/// The selected disc's text fields in the side dock.
#[derive(Default)]
pub struct DiscFields {
    /// Which disc they were filled from.
    disc: Option<usize>,
    /// What the fields hold.
    text: [String; 4],
    /// What the disc had when a field was last filled: a field whose text
    /// differs has been edited and stops following the disc.
    shown: [String; 4],
    note: Option<Note>,
}

const FIELD_LABELS: [&str; 4] = ["mass (kg)", "radius (m)", "v_x (m/s)", "v_y (m/s)"];
const FIELD_KEYS: [&str; 4] = ["disc_mass", "disc_radius", "disc_vx", "disc_vy"];

/// A combo box over `list`, showing `current` even when it is not in the
/// list (a scene may ask for 3 substeps); returns the new choice.
pub(super) fn setting_combo<T: Copy + PartialEq + Display>(
    ui: &mut Ui,
    label: &str,
    list: &[T],
    current: T,
) -> Option<T> {
    let mut chosen = None;
    ComboBox::from_label(label)
        .selected_text(current.to_string())
        .show_ui(ui, |ui| {
            for &item in list {
                if ui
                    .selectable_label(item == current, item.to_string())
                    .clicked()
                {
                    chosen = Some(item);
                }
            }
        });
    chosen.filter(|&c| c != current)
}

/// A slider under its label, as wide as the dock allows, with its value
/// (and unit) in a box beside it that can also be dragged or typed into.
/// Returns the track's response, so its rectangle is the track's, and
/// whether the value changed.
pub(super) fn slider(
    ui: &mut Ui,
    label: &str,
    value: &mut f64,
    range: std::ops::RangeInclusive<f64>,
    log: bool,
    decimals: usize,
    suffix: &str,
) -> (egui::Response, bool) {
    ui.label(label);
    let value_box = 96.0;
    ui.spacing_mut().slider_width = (ui.available_width() - value_box).max(60.0);
    ui.horizontal(|ui| {
        let track = ui.add(
            Slider::new(value, range.clone())
                .logarithmic(log)
                .show_value(false),
        );
        let speed = if log {
            0.01 * *value
        } else {
            0.005 * (range.end() - range.start())
        };
        let boxed = ui.add(
            egui::DragValue::new(value)
                .range(range)
                .speed(speed)
                .fixed_decimals(decimals)
                .suffix(suffix),
        );
        let changed = track.changed() || boxed.changed();
        (track, changed)
    })
    .inner
}

impl App {
    /// Draws the side dock; returns its rectangle (points).
    pub(super) fn controls(
        &mut self,
        ctx: &egui::Context,
        actions: &mut Vec<Action>,
    ) -> egui::Rect {
        let width = (ctx.screen_rect().width() * 0.26).clamp(210.0, 290.0);
        let panel = egui::SidePanel::right("controls")
            .resizable(false)
            .exact_width(width)
            .show(ctx, |ui| {
                self.transport(ui, actions);
                ui.separator();
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui.set_width(ui.available_width());
                    let r = CollapsingHeader::new("Collisions")
                        .default_open(true)
                        .show(ui, |ui| self.laws_section(ui));
                    self.widget(ui, "section_collisions", &r.header_response);
                    let r = CollapsingHeader::new("Show")
                        .default_open(true)
                        .show(ui, |ui| self.show_section(ui, actions));
                    self.widget(ui, "section_show", &r.header_response);
                    let r =
                        CollapsingHeader::new("New discs").show(ui, |ui| self.new_disc_section(ui));
                    self.widget(ui, "section_new_discs", &r.header_response);
                    let title = match self.selected {
                        Some(i) if i < self.world.particles.len() => format!("Selected disc ({i})"),
                        _ => "Selected disc".to_string(),
                    };
                    let r = CollapsingHeader::new(title)
                        .id_salt("selected")
                        .show(ui, |ui| self.selected_section(ui, actions));
                    self.widget(ui, "section_selected", &r.header_response);
                    let r = CollapsingHeader::new("Scene")
                        .show(ui, |ui| self.scene_section(ui, actions));
                    self.widget(ui, "section_scene", &r.header_response);
                    let r =
                        CollapsingHeader::new("View").show(ui, |ui| self.view_section(ui, actions));
                    self.widget(ui, "section_view", &r.header_response);
                    let r = CollapsingHeader::new("Details")
                        .default_open(false)
                        .show(ui, |ui| self.details_section(ui));
                    self.widget(ui, "section_details", &r.header_response);
                });
            });
        panel.response.rect
    }

    pub(super) fn widget(&mut self, ui: &Ui, name: &str, response: &egui::Response) {
        self.ui
            .note_widget(name, response.rect, super::px_per_point(ui.ctx()));
    }

    /// Play or pause, step, slower, faster, reset, presets, help, fit.
    fn transport(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        ui.horizontal_wrapped(|ui| {
            let play = if self.clock.paused {
                "▶ Play"
            } else {
                "⏸ Pause"
            };
            let r = ui.button(play).on_hover_text("Space");
            self.widget(ui, "play", &r);
            if r.clicked() {
                self.clock.paused = !self.clock.paused;
            }
            let r = ui.button("Step").on_hover_text("N: one step, paused");
            self.widget(ui, "step", &r);
            if r.clicked() {
                self.clock.single_step();
            }
            if ui
                .button("⟲ Reset")
                .on_hover_text("R: the scene as it opened")
                .clicked()
            {
                actions.push(Action::Reset);
            }
            if ui.button("Undo").on_hover_text("Ctrl+Z").clicked() {
                actions.push(Action::Undo);
            }
            if ui
                .button("Redo")
                .on_hover_text("Ctrl+Shift+Z or Ctrl+Y")
                .clicked()
            {
                actions.push(Action::Redo);
            }
            if ui.button("« Slower").on_hover_text("[").clicked() {
                self.clock.change_time_scale(-1);
            }
            if ui.button("Faster »").on_hover_text("]").clicked() {
                self.clock.change_time_scale(1);
            }
            let r = ui
                .button("Presets…")
                .on_hover_text("P, or the keys 1 … 9, 0");
            self.widget(ui, "presets", &r);
            if r.clicked() {
                self.ui.presets_open = !self.ui.presets_open;
            }
            if ui.button("Fit view").on_hover_text("F").clicked() {
                actions.push(Action::Fit);
            }
            if ui.button("? Help").on_hover_text("H or F1").clicked() {
                self.ui.help_open = !self.ui.help_open;
            }
        });
    }

    fn show_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        let o = &mut self.overlays;
        ui.checkbox(&mut o.velocity, "velocity arrows (white)")
            .on_hover_text("V");
        ui.checkbox(&mut o.momentum, "momentum arrows (pink)")
            .on_hover_text("M");
        ui.checkbox(&mut o.delta_p, "Δp after a collision (amber)")
            .on_hover_text("each disc's change of momentum, for a second after each collision");
        const SCOPES: [(ReadoutScope, &str); 3] = [
            (ReadoutScope::Off, "none"),
            (ReadoutScope::Selected, "selected disc"),
            (ReadoutScope::All, "every disc"),
        ];
        let current = SCOPES
            .iter()
            .find(|(s, _)| *s == o.readouts)
            .map_or("none", |(_, l)| l);
        ComboBox::from_label("values beside")
            .selected_text(current)
            .show_ui(ui, |ui| {
                for (scope, label) in SCOPES {
                    ui.selectable_value(&mut o.readouts, scope, label);
                }
            })
            .response
            .on_hover_text("I");
        ui.checkbox(&mut self.lesson.center_of_mass, "centre of mass")
            .on_hover_text("O");
        ui.checkbox(&mut self.trails.on, "path traces, a dot every 0.1 s")
            .on_hover_text("A");
        ui.checkbox(&mut self.overlays.safe_palette, "colour-blind-safe")
            .on_hover_text("F3");
        ui.horizontal_wrapped(|ui| {
            if ui
                .button("Next collision")
                .on_hover_text("J: run to the next collision and pause at the instant of impact")
                .clicked()
            {
                actions.push(Action::NextCollision);
            }
            if ui
                .button("◀ Back")
                .on_hover_text(", (Shift: 10 steps)")
                .clicked()
            {
                actions.push(Action::Scrub(-1));
            }
            if ui.button("Forward ▶").on_hover_text(".").clicked() {
                actions.push(Action::Scrub(1));
            }
            let mut on = self.lesson.com_view.is_some();
            let r = ui.checkbox(&mut on, "centre-of-mass view").on_hover_text(
                "Z: the view moves with the centre of mass and arrows show velocities \
                     relative to it; the experiment is not changed",
            );
            if r.clicked() {
                actions.push(Action::CenterOfMassFrame);
            }
        });
    }

    fn new_disc_section(&mut self, ui: &mut Ui) {
        ui.label("Drag on empty space to launch one.");
        let r = ui
            .checkbox(&mut self.size_follows_mass, "size follows mass (same density)")
            .on_hover_text("a 1 kg disc is 0.4 m in radius; the radius grows as √m, for new discs and mass edits");
        self.widget(ui, "size_follows_mass", &r);
        let biggest = 0.45 * self.world.laws.size.min_element();
        if self.size_follows_mass {
            let r = crate::app::interaction::radius_for_mass(self.new_disc.mass).min(biggest);
            self.new_disc.radius = r;
            ui.label(format!("Radius {} (from the mass)", with_unit(r, 2, "m")));
        } else {
            let mut r = self.new_disc.radius;
            let (track, changed) = slider(
                ui,
                "Radius",
                &mut r,
                0.05..=2.0f64.min(biggest).max(0.06),
                true,
                2,
                " m",
            );
            if changed {
                self.new_disc.radius = r.min(biggest);
            }
            self.widget(ui, "new_radius", &track.on_hover_text("PgUp / PgDn"));
        }
        let mut m = self.new_disc.mass;
        let (track, changed) = slider(ui, "Mass", &mut m, 0.01..=100.0, true, 2, " kg");
        if changed {
            self.new_disc.mass = m;
        }
        self.widget(ui, "new_mass", &track.on_hover_text("Home / End"));
    }

    fn selected_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        let selected = self.selected.filter(|&i| i < self.world.particles.len());
        let Some(i) = selected else {
            self.ui.fields.disc = None;
            ui.label("None: click a disc to select it.");
            return;
        };
        let p = self.world.particles[i];
        let fields = &mut self.ui.fields;
        if fields.disc != Some(i) {
            *fields = DiscFields {
                disc: Some(i),
                ..DiscFields::default()
            };
        }
        // Untouched fields follow the disc as it moves.
        let live = [p.mass, p.radius, p.vel.x, p.vel.y].map(field);
        for (k, value) in live.into_iter().enumerate() {
            if fields.text[k] == fields.shown[k] {
                fields.text[k] = value.clone();
                fields.shown[k] = value;
            }
        }
        let mut enter = false;
        egui::Grid::new("selected_fields")
            .num_columns(2)
            .show(ui, |ui| {
                for k in 0..4 {
                    let r = ui.add(
                        egui::TextEdit::singleline(&mut self.ui.fields.text[k])
                            .desired_width(100.0),
                    );
                    select_all_on_focus(ui, &r, &self.ui.fields.text[k]);
                    self.ui.note_text_field(&r);
                    self.ui
                        .note_widget(FIELD_KEYS[k], r.rect, super::px_per_point(ui.ctx()));
                    if r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                        enter = true;
                    }
                    ui.label(FIELD_LABELS[k]);
                    ui.end_row();
                }
            });
        ui.horizontal(|ui| {
            let r = ui.button("Apply").on_hover_text("Enter in a field");
            self.widget(ui, "apply", &r);
            if r.clicked() || enter {
                actions.push(Action::ApplySelected);
            }
            let r = ui.button("Delete").on_hover_text("Delete / Backspace");
            self.widget(ui, "delete", &r);
            if r.clicked() {
                actions.push(Action::DeleteSelected);
            }
        });
        if let Some(note) = &self.ui.fields.note {
            show_note(ui, note);
        }
    }

    fn scene_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        ComboBox::from_label("preset")
            .selected_text("open a preset…")
            .show_ui(ui, |ui| {
                for (k, label) in scenes::preset_labels().iter().enumerate() {
                    if ui.selectable_label(false, label).clicked() {
                        actions.push(Action::OpenPreset(k));
                    }
                }
            });
        // The browser has no folders to type: a scene file is dropped on
        // the page, saves and exports download, and a link can carry it.
        let in_browser = cfg!(target_arch = "wasm32");
        let mut enter = false;
        if in_browser {
            ui.label("Open a scene file: drop it on the page.");
        } else {
            ui.label("Scene file:");
            let r = ui.add(
                egui::TextEdit::singleline(&mut self.ui.path)
                    .hint_text("assets/scenes/preset-8-gas.toml")
                    .desired_width(f32::INFINITY),
            );
            self.widget(ui, "scene_path", &r);
            self.ui.note_text_field(&r);
            enter = r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        }
        ui.horizontal_wrapped(|ui| {
            if !in_browser {
                let r = ui.button("Open").on_hover_text("Enter in the field");
                self.widget(ui, "open", &r);
                if r.clicked() || enter {
                    actions.push(Action::Open);
                }
            }
            let r = ui.button("Save").on_hover_text("Ctrl+S");
            self.widget(ui, "save", &r);
            if r.clicked() {
                actions.push(Action::Save);
            }
            if in_browser {
                let r = ui
                    .button("Share link")
                    .on_hover_text("puts this scene into the page's address, to send as a link");
                self.widget(ui, "share", &r);
                if r.clicked() {
                    actions.push(Action::Share);
                }
            }
            if ui.button("Clear discs").on_hover_text("C").clicked() {
                actions.push(Action::Clear);
            }
            if ui
                .button("Export CSV")
                .on_hover_text("X: totals, discs and collisions")
                .clicked()
            {
                actions.push(Action::Export);
            }
            if ui.button("Screenshot").on_hover_text("F12").clicked() {
                actions.push(Action::Screenshot);
            }
        });
        if in_browser {
            ui.label("Saves, exports and screenshots download as files.");
        } else {
            ui.label(format!("Saves go to {}/", self.options.out.display()));
        }
        if let Some(note) = &self.ui.scene_note {
            show_note(ui, note);
        }
    }

    fn view_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        let mut scale = f64::from(self.ui.scale);
        let range = f64::from(*UI_SCALE_RANGE.start())..=f64::from(*UI_SCALE_RANGE.end());
        let (r, changed) = slider(
            ui,
            "Size of text and lines",
            &mut scale,
            range,
            false,
            1,
            "×",
        );
        self.widget(ui, "ui_scale", &r);
        // Applied when let go: the panel must not change size under the pointer.
        if r.drag_stopped() || (changed && !r.dragged()) {
            self.ui.set_scale(((scale * 10.0).round() / 10.0) as f32);
        }
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .button("Projector size")
                .on_hover_text("F2: 1.0, 1.5, 2.0");
            self.widget(ui, "projector", &r);
            if r.clicked() {
                self.ui.set_scale(next_scale(self.ui.scale));
            }
            let other = match self.ui.theme {
                Theme::Dark => Theme::Light,
                Theme::Light => Theme::Dark,
            };
            let r = ui
                .button(format!(
                    "{} theme",
                    if other == Theme::Light {
                        "Light"
                    } else {
                        "Dark"
                    }
                ))
                .on_hover_text("a bright room wants the light one");
            self.widget(ui, "theme", &r);
            if r.clicked() {
                self.ui.theme = other;
            }
            if ui
                .button("Zoom +")
                .on_hover_text("+ or the wheel")
                .clicked()
            {
                actions.push(Action::Zoom(1.15));
            }
            if ui.button("Zoom −").on_hover_text("−").clicked() {
                actions.push(Action::Zoom(1.0 / 1.15));
            }
            // A page may go full screen only inside the click's own event,
            // which a frame never is: in the browser its own full-screen
            // key (F11, or the Chromebook's) does it.
            if !cfg!(target_arch = "wasm32")
                && ui.button("Full screen").on_hover_text("F11").clicked()
            {
                actions.push(Action::Fullscreen);
            }
            if ui
                .button("Hide panels")
                .on_hover_text("Tab brings them back")
                .clicked()
            {
                self.ui.docks_open = false;
            }
        });
    }

    fn details_section(&mut self, ui: &mut Ui) {
        let w = &mut self.world;
        if let Some(m) = setting_combo(ui, "method", &METHODS, w.method) {
            w.method = m;
        }
        if let Some(b) = setting_combo(ui, "broad phase", &BROAD_PHASES, w.broad_phase) {
            w.broad_phase = b;
        }
        if let Some(k) = setting_combo(ui, "substeps", &SUBSTEPS, w.substeps) {
            w.substeps = k;
        }
        ui.label(self.method_line());
        let mut micros: Vec<f64> = self.step_micros.iter().copied().collect();
        micros.sort_by(f64::total_cmp);
        let median = micros.get(micros.len() / 2).copied().unwrap_or(0.0);
        ui.label(format!(
            "time step dt = {}",
            with_unit(self.clock.dt * 1e3, 3, "ms")
        ));
        ui.label(format!(
            "step time {} (median), {} steps in the last frame",
            with_unit(median, 1, "µs"),
            self.steps_last_frame
        ));
        ui.label(format!("{} frames per second", macroquad::time::get_fps()));
        ui.label(format!("{} discs", self.world.particles.len()));
        if let Some(rate) = self.sim_rate() {
            ui.label(format!(
                "simulated seconds per real second: {}",
                plain(rate, 2)
            ));
        }
    }

    /// Writes the edited fields into the selected disc, or says what is wrong.
    pub(in crate::app) fn apply_disc_fields(&mut self) {
        let Some(i) = self.selected.filter(|&i| i < self.world.particles.len()) else {
            return;
        };
        let fields = &self.ui.fields;
        let changed: [Option<&str>; 4] = std::array::from_fn(|k| {
            (fields.text[k] != fields.shown[k]).then_some(fields.text[k].as_str())
        });
        let biggest = 0.45 * self.world.laws.size.min_element();
        let parsed = parse_disc_edit(changed, biggest).and_then(|e| self.sized_edit(i, e));
        let note = match parsed {
            Ok(edit) if edit.is_empty() => Note::ok("Nothing changed: type a new value first"),
            Ok(edit) => {
                self.remember_edit("edit a disc");
                edit.apply(&mut self.world.particles[i]);
                // Let every field follow the disc again.
                let fields = &mut self.ui.fields;
                fields.shown = fields.text.clone();
                Note::ok(format!("Applied to disc {i}"))
            }
            Err(e) => Note::error(e),
        };
        self.ui.fields.note = Some(note);
        let _ = FIELDS;
    }
}

/// Selects a text field's whole text when it gains the keyboard, so what is
/// typed replaces the old value (typing 5 into "1" gives 5, not 51).
pub fn select_all_on_focus(ui: &Ui, response: &egui::Response, text: &str) {
    if response.gained_focus() {
        if let Some(mut state) = egui::TextEdit::load_state(ui.ctx(), response.id) {
            let all = egui::text::CCursorRange::two(
                egui::text::CCursor::new(0),
                egui::text::CCursor::new(text.chars().count()),
            );
            state.cursor.set_char_range(Some(all));
            state.store(ui.ctx(), response.id);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gravity_sticks_to_earth_and_rounds_to_tenths() {
        assert_eq!(snap_gravity(9.7), EARTH_GRAVITY);
        assert_eq!(snap_gravity(9.9), EARTH_GRAVITY);
        assert!((snap_gravity(3.04) - 3.0).abs() < 1e-12);
        assert_eq!(snap_gravity(0.02), 0.0, "the left end switches gravity off");
    }
}
