//! The "Scene" section: a menu of the classroom presets, then a path field
//! for scene files (TOML) with Open (or Enter) and
//! Save (or Ctrl+S), where saves go, and a note on how the last one went.
//! A file that does not load is reported and the current scene stays.

use super::widgets::combo;
use super::{Action, Note, LABEL_X, ROW};
use crate::app::{scenes, App};
use impulse::Scene;
use macroquad::prelude::*;
use macroquad::ui::{hash, Ui};
use std::path::Path;

impl App {
    pub(super) fn scene_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        self.panel.header(ui, "Scene");
        // The classroom presets, as a menu (the number keys do the same).
        let mut labels = vec!["open a preset...".to_string()];
        labels.extend(scenes::preset_labels().iter().cloned());
        if let Some(k) = combo(ui, hash!(), "preset", &labels, 0) {
            actions.push(Action::OpenPreset(k - 1));
        }
        let panel = &mut self.panel;
        let r = panel.row(ui, ROW);
        let at = Rect::new(r.x, r.y + 1.0, r.w, ROW - 2.0);
        let mut path = std::mem::take(&mut panel.path);
        let enter =
            panel.text_field(ui, "scene_path", at, &mut path) && is_key_pressed(KeyCode::Enter);
        panel.path = path;
        // A hint under an empty field; the row stays so the buttons do not move.
        let hint = match panel.path.trim() {
            "" => "e.g. assets/scenes/preset-8-gas.toml",
            _ => "",
        };
        panel.lines(ui, hint, |s| &s.hint);
        let r = panel.row(ui, ROW + 2.0);
        let open = Rect::new(r.x, r.y, 110.0, r.h);
        let save = Rect::new(r.x + LABEL_X, r.y, 120.0, r.h);
        if panel.button(ui, "open", open, "Open (Enter)") || enter {
            ui.clear_input_focus();
            actions.push(Action::Open);
        }
        if panel.button(ui, "save", save, "Save (Ctrl+S)") {
            actions.push(Action::Save);
        }
        let out = format!("Saves go to {}/", self.options.out.display());
        panel.lines(ui, &out, |s| &s.base);
        if let Some(note) = panel.scene_note.clone() {
            panel.note(ui, &note);
        }
    }

    /// Opens the file named in the path field; a bad file is reported and
    /// the current scene stays.
    pub(super) fn open_from_panel(&mut self) {
        let path = self.panel.path.trim().to_string();
        if path.is_empty() {
            self.panel.scene_note = Some(Note::error("Type the path of a scene file first"));
            return;
        }
        let result = match Scene::load(Path::new(&path)) {
            Ok(scene) => self.open_scene(scene, path.clone()),
            Err(e) => {
                let message = format!("{e} (kept the current scene)");
                self.report(message.clone());
                Err(message)
            }
        };
        self.panel.scene_note = Some(match result {
            Ok(()) => Note::ok(format!("Opened {path}")),
            Err(e) => Note::error(e),
        });
    }

    /// Saves the scene and says where it went, or what went wrong.
    pub(super) fn save_from_panel(&mut self) {
        self.panel.scene_note = Some(match self.save_scene() {
            Ok(path) => Note::ok(format!("Saved {}", path.display())),
            Err(e) => Note::error(e),
        });
    }
}
