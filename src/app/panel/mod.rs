//! The side panel: the world's laws, the step's method, new discs, overlays,
//! the selected disc and scene files, as widgets of macroquad's built-in UI
//! (`macroquad::ui`) on the right of the window. `L` shows and hides it.
//!
//! The panel is drawn first in each frame, so the frame loop knows before the
//! key and mouse bindings run whether a text field took the keyboard
//! ([`Panel::typing`]: the shortcuts then stay quiet, so typing a path such as
//! `scenes/c1.toml` neither clears the discs nor opens preset 1) and whether
//! the cursor is over the panel ([`Panel::covers`]: clicks and the wheel then
//! belong to the panel, not to the world).
//!
//! Clicks on the panel's buttons are collected while it is drawn and carried
//! out afterwards ([`App::panel_ui`]), once the UI no longer borrows the app.
//!
//! This file holds the [`Panel`] state, its skins, the layout sizes every
//! section shares and the frame's entry point; the rest is split by concern:
//!
//! - [`widgets`]: the row layout helpers, labels, buttons, text fields, combo
//!   and check boxes, wrapped notes and the hand-drawn sliders (log scales
//!   for the radius and mass of new discs).
//! - [`sections`]: the World, Method, New discs and Overlays sections.
//! - [`selected`]: the selected disc's fields, their validation, Apply and
//!   Delete.
//! - [`scene`]: the scene-file field, Open and Save.
//!
//! Everything that is not drawing (slider scales, parsing the selected disc's
//! fields, wrapping messages, combo lists) is plain functions, tested in the
//! submodule that holds them.

mod scene;
mod sections;
mod selected;
mod widgets;

pub use widgets::wrap;

use super::App;
use glam::DVec2;
use macroquad::math::RectOffset;
use macroquad::prelude::*;
use macroquad::ui::{hash, root_ui, widgets as ui_widgets, Skin, Ui};
use selected::DiscFields;
use std::collections::BTreeMap;

/// Width of the panel (px).
pub const PANEL_WIDTH: f32 = 300.0;
/// Gap between widgets and around the edges (px).
const MARGIN: f32 = 3.0;
/// Width the rows use: the panel less its border, margins and a scroll bar.
const CONTENT_WIDTH: f32 = PANEL_WIDTH - 2.0 - 2.0 * MARGIN - 12.0;
/// Height of a row (px).
const ROW: f32 = 22.0;
/// Width of the control column (slider tracks, combo boxes, text fields).
const CONTROL_WIDTH: f32 = 130.0;
/// Where the label column starts, from the row's left edge.
const LABEL_X: f32 = CONTROL_WIDTH + 14.0;

/// A line of feedback in the panel.
#[derive(Clone, Debug, PartialEq)]
struct Note {
    text: String,
    error: bool,
}

impl Note {
    fn ok(text: impl Into<String>) -> Self {
        Note {
            text: text.into(),
            error: false,
        }
    }
    fn error(text: impl Into<String>) -> Self {
        Note {
            text: text.into(),
            error: true,
        }
    }
}

/// What a click asked for, done once the panel is drawn.
enum Action {
    OpenPreset(usize),
    CenterOfMassFrame,
    Apply,
    Delete,
    Open,
    Save,
}

/// The skins the panel draws with (made once the UI exists).
struct Skins {
    base: Skin,
    header: Skin,
    hint: Skin,
    error: Skin,
    ok: Skin,
}

impl Skins {
    fn new(ui: &Ui) -> Self {
        let mut base = ui.default_skin();
        base.margin = MARGIN;
        base.checkbox_style = ui
            .style_builder()
            .color(Color::from_rgba(205, 206, 210, 255))
            .color_hovered(Color::from_rgba(185, 190, 200, 255))
            .color_clicked(Color::from_rgba(120, 150, 200, 255))
            .color_selected(Color::from_rgba(50, 110, 200, 255))
            .color_selected_hovered(Color::from_rgba(70, 130, 220, 255))
            .build();
        base.editbox_style = ui
            .style_builder()
            .color(Color::from_rgba(255, 255, 255, 255))
            .color_clicked(Color::from_rgba(255, 255, 240, 255))
            .color_selected(Color::from_rgba(180, 200, 240, 255))
            .text_color(Color::from_rgba(0, 0, 0, 255))
            .build();
        let label = |color: Color| {
            ui.style_builder()
                .margin(RectOffset::new(2.0, 2.0, 2.0, 2.0))
                .text_color(color)
                .text_color_hovered(color)
                .text_color_clicked(color)
                .build()
        };
        let with_label = |color: Color| Skin {
            label_style: label(color),
            ..base.clone()
        };
        Skins {
            header: with_label(Color::from_rgba(20, 40, 90, 255)),
            hint: with_label(Color::from_rgba(100, 100, 110, 255)),
            error: with_label(Color::from_rgba(170, 20, 20, 255)),
            ok: with_label(Color::from_rgba(20, 110, 40, 255)),
            base,
        }
    }
}

/// The panel's state between frames.
pub struct Panel {
    /// Whether it is shown (`L`).
    pub visible: bool,
    /// A text field took keyboard input this frame: the shortcuts stay quiet.
    pub typing: bool,
    /// Screen rectangles (x, y, width, height) of the panel and its sliders,
    /// text fields and buttons, by name, for the state dump.
    pub widgets: BTreeMap<&'static str, [f32; 4]>,
    /// The slider being dragged.
    dragging: Option<&'static str>,
    fields: DiscFields,
    /// The scene path field.
    path: String,
    scene_note: Option<Note>,
    skins: Option<Skins>,
    /// Where the content area starts on screen this frame (for labels and
    /// buttons, which the UI places relative to it).
    origin: Vec2,
    /// Characters per line of wrapped text.
    wrap_chars: usize,
}

impl Panel {
    /// A visible panel whose path field starts with `path`.
    pub fn new(path: String) -> Self {
        Panel {
            visible: true,
            typing: false,
            widgets: BTreeMap::new(),
            dragging: None,
            fields: DiscFields::default(),
            path,
            scene_note: None,
            skins: None,
            origin: Vec2::ZERO,
            wrap_chars: 34,
        }
    }

    /// Pixels the panel takes from the right of the window.
    pub fn width_on_screen(&self) -> f32 {
        if self.visible {
            PANEL_WIDTH
        } else {
            0.0
        }
    }

    /// Whether a screen point is on the panel (or an open drop-down list).
    pub fn covers(&self, point: DVec2) -> bool {
        if !self.visible {
            return false;
        }
        let p = vec2(point.x as f32, point.y as f32);
        p.x >= screen_width() - PANEL_WIDTH || root_ui().is_mouse_over(p)
    }
}

impl App {
    /// Draws the panel (when shown) and applies what was changed in it.
    /// Runs before the key and mouse bindings of the frame.
    pub(super) fn panel_ui(&mut self) {
        self.panel.typing = false;
        self.panel.widgets.clear();
        if !self.panel.visible {
            return;
        }
        let mut ui = root_ui();
        if self.panel.skins.is_none() {
            self.panel.skins = Some(Skins::new(&ui));
        }
        if let Some(skins) = &self.panel.skins {
            ui.push_skin(&skins.base);
        }
        let at = vec2(screen_width() - PANEL_WIDTH, 0.0);
        let size = vec2(PANEL_WIDTH, screen_height());
        self.panel
            .widgets
            .insert("panel", [at.x, at.y, size.x, size.y]);
        let mut actions = Vec::new();
        ui_widgets::Window::new(hash!(), at, size)
            .titlebar(false)
            .movable(false)
            .ui(&mut ui, |ui| {
                self.panel.origin = ui.canvas().cursor() - vec2(MARGIN, MARGIN);
                let ten = ui.calc_size("0000000000").x - 4.0;
                self.panel.wrap_chars = ((CONTENT_WIDTH - 4.0) / (ten / 10.0)).max(10.0) as usize;
                self.world_section(ui);
                self.method_section(ui);
                self.new_disc_section(ui);
                self.overlay_section(ui, &mut actions);
                self.selected_section(ui, &mut actions);
                self.scene_section(ui, &mut actions);
            });
        if self.panel.skins.is_some() {
            ui.pop_skin();
        }
        drop(ui);
        for action in actions {
            match action {
                Action::OpenPreset(k) => self.open_preset(k),
                Action::CenterOfMassFrame => self.center_of_mass_frame(),
                Action::Apply => self.apply_disc_fields(),
                Action::Delete => self.delete_selected(),
                Action::Open => self.open_from_panel(),
                Action::Save => self.save_from_panel(),
            }
        }
    }

    /// Fits the box to the window, beside the panel when it is shown.
    pub(super) fn fit_camera(&mut self) {
        let right = f64::from(self.panel.width_on_screen());
        self.camera.fit_left_of(self.world.size, 30.0, right);
    }
}
