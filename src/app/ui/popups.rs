//! What the user opens and closes, the only things allowed over the world:
//! the key list (H), made from the bindings table, the preset menu (P), and
//! the question whether to restore a session that ended with unsaved work.
//! Each fits the window at every scale: a fixed size within the window,
//! two columns where it is wide, each key over its meaning where it is
//! narrow, scrolling where it is tall.

use super::dialog::{scroll, scroll_by_any_keys, Dialog};
use super::Cx;
use crate::app::lang::tr;
use crate::app::model::bindings::{browser_keeps, control_of, BINDINGS};
use crate::app::model::{scenes, Command};
use egui::RichText;

/// The popups (no state of their own: which are open is the model's).
pub struct Popups;

/// A popup's size (points) in a window of `screen` points: at most
/// `wanted`, and inside the window with a margin.
fn fitted(screen: egui::Rect, wanted: egui::Vec2) -> egui::Vec2 {
    egui::vec2(
        wanted.x.min(screen.width() - 32.0).max(120.0),
        wanted.y.min(screen.height() - 96.0).max(80.0),
    )
}

/// What a help line says its keys do, with the control that does the same.
fn help_text(help: &str, control: Option<&str>) -> String {
    match control {
        Some(c) => format!("{help} ({c})"),
        None => help.to_string(),
    }
}

/// Where a help line's keys and their meaning were laid out.
type LineRects = (egui::Rect, egui::Rect);

/// One help line in a table: its keys (bold) and what they do.
fn help_row(ui: &mut egui::Ui, keys: &str, what: &str) -> LineRects {
    let keys = ui.label(RichText::new(keys).strong()).rect;
    let meaning = ui.add(egui::Label::new(what).wrap()).rect;
    ui.end_row();
    (keys, meaning)
}

/// The key list where a table's two columns would squeeze both (a
/// projector's scale): each line's keys in bold over what they do, indented,
/// on a stripe of its own. Laid out in one pass, so nothing moves after H.
fn help_stacked(ui: &mut egui::Ui, lines: &[(String, String)]) -> Option<LineRects> {
    let stripe = ui.visuals().faint_bg_color;
    let mut first = None;
    for (i, (keys, what)) in lines.iter().enumerate() {
        let fill = if i % 2 == 1 {
            stripe
        } else {
            egui::Color32::TRANSPARENT
        };
        egui::Frame::NONE
            .fill(fill)
            .inner_margin(egui::Margin::symmetric(4, 3))
            .show(ui, |ui| {
                ui.set_width(ui.available_width());
                // Ragged, not justified as in `ui.columns`: justified words
                // drift apart on a line that wraps.
                ui.with_layout(egui::Layout::top_down(egui::Align::Min), |ui| {
                    let shown = ui.add(egui::Label::new(RichText::new(keys).strong()).wrap());
                    let meaning =
                        ui.indent(keys, |ui| ui.add(egui::Label::new(what.as_str()).wrap()));
                    first.get_or_insert((shown.rect, meaning.inner.rect));
                });
            });
    }
    first
}

/// Below this width (points) a column of the key list stacks each line's
/// keys over what they do instead of a table of two columns, which gave
/// the meanings a third of it (three to five lines in German).
const STACKED_BELOW: f32 = 640.0;

impl Popups {
    /// The popups that are open.
    pub fn show(&mut self, ctx: &egui::Context, cx: &mut Cx) {
        let screen = ctx.screen_rect();
        let panels = &cx.model.panels;
        // The help opens at its top, as a page does: it had kept where it
        // was read to the last time, the first lines out of sight.
        let was_open = egui::Id::new("help_was_open");
        let opened = !ctx.data(|d| d.get_temp(was_open)).unwrap_or(false);
        ctx.data_mut(|d| d.insert_temp(was_open, panels.help_open));
        if panels.help_open {
            self.help(ctx, cx, screen, opened);
        }
        if panels.presets_open {
            self.presets(ctx, cx, screen);
        }
        if let Some(question) = cx.model.recovery_prompt() {
            // The question comes first: nothing behind it takes the keyboard
            // or the pointer until it is answered.
            let dialog = Dialog::new("recovery", Some(tr!("recovery-title")))
                .max_width(fitted(screen, egui::vec2(560.0, 400.0)).x)
                .modal(ctx);
            dialog.show(ctx, cx, |ui, cx| {
                ui.add(egui::Label::new(question).wrap());
                ui.label(tr!("recovery-waits"));
                ui.horizontal_wrapped(|ui| {
                    let r = ui.button(tr!("recovery-restore"));
                    cx.note("recovery_restore", &r);
                    if r.clicked() {
                        cx.send(Command::RestoreRecovery);
                    }
                    let r = ui.button(tr!("recovery-set-aside"));
                    cx.note("recovery_set_aside", &r);
                    if r.clicked() {
                        cx.send(Command::SetRecoveryAside);
                    }
                });
            });
        }
    }

    fn help(&mut self, ctx: &egui::Context, cx: &mut Cx, screen: egui::Rect, opened: bool) {
        let size = fitted(screen, egui::vec2(1100.0, 900.0));
        let two_columns = size.x >= 860.0;
        let lines: Vec<_> = BINDINGS
            .iter()
            // The browser keeps these keys for itself.
            .filter(|b| !(cfg!(target_arch = "wasm32") && browser_keeps(b)))
            .map(|b| (b.keys(), help_text(&b.help(), control_of(b).as_deref())))
            .collect();
        // Modal: it covers most of the window (all of it at a projector's
        // scale), and Tab must not walk the controls hidden behind it.
        let shown = Dialog::new("help_window", Some(tr!("help-title")))
            .fixed_size(size)
            .closable()
            .modal(ctx)
            .show(ctx, cx, |ui, cx| {
                let mut area = egui::ScrollArea::vertical();
                if opened {
                    area = area.vertical_scroll_offset(0.0);
                }
                scroll_by_any_keys(ui, cx, area, "keys", |ui, cx| {
                    let grid = |ui: &mut egui::Ui, id: &str, part: &[(String, String)]| {
                        egui::Grid::new(id)
                            .striped(true)
                            .num_columns(2)
                            .max_col_width(ui.available_width() * 0.62)
                            .show(ui, |ui| {
                                let mut first = None;
                                for (keys, what) in part {
                                    first.get_or_insert(help_row(ui, keys, what));
                                }
                                first
                            })
                            .inner
                    };
                    let list = |ui: &mut egui::Ui, id: &str, part: &[(String, String)]| {
                        if ui.available_width() < STACKED_BELOW {
                            help_stacked(ui, part)
                        } else {
                            grid(ui, id, part)
                        }
                    };
                    // Where the first line is, for the state dump: the window
                    // tests check that its meaning has room, and stays put.
                    let first = if two_columns {
                        let half = lines.len().div_ceil(2);
                        ui.columns(2, |columns| {
                            let first = list(&mut columns[0], "help_left", &lines[..half]);
                            list(&mut columns[1], "help_right", &lines[half..]);
                            first
                        })
                    } else {
                        list(ui, "help_grid", &lines)
                    };
                    if let Some((keys, meaning)) = first {
                        cx.marks.note("help_first_keys", keys);
                        cx.marks.note("help_first_meaning", meaning);
                    }
                });
            });
        cx.marks.note("help_window", shown.rect);
        // Esc closes the help even when a control in it has the keys (egui
        // takes them back first: it needed a second Esc).
        let esc_in_help =
            cx.keys == super::Keys::Controls && ctx.input(|i| i.key_pressed(egui::Key::Escape));
        if shown.close || esc_in_help {
            cx.send(Command::ToggleHelp);
        }
    }

    fn presets(&mut self, ctx: &egui::Context, cx: &mut Cx, screen: egui::Rect) {
        let size = fitted(screen, egui::vec2(640.0, 900.0));
        // Modal, as the key list: a choice to make (choosing closes it),
        // over most of the window at a projector's scale.
        let shown = Dialog::new("presets_window", Some(tr!("presets-title")))
            .fixed_size(size)
            .closable()
            .modal(ctx)
            .show(ctx, cx, |ui, cx| {
                if cx.model.recovery.aside.is_some() {
                    let label = crate::app::model::bindings::label(&Command::ReopenKept);
                    let r = ui.button(RichText::new(label.unwrap_or_default()).strong());
                    cx.note("reopen_kept_menu", &r);
                    if r.clicked() {
                        cx.send(Command::ReopenKept);
                    }
                    ui.label(tr!("reopen-kept-hover"));
                    ui.separator();
                }
                ui.label(tr!("presets-press"));
                scroll(ui, cx, egui::ScrollArea::vertical(), "presets", |ui, cx| {
                    for (k, label) in scenes::preset_labels().iter().enumerate() {
                        let r = ui.button(RichText::new(label.as_str()).strong());
                        cx.note(format!("preset_{k}"), &r);
                        if r.clicked() {
                            cx.send(Command::OpenPreset(k));
                        }
                        if let Some(d) = scenes::preset_description(k) {
                            ui.add(egui::Label::new(d).wrap());
                        }
                        ui.add_space(4.0);
                    }
                });
            });
        cx.marks.note("preset_menu", shown.rect);
        if shown.close {
            cx.send(Command::TogglePresets);
        }
    }
}
