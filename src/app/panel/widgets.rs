//! The panel's building blocks: the row layout (each widget reserves the
//! next row of the panel's canvas: a control column on the left, a label
//! column on the right), labels, buttons, text fields, combo boxes, check
//! boxes, wrapped notes and the hand-drawn sliders.
//!
//! The sliders are drawn on the UI's canvas rather than with the built-in
//! `Slider`: that one carries a number box which takes the keyboard without
//! the program being able to tell, is linear only, and moves only when its
//! 8-pixel handle is caught. These jump to a click anywhere on the track and
//! can run on a log scale ([`SliderScale`]).

use super::{Note, Panel, Skins, CONTENT_WIDTH, CONTROL_WIDTH, LABEL_X, MARGIN, PANEL_WIDTH, ROW};
use macroquad::prelude::*;
use macroquad::ui::{hash, widgets, Skin, Ui};

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

impl Panel {
    /// Reserves the next row of the panel; its rectangle on screen.
    pub(super) fn row(&self, ui: &mut Ui, height: f32) -> Rect {
        let at = ui.canvas().request_space(vec2(CONTENT_WIDTH, height));
        Rect::new(at.x, at.y, CONTENT_WIDTH, height)
    }

    pub(super) fn label(&self, ui: &mut Ui, at: Vec2, text: &str) {
        widgets::Label::new(text).position(at - self.origin).ui(ui);
    }

    pub(super) fn button(&mut self, ui: &mut Ui, key: &'static str, at: Rect, text: &str) -> bool {
        self.widgets.insert(key, [at.x, at.y, at.w, at.h]);
        widgets::Button::new(text)
            .position(vec2(at.x, at.y) - self.origin)
            .size(vec2(at.w, at.h))
            .ui(ui)
    }

    /// A one-line text field; whether it was typed into this frame (Enter
    /// and Escape included).
    pub(super) fn text_field(
        &mut self,
        ui: &mut Ui,
        key: &'static str,
        at: Rect,
        text: &mut String,
    ) -> bool {
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
    pub(super) fn header(&self, ui: &mut Ui, title: &str) {
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
    pub(super) fn row_label(&self, ui: &mut Ui, r: Rect, text: &str) {
        self.label(ui, vec2(r.x + LABEL_X, r.y + 1.0), text);
    }

    pub(super) fn styled(
        &self,
        ui: &mut Ui,
        skin: fn(&Skins) -> &Skin,
        f: impl FnOnce(&Self, &mut Ui),
    ) {
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
    pub(super) fn note(&self, ui: &mut Ui, note: &Note) {
        let skin: fn(&Skins) -> &Skin = if note.error { |s| &s.error } else { |s| &s.ok };
        self.lines(ui, &note.text, skin);
    }

    pub(super) fn lines(&self, ui: &mut Ui, text: &str, skin: fn(&Skins) -> &Skin) {
        for line in wrap(text, self.wrap_chars) {
            let r = self.row(ui, 17.0);
            self.styled(ui, skin, |panel, ui| {
                panel.label(ui, vec2(r.x, r.y - 1.0), &line);
            });
        }
    }

    /// A slider over `scale` showing `value`; the new value while it is
    /// dragged (after `round`), else `None`. `text` labels it.
    pub(super) fn slider(
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
pub(super) fn combo(
    ui: &mut Ui,
    id: u64,
    label: &str,
    labels: &[String],
    index: usize,
) -> Option<usize> {
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

pub(super) fn checkbox(ui: &mut Ui, id: u64, label: &str, value: &mut bool) {
    let width = PANEL_WIDTH - 2.0 - 2.0 * MARGIN;
    widgets::Checkbox::new(id)
        .label(label)
        .ratio((LABEL_X + 1.0) / width)
        .ui(ui, value);
}

#[cfg(test)]
mod tests {
    use super::super::sections::{NEW_MASS, RESTITUTION};
    use super::*;

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
    fn linear_sliders() {
        let s = RESTITUTION;
        assert_eq!(s.fraction(0.25), 0.25);
        assert_eq!(s.value(0.5), 0.5);
        assert_eq!(s.fraction(2.0), 1.0);
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
}
