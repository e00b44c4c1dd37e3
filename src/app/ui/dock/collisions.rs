//! The *Collisions* tab: the impacts counted (between discs and with walls,
//! as the top bar counts them), the last ones kept, newest first, and the
//! newest before and after, disc by disc. Side by side where the dock is
//! wide, one under the other where it is narrow; nothing overlaps.

use super::super::dialog::scroll;
use super::super::widgets::command_button;
use super::super::{Cx, View};
use crate::app::lang::tr;
use crate::app::model::lesson::{count_line, LEDGER_KEEP};
use crate::app::model::Command;
use crate::app::numbers::{plain, vector, with_unit};
use glam::DVec2;
use impulse::ledger::Impact;

/// The tab (no state of its own).
pub struct Collisions;

/// Below this width (points) the list and the newest impact stack.
const SIDE_BY_SIDE: f32 = 760.0;
/// Room kept for a scroll bar beside the table, in points.
const SCROLL_BAR: f32 = 16.0;
/// The names of the newest impact's rows keep at least this share of the
/// width, wrapping, however wide the numbers.
const NAMES_AT_LEAST: f32 = 0.3;

/// "discs 1 and 0" or "disc 0 and the left wall".
fn who(impact: &Impact) -> String {
    match impact {
        Impact::Pair(c) => tr!("ledger-pair", a = c.discs[0], b = c.discs[1]),
        Impact::Wall(w) => tr!("ledger-wall", disc = w.disc, wall = w.wall.name()),
    }
}

impl View for Collisions {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let world = &model.world;
        ui.horizontal_wrapped(|ui| {
            let r = ui.label(count_line(world));
            cx.note("ledger_count", &r);
            command_button(ui, cx, Command::NextCollision, None);
        });
        let recent: Vec<Impact> = world
            .ledger
            .impacts()
            .rev()
            .take(LEDGER_KEEP)
            .copied()
            .collect();
        let Some(newest) = recent.first() else {
            ui.add(egui::Label::new(tr!("ledger-empty")).wrap());
            return;
        };
        if ui.available_width() >= SIDE_BY_SIDE {
            ui.columns(2, |columns| {
                list(&mut columns[0], cx, &recent);
                detail(&mut columns[1], cx, newest);
            });
        } else {
            scroll(
                ui,
                cx,
                egui::ScrollArea::vertical(),
                "ledger_stacked",
                |ui, cx| {
                    detail(ui, cx, newest);
                    ui.separator();
                    list(ui, cx, &recent);
                },
            );
        }
    }
}

/// The kept impacts, newest first.
fn list(ui: &mut egui::Ui, cx: &mut Cx, recent: &[Impact]) {
    ui.strong(tr!("ledger-last", count = recent.len()));
    let area = egui::ScrollArea::both().auto_shrink([false, true]);
    scroll(ui, cx, area, "ledger_list", |ui, _| {
        egui::Grid::new("ledger")
            .striped(true)
            .num_columns(4)
            .spacing([18.0, 4.0])
            .show(ui, |ui| {
                for (h, hover) in [
                    ("t (s)".to_string(), tr!("ledger-time-hover")),
                    (tr!("ledger-what"), tr!("ledger-what-hover")),
                    ("Δp (kg·m/s)".to_string(), tr!("ledger-dp-hover")),
                    (
                        format!("Δ{} (J)", tr!("symbol-ke")),
                        tr!("ledger-dke-hover"),
                    ),
                ] {
                    ui.strong(h).on_hover_text(hover);
                }
                ui.end_row();
                for impact in recent {
                    let (dp, dke) = impact.total_change();
                    ui.label(plain(impact.time(), 3));
                    ui.label(who(impact));
                    ui.label(vector(dp, 3, ""));
                    ui.label(plain(dke, 3));
                    ui.end_row();
                }
            });
    });
}

/// The newest impact, disc by disc, before and after.
fn detail(ui: &mut egui::Ui, cx: &mut Cx, impact: &Impact) {
    ui.strong(tr!(
        "ledger-newest",
        who = who(impact),
        time = with_unit(impact.time(), 3, "s")
    ));
    // Per disc: momentum and kinetic energy, and the velocity along the
    // line of impact and across it (at a wall: away from it and along it).
    type Split = ((f64, f64), (f64, f64));
    let disc_rows = |d: usize,
                     (p0, p1): (DVec2, DVec2),
                     (e0, e1): (f64, f64),
                     split: Split,
                     names: [String; 2]| {
        let ((n0, t0), (n1, t1)) = split;
        let [along, across] = names;
        [
            (
                tr!("ledger-disc-p", disc = d),
                vector(p0, 3, ""),
                vector(p1, 3, ""),
            ),
            (
                tr!("ledger-disc-ke", disc = d, ke = tr!("symbol-ke")),
                plain(e0, 3),
                plain(e1, 3),
            ),
            (
                tr!("ledger-disc-v", disc = d, part = along),
                plain(n0, 3),
                plain(n1, 3),
            ),
            (
                tr!("ledger-disc-v", disc = d, part = across),
                plain(t0, 3),
                plain(t1, 3),
            ),
        ]
    };
    let mut rows: Vec<(String, String, String)> = Vec::new();
    match impact {
        Impact::Pair(c) => {
            for k in 0..2 {
                let names = [tr!("ledger-along-impact"), tr!("ledger-across-impact")];
                let split = c.components(k);
                rows.extend(disc_rows(
                    c.discs[k],
                    c.momentum(k),
                    c.kinetic_energy(k),
                    split,
                    names,
                ));
            }
        }
        Impact::Wall(w) => {
            let names = [tr!("ledger-away-from-wall"), tr!("ledger-along-wall")];
            rows.extend(disc_rows(
                w.disc,
                w.momentum(),
                w.kinetic_energy(),
                w.components(),
                names,
            ));
            rows.push((
                tr!("ledger-wall-push"),
                String::new(),
                vector(w.wall_impulse(), 3, ""),
            ));
        }
    }
    // The names wrap before the numbers are pushed out of sight: at a
    // projector's size "disc 1: v along the line of impact (m/s)" took the
    // width, and the after column was cut off.
    let (before, after) = (tr!("ledger-before"), tr!("ledger-after"));
    let font = egui::TextStyle::Body.resolve(ui.style());
    let widest = |texts: &mut dyn Iterator<Item = &String>| {
        texts
            .map(|t| {
                ui.fonts(|f| f.layout_no_wrap(t.clone(), font.clone(), egui::Color32::WHITE))
                    .size()
                    .x
            })
            .fold(0.0, f32::max)
    };
    let numbers = widest(
        &mut rows
            .iter()
            .flat_map(|(_, b, a)| [b, a])
            .chain([&before, &after]),
    );
    let spacing = 18.0;
    let names = (ui.available_width() - 2.0 * (numbers + spacing) - SCROLL_BAR)
        .max(NAMES_AT_LEAST * ui.available_width());
    let area = egui::ScrollArea::both().auto_shrink([false, true]);
    scroll(ui, cx, area, "ledger_detail", |ui, cx| {
        let r = egui::Grid::new("ledger_newest")
            .striped(true)
            .num_columns(3)
            .spacing([spacing, 4.0])
            .max_col_width(names.max(numbers))
            .show(ui, |ui| {
                for h in [String::new(), before, after] {
                    ui.strong(h);
                }
                ui.end_row();
                for (what, before, after) in rows {
                    ui.add(egui::Label::new(what).wrap());
                    ui.label(before);
                    ui.label(after);
                    ui.end_row();
                }
            })
            .response
            .on_hover_text(tr!("ledger-detail-hover"));
        // Its whole width (the dump shows whether any is cut off).
        cx.note("ledger_newest", &r);
    });
}
