//! A table's header row kept at the top of its scroll area while the
//! table's rows are still in sight. At a projector the ledger's page holds
//! three or four rows: scrolled to the discs' energies, its numbers stood
//! under no "before" and "after".
//!
//! egui's grid has no fixed header, so the row the page scrolled out is
//! drawn again over the top of what is in sight (the same texts at the same
//! columns, on the panel's colour, a line under it), the way
//! [`super::disc_column`] keeps the Discs table's first column.

use super::super::Cx;
use egui::{Rect, RichText};

/// A table's header as laid out this frame: each cell's place (in the
/// scrolled content, so above the top when scrolled past) and text.
#[derive(Default)]
pub struct HeaderRow {
    pub cells: Vec<(Rect, String)>,
}

impl HeaderRow {
    /// Notes a header cell the table laid out.
    pub fn add(&mut self, response: &egui::Response, text: impl Into<String>) {
        self.cells.push((response.rect, text.into()));
    }

    /// Draws the row again at the top of what `ui` has in sight where the
    /// page has scrolled it (even partly) out of sight while the table's
    /// rows, `table`, still show under it; notes where as `name`.
    pub fn keep_in_sight(&self, ui: &egui::Ui, cx: &mut Cx, name: &str, table: Rect) {
        let Some(top) = self.cells.iter().map(|(r, _)| r.top()).reduce(f32::min) else {
            return;
        };
        let bottom = self
            .cells
            .iter()
            .map(|(r, _)| r.bottom())
            .fold(top, f32::max);
        let sight = ui.clip_rect();
        let height = bottom - top;
        if top >= sight.top() - 0.5 || table.bottom() <= sight.top() + height {
            return;
        }
        let gap = ui.spacing().item_spacing.y;
        let band = Rect::from_min_max(
            egui::pos2(table.left().min(sight.left()), sight.top()),
            egui::pos2(sight.right(), sight.top() + height + gap),
        );
        let visuals = ui.visuals();
        let painter = ui.painter().with_clip_rect(band.intersect(sight));
        painter.rect_filled(band, 0.0, visuals.panel_fill);
        let font = egui::TextStyle::Body.resolve(ui.style());
        for (cell, text) in &self.cells {
            let galley = egui::WidgetText::from(RichText::new(text).strong()).into_galley(
                ui,
                Some(egui::TextWrapMode::Wrap),
                cell.width().max(1.0),
                font.clone(),
            );
            let at = egui::pos2(cell.left(), sight.top() + (cell.top() - top));
            painter.galley(at, galley, visuals.strong_text_color());
        }
        painter.hline(
            band.x_range(),
            band.bottom() - 0.5,
            visuals.widgets.noninteractive.bg_stroke,
        );
        cx.marks.note(name, band.intersect(sight));
    }
}
