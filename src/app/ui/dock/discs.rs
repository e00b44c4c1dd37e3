//! The Discs tab: every disc's mass, position, velocity, speed, momentum and
//! kinetic energy in a table (like PhET's "more data"; when spin is shown
//! also its spin ω, rotational KE and angular momentum L), with the mass and
//! the velocity editable in place. An edit is sent to the model, which
//! checks it before it touches the disc; a bad one keeps the disc as it was.
//! The answer shows in the strip above the dock and, where the tab has room
//! for it, on a line above the table; a refused cell stays open in red with
//! the answer as its tooltip (left with Enter, it keeps the keyboard).

use super::super::dialog::{into_sight, just_focused};
use super::super::widgets::{select_all_on_focus, show_note};
use super::super::{Cx, Stop, View};
use super::disc_column::{FirstCell, FirstColumn};
use crate::app::lang::tr;
use crate::app::model::command::EditPlace;
use crate::app::model::overlays::spin_shown;
use crate::app::model::Command;
use crate::app::numbers::{disc_number, quantity};
use crate::app::ui::tip::Tip;
use egui::Color32;
use egui_extras::{Column, TableBuilder};

/// A cell being edited: disc, field (index into [`FIELDS`]) and its text.
#[derive(Clone, Debug, PartialEq)]
pub struct CellEdit {
    pub disc: usize,
    pub field: usize,
    pub text: String,
}

/// The table's edit in progress.
#[derive(Clone, Debug, Default)]
pub struct DiscsTable {
    editing: Option<CellEdit>,
    /// An edit sent to the model, kept until it answers: refused, the cell
    /// stays open with its text; and whether it was left with Enter (then
    /// refused, the cell takes the keyboard back, its text selected to be
    /// typed over).
    sent: Option<(CellEdit, bool)>,
    /// The disc selected when the table was last shown: a disc selected
    /// since (in the world, by Q) is scrolled into sight.
    seen_selection: Option<usize>,
    /// The cell open is one the model refused: it closes when the refusal
    /// goes (a reset, another scene, an undo), not to show a red value
    /// the disc never had.
    refused: bool,
}

/// The spin columns' headings, with units on a second line, and what they
/// mean.
fn spin_headings() -> [(String, String); 3] {
    [
        (tr!("table-spin"), tr!("table-spin-hover")),
        (
            format!("{}\n(J)", tr!("totals-rotational-ke")),
            tr!("table-rotational-ke-hover"),
        ),
        (
            "L\n(kg·m²/s)".to_string(),
            tr!("table-angular-momentum-hover"),
        ),
    ]
}

/// The first column's least width (the disc's colour and number), and the
/// others', wide and narrow (with the units under the names), in points.
const FIRST_COLUMN: f32 = 60.0;
const WIDE_COLUMN: f32 = 90.0;
const NARROW_COLUMN: f32 = 64.0;
/// Up to this many discs every row of the table is laid out, each frame;
/// a larger gas lays out only the rows in sight.
const EVERY_ROW_UP_TO: usize = 100;

/// Column headings, with units; `line`: the axis of a one-dimensional
/// world, whose momentum column is signed along it.
fn headings(line: Option<usize>) -> [String; 9] {
    [
        tr!("table-disc"),
        "m (kg)".into(),
        "x (m)".into(),
        "y (m)".into(),
        "v_x (m/s)".into(),
        "v_y (m/s)".into(),
        "|v| (m/s)".into(),
        match line {
            Some(0) => "p_x (kg·m/s)".into(),
            Some(_) => "p_y (kg·m/s)".into(),
            None => "|p| (kg·m/s)".into(),
        },
        format!("{} (J)", tr!("symbol-ke")),
    ]
}

impl View for DiscsTable {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let note = model.messages.table.clone();
        // The row just edited, kept in sight as its answer comes (which
        // may take a line above the table).
        let mut refocus = false;
        let answered = self.sent.take().map(|(sent, with_enter)| {
            let disc = sent.disc;
            self.editing = note.as_ref().filter(|n| n.error).map(|_| sent);
            self.refused = self.editing.is_some();
            refocus = self.refused && with_enter;
            disc
        });
        if self.refused && !note.as_ref().is_some_and(|n| n.error) {
            (self.editing, self.refused) = (None, false);
        }
        let row_height = ui.spacing().interact_size.y + 2.0;
        // How to edit, on a line above the table where there is room for it
        // and three rows (or every disc) besides; in a short tab (a
        // projector's at 1024×768) the line would take a disc's row, and the
        // headings' tooltips say it instead.
        let line = ui.text_style_height(&egui::TextStyle::Body) + ui.spacing().item_spacing.y;
        let rows = model.world.particles.len().clamp(1, 3) as f32;
        let header = if spin_shown(&model.world) { 2.0 } else { 1.0 } * row_height;
        let needed = line + header + rows * (row_height + ui.spacing().item_spacing.y);
        let hint_line = ui.available_height() >= needed || model.world.particles.is_empty();
        // The answer to an edit goes on that line too; in a short tab it is
        // in the strip above (the model shows every answer there) and in
        // the refused cell's tooltip: a line of its own here took the row
        // edited out of sight.
        if hint_line {
            ui.horizontal_wrapped(|ui| {
                ui.label(tr!("table-line"));
                if let Some(note) = &note {
                    let r = show_note(ui, note);
                    cx.note("table_note", &r);
                }
            });
        }
        if model.world.particles.is_empty() {
            ui.label(tr!("table-no-discs"));
            return;
        }
        let how_to_edit = (!hint_line).then(|| tr!("table-line"));
        let mut commit: Option<CellEdit> = None;
        let mut start: Option<CellEdit> = None;
        let mut cancel = false;
        let mut with_enter = false;
        let mut cells = Vec::new();
        // Where each disc's number is in the table, and whether it has the
        // keyboard.
        let mut numbers = Vec::new();
        // The table's controls in the order made, for Tab (see `dialog`).
        let mut stops = Vec::new();
        let particles = &model.world.particles;
        let editing = self.editing.clone();
        let mut edit_text = editing.as_ref().map(|e| e.text.clone()).unwrap_or_default();
        let selected = model.selected;
        let mut select = None;
        // The cells typed in, noted after the table as every text field is.
        let mut fields: Vec<egui::Response> = Vec::new();
        let spin = spin_shown(&model.world);
        // On a rail, the momentum along it, signed: the column then adds
        // up to the top bar's (2.455 + 5.455 of |p| had made 7.91 where
        // light hits heavy and the total is 3).
        let line = model.world.laws.constrain.map(|axis| axis.index());
        let spin_columns = if spin { 3 } else { 0 };
        let spin_headings = spin_headings();
        // With the spin columns, narrower ones (units under the names), so
        // that all twelve fit the dock of a 1280-pixel window. (Not for want
        // of width alone: the names on two lines took the one row a
        // projector's tab has room for.)
        let columns = 8 + spin_columns;
        let gap = ui.spacing().item_spacing.x;
        let across = |width: f32| FIRST_COLUMN + columns as f32 * (width + gap) + gap;
        let (column_width, cell_width, header_height) = if spin {
            (NARROW_COLUMN, 62.0, 2.0 * row_height)
        } else {
            (WIDE_COLUMN, 84.0, row_height)
        };
        // Wider than the dock even so: it scrolls sideways (only then, as
        // its bar would lie over the last row; without it the last columns,
        // |v|, |p| and the energy, were cut off out of reach). The rows
        // scroll within the dock's height, with room for two of them at
        // least: the table's own least height (200 points) grew a short dock
        // over the world when there were many discs.
        let sideways = across(column_width) > ui.available_width();
        let height = ui.available_height();
        let one_row = row_height + ui.spacing().item_spacing.y;
        let two_rows = 2.0 * one_row;
        // No taller than the tab leaves: a table that claimed two rows in a
        // projector's tab, which has room for one, put the second out of
        // sight below the tab, where Tab went without scrolling to it.
        // The sideways bar has a thin line of its own under the rows
        // (floating, it lay over the last row's text; a thicker one took the
        // second row of a projector's tab).
        let scroll = ui.spacing().scroll;
        let sideways_bar = egui::style::ScrollStyle {
            floating: false,
            bar_width: 6.0,
            bar_inner_margin: 2.0,
            bar_outer_margin: 0.0,
            ..scroll
        };
        let bar = if sideways {
            sideways_bar.bar_width + sideways_bar.bar_inner_margin
        } else {
            0.0
        };
        let rows_height = (height - header_height - bar).max(one_row);
        // What the keyboard has just reached, to be shown sideways: the
        // rows scroll in an area of their own, which takes every scroll
        // request made inside it, so the sideways one is made after the
        // table. From a row's
        // last field (v_y) to its last column: |v|, |p| and the energy
        // hold no control Tab could reach.
        let mut reveal: Option<egui::Rect> = None;
        let mut first = FirstColumn::default();
        // A disc picked in the world had its row highlighted out of sight.
        let newly_selected = selected.filter(|_| selected != self.seen_selection);
        self.seen_selection = selected;
        if sideways {
            ui.spacing_mut().scroll = sideways_bar;
        }
        egui::ScrollArea::horizontal()
            .id_salt("discs_table_scroll")
            .enable_scrolling(sideways)
            .show(ui, |ui| {
                ui.spacing_mut().scroll = scroll;
                let mut table = TableBuilder::new(ui);
                if let Some(disc) = answered.or(newly_selected) {
                    table = table.scroll_to_row(disc, None);
                }
                table
                    .id_salt("discs_table")
                    .min_scrolled_height(two_rows.min(rows_height))
                    .max_scroll_height(rows_height)
                    .striped(true)
                    .cell_layout(egui::Layout::left_to_right(egui::Align::Center))
                    .column(Column::auto().at_least(FIRST_COLUMN))
                    .columns(Column::auto().at_least(column_width), columns)
                    .header(header_height, |mut header| {
                        // The last column noted: whether it is in sight.
                        let last = headings(line).len() - 1;
                        for (k, h) in headings(line).into_iter().enumerate() {
                            let h = if spin {
                                h.replacen(" (", "\n(", 1)
                            } else {
                                h.to_string()
                            };
                            let mut in_sight = egui::Rect::NOTHING;
                            let (_, r) = header.col(|ui| {
                                in_sight = ui.clip_rect();
                                let r = ui.strong(&h);
                                if let Some(how) = &how_to_edit {
                                    r.tip(how);
                                }
                            });
                            if k == 0 {
                                let cell = FirstCell {
                                    rect: r.rect,
                                    in_sight,
                                };
                                first.heading = Some((cell, h));
                            }
                            if k == last && spin_columns == 0 {
                                cx.note("discs_last_column", &r);
                            }
                        }
                        for (k, (h, meaning)) in spin_headings[..spin_columns].iter().enumerate() {
                            let (_, r) = header.col(|ui| {
                                ui.strong(h).tip(meaning);
                            });
                            if k + 1 == spin_columns {
                                cx.note("discs_last_column", &r);
                            }
                        }
                    })
                    .body(|mut body| {
                        let mut add_row = |mut row: egui_extras::TableRow| {
                            let i = row.index();
                            let p = &particles[i];
                            row.set_selected(selected == Some(i));
                            let c = model.overlays.disc_color(&model.world, i);
                            let color = Color32::from_rgb(c.r, c.g, c.b);
                            let mut in_sight = egui::Rect::NOTHING;
                            let (_, cell) = row.col(|ui| {
                                in_sight = ui.clip_rect();
                                let (rect, _) = ui.allocate_exact_size(
                                    egui::vec2(14.0, 14.0),
                                    egui::Sense::hover(),
                                );
                                ui.painter().circle_filled(rect.center(), 7.0, color);
                                let r = ui.selectable_label(
                                    selected == Some(i),
                                    disc_number(i).to_string(),
                                );
                                numbers.push((i, r.rect, r.has_focus()));
                                stops.push(Stop::control(&r));
                                if just_focused(&r) {
                                    reveal = Some(r.rect);
                                }
                                if r.clicked() {
                                    select = Some(i);
                                }
                            });
                            let cell = FirstCell {
                                rect: cell.rect,
                                in_sight,
                            };
                            first.rows.push((cell, i, color));
                            let values = [
                                p.mass,
                                p.pos.x,
                                p.pos.y,
                                p.vel.x,
                                p.vel.y,
                                p.vel.length(),
                                match line {
                                    Some(axis) => p.momentum()[axis],
                                    None => p.momentum().length(),
                                },
                                p.kinetic_energy(),
                            ];
                            let mut to_end = false;
                            let mut last = egui::Rect::NOTHING;
                            for (column, value) in values.into_iter().enumerate() {
                                // Editable: mass (column 0), v_x (3), v_y (4).
                                let field_index = match column {
                                    0 => Some(0),
                                    3 => Some(2),
                                    4 => Some(3),
                                    _ => None,
                                };
                                (last, _) = row.col(|ui| match field_index {
                                    None => {
                                        ui.label(quantity(value, 3));
                                    }
                                    Some(f) => {
                                        let mine = editing
                                            .as_ref()
                                            .is_some_and(|e| e.disc == i && e.field == f);
                                        let mut shown = quantity(value, 3);
                                        let text = if mine { &mut edit_text } else { &mut shown };
                                        let bad = mine && note.as_ref().is_some_and(|n| n.error);
                                        let mut edit = egui::TextEdit::singleline(text)
                                            .desired_width(cell_width);
                                        if bad {
                                            edit = edit.text_color(Color32::from_rgb(220, 40, 30));
                                        }
                                        let mut r = ui.add(edit);
                                        if mine && refocus {
                                            r.request_focus();
                                        }
                                        if let Some(note) = note.as_ref().filter(|_| bad) {
                                            r = r.tip(note.text.as_str());
                                        }
                                        select_all_on_focus(ui, &r, text);
                                        fields.push(r.clone());
                                        let name = ["discs_mass", "", "discs_vx", "discs_vy"][f];
                                        cells.push((format!("{name}_{i}"), r.rect, r.has_focus()));
                                        stops.push(Stop::control(&r));
                                        into_sight(&r);
                                        if just_focused(&r) {
                                            reveal = Some(r.rect);
                                            to_end = f == 3;
                                        }
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
                                                with_enter = ui
                                                    .input(|inp| inp.key_pressed(egui::Key::Enter));
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
                                    (last, _) = row.col(|ui| {
                                        ui.label(quantity(value, 3));
                                    });
                                }
                            }
                            if to_end {
                                reveal = reveal.map(|r| r.union(last));
                            }
                        };
                        // A class's scene: every row laid out, so that Tab
                        // reaches each (egui lays out only the rows in
                        // sight of a long table, and Tab skips the rest).
                        if particles.len() <= EVERY_ROW_UP_TO {
                            for _ in 0..particles.len() {
                                body.row(row_height, &mut add_row);
                            }
                        } else {
                            body.rows(row_height, particles.len(), add_row);
                        }
                    });
                for (i, rect, has_focus) in numbers.drain(..) {
                    let name = format!("discs_number_{i}");
                    if has_focus {
                        cx.marks.focused = Some(name.clone());
                    }
                    cx.marks.note(name, rect);
                }
                if let Some(i) = first.keep_in_sight(ui, selected, cx) {
                    select = Some(i);
                }
                if let Some(rect) = reveal {
                    // Clear of the disc numbers kept over the table's left
                    // edge: a field shown just inside the edge (Shift+Tab
                    // back to a row's mass) lay under them, heading and all.
                    let kept = first
                        .rows
                        .first()
                        .map_or(FIRST_COLUMN, |(cell, ..)| cell.rect.width())
                        + ui.spacing().item_spacing.x;
                    let rect = rect.with_min_x(rect.min.x - kept);
                    let none = egui::style::ScrollAnimation::none();
                    ui.scroll_to_rect_animation(rect, None, none);
                }
            });
        ui.spacing_mut().scroll = scroll;
        // Enter leaves the cell, changed or not; the keyboard stays with the
        // panel (a click elsewhere gives it back to the world): Enter in a
        // cell reached by Tab and left as it was had given the keys to the
        // world, and a 2 typed next opened a preset.
        for r in &fields {
            cx.marks.text_field(r);
        }
        cx.marks.stops.extend(stops);
        for (name, rect, has_focus) in cells {
            if has_focus {
                cx.marks.focused = Some(name.clone());
            }
            cx.marks.note(name, rect);
        }
        if let Some(i) = select {
            cx.send(Command::Select(Some(i)));
        }
        if let Some(e) = self.editing.as_mut() {
            e.text = edit_text;
        }
        if let Some(s) = start {
            (self.editing, self.refused) = (Some(s), false);
        }
        if cancel {
            (self.editing, self.refused) = (None, false);
        }
        if let Some(cell) = commit {
            let mut text: [Option<String>; 6] = Default::default();
            text[cell.field] = Some(cell.text.clone());
            cx.send(Command::EditDisc {
                disc: cell.disc,
                text,
                from: EditPlace::Table,
            });
            self.editing = None;
            self.sent = Some((cell, with_enter));
        }
    }
}

#[cfg(test)]
mod tests;
