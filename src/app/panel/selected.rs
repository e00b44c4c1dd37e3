//! The "Selected disc" section: text fields for the selected disc's mass,
//! radius and velocity, Apply (or Enter) and Delete.
//!
//! A field the user has not touched follows the disc as it moves; an edited
//! one keeps its text until Apply. Apply reads only the edited fields
//! ([`parse_disc_edit`]): a bad value leaves the disc as it is and says why
//! in one short line under the buttons.

use super::{Action, Note, CONTROL_WIDTH, LABEL_X, ROW};
use crate::app::App;
use impulse::Particle;
use macroquad::prelude::*;
use macroquad::ui::Ui;

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

/// The text fields of the selected disc.
#[derive(Default)]
pub(super) struct DiscFields {
    /// Which disc they were filled from.
    disc: Option<usize>,
    /// What the fields hold.
    text: [String; 4],
    /// What the disc had when the field was last filled: a field whose text
    /// differs has been edited and stops following the disc.
    shown: [String; 4],
    note: Option<Note>,
}

impl App {
    pub(super) fn selected_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
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

    /// Writes the edited fields into the selected disc, or says what is wrong.
    pub(super) fn apply_disc_fields(&mut self) {
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
    pub(in crate::app) fn delete_selected(&mut self) {
        if let Some(i) = self.selected.take() {
            if i < self.world.particles.len() {
                self.world.particles.remove(i);
                self.gesture.on_removed(i);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;
    use impulse::Color as DiscColor;

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
}
