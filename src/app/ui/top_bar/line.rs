//! The top bar's line: the scene's name (cut first), the items always
//! shown, the others while they fit, "… more" for the rest, and the buttons
//! at the right end; where the line is too full for the name, the items
//! with a short form take it.

use super::{sound_label, TopBar};
use crate::app::lang::tr;
use crate::app::model::Command;
use crate::app::ui::tip::Tip;
use crate::app::ui::Cx;
use egui::{RichText, WidgetText};
use std::sync::Arc;

/// The least room (points) the items always shown leave the scene's name
/// before they take their short forms.
const NAME_AT_LEAST: f32 = 100.0;
/// The room between the name and its kept end, as a share of the room
/// between items.
const NAME_END_GAP: f32 = 0.3;

/// One item of the line: its text, what hovering it says, its name in the
/// state dump, a shorter text for a line too full for the name, and (the
/// name's) an end kept whole where the text is cut.
pub(super) struct Item {
    text: RichText,
    hover: Option<String>,
    name: Option<String>,
    short: Option<RichText>,
    kept_end: Option<[RichText; 2]>,
    /// The name is cut (down to [`NAME_AT_LEAST`]) to show it and the
    /// items before it: the momentum.
    before_the_name: bool,
}

impl Item {
    /// The item's own width, and its kept end's, whole and short, each with
    /// the `gap` before it (points).
    fn widths(&self, ui: &egui::Ui, gap: f32) -> (f32, Option<[f32; 2]>) {
        let own = galley(ui, &self.text).size().x;
        let ends = self
            .kept_end
            .as_ref()
            .map(|ends| ends.clone().map(|end| galley(ui, &end).size().x + gap));
        (own, ends)
    }

    /// The item whole: its text and its whole end (points).
    fn whole_width(&self, ui: &egui::Ui, gap: f32) -> f32 {
        let (own, ends) = self.widths(ui, gap);
        own + ends.map_or(0.0, |[whole, _]| whole)
    }

    pub(super) fn new(text: impl Into<RichText>) -> Self {
        Item {
            text: text.into(),
            hover: None,
            name: None,
            short: None,
            kept_end: None,
            before_the_name: false,
        }
    }

    /// The name gives this item room ([`Item::before_the_name`]).
    pub(super) fn before_the_name(mut self) -> Self {
        self.before_the_name = true;
        self
    }

    /// Text after the item's own, kept where the item is cut, whole or, where
    /// the item would keep less than [`NAME_AT_LEAST`], short: the scene's
    /// name is cut before its "(edited)", or its "✎" at a projector.
    pub(super) fn kept_end(mut self, end: Option<[RichText; 2]>) -> Self {
        self.kept_end = end;
        self
    }

    pub(super) fn short(mut self, text: RichText) -> Self {
        self.short = Some(text);
        self
    }

    /// The item in its short form, if it has one: the whole text then
    /// comes first on hover.
    fn shortened(mut self) -> Self {
        if let Some(short) = self.short.take() {
            let whole = self.text.text().to_string();
            self.hover = Some(match self.hover {
                Some(h) => format!("{whole}: {h}"),
                None => whole,
            });
            self.text = short;
        }
        self
    }

    pub(super) fn hover(mut self, text: impl Into<String>) -> Self {
        self.hover = Some(text.into());
        self
    }

    pub(super) fn named(mut self, name: impl Into<String>) -> Self {
        self.name = Some(name.into());
        self
    }
}

impl TopBar {
    /// Lays the items out on one line: the essential ones, then the others
    /// while they fit, then "⋯ more" with the rest on hover, and the
    /// buttons at the right end.
    pub(super) fn line(
        &self,
        ui: &mut egui::Ui,
        cx: &mut Cx,
        essential: Vec<Item>,
        optional: Vec<Item>,
    ) {
        // Less room between items where the bar is narrow.
        let spacing = if ui.available_width() < 700.0 {
            12.0
        } else {
            18.0
        };
        let label = |c: &Command| crate::app::model::bindings::label(c).unwrap_or_default();
        let sound = sound_label(cx);
        let mut buttons: Vec<(String, Command, &str)> =
            vec![(label(&Command::ShowStart), Command::ShowStart, "start")];
        buttons.push((sound, Command::ToggleSound, "sound"));
        if cx.drawer && cx.model.panels.docks_open {
            let toggle = Command::ToggleDrawer;
            buttons.push((label(&toggle), toggle, "drawer_toggle"));
        }
        if !cx.model.panels.docks_open {
            buttons.push((tr!("show-panels"), Command::ToggleDocks, "show_panels"));
        }
        let more = RichText::new(tr!("top-bar-more"));
        let more_width = galley(ui, &more).size().x + spacing;
        // Everything always shown but the name, each with the room after
        // the one before it.
        // (`short`: each in its short form, where it has one.)
        let fixed_of = |essential: &[Item], short: bool| -> f32 {
            essential[1..]
                .iter()
                .map(|item| {
                    let text = item.short.as_ref().filter(|_| short).unwrap_or(&item.text);
                    galley(ui, text).size().x + spacing
                })
                .sum()
        };
        let mut fixed = fixed_of(&essential, false);
        let short_fixed = fixed_of(&essential, true);
        // A name shorter than NAME_AT_LEAST needs only its own width:
        // "Choque oblicuo" left room for "PAUSADO", which had taken its sign.
        let name_width = essential
            .first()
            .map_or(0.0, |name| name.whole_width(ui, NAME_END_GAP * spacing));
        // Where the buttons' words would leave the time and the state no
        // room (long words at a projector's scale), the buttons that have
        // an icon show only it, their words on hover.
        let padding = ui.spacing().button_padding.x * 2.0 + 8.0;
        let buttons_width: f32 = buttons
            .iter()
            .map(|(l, _, _)| galley(ui, &RichText::new(l.as_str())).size().x + padding)
            .sum();
        // What the name gives room to counts as always shown here: at a
        // projector's size the buttons' words and the state's word give way
        // to the momentum (1366×768 at text size 2 had kept "≡ Controls"
        // and "RUNNING" and put the momentum under "… more").
        // Only where it can be had: with the buttons' icons, the short
        // forms and the name at its least (at 1024×768 at text size 2 the
        // state had lost its word, and the momentum was not shown for it).
        let icon_of = |label: &str| {
            let (icon, _) = crate::app::model::bindings::icon_and_words(label);
            icon.unwrap_or(label).to_string()
        };
        let icons_width: f32 = buttons
            .iter()
            .map(|(l, _, _)| galley(ui, &RichText::new(icon_of(l))).size().x + padding)
            .sum();
        let name_least = name_width.min(NAME_AT_LEAST);
        let wanted = Some(before_the_name(ui, &optional, spacing))
            .filter(|&wanted| {
                let least = icons_width + spacing + short_fixed + wanted + more_width + name_least;
                ui.available_width() >= least
            })
            .unwrap_or(0.0);
        if ui.available_width() - buttons_width < fixed + wanted + more_width + 40.0 + 2.0 * spacing
        {
            for (label, _, _) in &mut buttons {
                *label = icon_of(label);
            }
        }
        // The line first and the buttons after it, at the right, so that Tab
        // meets everything in reading order (egui's Tab follows the order
        // controls are made). The buttons' group is as wide as it was last
        // frame; the line gets what it leaves.
        let group = ui.id().with("top_bar_buttons");
        let width = ui
            .data(|d| d.get_temp::<f32>(group))
            .unwrap_or(buttons_width);
        // Where the items always shown would leave the name less than this
        // (the π blocks' count at a projector's size), they take their
        // short forms: the state its sign, its word on hover.
        let name_room = ui.available_width() - width - spacing - fixed - wanted - more_width;
        let mut essential = essential;
        if name_room < name_least {
            essential = essential.into_iter().map(Item::shortened).collect();
            fixed = short_fixed;
        }
        ui.with_layout(egui::Layout::left_to_right(egui::Align::Center), |ui| {
            let line = egui::vec2(
                (ui.available_width() - width - spacing).max(0.0),
                ui.available_height(),
            );
            ui.allocate_ui_with_layout(
                line,
                egui::Layout::left_to_right(egui::Align::Center),
                |ui| {
                    let words = Words {
                        essential,
                        optional,
                        more,
                        spacing,
                        more_width,
                        fixed,
                        wanted,
                    };
                    items(ui, cx, words);
                },
            );
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                button_group(ui, cx, buttons, (group, width));
            });
        });
    }
}

/// What the line says: the essential items, the others while they fit,
/// "… more" for the rest, and the room between items (points); with the
/// widths [`TopBar::line`] measured: "… more" and the room after it, and
/// the time and the state with theirs.
struct Words {
    /// The name first, then the time, the state, and in the π blocks
    /// their count.
    essential: Vec<Item>,
    optional: Vec<Item>,
    more: RichText,
    spacing: f32,
    more_width: f32,
    fixed: f32,
    /// What the name gives room to ([`before_the_name`]).
    wanted: f32,
}

/// What the items up to the one the name gives room to
/// ([`Item::before_the_name`]) take at least: each in its shorter form,
/// with the room before it (points; 0 without such an item).
fn before_the_name(ui: &egui::Ui, optional: &[Item], spacing: f32) -> f32 {
    let Some(last) = optional.iter().position(|item| item.before_the_name) else {
        return 0.0;
    };
    optional[..=last]
        .iter()
        .map(|item| {
            let whole = galley(ui, &item.text).size().x;
            let short = item
                .short
                .as_ref()
                .map_or(whole, |t| galley(ui, t).size().x);
            whole.min(short) + spacing
        })
        .sum()
}

/// `text` in one line of body text.
fn galley(ui: &egui::Ui, text: &RichText) -> Arc<egui::Galley> {
    WidgetText::from(text.clone()).into_galley(
        ui,
        Some(egui::TextWrapMode::Extend),
        f32::INFINITY,
        egui::TextStyle::Body,
    )
}

/// The line's items in the room `ui` has: the scene's name (cut first,
/// whole on hover), the items always shown (the time, the state, the π
/// blocks' count), then the others in order while they fit, then "… more"
/// with the rest.
fn items(ui: &mut egui::Ui, cx: &mut Cx, words: Words) {
    let Words {
        essential,
        optional,
        more,
        spacing,
        more_width,
        fixed,
        wanted,
    } = words;
    let mut essential = essential.into_iter();
    let Some(name) = essential.next() else {
        return;
    };
    let always: Vec<Item> = essential.collect();
    // What the name and the other items may take, "… more" kept room for.
    let free = ui.available_width() - more_width - fixed;
    // The name's own width, and its kept end's (whole and short) with the
    // room before it.
    let gap = NAME_END_GAP * spacing;
    let (own, ends) = name.widths(ui, gap);
    let full_name = name.whole_width(ui, gap);
    let mut name_width = full_name.min((0.6 * free).max(40.0));
    // The momentum is the lesson: the name is cut further (down to
    // NAME_AT_LEAST) where that shows it, and the items before it. At a
    // projector's text size 1.5 at 1024×768 the name had kept 60 % of the
    // line and the momentum went under "… more".
    if free - name_width < wanted {
        let least = NAME_AT_LEAST.min(full_name);
        name_width = name_width.min((free - wanted).max(least));
    }
    let name_width = name_width;
    // The other items that fit beside the name at that width, in order (the
    // last may use the room kept for "… more")...
    // (`free` has the room between items: `fixed` the one before each item
    // always shown, `more_width` the one before "… more", each other item's
    // its own before it.) An item too long whole goes in its short form if
    // that fits (the momentum without "(walls push)"): a German line with a
    // long name had dropped the momentum for its note.
    let (mut room, mut used, mut shown) = (free - name_width, 0.0, 0);
    let mut galleys = Vec::new();
    for (k, item) in optional.iter().enumerate() {
        let last = k + 1 == optional.len();
        let fits = |g: &Arc<egui::Galley>| {
            g.size().x + spacing - if last { more_width } else { 0.0 } <= room
        };
        let whole = galley(ui, &item.text);
        let short = || item.short.as_ref().map(|text| galley(ui, text));
        let Some(g) = Some(whole).filter(fits).or_else(|| short().filter(fits)) else {
            break;
        };
        room -= g.size().x + spacing;
        used += g.size().x + spacing;
        shown += 1;
        galleys.push(g);
    }
    // ... and the room they leave goes back to the name, so that it is cut
    // only where the line is really full.
    let name_width = full_name.min((free - used).max(name_width));
    ui.spacing_mut().item_spacing.x = spacing;
    ui.set_clip_rect(ui.max_rect().intersect(ui.clip_rect()));
    let height = ui.available_height();
    // The end whole where the name keeps its least room beside it (or is
    // whole), else short.
    let end = name.kept_end.zip(ends).map(|([whole, short], [w, s])| {
        let hover = whole.text().to_string();
        if name_width - w >= own.min(NAME_AT_LEAST) {
            (whole, w, None)
        } else {
            (short, s, Some(hover))
        }
    });
    let end_width = end.as_ref().map_or(0.0, |(_, w, _)| *w);
    if end.is_some() {
        ui.spacing_mut().item_spacing.x = gap;
    }
    // Cut, the name says itself whole on hover, with its end.
    let whole = match &end {
        Some((_, _, Some(hover))) => Some(format!("{} {hover}", name.text.text())),
        _ => None,
    };
    // Laid out from the left, as wide as its text: the end follows it.
    let layout = egui::Layout::left_to_right(egui::Align::Center);
    let r = ui
        .allocate_ui_with_layout(egui::vec2(name_width - end_width, height), layout, |ui| {
            crate::app::ui::widgets::one_line(ui, name.text, whole)
        })
        .inner;
    ui.spacing_mut().item_spacing.x = spacing;
    let r = match end {
        Some((end, _, hover)) => {
            let end = ui.add(egui::Label::new(end).extend());
            r.union(match hover {
                Some(h) => end.tip(h),
                None => end,
            })
        }
        None => r,
    };
    cx.note("scene_name", &r);
    if name_width - end_width + 0.5 < own {
        cx.marks.cut.insert("scene_name".into());
    }
    let always_shown = always.len();
    let said = always.into_iter().map(|item| (item, None));
    let mut galleys = galleys.into_iter();
    let others = optional.into_iter().map(|item| (item, galleys.next()));
    let mut hidden = Vec::new();
    for (k, (item, g)) in said.chain(others).enumerate() {
        if k >= always_shown + shown {
            hidden.push(item.text.text().to_string());
            continue;
        }
        let r = match g {
            Some(g) => ui.label(g),
            None => ui.label(item.text),
        };
        let r = match item.hover {
            Some(h) => r.tip(h),
            None => r,
        };
        if let Some(name) = item.name {
            cx.note(name, &r);
        }
    }
    if !hidden.is_empty() {
        more_label(ui, cx, more, hidden.join("\n"));
    }
}

/// "… more", with `hidden` on hover, while it has the keys (Tab reaches
/// it), or from a click until the next click elsewhere or Esc: a touch
/// screen (a classroom's board) has no hover.
fn more_label(ui: &mut egui::Ui, cx: &mut Cx, more: RichText, hidden: String) {
    let r = ui.add(egui::Label::new(more).sense(egui::Sense::click()));
    let pinned_id = r.id.with("pinned");
    let mut pinned = ui.data(|d| d.get_temp::<bool>(pinned_id)).unwrap_or(false);
    if r.clicked() {
        pinned = !pinned;
    } else if ui.input(|i| i.pointer.any_pressed()) && !r.hovered() {
        pinned = false;
    }
    // Esc lets go of it, as of any popup; and it gives way to the key list
    // and the start screen, which it would cover.
    let panels = &cx.model.panels;
    if ui.input(|i| i.key_pressed(egui::Key::Escape)) || panels.help_open || panels.start_open {
        pinned = false;
    }
    ui.data_mut(|d| d.insert_temp(pinned_id, pinned));
    let r = if r.has_focus() || pinned {
        r.tip_now(hidden);
        r
    } else {
        r.tip(hidden)
    };
    cx.note("top_bar_more", &r);
}

/// The buttons at the bar's right end, in a group as wide as it was last
/// frame (`group` keeps the width); a change of width lays the frame out
/// again.
fn button_group(
    ui: &mut egui::Ui,
    cx: &mut Cx,
    buttons: Vec<(String, Command, &str)>,
    (group, width): (egui::Id, f32),
) {
    let size = egui::vec2(width, ui.available_height());
    let used = ui
        .allocate_ui_with_layout(
            size,
            egui::Layout::left_to_right(egui::Align::Center),
            |ui| {
                ui.spacing_mut().item_spacing.x = 8.0;
                for (label, command, name) in buttons.into_iter().rev() {
                    crate::app::ui::widgets::labelled_button(ui, cx, label, command, Some(name));
                }
                ui.min_rect().width()
            },
        )
        .inner;
    if (used - width).abs() > 0.5 {
        ui.data_mut(|d| d.insert_temp(group, used));
        ui.ctx()
            .request_discard("the top bar's buttons changed width");
    }
}
