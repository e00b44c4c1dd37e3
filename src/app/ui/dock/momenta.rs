//! The *Momenta* tab: each disc's momentum drawn tip to tail, and their
//! sum, in one scale for p_x and p_y.

use super::super::{Cx, View};
use super::plots::*;
use crate::app::model::totals::DIAGRAM_MAX_DISCS;
use crate::app::numbers::{plain, vector};
use egui::Color32;
use egui_plot::{Arrows, Corner, Legend, Line, PlotPoints, Points};

/// The tab (no state of its own).
pub struct Momenta;

impl View for Momenta {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let ps = &model.world.particles;
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
