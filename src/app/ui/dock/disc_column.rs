//! The Discs table's first column, each disc's colour and number, kept at
//! the table's left edge while the table is scrolled sideways. On a
//! projector the table is wider than the dock and scrolls to its energy
//! column; without this its rows there belonged to no disc in sight.
//!
//! egui's table has no fixed columns, so the column the table scrolled out
//! is drawn again over the table's left edge, and answers a click as the
//! number it stands for does (it selects the disc).

use super::super::Cx;
use crate::app::numbers::disc_number;
use egui::{Color32, Rect};

/// A cell of the first column as the table laid it out: where it is (in
/// the scrolled content, so out at the left when scrolled), and the part of
/// the table in sight round it.
#[derive(Clone, Copy, Debug)]
pub struct FirstCell {
    pub rect: Rect,
    pub in_sight: Rect,
}

/// The first column of one frame's table: its heading, and each row laid
/// out with its disc and colour.
#[derive(Default)]
pub struct FirstColumn {
    pub heading: Option<(FirstCell, String)>,
    pub rows: Vec<(FirstCell, usize, Color32)>,
}

impl FirstColumn {
    /// Draws the column at the left edge of what `ui` has in sight where
    /// the table has scrolled it out of it, and notes where each number is
    /// seen as `discs_number_{disc}` (over where the table put it). Returns
    /// the disc whose number was clicked.
    pub fn keep_in_sight(
        &self,
        ui: &egui::Ui,
        selected: Option<usize>,
        cx: &mut Cx,
    ) -> Option<usize> {
        let edge = ui.clip_rect().left();
        let scrolled = |cell: &FirstCell| cell.rect.left() < edge - 0.5;
        let moved = |cell: &FirstCell| {
            Rect::from_min_size(egui::pos2(edge, cell.rect.top()), cell.rect.size())
                .intersect(cell.in_sight)
        };
        let visuals = ui.visuals();
        let font = egui::TextStyle::Body.resolve(ui.style());
        let line = visuals.widgets.noninteractive.bg_stroke;
        let gap = ui.spacing().item_spacing.x;
        if let Some((cell, heading)) = self.heading.as_ref().filter(|(c, _)| scrolled(c)) {
            let rect = moved(cell);
            let painter = ui.painter().with_clip_rect(rect);
            painter.rect_filled(rect, 0.0, visuals.panel_fill);
            painter.text(
                rect.left_center() + egui::vec2(gap, 0.0),
                egui::Align2::LEFT_CENTER,
                heading,
                font.clone(),
                visuals.strong_text_color(),
            );
            painter.vline(rect.right() - 0.5, rect.y_range(), line);
        }
        let mut clicked = None;
        for (cell, disc, color) in &self.rows {
            if !scrolled(cell) {
                continue;
            }
            let rect = moved(cell);
            if rect.height() <= 0.0 {
                continue;
            }
            let chosen = selected == Some(*disc);
            // The row's own background, as the table paints it: every
            // other row striped (rows are in the discs' order, and a long
            // table lays out only those in sight), the chosen one marked.
            let fill = if chosen {
                visuals.selection.bg_fill
            } else if disc % 2 == 0 {
                visuals.faint_bg_color
            } else {
                Color32::TRANSPARENT
            };
            let painter = ui.painter().with_clip_rect(rect);
            let whole = Rect::from_min_size(egui::pos2(edge, cell.rect.top()), cell.rect.size());
            painter.rect_filled(whole, 0.0, visuals.panel_fill);
            painter.rect_filled(whole, 0.0, fill);
            let dot = whole.left_center() + egui::vec2(gap + 7.0, 0.0);
            painter.circle_filled(dot, 7.0, *color);
            let text = if chosen {
                visuals.selection.stroke.color
            } else {
                visuals.text_color()
            };
            let number = painter.text(
                dot + egui::vec2(7.0 + gap, 0.0),
                egui::Align2::LEFT_CENTER,
                disc_number(*disc).to_string(),
                font.clone(),
                text,
            );
            painter.vline(whole.right() - 0.5, whole.y_range(), line);
            let id = ui.id().with(("discs_number", *disc));
            // Clicked, not focused: Tab reaches the number in the table.
            if ui.interact(rect, id, egui::Sense::CLICK).clicked() {
                clicked = Some(*disc);
            }
            cx.marks
                .note(format!("discs_number_{disc}"), number.intersect(rect));
        }
        clicked
    }
}
