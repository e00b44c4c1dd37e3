//! What the user opens and closes, the only things allowed over the world:
//! the key list (H), made from the bindings table, the preset menu (P), and
//! the question whether to restore a session that did not close normally.
//! Each fits the window at every scale: a fixed size within the window,
//! two columns where it is wide, scrolling where it is tall.

use super::dialog::{scroll, Dialog};
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

/// One help line: its keys (bold) and what they do, with the control that
/// does the same.
fn help_row(ui: &mut egui::Ui, keys: &str, help: &str, control: Option<&str>) {
    ui.label(RichText::new(keys).strong());
    let what = match control {
        Some(c) => format!("{help} ({c})"),
        None => help.to_string(),
    };
    ui.add(egui::Label::new(what).wrap());
    ui.end_row();
}

impl Popups {
    /// The popups that are open.
    pub fn show(&mut self, ctx: &egui::Context, cx: &mut Cx) {
        let screen = ctx.screen_rect();
        let panels = &cx.model.panels;
        if panels.help_open {
            self.help(ctx, cx, screen);
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

    fn help(&mut self, ctx: &egui::Context, cx: &mut Cx, screen: egui::Rect) {
        let size = fitted(screen, egui::vec2(1100.0, 900.0));
        let two_columns = size.x >= 860.0;
        let lines: Vec<_> = BINDINGS
            .iter()
            // The browser keeps these keys for itself.
            .filter(|b| !(cfg!(target_arch = "wasm32") && browser_keeps(b)))
            .collect();
        // Modal: it covers most of the window (all of it at a projector's
        // scale), and Tab must not walk the controls hidden behind it.
        let shown = Dialog::new("help_window", Some(tr!("help-title")))
            .fixed_size(size)
            .closable()
            .modal(ctx)
            .show(ctx, cx, |ui, cx| {
                scroll(ui, cx, egui::ScrollArea::vertical(), "keys", |ui, _| {
                    let grid =
                        |ui: &mut egui::Ui,
                         id: &str,
                         part: &[&&crate::app::model::bindings::Binding]| {
                            egui::Grid::new(id)
                                .striped(true)
                                .num_columns(2)
                                .max_col_width(ui.available_width() * 0.62)
                                .show(ui, |ui| {
                                    for b in part {
                                        help_row(
                                            ui,
                                            &b.keys(),
                                            &b.help(),
                                            control_of(b).as_deref(),
                                        );
                                    }
                                });
                        };
                    let refs: Vec<_> = lines.iter().collect();
                    if two_columns {
                        let half = refs.len().div_ceil(2);
                        ui.columns(2, |columns| {
                            grid(&mut columns[0], "help_left", &refs[..half]);
                            grid(&mut columns[1], "help_right", &refs[half..]);
                        });
                    } else {
                        grid(ui, "help_grid", &refs);
                    }
                });
            });
        cx.marks.note("help_window", shown.rect);
        if shown.close {
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
