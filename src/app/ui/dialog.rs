//! Boxes over the world (the start screen, the key list, the presets, the
//! recovery question, the drawer) and scroll areas, made so that Tab stops
//! only on controls.
//!
//! egui 0.31 lets Tab land on parts of its containers that show nothing and
//! do nothing when they have the keyboard: a window's frame and title bar,
//! a scroll area's content (dragged to scroll on a touch screen) and its
//! bar. A keyboard user then sees a ring round a whole window and presses
//! Enter to no effect. (egui fixed this in a later version, PR 7827, which
//! `egui-macroquad` does not take yet.) So a box here is an egui `Area` that
//! only senses hover, in a window's frame with its title drawn as a heading,
//! and a scroll area notes its own parts in the frame's list of Tab stops,
//! for [`pass_over_containers`] to move the keyboard on from them.

use super::{marks::Stop, Cx, Marks};
use crate::app::ui::tip::Tip;

/// Where a box goes.
pub enum Place {
    /// In the middle of the window.
    Centre,
    /// In the middle of this part of the window (points).
    CentreOf(egui::Rect),
    /// With its top left corner here (points).
    At(egui::Pos2),
}

/// A box over the world.
pub struct Dialog {
    name: String,
    id: egui::Id,
    title: Option<String>,
    place: Place,
    size: Option<egui::Vec2>,
    /// The height of `size` is the most it takes, not what it takes.
    shrinks: bool,
    max_width: Option<f32>,
    closable: bool,
    /// Modal: what is behind is dimmed, as it does not answer.
    modal: bool,
}

/// What [`Dialog::show`] gives back.
pub struct Shown {
    /// The box's rectangle (points).
    pub rect: egui::Rect,
    /// Its close button was clicked.
    pub close: bool,
}

impl Dialog {
    /// A box named `id` (its egui id and layer), with `title` as a heading.
    pub fn new(id: &str, title: Option<String>) -> Self {
        Dialog {
            name: id.to_string(),
            id: egui::Id::new(id),
            title,
            place: Place::Centre,
            size: None,
            shrinks: false,
            max_width: None,
            closable: false,
            modal: false,
        }
    }

    pub fn place(mut self, place: Place) -> Self {
        self.place = place;
        self
    }

    /// Its size inside the frame, title included (points), whatever the
    /// content asks.
    pub fn fixed_size(mut self, size: egui::Vec2) -> Self {
        self.size = Some(size);
        self
    }

    /// Its width, and the most height it takes (it is as tall as its
    /// content up to that).
    pub fn width_and_max_height(mut self, size: egui::Vec2) -> Self {
        self.size = Some(size);
        self.shrinks = true;
        self
    }

    pub fn max_width(mut self, width: f32) -> Self {
        self.max_width = Some(width);
        self
    }

    /// A close button (×) at the right of the title.
    pub fn closable(mut self) -> Self {
        self.closable = true;
        self
    }

    /// Nothing behind it takes the keyboard or the pointer while it is
    /// shown (egui's modal layer); Tab goes round its controls.
    pub fn modal(mut self, ctx: &egui::Context) -> Self {
        ctx.memory_mut(|m| m.set_modal_layer(self.layer()));
        self.modal = true;
        self
    }

    /// The layer it is drawn on.
    pub fn layer(&self) -> egui::LayerId {
        egui::LayerId::new(egui::Order::Foreground, self.id)
    }

    pub fn show(
        self,
        ctx: &egui::Context,
        cx: &mut Cx,
        add: impl FnOnce(&mut egui::Ui, &mut Cx),
    ) -> Shown {
        let area = egui::Area::new(self.id)
            .order(egui::Order::Foreground)
            .sense(egui::Sense::hover())
            .constrain(true);
        let area = match self.place {
            Place::Centre => area.anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO),
            Place::CentreOf(part) => area.anchor(
                egui::Align2::CENTER_CENTER,
                part.center() - ctx.screen_rect().center(),
            ),
            Place::At(pos) => area.fixed_pos(pos),
        };
        let mut close = false;
        let screen = ctx.screen_rect();
        let response = area.show(ctx, |ui| {
            if self.modal {
                // What is behind does not answer: it is dimmed.
                ui.painter().with_clip_rect(screen).rect_filled(
                    screen,
                    0.0,
                    egui::Color32::from_black_alpha(140),
                );
            }
            egui::Frame::window(ui.style())
                .show(ui, |ui| {
                    let top = ui.cursor().top();
                    if let Some(size) = self.size {
                        ui.set_width(size.x);
                    } else if let Some(width) = self.max_width {
                        ui.set_max_width(width);
                    }
                    if let Some(title) = &self.title {
                        ui.horizontal(|ui| {
                            let side = ui.spacing().interact_size.y;
                            let (close_width, height) = if self.closable {
                                (side + ui.spacing().item_spacing.x, side)
                            } else {
                                (0.0, 0.0)
                            };
                            ui.add_sized(
                                [ui.available_width() - close_width, height],
                                egui::Label::new(egui::RichText::new(title).heading()).wrap(),
                            );
                            if self.closable {
                                let r = ui
                                    .add(egui::Button::new("×").min_size(egui::vec2(side, side)))
                                    .tip(crate::app::lang::tr!("close"));
                                cx.note(format!("{}_close", self.name), &r);
                                close = r.clicked();
                            }
                        });
                        ui.separator();
                    }
                    match self.size {
                        Some(size) => {
                            // What the title left of the size.
                            let height = (size.y - (ui.cursor().top() - top)).max(40.0);
                            ui.allocate_ui(egui::vec2(size.x, height), |ui| {
                                if !self.shrinks {
                                    ui.set_min_height(height);
                                }
                                ui.set_max_height(height);
                                add(ui, cx)
                            })
                            .inner
                        }
                        None => add(ui, cx),
                    }
                })
                .inner
        });
        cx.marks.covers.push((self.layer(), response.response.rect));
        Shown {
            rect: response.response.rect,
            close,
        }
    }
}

/// A scroll area whose own parts (its content, dragged to scroll, and its
/// bars) are noted as Tab stops to pass over. `salt` names it among the
/// scroll areas of `ui`.
///
/// A list to read, with no control in it, is itself a Tab stop once it is
/// taller or wider than its place (egui makes it one only then), named
/// `scroll_<salt>`: the ring goes round it, and while it has the keyboard
/// the arrows, Page Up, Page Down, Space, Home and End scroll it, as a
/// browser scrolls a page. Without that a keyboard alone could not read
/// the end of the key list or of the ledger (egui 0.31 scrolls only to a
/// control).
pub fn scroll<R>(
    ui: &mut egui::Ui,
    cx: &mut Cx,
    area: egui::ScrollArea,
    salt: &str,
    add: impl FnOnce(&mut egui::Ui, &mut Cx) -> R,
) -> R {
    scroll_area(ui, cx, area, salt, (false, false), add)
}

/// A [`scroll`] area that the keys scroll whenever no control has them:
/// the help's list, which covers the world (whose keys wait meanwhile), is
/// read with Page Down at once, without a Tab to it first.
pub fn scroll_by_any_keys<R>(
    ui: &mut egui::Ui,
    cx: &mut Cx,
    area: egui::ScrollArea,
    salt: &str,
    add: impl FnOnce(&mut egui::Ui, &mut Cx) -> R,
) -> R {
    let free = cx.keys == super::Keys::World;
    scroll_area(ui, cx, area, salt, (false, free), add)
}

/// A [`scroll`] area read as a page: a Tab stop to read whenever it is
/// taller or wider than its place, with controls in it or not. (A tab's
/// text and tables with a button among them: the rows after the button
/// are reached by reading, as no control shows them.)
pub fn page<R>(
    ui: &mut egui::Ui,
    cx: &mut Cx,
    area: egui::ScrollArea,
    salt: &str,
    add: impl FnOnce(&mut egui::Ui, &mut Cx) -> R,
) -> R {
    scroll_area(ui, cx, area, salt, (true, false), add)
}

fn scroll_area<R>(
    ui: &mut egui::Ui,
    cx: &mut Cx,
    area: egui::ScrollArea,
    salt: &str,
    (read_past_controls, keys_free): (bool, bool),
    add: impl FnOnce(&mut egui::Ui, &mut Cx) -> R,
) -> R {
    // egui's id for it, as `ScrollArea::show` makes it from the salt.
    let id = ui.make_persistent_id(egui::Id::new(salt));
    let content = id.with("area");
    let at = cx.marks.stops.len();
    cx.marks.pass_over(content, ui.layer_id());
    let reading = ui.memory(|m| m.has_focus(content));
    let out = area.id_salt(salt).show(ui, |ui| {
        if reading || keys_free {
            scroll_by_keys(ui, content);
        }
        let inner = add(ui, cx);
        reveal_focus(ui, cx.marks, at + 1);
        inner
    });
    debug_assert_eq!(out.id, id, "egui names a scroll area otherwise");
    let has_controls = cx.marks.stops[at + 1..].iter().any(|s| !s.pass);
    let view = out.inner_rect.size();
    let max = (out.content_size - view).max(egui::Vec2::ZERO);
    if (read_past_controls || !has_controls) && (max.x > 0.5 || max.y > 0.5) {
        cx.marks.stops[at].pass = false;
        let name = format!("scroll_{salt}");
        if reading {
            cx.marks.focused = Some(name.clone());
        }
        let ppp = cx.marks.ppp;
        let offset = out.state.offset;
        cx.marks.lists.insert(
            name.clone(),
            super::ListScroll {
                offset: [offset.x * ppp, offset.y * ppp],
                max: [max.x * ppp, max.y * ppp],
            },
        );
        cx.marks.note(name, out.inner_rect);
    }
    for bar in 0..2_usize {
        cx.marks.pass_over(id.with(bar), ui.layer_id());
    }
    out.inner
}

/// Scrolls the list to read whose content `ui` lays out by this frame's
/// keys, which it keeps (the arrows do not move the keyboard on).
fn scroll_by_keys(ui: &egui::Ui, content: egui::Id) {
    ui.memory_mut(|m| {
        m.set_focus_lock_filter(
            content,
            egui::EventFilter {
                horizontal_arrows: true,
                vertical_arrows: true,
                ..Default::default()
            },
        )
    });
    use egui::Key;
    // A line: two lines of text, as a browser's arrow scrolls about 40 px;
    // a page: most of what shows, so a line stays in sight across it.
    let line = 2.0 * ui.text_style_height(&egui::TextStyle::Body);
    let page = 0.85 * ui.clip_rect().size();
    let ends = 1.0e6;
    let down = ui.input(|i| {
        let n = |key| i.num_presses(key) as f32;
        let space = if i.modifiers.shift { -1.0 } else { 1.0 } * n(Key::Space);
        egui::vec2(
            (n(Key::ArrowRight) - n(Key::ArrowLeft)) * line,
            (n(Key::ArrowDown) - n(Key::ArrowUp)) * line
                + (n(Key::PageDown) - n(Key::PageUp) + space) * page.y
                + (n(Key::End) - n(Key::Home)) * ends,
        )
    });
    if down != egui::Vec2::ZERO {
        // egui's delta moves the content: down the list is up the screen.
        ui.scroll_with_delta_animation(-down, egui::style::ScrollAnimation::none());
    }
}

/// egui 0.31 does not scroll to a control Tab brought the keyboard to:
/// where it is in the content just laid out in `ui` (a scroll area's, whose
/// stops begin at `first` in `marks`), scrolls it into sight. (Asked
/// outside the scroll area, egui drops it.) A control noted elsewhere is
/// left alone, even where its rectangle falls in this content: a list after
/// a taller one, in a scroll area round both, is the outer area's to show.
fn reveal_focus(ui: &egui::Ui, marks: &Marks, first: usize) {
    let Some(id) = ui.ctx().memory(|m| m.focused()) else {
        return;
    };
    let Some(r) = ui.ctx().read_response(id) else {
        return;
    };
    let inside = if marks.stops[first..].iter().any(|s| s.id == id) {
        true
    } else {
        // One not noted at all (egui's own): where it lies.
        let noted = marks.stops.iter().any(|s| s.id == id) || marks.last_stops.contains(&id);
        !noted && r.layer_id == ui.layer_id() && ui.min_rect().contains_rect(r.rect)
    };
    if inside {
        into_sight(&r);
    }
}

/// Scrolls the control that has just got the keyboard into sight; called
/// inside its scroll area (a table's own, where [`scroll`] is not used).
/// Once for each time it gets the keyboard: egui's `gained_focus` and
/// [`note_focus`] may both say so, a frame apart, and the second time, with
/// the rectangle of before the scroll, had scrolled as far again (Tab from
/// the ledger's page to its button put the button above the tab).
pub fn into_sight(r: &egui::Response) {
    let shown = revealed_id();
    if just_focused(r) && r.ctx.data(|d| d.get_temp::<egui::Id>(shown)) != Some(r.id) {
        r.ctx.data_mut(|d| d.insert_temp(shown, r.id));
        r.scroll_to_me_animation(None, egui::style::ScrollAnimation::none());
    }
}

/// The id under which [`into_sight`] keeps the control it last showed,
/// while that control keeps the keyboard.
fn revealed_id() -> egui::Id {
    egui::Id::new("dialog_revealed")
}

/// Whether the control has just got the keyboard: this frame, or between
/// the frames (see [`note_focus`]).
pub fn just_focused(r: &egui::Response) -> bool {
    r.gained_focus() || (r.has_focus() && focus_is_new(&r.ctx))
}

/// The id under which [`note_focus`] keeps whether the keyboard moved.
fn focus_moved_id() -> egui::Id {
    egui::Id::new("dialog_focus_moved")
}

/// Notes, before the views of a frame, whether what has the keyboard is
/// not what had it when the last frame's views were laid out (`last`,
/// updated). egui's `gained_focus` misses a control the keyboard was
/// passed on to between frames ([`pass_over_containers`]).
pub fn note_focus(ctx: &egui::Context, last: &mut Option<egui::Id>) {
    let now = ctx.memory(|m| m.focused());
    ctx.data_mut(|d| {
        d.insert_temp(focus_moved_id(), now != *last);
        if d.get_temp::<egui::Id>(revealed_id()) != now {
            d.remove::<egui::Id>(revealed_id());
        }
    });
    *last = now;
}

fn focus_is_new(ctx: &egui::Context) -> bool {
    ctx.data(|d| d.get_temp(focus_moved_id())).unwrap_or(false)
}

/// Where Tab brought the keyboard to a container's part (noted with
/// [`Marks::pass_over`]) or to a control a dialog covers in part
/// ([`Marks::covered_over`]), moves it on to the next control the frame noted,
/// or back to the one before where the last Tab was Shift+Tab (`back`;
/// egui may hand the keyboard over a frame after the key). Returns what
/// has the keyboard now. (Past the last control egui itself goes round to
/// the first, a frame later.)
pub fn pass_over_containers(ctx: &egui::Context, marks: &Marks, back: bool) -> Option<egui::Id> {
    let focused = ctx.memory(|m| m.focused())?;
    let stops = &marks.stops;
    // A container's part, or a control under a dialog (the drawer).
    let passed = |s: &Stop| {
        s.pass
            || ctx
                .read_response(s.id)
                .is_some_and(|r| marks.covered_over(s.layer, r.rect))
    };
    let Some(at) = stops.iter().position(|s| s.id == focused && passed(s)) else {
        return Some(focused);
    };
    let n = stops.len();
    let next = (1..n)
        .map(|k| if back { (at + n - k) % n } else { (at + k) % n })
        .map(|k| stops[k])
        .find(|s| !passed(s) && ctx.memory(|m| m.allows_interaction(s.layer)));
    ctx.memory_mut(|m| match next {
        Some(stop) => m.request_focus(stop.id),
        None => m.surrender_focus(focused),
    });
    next.map(|s| s.id)
}
