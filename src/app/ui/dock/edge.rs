//! The top edge of the dock's open tab, a control of its own: dragged, it
//! makes the tab taller or shorter (a table or a plot gets more room at a
//! projector's size, the world less); with the keyboard (Tab reaches it),
//! the arrows move it a row, Page Up and Page Down three, Home and End to
//! the tallest and the shortest, Enter back to the tab's own height; so
//! does a double-click. The layout keeps it within what the world leaves
//! ([`crate::app::layout::tab_range`]). Where it is set is remembered for
//! the next start ([`crate::app::model::settings`]).

use super::super::Cx;
use crate::app::lang::tr;
use crate::app::model::Command;
use crate::app::ui::tip::Tip;

/// The open tab's height and what it may be, in px.
#[derive(Clone, Copy, Debug)]
pub struct TabEdge {
    pub height: f32,
    pub least: f32,
    pub most: f32,
    /// One row (a step of the arrows).
    pub row: f32,
    /// Px per egui point.
    pub ppp: f32,
}

/// The edge's id: the strip says what its keys do while it has them.
pub fn id() -> egui::Id {
    egui::Id::new("tab_edge")
}

/// How far below the edge the pointer takes it, in points (above it is the
/// caption strip, another panel).
const GRIP_POINTS: f32 = 4.0;

/// The edge along the top of `area` (the tab's content, in points), noted
/// as `tab_edge`.
pub fn show(ui: &mut egui::Ui, cx: &mut Cx, area: egui::Rect, edge: TabEdge) {
    let ppp = edge.ppp;
    let top = ui.clip_rect().top().min(area.top());
    let grip = egui::Rect::from_min_max(
        egui::pos2(area.left(), top),
        egui::pos2(area.right(), area.top() + GRIP_POINTS),
    );
    let id = id();
    let r = ui.interact(grip, id, egui::Sense::click_and_drag());
    let r = r.tip(tr!("tab-edge-hover"));
    r.widget_info(|| {
        egui::WidgetInfo::slider(
            ui.is_enabled(),
            (edge.height / ppp).round() as f64,
            tr!("tab-edge"),
        )
    });
    cx.note("tab_edge", &r);
    let live = r.hovered() || r.dragged() || r.has_focus();
    if live {
        ui.ctx().set_cursor_icon(egui::CursorIcon::ResizeVertical);
    }
    // Marked only while it can be moved, as egui marks a panel's edge: a
    // grip drawn always struck through the caption or the tab's first line.
    // With the keyboard, a thicker line in the colour of focus, instead of
    // the ring round other controls (round the edge it struck through the
    // caption and the count under it); the strip says what the keys do.
    if live {
        let layer = egui::LayerId::new(egui::Order::Foreground, id.with("line"));
        let stroke = if r.has_focus() {
            crate::app::ui::focus::marks_own_focus(ui.ctx(), id);
            egui::Stroke::new(
                4.0,
                crate::app::ui::focus::focus_color(cx.model.panels.theme),
            )
        } else {
            egui::Stroke::new(2.0, ui.visuals().strong_text_color())
        };
        ui.ctx()
            .layer_painter(layer)
            .hline(grip.x_range(), top, stroke);
    }
    let set = |h: f32| Command::SetTabHeight(Some(h.clamp(edge.least, edge.most)));
    // A height set at once (a key, a double-click) is remembered for the
    // next start at once; a drag's, when it is let go.
    let set_and_keep = |cx: &mut Cx, height: Command| {
        cx.send(height);
        cx.send(Command::KeepTabHeight);
    };
    if r.double_clicked() {
        set_and_keep(cx, Command::SetTabHeight(None));
    } else if r.drag_stopped() {
        cx.send(Command::KeepTabHeight);
    } else if r.dragged() {
        // Where the pointer is, less where on the grip it was taken: no
        // rounding adds up over a slow drag.
        let taken = egui::Id::new("tab_edge_taken");
        if let Some(at) = ui.input(|i| i.pointer.interact_pos()) {
            if r.drag_started() {
                ui.data_mut(|d| d.insert_temp(taken, at.y - area.top()));
            }
            let offset = ui.data(|d| d.get_temp::<f32>(taken)).unwrap_or(0.0);
            let bottom = area.top() + edge.height / ppp;
            cx.send(set((bottom - (at.y - offset)) * ppp));
        }
    }
    if r.has_focus() {
        // The arrows stay here instead of moving the keyboard on.
        ui.memory_mut(|m| {
            m.set_focus_lock_filter(
                id,
                egui::EventFilter {
                    vertical_arrows: true,
                    ..Default::default()
                },
            )
        });
        let keys = [
            (egui::Key::ArrowUp, edge.row),
            (egui::Key::ArrowDown, -edge.row),
            (egui::Key::PageUp, 3.0 * edge.row),
            (egui::Key::PageDown, -3.0 * edge.row),
            (egui::Key::Home, f32::INFINITY),
            (egui::Key::End, f32::NEG_INFINITY),
        ];
        for (key, by) in keys {
            if ui.input(|i| i.key_pressed(key)) {
                set_and_keep(cx, set(edge.height + by));
            }
        }
        if ui.input(|i| i.key_pressed(egui::Key::Enter)) {
            set_and_keep(cx, Command::SetTabHeight(None));
        }
    }
}
