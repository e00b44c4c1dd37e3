//! The *Momenta* tab: each disc's momentum drawn tip to tail, and their
//! sum, in one scale for p_x and p_y.

use super::super::{Cx, View};
use super::plots::*;
use crate::app::lang::tr;
use crate::app::model::totals::DIAGRAM_MAX_DISCS;
use crate::app::numbers::{disc_number, vector};
use crate::app::ui::widgets::one_line;
use egui::Color32;
use egui_plot::{Arrows, Line, PlotPoint, PlotPoints, Points};

/// Roughly what the numbers under the plot and its axis name take, in
/// points (body text); and the numbers and the name beside it.
const X_AXIS_POINTS: f32 = 45.0;
const Y_AXIS_POINTS: f32 = 60.0;
/// The length of an arrow's head, in points.
const ARROW_HEAD_POINTS: f32 = 12.0;

/// The tab (no state of its own).
pub struct Momenta;

impl View for Momenta {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let ps = &model.world.particles;
        if ps.is_empty() {
            ui.label(tr!("momenta-no-discs"));
            return;
        }
        if ps.len() > DIAGRAM_MAX_DISCS {
            // The total here: the top bar, which this once pointed to,
            // keeps it behind "… more" on a projector.
            let total = ps.iter().map(|p| p.momentum()).sum::<glam::DVec2>();
            ui.label(tr!(
                "momenta-too-many",
                total = vector(total, 3, "kg·m/s"),
                count = ps.len(),
                most = DIAGRAM_MAX_DISCS
            ));
            return;
        }
        let mut at = glam::DVec2::ZERO;
        let mut chain = Vec::new();
        for (i, p) in ps.iter().enumerate() {
            let color = cx.model.overlays.disc_color(&cx.model.world, i);
            chain.push((at, at + p.momentum(), color));
            at += p.momentum();
        }
        // One line, so the plot keeps the height: the whole on hover.
        let line = tr!("momenta-line", total = vector(at, 3, "kg·m/s"));
        let more = tr!("momenta-hover", line = line.clone());
        one_line(ui, line, Some(more));
        let sum_color = ui.visuals().strong_text_color();
        let height = ui.available_height();
        // Axis names only where there is room for them beside the plot.
        let roomy = height >= ROOMY_PLOT;
        // Below that, no numbers under it either: they and the line egui
        // keeps for the axis name took two thirds of a projector's dock
        // (a diagram 23 points high in 67). One scale both ways, so the
        // numbers beside it read p_x as well.
        let frame_height = if roomy {
            height - X_AXIS_POINTS
        } else {
            height
        };
        // As wide as the chain at that height (plus the numbers beside it):
        // wider would leave the arrows small in the middle of a flat plot.
        let (lo, hi) = chain.iter().fold(
            (at.min(glam::DVec2::ZERO), at.max(glam::DVec2::ZERO)),
            |(lo, hi), (a, b, _)| (lo.min(*a).min(*b), hi.max(*a).max(*b)),
        );
        let extent = hi - lo;
        // A margin all round, so no arrow runs along the frame.
        let pad = 0.08 * extent.max_element();
        let (lo, hi) = (lo - pad, hi + pad);
        let aspect = if extent.y > 1e-9 * extent.x {
            extent.x / extent.y
        } else {
            f64::INFINITY
        };
        let wanted = frame_height * (aspect as f32).clamp(1.2, 1e4) * 1.1 + Y_AXIS_POINTS;
        let width = ui.available_width().min(wanted);
        let readout = Readout::default();
        let plot = still_plot("momenta_plot")
            .height(height)
            .width(width)
            .data_aspect(1.0)
            .show_axes([roomy, true])
            .x_axis_label(if roomy { "p_x (kg·m/s)" } else { "" })
            .y_axis_label(if roomy { "p_y (kg·m/s)" } else { "" })
            .include_x(lo.x)
            .include_x(hi.x)
            .include_y(lo.y)
            .include_y(hi.y)
            .label_formatter(readout.keeping(|name: &str, v: &PlotPoint| {
                on_a_line(name, || vector(glam::DVec2::new(v.x, v.y), 3, "kg·m/s"))
            }))
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
                            .name(tr!("disc-numbered", disc = disc_number(k))),
                    );
                    plot.arrows(
                        Arrows::new(vec![[a.x, a.y]], vec![[b.x, b.y]])
                            // egui_plot's head is a quarter of the arrow:
                            // across the whole plot for a long one.
                            .tip_length(ARROW_HEAD_POINTS)
                            .color(color)
                            .name(tr!("disc-numbered", disc = disc_number(k))),
                    );
                }
            });
        readout.show(ui, &plot.response);
        cx.note("momenta_plot", &plot.response);
    }
}

#[cfg(test)]
mod tests {
    use super::Momenta;
    use crate::app::model::tests::sandbox_with;
    use crate::app::numbers::vector;
    use crate::app::ui::widgets::texts_drawn;

    /// A gas too large for the diagram: the tab gives its total momentum.
    /// It pointed to the top bar, which on a projector keeps the total
    /// behind "… more".
    #[test]
    fn a_gas_too_large_for_the_diagram_gets_its_total_in_the_tab() {
        let dir = tempfile::tempdir().unwrap();
        let model = sandbox_with(dir.path(), "preset-8-gas.toml", true, 0.0);
        let n = model.world.particles.len();
        assert!(n > super::DIAGRAM_MAX_DISCS, "{n} discs");
        let total = model.world.particles.iter().map(|p| p.momentum()).sum();
        let text: String = texts_drawn(&model, egui::vec2(600.0, 200.0), &mut Momenta).concat();
        let total = vector(total, 3, "kg·m/s");
        assert!(text.contains(&total), "{text:?} without {total}");
        assert!(
            text.contains(&n.to_string()) && !text.contains("top bar"),
            "{text:?}"
        );
    }
}
