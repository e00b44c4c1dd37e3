//! Small widgets the panels share: a slider with its value box, a choice
//! from a list, a line of feedback, a text field that selects its text when
//! it gets the keyboard, a button whose tooltip comes from the key
//! bindings, one line cut to its room with one tooltip, and the tip of
//! every readout of the angular momentum L.

use super::Cx;
use crate::app::lang::tr;
use crate::app::model::bindings;
use crate::app::model::{Command, Note};
use crate::app::ui::tip::Tip;
use egui::{ComboBox, Slider, Ui};
use std::fmt::Display;

mod arrows;
use arrows::arrow_steps;

/// One line of text, cut with "…" where it has no room. Hovered, it shows
/// `more` when given, else the whole line if it was cut: one tooltip. (egui's
/// own label adds the whole line's tooltip whenever it cuts, and a second
/// tooltip ([`super::tip::Tip::tip`]) stacked another under it: the name
/// twice, or the line under its explanation.)
pub fn one_line(
    ui: &mut Ui,
    text: impl Into<egui::WidgetText>,
    more: Option<String>,
) -> egui::Response {
    cut_label(ui, egui::Label::new(text).truncate(), more)
}

/// `label` laid out and drawn with one tooltip, as [`one_line`] is: `more`
/// when given, else the whole text if it was cut.
pub fn cut_label(ui: &mut Ui, label: egui::Label, more: Option<String>) -> egui::Response {
    let (pos, galley, response) = label.layout_in_ui(ui);
    response.widget_info(|| {
        egui::WidgetInfo::labeled(egui::WidgetType::Label, ui.is_enabled(), galley.text())
    });
    if ui.is_rect_visible(response.rect) {
        let color = ui.visuals().text_color();
        ui.painter().galley(pos, galley.clone(), color);
    }
    match more {
        Some(more) => response.tip(more),
        None if galley.elided => response.tip(galley.text()),
        None => response,
    }
}

/// A button that sends `command` when clicked, labelled and with its key in
/// the tooltip as the bindings table says; noted under `name` in the dump.
pub fn command_button(
    ui: &mut Ui,
    cx: &mut Cx,
    command: Command,
    name: Option<&str>,
) -> egui::Response {
    let label = bindings::label(&command).unwrap_or_default();
    labelled_button(ui, cx, label, command, name)
}

/// [`command_button`] with a label of its own (one that follows the state:
/// Play or Pause).
pub fn labelled_button(
    ui: &mut Ui,
    cx: &mut Cx,
    label: impl Into<egui::WidgetText>,
    command: Command,
    name: Option<&str>,
) -> egui::Response {
    wide_labelled_button(ui, cx, (label, 0.0), command, name)
}

/// [`labelled_button`] at least `width` points wide: a button whose label
/// changes ("▶ Play", "⏸ Pause") keeps one width, so that the buttons
/// after it do not move under the pointer.
pub fn wide_labelled_button(
    ui: &mut Ui,
    cx: &mut Cx,
    (label, width): (impl Into<egui::WidgetText>, f32),
    command: Command,
    name: Option<&str>,
) -> egui::Response {
    let tip = bindings::tooltip(&command);
    let mut r = ui.add(egui::Button::new(label).min_size(egui::vec2(width, 0.0)));
    if !tip.is_empty() {
        r = r.tip(tip);
    }
    match name {
        Some(name) => cx.note(name, &r),
        None => cx.marks.stops.push(super::Stop::control(&r)),
    }
    if r.clicked() {
        cx.send(command);
    }
    r
}

/// How wide `text` is on one line in a button's text style (points).
pub fn button_text_width(ui: &Ui, text: impl Into<egui::WidgetText>) -> f32 {
    text.into()
        .into_galley(
            ui,
            Some(egui::TextWrapMode::Extend),
            f32::INFINITY,
            egui::TextStyle::Button,
        )
        .size()
        .x
}

/// A combo box named `label` (its egui id from `salt`), showing
/// `selected`: the name beside it where both fit the dock's width, else on
/// a line of its own above it (long words: German, a projector's scale),
/// so nothing is cut at the edge.
pub fn combo(ui: &mut Ui, salt: &str, label: &str, selected: &str) -> ComboBox {
    let width = |text: &str| button_text_width(ui, text);
    let button = ui
        .spacing()
        .combo_width
        .max(width(selected) + 2.0 * ui.spacing().icon_width + ui.spacing().button_padding.x * 2.0);
    let beside = button + ui.spacing().item_spacing.x + width(label);
    // Its id from `salt`, not from the label: in another language the
    // label changes, and the keyboard must stay on the language's box.
    if beside > ui.available_width() {
        ui.add(egui::Label::new(label).wrap());
        ComboBox::from_id_salt(salt).selected_text(selected.to_string())
    } else {
        ComboBox::new(salt, label).selected_text(selected.to_string())
    }
}

/// A combo box over `list`, showing `current` even when it is not in the
/// list (a scene may ask for 3 substeps), noted under `name`; returns the
/// new choice (clicked, or stepped to with the arrows: [`arrow_choice`]).
pub fn setting_combo<T: Copy + PartialEq + Display>(
    ui: &mut Ui,
    cx: &mut Cx,
    words: (&str, &str, &str),
    list: &[T],
    current: T,
) -> Option<T> {
    let names: Vec<String> = list.iter().map(ToString::to_string).collect();
    let at = list.iter().position(|&item| item == current);
    pick(ui, cx, words, &names, at, &current.to_string())
        .map(|k| list[k])
        .filter(|&c| c != current)
}

/// A combo box of `choices` (by their names) under `label`, with `hover`,
/// noted under `name`, showing `shown` and marking choice `current`:
/// returns the choice clicked (the current one too) or the one the arrows
/// stepped to ([`arrow_choice`]).
pub fn pick(
    ui: &mut Ui,
    cx: &mut Cx,
    (label, hover, name): (&str, &str, &str),
    choices: &[String],
    current: Option<usize>,
    shown: &str,
) -> Option<usize> {
    let mut clicked = None;
    let r = combo(ui, name, label, shown)
        .show_ui(ui, |ui| {
            for (k, choice) in choices.iter().enumerate() {
                if ui.selectable_label(current == Some(k), choice).clicked() {
                    clicked = Some(k);
                }
            }
        })
        .response
        .tip(hover);
    cx.note(name, &r);
    arrow_choice(&r, current, choices.len()).or(clicked)
}

/// The keyboard on a combo box (its button `r`), as on a browser's list
/// box: Up and Down choose the choice before or after `current` (of
/// `count`), Home and End the first and the last, with the list open or
/// shut. egui 0.31 has no keys for a combo box: its arrows moved the
/// keyboard to whatever lay above or below, often a control hidden under
/// the open list. Returns the choice the keys made, if they changed it.
pub fn arrow_choice(r: &egui::Response, current: Option<usize>, count: usize) -> Option<usize> {
    if !r.has_focus() || count == 0 {
        return None;
    }
    if r.interact_rect != r.rect {
        // Partly hidden in its scroll area (the text above it reflowed: a
        // choice of language) while it has the keyboard: back into sight.
        r.scroll_to_me_animation(None, egui::style::ScrollAnimation::none());
    }
    r.ctx.memory_mut(|m| {
        m.set_focus_lock_filter(
            r.id,
            egui::EventFilter {
                vertical_arrows: true,
                ..Default::default()
            },
        )
    });
    use egui::Key;
    let (down, up, home, end) = r.ctx.input(|i| {
        (
            i.num_presses(Key::ArrowDown),
            i.num_presses(Key::ArrowUp),
            i.key_pressed(Key::Home),
            i.key_pressed(Key::End),
        )
    });
    let last = count - 1;
    let next = if home {
        0
    } else if end {
        last
    } else if down + up > 0 {
        match current {
            Some(at) => (at + down).saturating_sub(up).min(last),
            None => 0,
        }
    } else {
        return None;
    };
    (Some(next) != current).then_some(next)
}

/// How a slider's value reads: its track, the decimals shown, its unit,
/// and whether the number is a size whose direction the label gives (a sign
/// typed is dropped, and said so: "−9.8" for gravity pointing down).
#[derive(Clone, Copy, Debug)]
pub struct Reading {
    pub log: bool,
    pub decimals: usize,
    pub suffix: &'static str,
    pub magnitude: bool,
}

impl Reading {
    /// A linear track, `decimals` shown, `suffix` after the number.
    pub fn new(decimals: usize, suffix: &'static str) -> Self {
        Self {
            log: false,
            decimals,
            suffix,
            magnitude: false,
        }
    }

    /// A logarithmic track.
    pub fn log(self) -> Self {
        Self { log: true, ..self }
    }

    /// A size only: a sign typed is dropped.
    pub fn magnitude(self) -> Self {
        Self {
            magnitude: true,
            ..self
        }
    }
}

/// How long the line under a slider that says what became of a typed
/// number stays (s).
const TYPED_NOTE_SECONDS: f64 = 8.0;

/// A slider under its label, as wide as the dock allows, with its value
/// (and unit) in a box beside it that can also be dragged or typed into
/// (while it has the keyboard the shortcuts stay quiet). A number typed
/// outside the range is taken at the nearest end, and a line under the
/// slider says so for a few seconds: nothing changes without a word.
/// Returns the track's response, so its rectangle is the track's, and
/// whether the value changed.
pub fn slider(
    ui: &mut Ui,
    label: &str,
    value: &mut f64,
    range: std::ops::RangeInclusive<f64>,
    reading: Reading,
) -> (egui::Response, bool) {
    let Reading {
        log,
        decimals,
        suffix,
        magnitude,
    } = reading;
    ui.add(egui::Label::new(label).wrap());
    let value_box = 96.0;
    ui.spacing_mut().slider_width = (ui.available_width() - value_box).max(60.0);
    let note_id = ui.id().with(("typed_note", label));
    let (track, changed) = ui
        .horizontal(|ui| {
            // The track's id, as egui made it last frame (inside a layout
            // of its own, so not this one's next).
            let track_id = ui.id().with(("slider_track", label));
            let last = ui.data(|d| d.get_temp::<egui::Id>(track_id));
            let stepped = last.is_some_and(|id| arrow_steps(ui, id, value, &range, log));
            let track = ui.add(
                Slider::new(value, range.clone())
                    .logarithmic(log)
                    .show_value(false),
            );
            ui.data_mut(|d| d.insert_temp(track_id, track.id));
            let speed = if log {
                0.01 * *value
            } else {
                0.005 * (range.end() - range.start())
            };
            if !ui.is_enabled() {
                // egui's value box takes Tab even where it is disabled, and
                // then lets the keyboard drop: a plain box shows the value.
                let text = format!("{}{suffix}", crate::app::numbers::plain(*value, decimals));
                ui.add(egui::Button::new(text));
                return (track, false);
            }
            // What was typed, before egui keeps it to the range.
            let typed = std::cell::Cell::new(None);
            let boxed = ui.add(
                egui::DragValue::new(value)
                    .range(range.clone())
                    .speed(speed)
                    .suffix(suffix)
                    // In the language's numbers (2,50), either separator typed.
                    .custom_formatter(move |v, _| crate::app::numbers::plain(v, decimals))
                    .custom_parser(|text| {
                        let v = crate::app::numbers::parse(text)?;
                        typed.set(Some((text.trim().replace('-', "−"), v)));
                        Some(if magnitude { v.abs() } else { v })
                    }),
            );
            if boxed.has_focus() {
                // Typed into: the shortcuts stay quiet (a digit is a digit).
                ui.ctx()
                    .data_mut(|d| d.insert_temp(egui::Id::new(TYPING_IN_A_BOX), true));
            }
            let typed = typed
                .take()
                .filter(|_| boxed.changed() || boxed.lost_focus());
            if let Some((text, v)) = typed {
                let number = |v: f64| crate::app::numbers::plain(v, decimals);
                let taken = format!("{}{suffix}", number(*value));
                let said = if !range.contains(&if magnitude { v.abs() } else { v }) {
                    Some(Note::error(tr!(
                        "slider-out-of-range",
                        typed = text,
                        low = number(*range.start()),
                        high = format!("{}{suffix}", number(*range.end())),
                        value = taken
                    )))
                } else if magnitude && v < 0.0 {
                    Some(Note::ok(tr!(
                        "slider-sign-dropped",
                        typed = text,
                        value = taken
                    )))
                } else {
                    None
                };
                let until = ui.input(|i| i.time) + TYPED_NOTE_SECONDS;
                ui.ctx().data_mut(|d| match said {
                    Some(said) => d.insert_temp(note_id, (said, until, true)),
                    None => d.remove::<(Note, f64, bool)>(note_id),
                });
            }
            let changed = stepped || track.changed() || boxed.changed();
            (track, changed)
        })
        .inner;
    if track.dragged() {
        ui.ctx()
            .data_mut(|d| d.remove::<(Note, f64, bool)>(note_id));
    }
    let note = ui.ctx().data(|d| d.get_temp::<(Note, f64, bool)>(note_id));
    if let Some((said, until, fresh)) = note {
        let now = ui.input(|i| i.time);
        if now < until {
            let r = show_note(ui, &said);
            if fresh {
                // Into sight once (a projector's drawer had it below its
                // fold), then left where the person scrolls.
                r.scroll_to_me(None);
                ui.ctx()
                    .data_mut(|d| d.insert_temp(note_id, (said, until, false)));
            }
            ui.ctx()
                .request_repaint_after(std::time::Duration::from_secs_f64(until - now));
        } else {
            ui.ctx()
                .data_mut(|d| d.remove::<(Note, f64, bool)>(note_id));
        }
    }
    (track, changed)
}

/// Where a value box notes that it has the keyboard (egui's memory).
pub const TYPING_IN_A_BOX: &str = "typing_in_a_box";

/// A red or green line of feedback.
pub fn show_note(ui: &mut Ui, note: &Note) -> egui::Response {
    let color = if note.error {
        if ui.visuals().dark_mode {
            egui::Color32::from_rgb(255, 120, 110)
        } else {
            egui::Color32::from_rgb(170, 0, 0)
        }
    } else if ui.visuals().dark_mode {
        egui::Color32::from_rgb(120, 230, 140)
    } else {
        egui::Color32::from_rgb(0, 110, 30)
    };
    ui.add(egui::Label::new(egui::RichText::new(&note.text).color(color)).wrap())
}

/// Selects a text field's whole text when it gains the keyboard, so what is
/// typed replaces the old value (typing 5 into "1" gives 5, not 51).
pub fn select_all_on_focus(ui: &Ui, response: &egui::Response, text: &str) {
    if response.gained_focus() {
        if let Some(mut state) = egui::TextEdit::load_state(ui.ctx(), response.id) {
            let all = egui::text::CCursorRange::two(
                egui::text::CCursor::new(0),
                egui::text::CCursor::new(text.chars().count()),
            );
            state.cursor.set_char_range(Some(all));
            state.store(ui.ctx(), response.id);
        }
    }
}

/// `tip` for a readout of the total angular momentum L, followed, where the
/// world's edges wrap round, by why L jumps there (a disc's place about
/// (0, 0) jumps at an edge, its momentum does not).
pub fn angular_momentum_tip(tip: String, world: &impulse::World) -> String {
    if world.laws.boundary == impulse::Boundary::Periodic {
        format!(
            "{tip}\n\n{}",
            crate::app::lang::tr!("totals-hover-wrapping")
        )
    } else {
        tip
    }
}

#[cfg(test)]
mod test_frames;
#[cfg(test)]
pub use test_frames::{headless, key_press, shapes_drawn, texts_drawn};

#[cfg(test)]
mod tests;
