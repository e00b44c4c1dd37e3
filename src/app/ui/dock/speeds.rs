//! The *Speeds* tab: the speed histogram against Maxwell–Boltzmann; with
//! spin shown also the rim speeds |ω|·r, and how the energy is shared
//! between moving and turning over time.

use super::super::{Cx, View};
use super::plots::*;
use crate::app::lang::tr;
use crate::app::model::overlays::spin_shown;
use crate::app::model::totals::{RimHistogram, SpeedHistogram};
use crate::app::numbers::{plain, with_unit};
use crate::app::ui::widgets::one_line;
use egui_plot::{HLine, Line, LineStyle, PlotPoints};

/// The tab (no state of its own).
pub struct Speeds;

impl View for Speeds {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let Some(h) = SpeedHistogram::of(&model.world) else {
            ui.label(tr!("speeds-too-few"));
            return;
        };
        if !spin_shown(&model.world) {
            // One line, so the plot keeps its height; the whole on hover.
            let line = tr!("speeds-line");
            let more = tr!(
                "speeds-hover",
                line = line.clone(),
                kt = with_unit(h.kt, 3, "J")
            );
            one_line(ui, line, Some(more));
            let height = ui.available_height();
            // The line above names bars and curve; a short plot has no room for a legend box.
            let r = speed_plot(ui, &h, None, height, height >= ROOMY_PLOT);
            cx.note("speeds_plot", &r);
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
                let meaning = tr!("speeds-rim-meaning", kt = kt.as_str());
                named(ui, &format!("■ {}", tr!("speeds-name")), PX_COLOR).on_hover_text(&meaning);
                named(ui, &format!("■ {}", tr!("rim-speeds")), RIM_COLOR)
                    .on_hover_text(tr!("rim-speeds-hover", meaning = meaning.as_str()));
            });
            let height = ui.available_height();
            let r = speed_plot(ui, &h, Some(&rims), height, false);
            cx.note("speeds_plot", &r);
            let ui = &mut columns[1];
            ui.horizontal_wrapped(|ui| {
                ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
                ui.label(tr!("shares-energy"))
                    .on_hover_text(tr!("shares-energy-hover"));
                named(ui, &format!("— {}", tr!("shares-moving")), KE_COLOR);
                named(ui, &format!("— {}", tr!("shares-turning")), ROT_COLOR);
                named(ui, &format!("- - {}", tr!("shares-one-third")), ROT_COLOR)
                    .on_hover_text(tr!("shares-one-third-hover"));
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
            x_axis(still_plot("shares_plot"), height, tr!("axis-time"), "s")
                .height(height)
                .y_axis_label(if height >= ROOMY_PLOT { "%" } else { "" })
                .include_y(0.0)
                .include_y(100.0)
                .label_formatter(|name, v| {
                    format!("{name}\nt = {} s\n{} %", plain(v.x, 2), plain(v.y, 1))
                })
                .show(ui, |plot| {
                    plot.hline(
                        HLine::new(100.0 / 3.0)
                            .name(tr!("shares-one-third"))
                            .color(ROT_COLOR)
                            .style(LineStyle::dashed_loose())
                            .width(1.5),
                    );
                    plot.line(
                        Line::new(PlotPoints::from(moving))
                            .name(tr!("shares-moving-ke"))
                            .color(KE_COLOR)
                            .width(2.5),
                    );
                    plot.line(
                        Line::new(PlotPoints::from(turning))
                            .name(tr!("shares-turning-ke"))
                            .color(ROT_COLOR)
                            .width(2.5),
                    );
                });
        });
    }
}
