//! The bottom dock: a row of tabs (fixed height) and the chosen tab under
//! it, in the height the layout grants (its content scrolls or shrinks in
//! it). Each tab is a [`View`] in a file of its own, listed once in
//! [`tabs`]: *Totals* plots p_x, p_y, L and the energy against time;
//! *Collisions* is the ledger; *Discs* the table of every disc; *Speeds*
//! the histogram against Maxwell–Boltzmann; *Momenta* every disc's
//! momentum tip to tail and their sum; *In words* the scene described and
//! what was said as it happened (for a screen reader, in the browser's
//! page too).

mod collisions;
mod disc_column;
pub mod discs;
pub mod edge;
mod momenta;
mod pinned_header;
mod plots;
mod speeds;
mod totals;
mod words;

use super::{Cx, View};
use crate::app::model::{Command, DockTab};
use crate::app::ui::tip::Tip;
use crate::app::ui::widgets::button_text_width;
use egui::RichText;

/// The narrowest tab laid out beside the open drawer (points).
const MIN_BESIDE_DRAWER: f32 = 400.0;

/// Every tab, in the row's order ([`DockTab::IN_ROW`]): its key in the
/// model and its view.
fn tabs() -> Vec<(DockTab, Box<dyn View>)> {
    let view = |tab| -> Box<dyn View> {
        match tab {
            DockTab::Totals => Box::new(totals::Totals),
            DockTab::Collisions => Box::new(collisions::Collisions),
            DockTab::Discs => Box::new(discs::DiscsTable::default()),
            DockTab::Speeds => Box::new(speeds::Speeds),
            DockTab::Momenta => Box::new(momenta::Momenta),
            DockTab::Words => Box::new(words::Words),
        }
    };
    DockTab::IN_ROW.iter().map(|&t| (t, view(t))).collect()
}

/// The dock's tabs, each with its own state.
pub struct BottomDock {
    tabs: Vec<(DockTab, Box<dyn View>)>,
}

impl BottomDock {
    pub fn new() -> Self {
        BottomDock { tabs: tabs() }
    }

    /// The chosen tab (if it has room: `edge`, with its top edge to drag)
    /// and, under it at the window's bottom edge, the tab row, `row` points
    /// high: a tab clicked never moves.
    pub fn show(&mut self, ui: &mut egui::Ui, cx: &mut Cx, row: f32, edge: Option<edge::TabEdge>) {
        let model = cx.model;
        let content = edge.is_some();
        let expanded = model.panels.dock_expanded && content;
        let full = ui.max_rect();
        let split = full.bottom() - row;
        let row_rect = egui::Rect::from_min_max(egui::pos2(full.left(), split), full.max);
        if expanded {
            let mut area =
                egui::Rect::from_min_max(full.min, egui::pos2(full.right(), split - 4.0));
            // The open drawer floats over the dock's right end: the tab is
            // laid out beside it (the ledger's "after" column and the
            // plots' right ends were under it).
            // Where that leaves too little (1024×768 at size 2: the ledger's
            // "after" went letter by letter), it stays under the drawer.
            if let Some(drawer) = cx.open_drawer.filter(|d| d.intersects(area)) {
                let left = drawer.left() - ui.spacing().item_spacing.x;
                if left - area.min.x >= MIN_BESIDE_DRAWER {
                    area.max.x = area.max.x.min(left);
                }
            }
            let mut tab = ui.new_child(egui::UiBuilder::new().max_rect(area));
            tab.set_clip_rect(area.intersect(ui.clip_rect()));
            let chosen = model.panels.tab;
            if let Some((_, view)) = self.tabs.iter_mut().find(|(t, _)| *t == chosen) {
                view.ui(&mut tab, cx);
            }
        }
        if let (true, Some(edge)) = (expanded, edge) {
            edge::show(ui, cx, full, edge);
        }
        let mut strip = ui.new_child(
            egui::UiBuilder::new()
                .max_rect(row_rect)
                .layout(egui::Layout::left_to_right(egui::Align::Center)),
        );
        strip.set_clip_rect(row_rect.intersect(ui.clip_rect()));
        // The dock's fold button: an arrow (its word on hover), so that
        // the tabs' names keep the row.
        let (toggle_label, toggle_hover) = if model.panels.dock_expanded {
            ("🔽", crate::app::lang::tr!("dock-hide"))
        } else {
            ("🔼", crate::app::lang::tr!("dock-show"))
        };
        // Where the tabs' names do not all fit on the row (long words, a
        // projector's scale), they first close up (less room between and
        // around them), and only then does the row offer them as one list.
        let wanted_at = |strip: &egui::Ui, spacing: f32, padding: f32| {
            self.tabs
                .iter()
                .map(|(t, _)| button_text_width(strip, RichText::new(t.title()).strong()) + padding)
                .sum::<f32>()
                + button_text_width(strip, RichText::new(toggle_label).strong())
                + padding
                + spacing * self.tabs.len() as f32
                + 2.0
        };
        let (spacing, padding) = (
            strip.spacing().item_spacing.x,
            strip.spacing().button_padding.x,
        );
        // Only as close as the row needs: closed up all the way at once, a
        // Spanish row with room to spare at its end had its chosen tab's
        // box touching the next name.
        if wanted_at(&strip, spacing, 2.0 * padding) > row_rect.width() {
            let closer = [0.8f32, 0.6, 0.4].into_iter().find(|&f| {
                let (s, p) = (f * spacing, (0.5 + 0.5 * f) * padding);
                wanted_at(&strip, s, 2.0 * p) <= row_rect.width()
            });
            let f = closer.unwrap_or(0.4);
            strip.spacing_mut().item_spacing.x = f * spacing;
            strip.spacing_mut().button_padding.x = (0.5 + 0.5 * f) * padding;
        }
        let wanted = wanted_at(
            &strip,
            strip.spacing().item_spacing.x,
            2.0 * strip.spacing().button_padding.x,
        );
        if wanted > row_rect.width() {
            let chosen = model.panels.tab;
            let r = egui::ComboBox::from_id_salt("tab_menu")
                .selected_text(RichText::new(chosen.title()).strong())
                .show_ui(&mut strip, |ui| {
                    for (tab, _) in &self.tabs {
                        if ui.selectable_label(*tab == chosen, tab.title()).clicked() {
                            cx.send(Command::ShowTab(*tab));
                        }
                    }
                })
                .response;
            cx.note("tab_menu", &r);
            let tabs: Vec<_> = self.tabs.iter().map(|(t, _)| *t).collect();
            let at = tabs.iter().position(|t| *t == chosen);
            if let Some(k) = super::widgets::arrow_choice(&r, at, tabs.len()) {
                cx.send(Command::ShowTab(tabs[k]));
            }
        }
        for (tab, _) in self.tabs.iter().filter(|_| wanted <= row_rect.width()) {
            let chosen = model.panels.tab == *tab && expanded;
            let r = strip.selectable_label(chosen, RichText::new(tab.title()).strong());
            cx.note(format!("tab_{}", tab.key().to_lowercase()), &r);
            let r = r.tip(crate::app::model::bindings::tab_tooltip(*tab));
            if r.clicked() {
                cx.send(Command::ClickTab(*tab));
                if !content {
                    let side_docked = !cx.drawer;
                    cx.send(Command::SayNoRoomForTab { side_docked });
                }
            }
        }
        strip.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            let r = ui.button(toggle_label).tip(toggle_hover);
            cx.note("dock_toggle", &r);
            if r.clicked() {
                cx.send(Command::ToggleDockExpanded);
            }
            if model.panels.dock_expanded && !content {
                // (A click on a tab says it in the strip too.)
                let why = crate::app::model::no_room_for_tab(!cx.drawer);
                let r = ui.add(egui::Label::new(why).truncate());
                cx.note("dock_no_room", &r);
            }
        });
        ui.allocate_rect(full, egui::Sense::hover());
    }
}
