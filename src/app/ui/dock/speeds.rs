//! The *Speeds* tab: the speed histogram against Maxwell–Boltzmann; with
//! spin shown also the rim speeds |ω|·r, and how the energy is shared
//! between moving and turning over time.

use super::super::{Cx, View};
use super::plots::*;
use crate::app::model::overlays::spin_shown;
use crate::app::model::totals::{RimHistogram, SpeedHistogram};
use crate::app::numbers::{plain, with_unit};
use egui_plot::{HLine, Line, LineStyle, PlotPoints};

/// The tab (no state of its own).
pub struct Speeds;

impl View for Speeds {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let Some(h) = SpeedHistogram::of(&model.world) else {
            ui.label("Too few moving discs for a distribution: try preset 8, a gas.");
            return;
        };
        if !spin_shown(&model.world) {
            // One line, so the plot keeps its height; the whole on hover.
            let line = "Bars: how many discs move at each speed. Curve: how a gas settles (Maxwell–Boltzmann).";
            ui.add(egui::Label::new(line).truncate()).on_hover_text(format!(
                "{line}\nThe curve is where the speeds end up once collisions have shared the energy \
                 out at random, for discs with this much energy each on average: kT = KE/N = {} \
                 (the temperature, in energy per disc).",
                with_unit(h.kt, 3, "J")
            ));
            let height = ui.available_height();
            // The line above names bars and curve; a short plot has no room for a legend box.
            speed_plot(ui, &h, None, height, height >= ROOMY_PLOT);
            return;
        }
        // Rough discs: the rim speeds beside the speeds, and how the energy
        // is shared between moving and turning. Each plot is named by a
        // line of coloured words above it, not a legend box, which in a
        // short dock covered the bars.
        let rims = RimHistogram::of(&model.world, &h);
        let samples: Vec<_> = model.record.totals.samples().copied().collect();
        let kt = with_unit(h.kt, 3, "J");
        ui.columns(2, |columns| {
            let ui = &mut columns[0];
            ui.horizontal_wrapped(|ui| {
                // Each name stays whole; a narrow column moves it down.
                ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
                let meaning = format!(
                    "Bars: how many discs move (or turn their edge) at each speed, per m/s. \
                     Curves: where they settle when the energy is shared equally, at the \
                     temperature kT = KE/N = {kt}: Maxwell–Boltzmann for the speeds (solid), \
                     and for the rim speeds (dashed)."
                );
                named(ui, "■ speeds |v|", PX_COLOR).on_hover_text(&meaning);
                named(ui, "■ rim speeds |ω|·r", RIM_COLOR).on_hover_text(format!(
                    "How fast the edge of each disc moves as it turns: its spin ω times its \
                     radius r.\n{meaning}"
                ));
            });
            let height = ui.available_height();
            speed_plot(ui, &h, Some(&rims), height, false);
            let ui = &mut columns[1];
            ui.horizontal_wrapped(|ui| {
                ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
                ui.label("energy:")
                    .on_hover_text("the share of the energy (%) in moving and in turning");
                named(ui, "— moving", KE_COLOR);
                named(ui, "— turning", ROT_COLOR);
                named(ui, "- - one third", ROT_COLOR).on_hover_text(
                    "Shared equally among the three ways a disc holds energy (moving along x, \
                     along y, turning), turning gets one third",
                );
            });
            let height = ui.available_height();
            let moving: Vec<[f64; 2]> = samples
                .iter()
                .map(|s| [s.time, 100.0 * (1.0 - s.rotation_share())])
                .collect();
            let turning: Vec<[f64; 2]> = samples
                .iter()
                .map(|s| [s.time, 100.0 * s.rotation_share()])
                .collect();
            still_plot("shares_plot")
                .height(height)
                .x_axis_label("time (s)")
                .y_axis_label(if height >= ROOMY_PLOT { "%" } else { "" })
                .include_y(0.0)
                .include_y(100.0)
                .label_formatter(|name, v| {
                    format!("{name}\nt = {} s\n{} %", plain(v.x, 2), plain(v.y, 1))
                })
                .show(ui, |plot| {
                    plot.hline(
                        HLine::new(100.0 / 3.0)
                            .name("one third")
                            .color(ROT_COLOR)
                            .style(LineStyle::dashed_loose())
                            .width(1.5),
                    );
                    plot.line(
                        Line::new(PlotPoints::from(moving))
                            .name("moving (KE)")
                            .color(KE_COLOR)
                            .width(2.5),
                    );
                    plot.line(
                        Line::new(PlotPoints::from(turning))
                            .name("turning (rotational KE)")
                            .color(ROT_COLOR)
                            .width(2.5),
                    );
                });
        });
    }
}
