//! The *Momenta* tab: each disc's momentum drawn tip to tail, and their
//! sum, in one scale for p_x and p_y.

use super::super::{Cx, View};
use super::plots::*;
use crate::app::lang::tr;
use crate::app::model::totals::DIAGRAM_MAX_DISCS;
use crate::app::numbers::vector;
use egui::Color32;
use egui_plot::{Arrows, Line, PlotPoints, Points};

/// The tab (no state of its own).
pub struct Momenta;

impl View for Momenta {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let ps = &model.world.particles;
        if ps.is_empty() || ps.len() > DIAGRAM_MAX_DISCS {
            ui.label(if ps.is_empty() {
                tr!("momenta-no-discs")
            } else {
                tr!("momenta-too-many")
            });
            return;
        }
        let mut at = glam::DVec2::ZERO;
        let mut chain = Vec::new();
        for p in ps {
            chain.push((at, at + p.momentum(), p.color));
            at += p.momentum();
        }
        // One line, so the plot keeps the height: the whole on hover.
        let line = tr!("momenta-line", total = vector(at, 3, "kg·m/s"));
        let r = ui.add(egui::Label::new(line.clone()).truncate());
        r.on_hover_text(tr!("momenta-hover", line = line));
        let sum_color = ui.visuals().strong_text_color();
        let height = ui.available_height();
        // Axis names only where there is room for them beside the plot.
        let roomy = height >= ROOMY_PLOT;
        // As wide as a chain needs: a wide, flat plot at one scale would
        // leave the arrows small in its middle.
        let width = ui.available_width().min(2.2 * height.max(60.0));
        still_plot("momenta_plot")
            .height(height)
            .width(width)
            .data_aspect(1.0)
            .x_axis_label(if roomy { "p_x (kg·m/s)" } else { "" })
            .y_axis_label(if roomy { "p_y (kg·m/s)" } else { "" })
            .include_x(0.0)
            .include_y(0.0)
            .label_formatter(|_, v| vector(glam::DVec2::new(v.x, v.y), 3, "kg·m/s"))
            .show(ui, |plot| {
                plot.line(
                    Line::new(PlotPoints::from(vec![[0.0, 0.0], [at.x, at.y]]))
                        .color(sum_color)
                        .width(5.0)
                        .name(tr!("totals-sum")),
                );
                plot.points(
                    Points::new(vec![[at.x, at.y]])
                        .radius(6.0)
                        .color(sum_color)
                        .name(tr!("totals-sum")),
                );
                for (k, (a, b, c)) in chain.into_iter().enumerate() {
                    let color = Color32::from_rgb(c.r, c.g, c.b);
                    plot.line(
                        Line::new(PlotPoints::from(vec![[a.x, a.y], [b.x, b.y]]))
                            .color(color)
                            .width(2.5)
                            .name(tr!("disc-numbered", disc = k)),
                    );
                    plot.arrows(
                        Arrows::new(vec![[a.x, a.y]], vec![[b.x, b.y]])
                            .color(color)
                            .name(tr!("disc-numbered", disc = k)),
                    );
                }
            });
    }
}
