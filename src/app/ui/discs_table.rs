//! The Discs tab: every disc's mass, position, velocity, speed, momentum and
//! kinetic energy in a table (like PhET's "more data"; when spin is shown
//! also its spin ω, rotational KE and angular momentum L), with the mass and
//! the velocity editable in place. An edit is checked before it touches the
//! disc ([`parse_disc_edit`]); a bad one keeps the disc as it was and says
//! why above the table, where it is seen without scrolling.

use super::controls::select_all_on_focus;
use super::numbers::{field, plain};
use super::{show_note, Note};
use crate::app::App;
use egui::Color32;
use egui_extras::{Column, TableBuilder};
use impulse::Particle;

/// The selected disc's editable quantities, in field order.
pub const FIELDS: [&str; 4] = ["mass", "radius", "v_x", "v_y"];

/// New values for a disc; `None` leaves a quantity as it is.
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

impl App {
    /// With "size follows mass", a new mass brings its radius, refused if
    /// the disc would then overlap another or cross a wall; otherwise the
    /// edit as it is.
    pub(in crate::app) fn sized_edit(
        &self,
        i: usize,
        mut edit: DiscEdit,
    ) -> Result<DiscEdit, String> {
        let (Some(m), true) = (edit.mass, self.size_follows_mass) else {
            return Ok(edit);
        };
        let r = crate::app::interaction::radius_for_mass(m);
        let w = &self.world;
        let Some(p) = w.particles.get(i) else {
            return Ok(edit);
        };
        let size = plain(r, 2);
        let overlapped = w.particles.iter().enumerate().find(|&(j, q)| {
            j != i
                && w.laws
                    .boundary
                    .separation(q.pos, p.pos, w.laws.size)
                    .length()
                    < r + q.radius
        });
        if let Some((j, _)) = overlapped {
            return Err(format!(
                "at {} kg the disc would be {size} m in radius (size follows mass) and overlap disc {j}",
                plain(m, 3)
            ));
        }
        if !w.laws.boundary.admits(w.laws.walls, w.laws.size, p.pos, r) {
            return Err(format!(
                "at {} kg the disc would be {size} m in radius (size follows mass) and cross a wall",
                plain(m, 3)
            ));
        }
        edit.radius = Some(r);
        Ok(edit)
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
            .replace('−', "-")
            .parse::<f64>()
            .map_err(|_| format!("{name}: “{text}” is not a number"))?;
        if !v.is_finite() {
            return Err(format!("{name} must be a finite number"));
        }
        if k < 2 && v <= 0.0 {
            return Err(format!("{name} must be more than 0"));
        }
        if k == 1 && v > max_radius {
            return Err(format!(
                "radius must be at most {} m here",
                field(max_radius)
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

/// A cell being edited: disc, field (index into [`FIELDS`]) and its text.
#[derive(Clone, Debug, PartialEq)]
pub struct CellEdit {
    pub disc: usize,
    pub field: usize,
    pub text: String,
}

/// The table's edit in progress and how the last one went.
#[derive(Clone, Debug, Default)]
pub struct TableState {
    pub editing: Option<CellEdit>,
    pub note: Option<Note>,
}

/// The spin columns' headings, with units on a second line, and what they
/// mean.
const SPIN_HEADINGS: [(&str, &str); 3] = [
    (
        "spin ω\n(rad/s)",
        "how fast the disc turns: radians per second, anticlockwise positive",
    ),
    (
        "rotational\nKE (J)",
        "the energy of its turning, ½·I·ω² with I = ½·m·r²",
    ),
    (
        "L\n(kg·m²/s)",
        "angular momentum about the corner (0, 0): m·(x·v_y − y·v_x) of its moving plus I·ω of its turning",
    ),
];

/// Column headings, with units.
const HEADINGS: [&str; 9] = [
    "disc",
    "m (kg)",
    "x (m)",
    "y (m)",
    "v_x (m/s)",
    "v_y (m/s)",
    "|v| (m/s)",
    "|p| (kg·m/s)",
    "KE (J)",
];

impl App {
    /// The Discs tab.
    pub(super) fn discs_tab(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("Click a mass or velocity to change it; Enter applies, Esc cancels.");
            if let Some(note) = self.ui.table.note.clone() {
                let r = show_note(ui, &note);
                self.ui
                    .note_widget("table_note", r.rect, super::px_per_point(ui.ctx()));
            }
        });
        if self.world.particles.is_empty() {
            ui.label("No discs: drag on empty space to launch one.");
            return;
        }
        let row_height = ui.spacing().interact_size.y + 2.0;
        let mut commit: Option<CellEdit> = None;
        let mut start: Option<CellEdit> = None;
        let mut cancel = false;
        let ppp = super::px_per_point(ui.ctx());
        let mut cells = Vec::new();
        let particles = &self.world.particles;
        let editing = self.ui.table.editing.clone();
        let mut edit_text = editing.as_ref().map(|e| e.text.clone()).unwrap_or_default();
        let selected = self.selected;
        let mut select = None;
        let mut focused = false;
        let spin = crate::app::draw::spin_shown(&self.world);
        let spin_columns = if spin { SPIN_HEADINGS.len() } else { 0 };
        // With the spin columns, narrower ones (units under the names), so
        // that all twelve fit the dock of a 1280-pixel window.
        let (column_width, cell_width, header_height) = if spin {
            (64.0, 62.0, 2.0 * row_height)
        } else {
            (90.0, 84.0, row_height)
        };
        // Wider than the dock with the spin columns: it scrolls sideways
        // then (only then, as its bar would lie over the last row). The rows
        // scroll within the dock's height, with room for two of them at
        // least: the table's own least height (200 points) grew a short dock
        // over the world when there were many discs.
        let height = ui.available_height();
        let two_rows = 2.0 * (row_height + ui.spacing().item_spacing.y);
        egui::ScrollArea::horizontal()
            .id_salt("discs_table_scroll")
            .enable_scrolling(spin)
            .show(ui, |ui| {
                TableBuilder::new(ui)
                    .id_salt("discs_table")
                    .min_scrolled_height(two_rows)
                    .max_scroll_height((height - header_height).max(two_rows))
                    .striped(true)
                    .cell_layout(egui::Layout::left_to_right(egui::Align::Center))
                    .column(Column::auto().at_least(60.0))
                    .columns(Column::auto().at_least(column_width), 8 + spin_columns)
                    .header(header_height, |mut header| {
                        for h in HEADINGS {
                            let h = if spin {
                                h.replacen(" (", "\n(", 1)
                            } else {
                                h.to_string()
                            };
                            header.col(|ui| {
                                ui.strong(h);
                            });
                        }
                        for (h, meaning) in &SPIN_HEADINGS[..spin_columns] {
                            header.col(|ui| {
                                ui.strong(*h).on_hover_text(*meaning);
                            });
                        }
                    })
                    .body(|body| {
                        body.rows(row_height, particles.len(), |mut row| {
                            let i = row.index();
                            let p = &particles[i];
                            row.set_selected(selected == Some(i));
                            row.col(|ui| {
                                let c = p.color;
                                let (rect, _) = ui.allocate_exact_size(
                                    egui::vec2(14.0, 14.0),
                                    egui::Sense::hover(),
                                );
                                ui.painter().circle_filled(
                                    rect.center(),
                                    7.0,
                                    Color32::from_rgb(c.r, c.g, c.b),
                                );
                                if ui
                                    .selectable_label(selected == Some(i), format!("{i}"))
                                    .clicked()
                                {
                                    select = Some(i);
                                }
                            });
                            let values = [
                                p.mass,
                                p.pos.x,
                                p.pos.y,
                                p.vel.x,
                                p.vel.y,
                                p.vel.length(),
                                p.momentum().length(),
                                p.kinetic_energy(),
                            ];
                            for (column, value) in values.into_iter().enumerate() {
                                // Editable: mass (column 0), v_x (3), v_y (4).
                                let field_index = match column {
                                    0 => Some(0),
                                    3 => Some(2),
                                    4 => Some(3),
                                    _ => None,
                                };
                                row.col(|ui| match field_index {
                                    None => {
                                        ui.label(plain(value, 3));
                                    }
                                    Some(f) => {
                                        let mine = editing
                                            .as_ref()
                                            .is_some_and(|e| e.disc == i && e.field == f);
                                        let mut shown = plain(value, 3).replace('−', "-");
                                        let text = if mine { &mut edit_text } else { &mut shown };
                                        let bad = mine
                                            && self.ui.table.note.as_ref().is_some_and(|n| n.error);
                                        let mut edit = egui::TextEdit::singleline(text)
                                            .desired_width(cell_width);
                                        if bad {
                                            edit = edit.text_color(Color32::from_rgb(220, 40, 30));
                                        }
                                        let r = ui.add(edit);
                                        select_all_on_focus(ui, &r, text);
                                        focused |= r.has_focus();
                                        let name = ["discs_mass", "", "discs_vx", "discs_vy"][f];
                                        cells.push((format!("{name}_{i}"), r.rect));
                                        if r.changed() && !mine {
                                            start = Some(CellEdit {
                                                disc: i,
                                                field: f,
                                                text: text.clone(),
                                            });
                                        }
                                        if r.lost_focus() {
                                            if ui.input(|inp| inp.key_pressed(egui::Key::Escape)) {
                                                cancel = true;
                                            } else if mine || r.changed() {
                                                commit = Some(CellEdit {
                                                    disc: i,
                                                    field: f,
                                                    text: text.clone(),
                                                });
                                            }
                                        }
                                    }
                                });
                            }
                            if spin {
                                for value in [p.spin, p.rotational_energy(), p.angular_momentum()] {
                                    row.col(|ui| {
                                        ui.label(plain(value, 3));
                                    });
                                }
                            }
                        });
                    });
            });
        self.ui.text_focus |= focused;
        for (name, rect) in cells {
            self.ui.note_widget(name, rect, ppp);
        }
        if let Some(i) = select {
            self.selected = Some(i);
        }
        if let Some(e) = self.ui.table.editing.as_mut() {
            e.text = edit_text;
        }
        if let Some(s) = start {
            self.ui.table.editing = Some(s);
        }
        if cancel {
            self.ui.table.editing = None;
            self.ui.table.note = None;
        }
        if let Some(c) = commit {
            self.commit_cell(c);
        }
    }

    /// Applies an edited cell, or keeps the disc and says what is wrong.
    fn commit_cell(&mut self, cell: CellEdit) {
        if cell.disc >= self.world.particles.len() {
            self.ui.table.editing = None;
            return;
        }
        // Enter leaves the cell; the keyboard stays with the panel.
        self.ui.panel_keyboard = true;
        let mut changed = [None; 4];
        changed[cell.field] = Some(cell.text.as_str());
        match parse_disc_edit(changed, f64::INFINITY).and_then(|e| self.sized_edit(cell.disc, e)) {
            Ok(edit) => {
                self.remember_edit("edit a disc");
                let p = &mut self.world.particles[cell.disc];
                edit.apply(p);
                let value = [p.mass, p.radius, p.vel.x, p.vel.y][cell.field];
                let unit = ["kg", "m", "m/s", "m/s"][cell.field];
                self.ui.table.note = Some(Note::ok(format!(
                    "Disc {}: {} = {} {unit}",
                    cell.disc,
                    FIELDS[cell.field],
                    field(value)
                )));
                self.ui.table.editing = None;
                self.totals.clear();
            }
            Err(e) => {
                self.ui.table.note = Some(Note::error(format!(
                    "Disc {}: {e}; nothing changed",
                    cell.disc
                )));
                self.ui.table.editing = Some(cell);
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
    fn edits_parse_only_what_changed_and_refuse_bad_numbers() {
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
            "mass: “abc” is not a number"
        );
        assert_eq!(
            error([Some("0"), None, None, None]),
            "mass must be more than 0"
        );
        assert_eq!(
            error([None, Some("-1"), None, None]),
            "radius must be more than 0"
        );
        assert_eq!(
            error([None, Some("5"), None, None]),
            "radius must be at most 4 m here"
        );
        assert_eq!(
            error([None, None, Some("inf"), None]),
            "v_x must be a finite number"
        );
        assert_eq!(
            error([None, None, None, Some("1e999")]),
            "v_y must be a finite number"
        );
        assert_eq!(
            error([None, None, None, Some("NaN")]),
            "v_y must be a finite number"
        );
        assert_eq!(error([None, None, Some("  "), None]), "v_x: type a number");
        assert_eq!(
            error([None, Some("1,5"), None, None]),
            "radius: “1,5” is not a number"
        );
        assert_eq!(
            parse_disc_edit([None, None, Some("−2"), None], 4.0)
                .unwrap()
                .vx,
            Some(-2.0),
            "a typographic minus"
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
}
