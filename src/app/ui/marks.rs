//! What the views note in a frame for the state dump and the keyboard: the
//! named widgets' rectangles (less what a dialog covers), the Tab stops,
//! the lists to read and how far they are scrolled.

use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

/// What the views noted this frame.
#[derive(Default)]
pub struct Marks {
    /// Screen rectangles of named widgets (px).
    pub widgets: BTreeMap<String, [f32; 4]>,
    /// A text field has the keyboard.
    pub text_focus: bool,
    /// A menu is open: its keys are its own (Esc closes it, and nothing
    /// under it).
    pub menu_open: bool,
    /// The text field left with Enter, if one was.
    pub left_with_enter: Option<egui::Id>,
    /// The named widget that has the keyboard, if one does.
    pub focused: Option<String>,
    /// Pixels per egui point.
    pub ppp: f32,
    /// The frame's Tab stops in the order egui made them: the controls
    /// noted, and the containers' parts to pass over ([`super::dialog`]).
    pub stops: Vec<Stop>,
    /// The last frame's stops.
    pub last_stops: Vec<egui::Id>,
    /// The rectangle of whatever has the keyboard (pixels), named or not.
    pub focus_rect: Option<[f32; 4]>,
    /// Lists to read (scroll areas without controls, taller or wider than
    /// their place): how far each is scrolled and how far it can be, in
    /// pixels ([`super::dialog::scroll`]).
    pub lists: BTreeMap<String, ListScroll>,
    /// Tooltips showing: hovering shows one at most.
    pub tooltips: usize,
    /// Where a tooltip showing is (pixels).
    pub tooltip_rect: Option<[f32; 4]>,
    /// The layers and ids of the widgets [`super::Cx::note`] noted.
    pub named: BTreeMap<String, (egui::LayerId, egui::Id)>,
    /// The dialogs shown this frame, bottom first: their layers and
    /// rectangles (points).
    pub covers: Vec<(egui::LayerId, egui::Rect)>,
    /// Named labels cut short for want of room (whole on hover).
    pub cut: BTreeSet<String>,
}

/// How far a list to read is scrolled (pixels).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ListScroll {
    /// Scrolled down (and across) from the top left.
    pub offset: [f32; 2],
    /// The most it can be scrolled.
    pub max: [f32; 2],
}

/// A place Tab can stop at. Every control after a container's part should
/// be among the stops (noted with [`super::Cx::note`] or pushed as they are made),
/// or Tab going on from the part passes it over.
#[derive(Clone, Copy, Debug)]
pub struct Stop {
    pub id: egui::Id,
    /// Its layer: one under an open start screen cannot take the keyboard.
    pub layer: egui::LayerId,
    /// A container's part, which shows nothing and does nothing with the
    /// keyboard: Tab goes on past it.
    pub pass: bool,
}

impl Stop {
    /// A control's stop.
    pub fn control(response: &egui::Response) -> Stop {
        Stop {
            id: response.id,
            layer: response.layer_id,
            pass: false,
        }
    }
}

impl Marks {
    /// Leaves out of the dump the widgets whose centre a dialog shown over
    /// them this frame covers (the drawer over the dock's plots): the dump
    /// lists what a person can see. (egui's own test of what is on top also
    /// counts a dialog closed this frame, for one frame more.)
    pub fn leave_out_covered(&mut self) {
        let widgets = std::mem::take(&mut self.widgets);
        self.widgets = widgets
            .into_iter()
            .filter(|(name, r)| {
                let Some(&(layer, _)) = self.named.get(name) else {
                    return true;
                };
                let centre = egui::pos2(r[0] + 0.5 * r[2], r[1] + 0.5 * r[3]) / self.ppp;
                !self.covered(layer, centre)
            })
            .collect();
    }

    /// Whether a dialog shown this frame over `layer` covers `point`
    /// (points): the drawer over the Collisions tab's controls. Tab passes
    /// over such a control, whose focus ring could not be seen.
    pub fn covered(&self, layer: egui::LayerId, point: egui::Pos2) -> bool {
        self.covered_over(layer, egui::Rect::from_min_max(point, point))
    }

    /// Whether a dialog shown this frame over `layer` covers any of `rect`
    /// (points): Tab passes over a control partly under the drawer (a
    /// list's ring was drawn across it).
    pub fn covered_over(&self, layer: egui::LayerId, rect: egui::Rect) -> bool {
        let covers = &self.covers;
        // A menu opened over a dialog (the drawer's "… more") is in
        // front of it: a layer in front that is no dialog is a popup.
        let dialog = covers.iter().any(|(l, _)| *l == layer);
        if layer.order >= egui::Order::Foreground && !dialog {
            return false;
        }
        // Under its own dialog, only the dialogs shown after it cover it.
        let above = covers
            .iter()
            .position(|(l, _)| *l == layer)
            .map_or(0, |k| k + 1);
        covers[above..]
            .iter()
            .any(|(l, cover)| *l != layer && cover.intersects(rect))
    }

    /// Records a widget's rectangle (egui points) under `name`, in pixels.
    pub fn note(&mut self, name: impl Into<String>, rect: egui::Rect) {
        self.widgets.insert(name.into(), to_px(rect, self.ppp));
    }

    /// Moves the stop of `id` to `place` in the list, for a control noted
    /// after what it contains (a section's header after its body).
    pub fn move_stop_to(&mut self, id: egui::Id, place: usize) {
        if let Some(at) = self.stops.iter().rposition(|s| s.id == id) {
            let stop = self.stops.remove(at);
            self.stops.insert(place.min(self.stops.len()), stop);
        }
    }

    /// Notes a container's part that egui lets Tab stop at, to pass over.
    pub fn pass_over(&mut self, id: egui::Id, layer: egui::LayerId) {
        self.stops.push(Stop {
            id,
            layer,
            pass: true,
        });
    }

    /// Notes a text field's response: while it has the keyboard, the
    /// shortcuts stay quiet; left with Enter, the keyboard stays with the
    /// panel (a digit typed next must not open a preset).
    pub fn text_field(&mut self, response: &egui::Response) {
        self.text_focus |= response.has_focus();
        if response.lost_focus() && response.ctx.input(|i| i.key_pressed(egui::Key::Enter)) {
            self.left_with_enter = Some(response.id);
        }
    }
}

/// An egui rectangle (points) as [x, y, w, h] in pixels.
pub fn to_px(rect: egui::Rect, ppp: f32) -> [f32; 4] {
    [
        rect.min.x * ppp,
        rect.min.y * ppp,
        rect.width() * ppp,
        rect.height() * ppp,
    ]
}
