//! *Scene* (presets, a file by its path, save, share, clear, export,
//! screenshot), *View* (size of text and controls, theme, zoom, full
//! screen, hide the panels) and, under *More*, *Details* (method, broad
//! phase, substeps and what a step costs).

use super::super::widgets::{
    combo, command_button, pick, setting_combo, show_note, slider, Reading,
};
use super::Cx;
use crate::app::lang::{tr, Lang};
use crate::app::model::apply::{BROAD_PHASES, METHODS, SUBSTEPS};
use crate::app::model::{next_scale, scenes, Command, Theme, UI_SCALE_RANGE};
use crate::app::numbers::{plain, with_unit};
use crate::app::ui::tip::Tip;
use egui::Ui;

/// The scene's name, in a field that follows it until typed in; Enter
/// renames the scene (the name heads the window and names saved files).
#[derive(Default)]
pub struct NameField {
    /// What the field holds.
    text: String,
    /// The name it was last filled with: text that differs was typed.
    shown: String,
}

impl NameField {
    fn ui(&mut self, ui: &mut Ui, cx: &mut Cx) {
        let name = cx.model.scene_name();
        if self.text == self.shown {
            self.text.clone_from(&name);
        }
        self.shown = name;
        ui.horizontal(|ui| {
            ui.label(tr!("scene-name-label"));
            let r = ui
                .add(egui::TextEdit::singleline(&mut self.text).desired_width(f32::INFINITY))
                .tip(tr!("scene-name-hover"));
            super::super::widgets::select_all_on_focus(ui, &r, &self.text);
            cx.note("scene_name_field", &r);
            cx.marks.text_field(&r);
            if r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                cx.send(Command::RenameScene(self.text.clone()));
                // Refused, it shows the name again; taken, the new one.
                self.text.clone_from(&self.shown);
            }
        });
    }
}

/// The name, presets, the path field, Open, Save, Share, Clear, Export,
/// Screenshot.
pub fn scene(ui: &mut Ui, cx: &mut Cx, path: &mut String, name: &mut NameField) {
    name.ui(ui, cx);
    // A list of things to do, not a setting: the arrows open nothing.
    let r = combo(
        ui,
        "preset_combo",
        &tr!("preset-label"),
        &tr!("preset-choose"),
    )
    .show_ui(ui, |ui| {
        for (k, label) in scenes::preset_labels().iter().enumerate() {
            if ui.selectable_label(false, label).clicked() {
                cx.send(Command::OpenPreset(k));
            }
        }
    });
    cx.note("preset_combo", &r.response);
    if cx.model.recovery.aside.is_some() {
        command_button(ui, cx, Command::ReopenKept, Some("reopen_kept"));
    }
    // The browser has no folders to type: a scene file is dropped on the
    // page, saves and exports download, and a link can carry it.
    let in_browser = cfg!(target_arch = "wasm32");
    let mut enter = false;
    if in_browser {
        ui.label(tr!("scene-drop"));
    } else {
        ui.label(tr!("scene-file-label"));
        let r = ui.add(
            egui::TextEdit::singleline(path)
                // An example, said to be one: a bare path in grey was read
                // as the file that is open.
                .hint_text(tr!("scene-file-hint"))
                .desired_width(f32::INFINITY),
        );
        cx.note("scene_path", &r);
        cx.marks.text_field(&r);
        // Enter here opens the file: Ctrl+S is no Enter.
        let no_enter = egui::Id::new(super::super::typing::NO_ENTER_ON_SAVE);
        ui.ctx().data_mut(|d| d.insert_temp(no_enter, r.id));
        enter = r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
    }
    ui.horizontal_wrapped(|ui| {
        if !in_browser {
            let r = ui.button(tr!("open")).tip(tr!("open-hover"));
            cx.note("open", &r);
            if r.clicked() || enter {
                cx.send(Command::OpenFile(path.clone()));
            }
        }
        command_button(ui, cx, Command::Save, Some("save"));
        if in_browser {
            let r = ui.button(tr!("share")).tip(tr!("share-hover"));
            cx.note("share", &r);
            if r.clicked() {
                cx.send(Command::Share);
            }
        }
        command_button(ui, cx, Command::Clear, Some("clear"));
        command_button(ui, cx, Command::Export, Some("export"));
        command_button(ui, cx, Command::Screenshot, Some("screenshot"));
    });
    if in_browser {
        ui.label(tr!("saves-download"));
    } else {
        let folder = cx.model.session.out.display().to_string();
        ui.label(tr!("saves-go-to", folder = folder));
    }
    if let Some(note) = &cx.model.messages.scene {
        show_note(ui, note);
    }
}

/// Size of text and controls, theme, zoom, full screen, hide the panels.
pub fn view(ui: &mut Ui, cx: &mut Cx) {
    let panels = &cx.model.panels;
    let mut scale = f64::from(panels.scale);
    let range = f64::from(*UI_SCALE_RANGE.start())..=f64::from(*UI_SCALE_RANGE.end());
    let (r, changed) = slider(
        ui,
        &tr!("ui-scale-label"),
        &mut scale,
        range,
        Reading::new(1, "×"),
    );
    cx.note("ui_scale", &r);
    // Applied when let go: the panel must not change size under the pointer.
    if r.drag_stopped() || (changed && !r.dragged()) {
        cx.send(Command::SetScale(((scale * 10.0).round() / 10.0) as f32));
    }
    let other = panels.theme.other();
    let _ = next_scale;
    ui.horizontal_wrapped(|ui| {
        command_button(ui, cx, Command::NextScale, Some("projector"));
        let label = match other {
            Theme::Light => tr!("theme-light"),
            Theme::Dark => tr!("theme-dark"),
        };
        let r = ui.button(label).tip(tr!("theme-hover"));
        cx.note("theme", &r);
        if r.clicked() {
            cx.send(Command::SetTheme(other));
        }
        command_button(ui, cx, Command::ZoomIn, Some("zoom_in"));
        command_button(ui, cx, Command::ZoomOut, Some("zoom_out"));
        // A page may go full screen only inside the click's own event,
        // which a frame never is: in the browser its own full-screen key
        // (F11, or the Chromebook's) does it.
        if !cfg!(target_arch = "wasm32") {
            command_button(ui, cx, Command::Fullscreen, Some("fullscreen"));
        }
        command_button(ui, cx, Command::ToggleDocks, Some("hide_panels"));
    });
    language(ui, cx);
}

/// The language of the window, each named in itself (also on the start
/// screen).
pub fn language(ui: &mut Ui, cx: &mut Cx) {
    let current = crate::app::lang::language();
    let name = crate::app::lang::native_name;
    let names = Lang::SHIPPED.map(name);
    let at = Lang::SHIPPED.iter().position(|&l| l == current);
    let words = (&*tr!("language-label"), &*tr!("language-hover"), "language");
    if let Some(k) = pick(ui, cx, words, &names, at, &name(current)) {
        if Lang::SHIPPED[k] != current {
            cx.send(Command::SetLanguage(Lang::SHIPPED[k]));
        }
    }
}

/// Method, broad phase, substeps, and what the steps cost.
pub fn details(ui: &mut Ui, cx: &mut Cx) {
    let model = cx.model;
    let w = &model.world;
    let (label, hover) = (tr!("method-label"), tr!("method-hover"));
    if let Some(m) = setting_combo(ui, cx, (&label, &hover, "method"), &METHODS, w.method) {
        cx.send(Command::SetMethod(m));
    }
    let (label, hover) = (tr!("broad-phase-label"), tr!("broad-phase-hover"));
    let names = (&*label, &*hover, "broad_phase");
    if let Some(b) = setting_combo(ui, cx, names, &BROAD_PHASES, w.broad_phase) {
        cx.send(Command::SetBroadPhase(b));
    }
    let (label, hover) = (tr!("substeps-label"), tr!("substeps-hover"));
    if let Some(k) = setting_combo(ui, cx, (&label, &hover, "substeps"), &SUBSTEPS, w.substeps) {
        cx.send(Command::SetSubsteps(k));
    }
    ui.add(egui::Label::new(model.method_line()).wrap());
    let mut micros: Vec<f64> = model.steps.step_micros.iter().copied().collect();
    micros.sort_by(f64::total_cmp);
    let median = micros.get(micros.len() / 2).copied().unwrap_or(0.0);
    ui.label(tr!(
        "dt-line",
        dt = with_unit(model.clock.dt * 1e3, 3, "ms")
    ))
    .tip(tr!("dt-hover"));
    ui.label(tr!(
        "step-time-line",
        time = with_unit(median, 1, "µs"),
        steps = model.steps.steps_last_frame
    ));
    ui.label(tr!("fps-line", fps = macroquad::time::get_fps()));
    ui.label(tr!("discs-count", count = w.particles.len()));
    if let Some(rate) = model.sim_rate() {
        ui.label(tr!("sim-rate-line", rate = plain(rate, 2)));
    }
}
