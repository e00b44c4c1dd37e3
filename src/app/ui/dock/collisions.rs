//! The *Collisions* tab: the impacts counted (between discs and with walls,
//! as the top bar counts them), the last ones kept, newest first, and the
//! newest before and after, disc by disc. Side by side where the dock is
//! wide, one under the other where it is narrow; nothing overlaps.

use super::super::widgets::command_button;
use super::super::{Cx, View};
use crate::app::model::lesson::{count_line, LEDGER_KEEP};
use crate::app::model::Command;
use crate::app::numbers::{plain, vector, with_unit};
use glam::DVec2;
use impulse::ledger::Impact;

/// The tab (no state of its own).
pub struct Collisions;

/// Below this width (points) the list and the newest impact stack.
const SIDE_BY_SIDE: f32 = 760.0;

/// "discs 1 and 0" or "disc 0 and the left wall".
fn who(impact: &Impact) -> String {
    match impact {
        Impact::Pair(c) => format!("discs {} and {}", c.discs[0], c.discs[1]),
        Impact::Wall(w) => format!("disc {} and the {} wall", w.disc, w.wall.name()),
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
            ui.add(
                egui::Label::new(
                    "None yet. Next collision (J) runs to the next one, between discs or with a \
                     wall, and pauses at the instant of impact.",
                )
                .wrap(),
            );
            return;
        };
        if ui.available_width() >= SIDE_BY_SIDE {
            ui.columns(2, |columns| {
                list(&mut columns[0], &recent);
                detail(&mut columns[1], newest);
            });
        } else {
            egui::ScrollArea::vertical()
                .id_salt("ledger_stacked")
                .show(ui, |ui| {
                    detail(ui, newest);
                    ui.separator();
                    list(ui, &recent);
                });
        }
    }
}

/// The kept impacts, newest first.
fn list(ui: &mut egui::Ui, recent: &[Impact]) {
    ui.strong(format!("The last {}, newest first", recent.len()));
    egui::ScrollArea::both()
        .id_salt("ledger_list")
        .auto_shrink([false, true])
        .show(ui, |ui| {
            egui::Grid::new("ledger")
                .striped(true)
                .num_columns(4)
                .spacing([18.0, 4.0])
                .show(ui, |ui| {
                    for (h, hover) in [
                        ("t (s)", "when it happened"),
                        ("what", "which discs, or which disc and wall"),
                        ("Δp (kg·m/s)", "the change of the total momentum of the discs in it: zero between discs, the wall's push at a wall"),
                        ("ΔKE (J)", "the change of their kinetic energy, the energy of moving: zero in an elastic collision, less than zero when some is lost"),
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
fn detail(ui: &mut egui::Ui, impact: &Impact) {
    ui.strong(format!(
        "Newest: {} at t = {}",
        who(impact),
        with_unit(impact.time(), 3, "s")
    ));
    // Per disc: momentum and kinetic energy, and the velocity along the
    // line of impact and across it (at a wall: away from it and along it).
    type Split = ((f64, f64), (f64, f64));
    let disc_rows = |d: usize,
                     (p0, p1): (DVec2, DVec2),
                     (e0, e1): (f64, f64),
                     split: Split,
                     names: [&str; 2]| {
        let ((n0, t0), (n1, t1)) = split;
        [
            (
                format!("disc {d}: p (kg·m/s)"),
                vector(p0, 3, ""),
                vector(p1, 3, ""),
            ),
            (format!("disc {d}: KE (J)"), plain(e0, 3), plain(e1, 3)),
            (
                format!("disc {d}: v {} (m/s)", names[0]),
                plain(n0, 3),
                plain(n1, 3),
            ),
            (
                format!("disc {d}: v {} (m/s)", names[1]),
                plain(t0, 3),
                plain(t1, 3),
            ),
        ]
    };
    let mut rows: Vec<(String, String, String)> = Vec::new();
    match impact {
        Impact::Pair(c) => {
            for k in 0..2 {
                let names = ["along the line of impact", "across it"];
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
            let names = ["away from the wall", "along the wall"];
            rows.extend(disc_rows(
                w.disc,
                w.momentum(),
                w.kinetic_energy(),
                w.components(),
                names,
            ));
            rows.push((
                "the wall's push, Δp (kg·m/s)".to_string(),
                String::new(),
                vector(w.wall_impulse(), 3, ""),
            ));
        }
    }
    egui::ScrollArea::both()
        .id_salt("ledger_detail")
        .auto_shrink([false, true])
        .show(ui, |ui| {
            egui::Grid::new("ledger_newest")
                .striped(true)
                .num_columns(3)
                .spacing([18.0, 4.0])
                .show(ui, |ui| {
                    for h in ["", "before", "after"] {
                        ui.strong(h);
                    }
                    ui.end_row();
                    for (what, before, after) in rows {
                        ui.label(what);
                        ui.label(before);
                        ui.label(after);
                        ui.end_row();
                    }
                })
                .response
                .on_hover_text(
                    "The line of impact runs through the centres of the two discs (or from the \
                     wall to the disc) at the instant they touch; only the speed along it \
                     changes in a smooth collision.",
                );
        });
}
