//! The bottom dock: a strip of tabs and the chosen one below it. *Totals*
//! plots p_x, p_y and KE against time; *Collisions* is the ledger;
//! *Discs* the table of every disc ([`super::discs_table`]); *Speeds* the
//! histogram against Maxwell–Boltzmann; *Momenta* every disc's momentum tip
//! to tail and their sum. At the projector's scale it starts folded to its
//! tab strip.

use super::numbers::{plain, vector, with_unit};
use super::DockTab;
use crate::app::plot::{SpeedHistogram, DIAGRAM_MAX_DISCS};
use crate::app::App;
use egui::{Color32, RichText};
use egui_plot::{Arrows, Bar, BarChart, Corner, Legend, Line, Plot, PlotPoints, Points};

/// Colours of the plotted totals (Okabe–Ito).
const PX_COLOR: Color32 = Color32::from_rgb(86, 180, 233); // sky blue
const PY_COLOR: Color32 = Color32::from_rgb(230, 159, 0); // orange
const KE_COLOR: Color32 = Color32::from_rgb(0, 158, 115); // bluish green
/// Below this height (points) a plot has no room for its legend box.
const COMPACT_PLOT_HEIGHT: f32 = 110.0;

impl App {
    /// Draws the dock; returns its rectangle (points).
    pub(super) fn dock(
        &mut self,
        ctx: &egui::Context,
        actions: &mut Vec<super::Action>,
    ) -> egui::Rect {
        let expanded = self.ui.dock_expanded;
        let screen = ctx.screen_rect();
        let panel = if expanded {
            egui::TopBottomPanel::bottom("dock")
                .resizable(true)
                .default_height((screen.height() * 0.22).clamp(130.0, 280.0))
                .height_range(100.0..=(screen.height() * 0.5).max(110.0))
        } else {
            egui::TopBottomPanel::bottom("dock_folded").resizable(false)
        };
        let response = panel.show(ctx, |ui| {
            self.tab_strip(ui);
            if self.ui.dock_expanded && expanded {
                ui.separator();
                match self.ui.tab {
                    DockTab::Totals => self.totals_tab(ui),
                    DockTab::Collisions => self.collisions_tab(ui, actions),
                    DockTab::Discs => self.discs_tab(ui),
                    DockTab::Speeds => self.speeds_tab(ui),
                    DockTab::Momenta => self.momenta_tab(ui),
                }
            }
        });
        response.response.rect
    }

    fn tab_strip(&mut self, ui: &mut egui::Ui) {
        let ppp = super::px_per_point(ui.ctx());
        ui.horizontal(|ui| {
            for tab in DockTab::ALL {
                let chosen = self.ui.tab == tab && self.ui.dock_expanded;
                let r = ui.selectable_label(chosen, RichText::new(tab.title()).strong());
                self.ui
                    .note_widget(format!("tab_{}", tab.title().to_lowercase()), r.rect, ppp);
                if r.clicked() {
                    if chosen {
                        self.ui.dock_expanded = false;
                    } else {
                        self.ui.tab = tab;
                        self.ui.dock_expanded = true;
                    }
                }
            }
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                let label = if self.ui.dock_expanded {
                    "Hide"
                } else {
                    "Show"
                };
                let r = ui.button(label);
                self.ui.note_widget("dock_toggle", r.rect, ppp);
                if r.clicked() {
                    self.ui.dock_expanded = !self.ui.dock_expanded;
                }
            });
        });
    }

    fn totals_tab(&mut self, ui: &mut egui::Ui) {
        let samples: Vec<_> = self.totals.samples().copied().collect();
        let drift = match (self.totals.drift(), samples.first(), samples.last()) {
            (Some(_), Some(a), Some(b)) => format!(
                "change since {}: momentum {}, kinetic energy {}",
                with_unit(a.time, 2, "s"),
                vector(b.momentum - a.momentum, 3, "kg·m/s"),
                with_unit(b.kinetic_energy - a.kinetic_energy, 3, "J")
            ),
            _ => "No record yet: run the simulation.".to_string(),
        };
        // A short dock (a laptop's browser) leaves the plots too low for a
        // legend box inside them, which then covered the line above: the
        // series are named in coloured words beside it instead (p in
        // kg·m/s, KE in J, as the line says).
        let compact = ui.available_height() < COMPACT_PLOT_HEIGHT + 24.0;
        ui.horizontal_wrapped(|ui| {
            ui.label(drift);
            if compact {
                for (name, color) in [("p_x", PX_COLOR), ("p_y", PY_COLOR), ("KE", KE_COLOR)] {
                    ui.label(RichText::new(format!("— {name}")).color(color).strong());
                }
            }
        });
        let height = ui.available_height();
        let legend = |corner| (!compact).then(|| Legend::default().position(corner));
        let series = |value: fn(&crate::app::plot::Sample) -> f64| -> Vec<[f64; 2]> {
            samples.iter().map(|s| [s.time, value(s)]).collect()
        };
        let (px, py, ke) = (
            series(|s| s.momentum.x),
            series(|s| s.momentum.y),
            series(|s| s.kinetic_energy),
        );
        ui.columns(2, |columns| {
            let (lo, hi) = padded_range(px.iter().chain(&py).map(|p| p[1]));
            let plot = still_plot("momentum_plot").height(height);
            let plot = match legend(Corner::RightBottom) {
                Some(l) => plot.legend(l),
                None => plot,
            };
            plot.x_axis_label("time (s)")
                // Too low for a rotated label: the line above gives the units.
                .y_axis_label(if compact { "" } else { "p (kg·m/s)" })
                .include_y(lo)
                .include_y(hi)
                .label_formatter(|name, v| {
                    format!("{name}\nt = {} s\n{} kg·m/s", plain(v.x, 2), plain(v.y, 3))
                })
                .show(&mut columns[0], |plot| {
                    plot.line(
                        Line::new(PlotPoints::from(px))
                            .name("p_x")
                            .color(PX_COLOR)
                            .width(2.5),
                    );
                    plot.line(
                        Line::new(PlotPoints::from(py))
                            .name("p_y")
                            .color(PY_COLOR)
                            .width(2.5),
                    );
                });
            let (lo, hi) = padded_range(ke.iter().map(|p| p[1]));
            let plot = still_plot("energy_plot").height(height);
            let plot = match legend(Corner::RightBottom) {
                Some(l) => plot.legend(l),
                None => plot,
            };
            plot.x_axis_label("time (s)")
                .y_axis_label(if compact { "" } else { "KE (J)" })
                .include_y(lo)
                .include_y(hi)
                .label_formatter(|name, v| {
                    format!("{name}\nt = {} s\n{} J", plain(v.x, 2), plain(v.y, 3))
                })
                .show(&mut columns[1], |plot| {
                    plot.line(
                        Line::new(PlotPoints::from(ke))
                            .name("KE")
                            .color(KE_COLOR)
                            .width(2.5),
                    );
                });
        });
    }

    fn collisions_tab(&mut self, ui: &mut egui::Ui, actions: &mut Vec<super::Action>) {
        let ledger = &self.world.ledger;
        ui.horizontal_wrapped(|ui| {
            ui.label(match ledger.recorded {
                1 => "1 collision between discs recorded".to_string(),
                n => format!("{n} collisions between discs recorded"),
            });
            if ui.button("Next collision").on_hover_text("J").clicked() {
                actions.push(super::Action::NextCollision);
            }
        });
        let recent: Vec<_> = ledger
            .entries()
            .rev()
            .take(crate::app::lesson::LEDGER_KEEP)
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

    fn speeds_tab(&mut self, ui: &mut egui::Ui) {
        let Some(h) = SpeedHistogram::of(&self.world) else {
            ui.label("Too few moving discs for a distribution: try preset 8, a gas.");
            return;
        };
        ui.label(format!(
            "Bars: the discs' speeds. Curve: Maxwell–Boltzmann at the same temperature, kT = KE/N = {}.",
            with_unit(h.kt, 3, "J")
        ));
        let bars: Vec<Bar> = h
            .density
            .iter()
            .enumerate()
            .map(|(k, &d)| Bar::new((k as f64 + 0.5) * h.bin_width, d).width(h.bin_width * 0.9))
            .collect();
        let top = h.bin_width * h.density.len() as f64;
        let law: Vec<[f64; 2]> = (0..=200)
            .map(|k| top * k as f64 / 200.0)
            .map(|v| [v, h.law(v)])
            .collect();
        still_plot("speeds_plot")
            .height(ui.available_height())
            .legend(Legend::default().position(Corner::RightTop))
            .x_axis_label("speed (m/s)")
            .y_axis_label("per m/s")
            .include_y(0.0)
            .label_formatter(|_, v| format!("{} m/s\n{} per m/s", plain(v.x, 2), plain(v.y, 3)))
            .show(ui, |plot| {
                plot.bar_chart(BarChart::new(bars).name("discs").color(PX_COLOR));
                plot.line(
                    Line::new(PlotPoints::from(law))
                        .name("Maxwell–Boltzmann")
                        .color(PY_COLOR)
                        .width(3.0),
                );
            });
    }

    fn momenta_tab(&mut self, ui: &mut egui::Ui) {
        let ps = &self.world.particles;
        if ps.is_empty() || ps.len() > DIAGRAM_MAX_DISCS {
            ui.label(if ps.is_empty() {
                "No discs."
            } else {
                "Too many discs to draw one arrow each: the total is in the top bar."
            });
            return;
        }
        let mut at = glam::DVec2::ZERO;
        let mut chain = Vec::new();
        for p in ps {
            chain.push((at, at + p.momentum(), p.color));
            at += p.momentum();
        }
        ui.label(format!(
            "Each disc's momentum, tip to tail; the sum (thick) ends where the chain ends: {}",
            vector(at, 3, "kg·m/s")
        ));
        let sum_color = ui.visuals().strong_text_color();
        still_plot("momenta_plot")
            .height(ui.available_height())
            .data_aspect(1.0)
            .legend(Legend::default().position(Corner::RightBottom))
            .x_axis_label("p_x (kg·m/s)")
            .y_axis_label("p_y (kg·m/s)")
            .include_x(0.0)
            .include_y(0.0)
            .label_formatter(|_, v| format!("({}, {}) kg·m/s", plain(v.x, 3), plain(v.y, 3)))
            .show(ui, |plot| {
                plot.line(
                    Line::new(PlotPoints::from(vec![[0.0, 0.0], [at.x, at.y]]))
                        .color(sum_color)
                        .width(5.0)
                        .name("sum"),
                );
                plot.points(
                    Points::new(vec![[at.x, at.y]])
                        .radius(6.0)
                        .color(sum_color)
                        .name("sum"),
                );
                for (k, (a, b, c)) in chain.into_iter().enumerate() {
                    let color = Color32::from_rgb(c.r, c.g, c.b);
                    plot.line(
                        Line::new(PlotPoints::from(vec![[a.x, a.y], [b.x, b.y]]))
                            .color(color)
                            .width(2.5)
                            .name(format!("disc {k}")),
                    );
                    plot.arrows(
                        Arrows::new(vec![[a.x, a.y]], vec![[b.x, b.y]])
                            .color(color)
                            .name(format!("disc {k}")),
                    );
                }
            });
    }
}

/// A plot that holds still: no scrolling, dragging or zooming, which in a
/// live plot would only lose the view (hover still reads values).
fn still_plot(id: &str) -> Plot<'static> {
    Plot::new(id)
        .allow_scroll(false)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_boxed_zoom(false)
}

/// A y range that shows a conserved total as a flat line, not its rounding
/// noise magnified: at least ±5 % of the values' size (or ±0.01) around them.
pub fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    let size = lo.abs().max(hi.abs());
    let pad = (0.1 * (hi - lo)).max(0.05 * size).max(0.01);
    (lo - pad, hi + pad)
}

#[cfg(test)]
mod tests {
    use super::padded_range;

    #[test]
    fn a_conserved_total_gets_a_range_wider_than_its_noise() {
        let (lo, hi) = padded_range([2.0, 2.0 + 1e-15, 2.0 - 1e-15].into_iter());
        assert!(hi - lo >= 0.2 - 1e-12, "{lo} {hi}");
        assert!(lo < 2.0 && hi > 2.0);
        assert_eq!(padded_range(std::iter::empty()), (-1.0, 1.0));
        let (lo, hi) = padded_range([0.0, 0.0].into_iter());
        assert!((lo + 0.01).abs() < 1e-12 && (hi - 0.01).abs() < 1e-12);
    }
}
