//! The *Collisions* tab: the ledger, newest first, and the newest impact
//! before and after, disc by disc.

use super::super::{Cx, View};
use crate::app::model::Command;
use crate::app::numbers::{plain, vector, with_unit};

/// The tab (no state of its own).
pub struct Collisions;

impl View for Collisions {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let ledger = &model.world.ledger;
        ui.horizontal_wrapped(|ui| {
            ui.label(match ledger.recorded {
                1 => "1 collision between discs recorded".to_string(),
                n => format!("{n} collisions between discs recorded"),
            });
            if ui.button("Next collision").on_hover_text("J").clicked() {
                cx.send(Command::NextCollision);
            }
        });
        let recent: Vec<_> = ledger
            .entries()
            .rev()
            .take(crate::app::model::lesson::LEDGER_KEEP)
            .cloned()
            .collect();
        if recent.is_empty() {
            ui.label("None yet. Next collision (J) runs to the next one and pauses at the instant of impact.");
            return;
        }
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
        ui.columns(2, |columns| {
            let ui = &mut columns[0];
            ui.strong("Newest first");
            egui_extras::TableBuilder::new(ui)
                .id_salt("ledger")
                .striped(true)
                .column(egui_extras::Column::auto().at_least(70.0))
                .column(egui_extras::Column::auto().at_least(80.0))
                .column(egui_extras::Column::auto().at_least(150.0))
                .column(egui_extras::Column::auto().at_least(90.0))
                .header(24.0, |mut h| {
                    for t in ["t (s)", "discs", "Δp (kg·m/s)", "ΔKE (J)"] {
                        h.col(|ui| {
                            ui.strong(t);
                        });
                    }
                })
                .body(|body| {
                    body.rows(24.0, recent.len(), |mut row| {
                        let c = &recent[row.index()];
                        let (dp, dke) = c.total_change();
                        row.col(|ui| {
                            ui.label(plain(c.time, 3));
                        });
                        row.col(|ui| {
                            ui.label(format!("{} and {}", c.discs[0], c.discs[1]));
                        });
                        row.col(|ui| {
                            ui.label(vector(dp, 3, ""));
                        });
                        row.col(|ui| {
                            ui.label(plain(dke, 3));
                        });
                    });
                });
            let ui = &mut columns[1];
            let c = &recent[0];
            ui.strong(format!(
                "Newest: discs {} and {} at t = {}",
                c.discs[0],
                c.discs[1],
                with_unit(c.time, 3, "s")
            ));
            egui::ScrollArea::vertical()
                .id_salt("ledger_detail")
                .show(ui, |ui| {
                    egui::Grid::new("ledger_newest")
                        .striped(true)
                        .show(ui, |ui| {
                            for h in ["", "before", "after"] {
                                ui.strong(h);
                            }
                            ui.end_row();
                            for k in 0..2 {
                                let (p0, p1) = c.momentum(k);
                                let (e0, e1) = c.kinetic_energy(k);
                                let ((n0, t0), (n1, t1)) = c.components(k);
                                let d = c.discs[k];
                                let rows = [
                                    ("p (kg·m/s)", vector(p0, 3, ""), vector(p1, 3, "")),
                                    ("KE (J)", plain(e0, 3), plain(e1, 3)),
                                    ("v along the normal (m/s)", plain(n0, 3), plain(n1, 3)),
                                    ("v along the tangent (m/s)", plain(t0, 3), plain(t1, 3)),
                                ];
                                for (what, before, after) in rows {
                                    ui.label(format!("disc {d}: {what}"));
                                    ui.label(before);
                                    ui.label(after);
                                    ui.end_row();
                                }
                            }
                        });
                });
        });
    }
}
