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
//! The sliders are drawn on the UI's canvas rather than with the built-in
//! `Slider`: that one carries a number box which takes the keyboard without
//! the program being able to tell, is linear only, and moves only when its
//! 8-pixel handle is caught. These jump to a click anywhere on the track and
//! can run on a log scale (radius and mass of new discs).
//!
//! Everything that is not drawing (slider scales, parsing the selected disc's
//! fields, wrapping messages, combo lists) is plain functions, tested below.

use super::clock::TIME_SCALES;
use super::draw::ReadoutScope;
use super::input::{BROAD_PHASES, METHODS, SUBSTEPS};
use super::App;
use glam::DVec2;
use impulse::{Boundary, Particle, Scene};
use macroquad::math::RectOffset;
use macroquad::prelude::*;
use macroquad::ui::{hash, root_ui, widgets, Skin, Ui};
use std::collections::BTreeMap;
use std::fmt::Display;
use std::path::Path;

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
/// Earth's gravity, where the gravity slider sticks (m/s²).
const EARTH_GRAVITY: f64 = 9.81;

const TRACK: Color = Color::new(0.78, 0.79, 0.82, 1.0);
const TRACK_EDGE: Color = Color::new(0.45, 0.46, 0.50, 1.0);
const TRACK_FILL: Color = Color::new(0.27, 0.51, 0.82, 1.0);
const HANDLE: Color = Color::new(0.16, 0.17, 0.22, 1.0);
const HEADER: Color = Color::new(0.80, 0.84, 0.92, 1.0);

/// How a slider maps its track onto values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SliderScale {
    /// Value at the left end.
    pub min: f64,
    /// Value at the right end.
    pub max: f64,
    /// Equal distances are equal ratios (needs `0 < min < max`).
    pub log: bool,
}

impl SliderScale {
    /// A linear scale.
    pub const fn linear(min: f64, max: f64) -> Self {
        SliderScale {
            min,
            max,
            log: false,
        }
    }

    /// A logarithmic scale.
    pub const fn log(min: f64, max: f64) -> Self {
        SliderScale {
            min,
            max,
            log: true,
        }
    }

    /// Where `value` sits along the track, 0 to 1 (clamped; NaN is 0).
    pub fn fraction(&self, value: f64) -> f64 {
        let t = if self.log {
            (value.ln() - self.min.ln()) / (self.max.ln() - self.min.ln())
        } else {
            (value - self.min) / (self.max - self.min)
        };
        if t.is_nan() {
            0.0
        } else {
            t.clamp(0.0, 1.0)
        }
    }

    /// The value at `fraction` of the track (clamped to the ends).
    pub fn value(&self, fraction: f64) -> f64 {
        if fraction.is_nan() || fraction <= 0.0 {
            return self.min; // exactly, not exp(ln(min))
        }
        if fraction >= 1.0 {
            return self.max;
        }
        let t = fraction;
        let v = if self.log {
            (self.min.ln() + t * (self.max.ln() - self.min.ln())).exp()
        } else {
            self.min + t * (self.max - self.min)
        };
        v.clamp(self.min, self.max)
    }
}

const RESTITUTION: SliderScale = SliderScale::linear(0.0, 1.0);
const GRAVITY: SliderScale = SliderScale::linear(0.0, 20.0);
const NEW_RADIUS: SliderScale = SliderScale::log(0.05, 2.0);
const NEW_MASS: SliderScale = SliderScale::log(0.01, 100.0);

/// `v` rounded to a multiple of `step`.
pub fn round_to_step(v: f64, step: f64) -> f64 {
    (v / step).round() * step
}

/// `v` rounded to `digits` significant digits (0 and non-finite unchanged).
pub fn round_significant(v: f64, digits: i32) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let scale = 10f64.powi(digits - 1 - v.abs().log10().floor() as i32);
    (v * scale).round() / scale
}

/// The gravity slider's value: tenths, sticking to 9.81 within 0.15.
pub fn snap_gravity(g: f64) -> f64 {
    if (g - EARTH_GRAVITY).abs() < 0.15 {
        EARTH_GRAVITY
    } else {
        round_to_step(g, 0.1)
    }
}

/// The labels of `list` for a combo box and the index of `current`; a
/// current value that is not in the list (a scene file may ask for 3
/// substeps) is added at the end, so the box always shows the truth.
pub fn choices<T: Copy + PartialEq + Display>(list: &[T], current: T) -> (Vec<String>, usize) {
    let mut labels: Vec<String> = list.iter().map(ToString::to_string).collect();
    let index = match list.iter().position(|&x| x == current) {
        Some(k) => k,
        None => {
            labels.push(current.to_string());
            labels.len() - 1
        }
    };
    (labels, index)
}

/// A number as a text field shows it: up to four decimals, no trailing
/// zeros; very large or very small magnitudes in scientific notation.
pub fn field_text(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if !(1e-3..1e7).contains(&v.abs()) {
        return format!("{v:.4e}");
    }
    let s = format!("{v:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// The selected disc's editable quantities, in field order.
pub const FIELDS: [&str; 4] = ["mass", "radius", "vx", "vy"];
const FIELD_UNITS: [&str; 4] = ["mass (kg)", "radius (m)", "vx (m/s)", "vy (m/s)"];

/// New values for the selected disc; `None` leaves a quantity as it is.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DiscEdit {
    /// Mass (kg).
    pub mass: Option<f64>,
    /// Radius (m).
    pub radius: Option<f64>,
    /// Velocity, x (m/s).
    pub vx: Option<f64>,
    /// Velocity, y (m/s).
    pub vy: Option<f64>,
}

impl DiscEdit {
    /// Whether nothing would change.
    pub fn is_empty(&self) -> bool {
        *self == DiscEdit::default()
    }

    /// Writes the new values into `p`.
    pub fn apply(&self, p: &mut Particle) {
        p.mass = self.mass.unwrap_or(p.mass);
        p.radius = self.radius.unwrap_or(p.radius);
        p.vel.x = self.vx.unwrap_or(p.vel.x);
        p.vel.y = self.vy.unwrap_or(p.vel.y);
    }
}

/// Reads the fields the user changed (`None`: untouched, in [`FIELDS`]
/// order). Every value must be a finite number; mass and radius positive,
/// the radius at most `max_radius`. The error is one short line.
pub fn parse_disc_edit(changed: [Option<&str>; 4], max_radius: f64) -> Result<DiscEdit, String> {
    let mut values = [None; 4];
    for (k, text) in changed.into_iter().enumerate() {
        let Some(text) = text else { continue };
        let name = FIELDS[k];
        let text = text.trim();
        if text.is_empty() {
            return Err(format!("{name}: type a number"));
        }
        let v = text
            .parse::<f64>()
            .map_err(|_| format!("{name}: {text:?} is not a number"))?;
        if !v.is_finite() {
            return Err(format!("{name} must be finite"));
        }
        if k < 2 && v <= 0.0 {
            return Err(format!("{name} must be positive"));
        }
        if k == 1 && v > max_radius {
            return Err(format!(
                "radius must be at most {} m here",
                field_text(max_radius)
            ));
        }
        values[k] = Some(v);
    }
    Ok(DiscEdit {
        mass: values[0],
        radius: values[1],
        vx: values[2],
        vy: values[3],
    })
}

/// `text` broken into lines of at most `width` characters, at spaces where
/// possible (a long path is cut wherever it must be).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let width = width.max(1);
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let mut word: Vec<char> = word.chars().collect();
        let used = line.chars().count();
        if used > 0 && used + 1 + word.len() <= width {
            line.push(' ');
            line.extend(&word);
            continue;
        }
        if used > 0 {
            lines.push(std::mem::take(&mut line));
        }
        while word.len() > width {
            lines.push(word.drain(..width).collect());
        }
        line.extend(&word);
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

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

/// The text fields of the selected disc.
#[derive(Default)]
struct DiscFields {
    /// Which disc they were filled from.
    disc: Option<usize>,
    /// What the fields hold.
    text: [String; 4],
    /// What the disc had when the field was last filled: a field whose text
    /// differs has been edited and stops following the disc.
    shown: [String; 4],
    note: Option<Note>,
}

/// What a click asked for, done once the panel is drawn.
enum Action {
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

    /// Reserves the next row of the panel; its rectangle on screen.
    fn row(&self, ui: &mut Ui, height: f32) -> Rect {
        let at = ui.canvas().request_space(vec2(CONTENT_WIDTH, height));
        Rect::new(at.x, at.y, CONTENT_WIDTH, height)
    }

    fn label(&self, ui: &mut Ui, at: Vec2, text: &str) {
        widgets::Label::new(text).position(at - self.origin).ui(ui);
    }

    fn button(&mut self, ui: &mut Ui, key: &'static str, at: Rect, text: &str) -> bool {
        self.widgets.insert(key, [at.x, at.y, at.w, at.h]);
        widgets::Button::new(text)
            .position(vec2(at.x, at.y) - self.origin)
            .size(vec2(at.w, at.h))
            .ui(ui)
    }

    /// A one-line text field; whether it was typed into this frame (Enter
    /// and Escape included).
    fn text_field(&mut self, ui: &mut Ui, key: &'static str, at: Rect, text: &mut String) -> bool {
        self.widgets.insert(key, [at.x, at.y, at.w, at.h]);
        let edited = widgets::Editbox::new(hash!("panel field", key), vec2(at.w, at.h))
            .position(vec2(at.x, at.y))
            .multiline(false)
            .ui(ui, text);
        if edited {
            self.typing = true;
            if is_key_pressed(KeyCode::Escape) {
                ui.clear_input_focus();
            }
        }
        edited
    }

    /// A section title on a tinted band.
    fn header(&self, ui: &mut Ui, title: &str) {
        let r = self.row(ui, ROW);
        ui.canvas().rect(r, None, Some(HEADER));
        self.styled(
            ui,
            |s| &s.header,
            |panel, ui| {
                panel.label(ui, vec2(r.x + 4.0, r.y + 1.0), title);
            },
        );
    }

    /// Text in the label column of a row.
    fn row_label(&self, ui: &mut Ui, r: Rect, text: &str) {
        self.label(ui, vec2(r.x + LABEL_X, r.y + 1.0), text);
    }

    fn styled(&self, ui: &mut Ui, skin: fn(&Skins) -> &Skin, f: impl FnOnce(&Self, &mut Ui)) {
        match &self.skins {
            Some(skins) => {
                ui.push_skin(skin(skins));
                f(self, ui);
                ui.pop_skin();
            }
            None => f(self, ui),
        }
    }

    /// A note, wrapped to the panel's width.
    fn note(&self, ui: &mut Ui, note: &Note) {
        let skin: fn(&Skins) -> &Skin = if note.error { |s| &s.error } else { |s| &s.ok };
        self.lines(ui, &note.text, skin);
    }

    fn lines(&self, ui: &mut Ui, text: &str, skin: fn(&Skins) -> &Skin) {
        for line in wrap(text, self.wrap_chars) {
            let r = self.row(ui, 17.0);
            self.styled(ui, skin, |panel, ui| {
                panel.label(ui, vec2(r.x, r.y - 1.0), &line);
            });
        }
    }

    /// A slider over `scale` showing `value`; the new value while it is
    /// dragged (after `round`), else `None`. `text` labels it.
    fn slider(
        &mut self,
        ui: &mut Ui,
        key: &'static str,
        value: f64,
        scale: SliderScale,
        round: fn(f64) -> f64,
        text: impl Fn(f64) -> String,
    ) -> Option<f64> {
        let r = self.row(ui, ROW);
        let track = Rect::new(r.x + 4.0, r.y + 6.0, CONTROL_WIDTH - 8.0, ROW - 12.0);
        self.widgets
            .insert(key, [track.x, track.y, track.w, track.h]);
        // The hit area is the whole row under the control column, so the
        // thin track is easy to catch.
        let hit = Rect::new(r.x, r.y, CONTROL_WIDTH, r.h);
        ui.canvas().rect(hit, None, None);
        let pressed = ui.last_item_clicked();
        if pressed {
            self.dragging = Some(key);
        }
        let mut changed = None;
        if self.dragging == Some(key) {
            let t = (mouse_position().0 - track.x) / track.w;
            let v = round(scale.value(f64::from(t)));
            if v != value {
                changed = Some(v);
            }
            if !is_mouse_button_down(MouseButton::Left) {
                self.dragging = None;
            }
        }
        let shown = changed.unwrap_or(value);
        let x = track.x + track.w * scale.fraction(shown) as f32;
        let mut canvas = ui.canvas();
        canvas.rect(track, Some(TRACK_EDGE), Some(TRACK));
        canvas.rect(
            Rect::new(track.x, track.y, x - track.x, track.h),
            None,
            Some(TRACK_FILL),
        );
        canvas.rect(
            Rect::new(x - 4.0, r.y + 2.0, 8.0, r.h - 4.0),
            None,
            Some(HANDLE),
        );
        self.row_label(ui, r, &text(shown));
        changed
    }
}

/// A combo box over `labels` with `label` beside it; the new index when
/// the user picked another entry.
fn combo(ui: &mut Ui, id: u64, label: &str, labels: &[String], index: usize) -> Option<usize> {
    let names: Vec<&str> = labels.iter().map(String::as_str).collect();
    let mut picked = index;
    // The box fills the control column; the label starts the label column.
    let width = PANEL_WIDTH - 2.0 - 2.0 * MARGIN;
    widgets::ComboBox::new(id, &names)
        .label(label)
        .ratio((LABEL_X + 1.0) / width)
        .ui(ui, &mut picked);
    (picked != index).then_some(picked)
}

fn checkbox(ui: &mut Ui, id: u64, label: &str, value: &mut bool) {
    let width = PANEL_WIDTH - 2.0 - 2.0 * MARGIN;
    widgets::Checkbox::new(id)
        .label(label)
        .ratio((LABEL_X + 1.0) / width)
        .ui(ui, value);
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
        widgets::Window::new(hash!(), at, size)
            .titlebar(false)
            .movable(false)
            .ui(&mut ui, |ui| {
                self.panel.origin = ui.canvas().cursor() - vec2(MARGIN, MARGIN);
                let ten = ui.calc_size("0000000000").x - 4.0;
                self.panel.wrap_chars = ((CONTENT_WIDTH - 4.0) / (ten / 10.0)).max(10.0) as usize;
                self.world_section(ui);
                self.method_section(ui);
                self.new_disc_section(ui);
                self.overlay_section(ui);
                self.selected_section(ui, &mut actions);
                self.scene_section(ui, &mut actions);
            });
        if self.panel.skins.is_some() {
            ui.pop_skin();
        }
        drop(ui);
        for action in actions {
            match action {
                Action::Apply => self.apply_disc_fields(),
                Action::Delete => self.delete_selected(),
                Action::Open => self.open_from_panel(),
                Action::Save => {
                    self.panel.scene_note = Some(match self.save_scene() {
                        Ok(path) => Note::ok(format!("Saved {}", path.display())),
                        Err(e) => Note::error(e),
                    });
                }
            }
        }
    }

    fn world_section(&mut self, ui: &mut Ui) {
        let panel = &mut self.panel;
        let r = panel.row(ui, ROW);
        panel.styled(
            ui,
            |s| &s.header,
            |panel, ui| {
                panel.label(ui, vec2(r.x, r.y + 1.0), "Controls   (L hides, H: keys)");
            },
        );
        panel.header(ui, "World");
        let w = &mut self.world;
        if let Some(e) = panel.slider(
            ui,
            "restitution",
            w.restitution,
            RESTITUTION,
            |v| round_to_step(v, 0.01),
            |v| format!("{v:.2} e disc-disc"),
        ) {
            w.restitution = e;
        }
        if let Some(e) = panel.slider(
            ui,
            "wall_restitution",
            w.wall_restitution,
            RESTITUTION,
            |v| round_to_step(v, 0.01),
            |v| format!("{v:.2} e disc-wall"),
        ) {
            w.wall_restitution = e;
        }
        // The slider shows |g| and sets it pointing down; a scene's sideways
        // gravity is only replaced once the slider is moved.
        if let Some(g) = panel.slider(
            ui,
            "gravity",
            w.gravity.length(),
            GRAVITY,
            snap_gravity,
            |v| {
                if v == 0.0 {
                    "gravity off".to_string()
                } else {
                    format!("g {v:.2} m/s^2")
                }
            },
        ) {
            w.gravity = DVec2::new(0.0, -g);
        }
        let (labels, index) = choices(&Boundary::ALL.map(Boundary::name), w.boundary.name());
        if let Some(k) = combo(ui, hash!(), "boundary", &labels, index) {
            w.boundary = Boundary::ALL[k];
        }
        let scales = TIME_SCALES.map(|s| format!("x{s}"));
        let index = self.clock.time_scale_index();
        if let Some(k) = combo(ui, hash!(), "time scale", &scales, index) {
            self.clock.set_time_scale_index(k);
        }
    }

    fn method_section(&mut self, ui: &mut Ui) {
        self.panel.header(ui, "Method");
        let w = &mut self.world;
        let (labels, index) = choices(&METHODS, w.method);
        if let Some(k) = combo(ui, hash!(), "method", &labels, index) {
            w.method = METHODS[k];
        }
        let (labels, index) = choices(&BROAD_PHASES, w.broad_phase);
        if let Some(k) = combo(ui, hash!(), "broad phase", &labels, index) {
            w.broad_phase = BROAD_PHASES[k];
        }
        let (labels, index) = choices(&SUBSTEPS, w.substeps);
        if let Some(k) = combo(ui, hash!(), "substeps", &labels, index) {
            w.substeps = SUBSTEPS[k];
        }
    }

    fn new_disc_section(&mut self, ui: &mut Ui) {
        let panel = &mut self.panel;
        panel.header(ui, "New discs (drag on empty space)");
        let biggest = 0.45 * self.world.size.min_element();
        if let Some(r) = panel.slider(
            ui,
            "new_radius",
            self.new_disc.radius,
            NEW_RADIUS,
            |v| round_significant(v, 2),
            |v| format!("radius {v:.2} m"),
        ) {
            self.new_disc.radius = r.min(biggest);
        }
        if let Some(m) = panel.slider(
            ui,
            "new_mass",
            self.new_disc.mass,
            NEW_MASS,
            |v| round_significant(v, 2),
            |v| format!("mass {} kg", field_text(v)),
        ) {
            self.new_disc.mass = m;
        }
    }

    fn overlay_section(&mut self, ui: &mut Ui) {
        self.panel.header(ui, "Overlays");
        let o = &mut self.overlays;
        checkbox(ui, hash!(), "velocity arrows", &mut o.velocity);
        checkbox(ui, hash!(), "momentum arrows", &mut o.momentum);
        checkbox(ui, hash!(), "totals (HUD)", &mut o.hud);
        const SCOPES: [ReadoutScope; 3] =
            [ReadoutScope::Off, ReadoutScope::Selected, ReadoutScope::All];
        let labels = ["off", "selected", "all"].map(String::from);
        let index = SCOPES.iter().position(|&s| s == o.readouts).unwrap_or(0);
        if let Some(k) = combo(ui, hash!(), "readouts", &labels, index) {
            o.readouts = SCOPES[k];
        }
    }

    fn selected_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        let selected = self.selected.filter(|&i| i < self.world.particles.len());
        let Some(i) = selected else {
            self.panel.fields.disc = None;
            self.panel.header(ui, "Selected disc");
            let r = self.panel.row(ui, ROW);
            self.panel
                .label(ui, vec2(r.x, r.y + 1.0), "none: click a disc to edit it");
            return;
        };
        let p = self.world.particles[i];
        let panel = &mut self.panel;
        panel.header(ui, &format!("Selected disc {i}"));
        let fields = &mut panel.fields;
        if fields.disc != Some(i) {
            *fields = DiscFields {
                disc: Some(i),
                ..DiscFields::default()
            };
        }
        // Untouched fields follow the disc as it moves.
        let live = [p.mass, p.radius, p.vel.x, p.vel.y].map(field_text);
        for (k, value) in live.into_iter().enumerate() {
            if fields.text[k] == fields.shown[k] {
                fields.text[k] = value.clone();
                fields.shown[k] = value;
            }
        }
        const KEYS: [&str; 4] = ["disc_mass", "disc_radius", "disc_vx", "disc_vy"];
        let mut enter = false;
        for k in 0..4 {
            let r = panel.row(ui, ROW);
            let at = Rect::new(r.x, r.y + 1.0, CONTROL_WIDTH, ROW - 2.0);
            let mut text = std::mem::take(&mut panel.fields.text[k]);
            if panel.text_field(ui, KEYS[k], at, &mut text) && is_key_pressed(KeyCode::Enter) {
                enter = true;
            }
            panel.fields.text[k] = text;
            panel.row_label(ui, r, FIELD_UNITS[k]);
        }
        let r = panel.row(ui, ROW + 2.0);
        let apply = Rect::new(r.x, r.y, 110.0, r.h);
        let delete = Rect::new(r.x + LABEL_X, r.y, 80.0, r.h);
        if panel.button(ui, "apply", apply, "Apply (Enter)") || enter {
            ui.clear_input_focus();
            actions.push(Action::Apply);
        }
        if panel.button(ui, "delete", delete, "Delete") {
            actions.push(Action::Delete);
        }
        if let Some(note) = panel.fields.note.clone() {
            panel.note(ui, &note);
        }
    }

    fn scene_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        let panel = &mut self.panel;
        panel.header(ui, "Scene file (TOML)");
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

    /// Writes the edited fields into the selected disc, or says what is wrong.
    fn apply_disc_fields(&mut self) {
        let Some(i) = self.selected.filter(|&i| i < self.world.particles.len()) else {
            return;
        };
        let fields = &mut self.panel.fields;
        let changed: [Option<&str>; 4] = std::array::from_fn(|k| {
            (fields.text[k] != fields.shown[k]).then_some(fields.text[k].as_str())
        });
        let biggest = 0.45 * self.world.size.min_element();
        fields.note = Some(match parse_disc_edit(changed, biggest) {
            Ok(edit) if edit.is_empty() => Note::ok("Nothing changed: type a new value first"),
            Ok(edit) => {
                edit.apply(&mut self.world.particles[i]);
                // Let every field follow the disc again.
                fields.shown = fields.text.clone();
                Note::ok(format!("Applied to disc {i}"))
            }
            Err(e) => Note::error(e),
        });
    }

    /// Deletes the selected disc (the panel's button and the Delete key).
    pub(super) fn delete_selected(&mut self) {
        if let Some(i) = self.selected.take() {
            if i < self.world.particles.len() {
                self.world.particles.remove(i);
                self.gesture.on_removed(i);
            }
        }
    }

    /// Opens the file named in the path field; a bad file is reported and
    /// the current scene stays.
    fn open_from_panel(&mut self) {
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

    /// Fits the box to the window, beside the panel when it is shown.
    pub(super) fn fit_camera(&mut self) {
        let right = f64::from(self.panel.width_on_screen());
        self.camera.fit_left_of(self.world.size, 30.0, right);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use impulse::method::Setting;
    use impulse::Color as DiscColor;

    #[test]
    fn log_sliders_map_equal_distances_to_equal_ratios() {
        let s = NEW_MASS;
        assert!((s.value(0.0) - 0.01).abs() < 1e-15);
        assert!((s.value(1.0) - 100.0).abs() < 1e-12);
        assert!(
            (s.value(0.5) - 1.0).abs() < 1e-12,
            "the middle of 0.01..100 is 1"
        );
        assert!((s.value(0.75) - 10.0).abs() < 1e-12);
        for v in [0.01, 0.3, 1.0, 42.0, 100.0] {
            assert!((s.value(s.fraction(v)) - v).abs() < 1e-12 * v, "{v}");
        }
        assert_eq!(s.fraction(1e-9), 0.0, "clamped below");
        assert_eq!(s.fraction(1e9), 1.0, "clamped above");
        assert_eq!(s.fraction(0.0), 0.0, "log of zero is clamped, not NaN");
        assert_eq!(s.fraction(f64::NAN), 0.0);
        assert_eq!(s.value(f64::NAN), 0.01);
        assert_eq!(s.value(-3.0), 0.01);
        assert_eq!(s.value(7.0), 100.0);
    }

    #[test]
    fn linear_sliders_and_rounding() {
        let s = RESTITUTION;
        assert_eq!(s.fraction(0.25), 0.25);
        assert_eq!(s.value(0.5), 0.5);
        assert_eq!(s.fraction(2.0), 1.0);
        assert_eq!(round_to_step(0.456, 0.01), 0.46);
        assert_eq!(round_significant(0.04137, 2), 0.041);
        assert_eq!(round_significant(1234.0, 2), 1200.0);
        assert_eq!(round_significant(0.0, 2), 0.0);
        assert_eq!(snap_gravity(9.7), EARTH_GRAVITY);
        assert_eq!(snap_gravity(9.9), EARTH_GRAVITY);
        assert!((snap_gravity(3.04) - 3.0).abs() < 1e-12);
        assert_eq!(snap_gravity(0.02), 0.0, "the left end switches gravity off");
    }

    #[test]
    fn disc_fields_parse_only_what_changed_and_refuse_bad_numbers() {
        let edit = parse_disc_edit([Some("2.5"), None, Some(" -1e-3 "), None], 4.0).unwrap();
        assert_eq!(
            edit,
            DiscEdit {
                mass: Some(2.5),
                radius: None,
                vx: Some(-1e-3),
                vy: None
            }
        );
        assert!(parse_disc_edit([None; 4], 4.0).unwrap().is_empty());
        let error = |fields| parse_disc_edit(fields, 4.0).unwrap_err();
        assert_eq!(
            error([Some("abc"), None, None, None]),
            "mass: \"abc\" is not a number"
        );
        assert_eq!(
            error([Some("0"), None, None, None]),
            "mass must be positive"
        );
        assert_eq!(
            error([None, Some("-1"), None, None]),
            "radius must be positive"
        );
        assert_eq!(
            error([None, Some("5"), None, None]),
            "radius must be at most 4 m here"
        );
        assert_eq!(error([None, None, Some("inf"), None]), "vx must be finite");
        assert_eq!(
            error([None, None, None, Some("1e999")]),
            "vy must be finite"
        );
        assert_eq!(error([None, None, None, Some("NaN")]), "vy must be finite");
        assert_eq!(error([None, None, Some("  "), None]), "vx: type a number");
        assert_eq!(
            error([None, Some("1,5"), None, None]),
            "radius: \"1,5\" is not a number"
        );
    }

    #[test]
    fn an_edit_changes_only_its_quantities() {
        let mut p = Particle::new(
            DVec2::new(1.0, 2.0),
            DVec2::new(3.0, 4.0),
            1.0,
            0.5,
            DiscColor::rgb(1, 2, 3),
        );
        DiscEdit {
            radius: Some(0.25),
            vy: Some(-1.0),
            ..DiscEdit::default()
        }
        .apply(&mut p);
        assert_eq!(
            (p.mass, p.radius, p.vel),
            (1.0, 0.25, DVec2::new(3.0, -1.0))
        );
        assert_eq!(p.pos, DVec2::new(1.0, 2.0));
    }

    #[test]
    fn fields_show_short_numbers() {
        assert_eq!(field_text(1.0), "1");
        assert_eq!(field_text(0.1 + 0.2), "0.3");
        assert_eq!(field_text(-2.345678), "-2.3457");
        assert_eq!(field_text(-0.00001), "-1.0000e-5");
        assert_eq!(field_text(-0.00004), "-4.0000e-5");
        assert_eq!(field_text(0.0), "0");
        assert_eq!(field_text(2.5e9), "2.5000e9");
        for v in [1.0, 0.3, -2.3457, 1e-5, 2.5e9] {
            assert_eq!(field_text(v).parse::<f64>().unwrap(), v, "{v} reads back");
        }
    }

    #[test]
    fn messages_wrap_at_spaces_and_cut_long_paths() {
        assert_eq!(wrap("one two three", 7), ["one two", "three"]);
        assert_eq!(wrap("", 10), [""]);
        assert_eq!(
            wrap("/tmp/abcdefghij/bad.toml: line 3", 10),
            ["/tmp/abcde", "fghij/bad.", "toml: line", "3"]
        );
        for line in wrap("a bb ccc dddd eeeee ffffff ggggggggggggggg", 5) {
            assert!(line.chars().count() <= 5, "{line}");
        }
    }

    #[test]
    fn combo_lists_show_values_that_are_not_among_the_choices() {
        assert_eq!(
            choices(&SUBSTEPS, Setting::Fixed(4)),
            (
                ["auto", "1", "2", "4", "8", "16"]
                    .map(String::from)
                    .to_vec(),
                3
            )
        );
        let (labels, index) = choices(&SUBSTEPS, Setting::Fixed(3));
        assert_eq!((labels.len(), index, labels[index].as_str()), (7, 6, "3"));
        assert_eq!(choices(&METHODS, Setting::Auto).1, 0);
        assert_eq!(choices(&BROAD_PHASES, BROAD_PHASES[4]).1, 4);
    }
}
