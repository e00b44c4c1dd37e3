//! *Scene* (presets, a file by its path, save, share, clear, export,
//! screenshot), *View* (size of text and controls, theme, zoom, full
//! screen, hide the panels) and, under *More*, *Details* (method, broad
//! phase, substeps and what a step costs).

use super::super::widgets::{command_button, setting_combo, show_note, slider};
use super::Cx;
use crate::app::model::apply::{BROAD_PHASES, METHODS, SUBSTEPS};
use crate::app::model::{next_scale, scenes, Command, Theme, UI_SCALE_RANGE};
use crate::app::numbers::{plain, with_unit};
use egui::{ComboBox, Ui};

/// Presets, the path field, Open, Save, Share, Clear, Export, Screenshot.
pub fn scene(ui: &mut Ui, cx: &mut Cx, path: &mut String) {
    ComboBox::from_label("preset")
        .selected_text("open a preset…")
        .show_ui(ui, |ui| {
            for (k, label) in scenes::preset_labels().iter().enumerate() {
                if ui.selectable_label(false, label).clicked() {
                    cx.send(Command::OpenPreset(k));
                }
            }
        });
    if cx.model.recovery.aside.is_some() {
        command_button(ui, cx, Command::ReopenKept, Some("reopen_kept"));
    }
    // The browser has no folders to type: a scene file is dropped on the
    // page, saves and exports download, and a link can carry it.
    let in_browser = cfg!(target_arch = "wasm32");
    let mut enter = false;
    if in_browser {
        ui.label("Open a scene file: drop it on the page.");
    } else {
        ui.label("Scene file:");
        let r = ui.add(
            egui::TextEdit::singleline(path)
                .hint_text("assets/scenes/preset-8-gas.toml")
                .desired_width(f32::INFINITY),
        );
        cx.note("scene_path", &r);
        cx.marks.text_field(&r);
        enter = r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
    }
    ui.horizontal_wrapped(|ui| {
        if !in_browser {
            let r = ui.button("Open").on_hover_text("Enter in the field");
            cx.note("open", &r);
            if r.clicked() || enter {
                cx.send(Command::OpenFile(path.clone()));
            }
        }
        command_button(ui, cx, Command::Save, Some("save"));
        if in_browser {
            let r = ui
                .button("Share link")
                .on_hover_text("puts this scene into the page's address, to send as a link");
            cx.note("share", &r);
            if r.clicked() {
                cx.send(Command::Share);
            }
        }
        command_button(ui, cx, Command::Clear, None);
        command_button(ui, cx, Command::Export, None);
        command_button(ui, cx, Command::Screenshot, None);
    });
    if in_browser {
        ui.label("Saves, exports and screenshots download as files.");
    } else {
        ui.label(format!("Saves go to {}/", cx.model.session.out.display()));
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
        "Size of text and controls",
        &mut scale,
        range,
        false,
        1,
        "×",
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
            Theme::Light => "Light theme",
            Theme::Dark => "Dark theme",
        };
        let r = ui
            .button(label)
            .on_hover_text("a bright room wants the light one");
        cx.note("theme", &r);
        if r.clicked() {
            cx.send(Command::SetTheme(other));
        }
        command_button(ui, cx, Command::ZoomIn, None);
        command_button(ui, cx, Command::ZoomOut, None);
        // A page may go full screen only inside the click's own event,
        // which a frame never is: in the browser its own full-screen key
        // (F11, or the Chromebook's) does it.
        if !cfg!(target_arch = "wasm32") {
            command_button(ui, cx, Command::Fullscreen, None);
        }
        command_button(ui, cx, Command::ToggleDocks, None);
    });
}

/// Method, broad phase, substeps, and what the steps cost.
pub fn details(ui: &mut Ui, cx: &mut Cx) {
    let model = cx.model;
    let w = &model.world;
    if let Some(m) = setting_combo(ui, ("method", "How the computer works out the collisions: auto chooses; exact finds each one at its instant; the others step in small fixed times and correct overlaps"), &METHODS, w.method) {
        cx.send(Command::SetMethod(m));
    }
    if let Some(b) = setting_combo(ui, ("broad phase", "How the computer finds which discs are near each other before checking them closely: it only changes the speed, not the result"), &BROAD_PHASES, w.broad_phase) {
        cx.send(Command::SetBroadPhase(b));
    }
    if let Some(k) = setting_combo(
        ui,
        (
            "substeps",
            "How many smaller steps each time step is cut into: more is more accurate and slower",
        ),
        &SUBSTEPS,
        w.substeps,
    ) {
        cx.send(Command::SetSubsteps(k));
    }
    ui.add(egui::Label::new(model.method_line()).wrap());
    let mut micros: Vec<f64> = model.steps.step_micros.iter().copied().collect();
    micros.sort_by(f64::total_cmp);
    let median = micros.get(micros.len() / 2).copied().unwrap_or(0.0);
    ui.label(format!(
        "time step dt = {}",
        with_unit(model.clock.dt * 1e3, 3, "ms")
    ))
    .on_hover_text("how much simulated time one step of the computer covers");
    ui.label(format!(
        "step time {} (median), {} steps in the last frame",
        with_unit(median, 1, "µs"),
        model.steps.steps_last_frame
    ));
    ui.label(format!("{} frames per second", macroquad::time::get_fps()));
    ui.label(format!("{} discs", w.particles.len()));
    if let Some(rate) = model.sim_rate() {
        ui.label(format!(
            "simulated seconds per real second: {}",
            plain(rate, 2)
        ));
    }
}
