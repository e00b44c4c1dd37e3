//! The *Speeds* tab: the speed histogram against Maxwell–Boltzmann; with
//! spin shown also the rim speeds |ω|·r, and how the energy is shared
//! between moving and turning over time.

use super::super::{Cx, View};
use super::plots::*;
use crate::app::lang::tr;
use crate::app::model::overlays::spin_shown;
use crate::app::model::totals::{RimHistogram, SpeedHistogram, GAS_AT_LEAST};
use crate::app::numbers::with_unit;
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
            let line = if h.is_a_gas() {
                tr!("speeds-line")
            } else {
                tr!("speeds-line-few", n = GAS_AT_LEAST)
            };
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
        plot_columns(ui, 2, |columns| {
            let ui = &mut columns[0];
            let meaning = tr!("speeds-rim-meaning", kt = kt.as_str());
            let rim_meaning = tr!("rim-speeds-hover", meaning = meaning.as_str());
            let names = [
                (format!("■ {}", tr!("speeds-name")), PX_COLOR),
                (format!("■ {}", tr!("rim-speeds")), RIM_COLOR),
            ];
            names_line(ui, None, &names, format!("{meaning}\n\n{rim_meaning}"));
            let height = ui.available_height();
            let r = speed_plot(ui, &h, Some(&rims), height, false);
            cx.note("speeds_plot", &r);
            let ui = &mut columns[1];
            let names = [
                (format!("— {}", tr!("shares-moving")), KE_COLOR),
                (format!("— {}", tr!("shares-turning")), ROT_COLOR),
                (format!("- - {}", tr!("shares-one-third")), ROT_COLOR),
            ];
            let more = format!(
                "{}\n\n{}",
                tr!("shares-energy-hover"),
                tr!("shares-one-third-hover")
            );
            names_line(ui, Some(tr!("shares-energy")), &names, more);
            let height = ui.available_height();
            let moving: Vec<[f64; 2]> = samples
                .iter()
                .map(|s| [s.time, 100.0 * (1.0 - s.rotation_share())])
                .collect();
            let turning: Vec<[f64; 2]> = samples
                .iter()
                .map(|s| [s.time, 100.0 * s.rotation_share()])
                .collect();
            let start = samples.first().map_or(model.world.time, |s| s.time);
            let readout = Readout::default();
            let plot = from_start(still_plot("shares_plot"), start);
            let plot = x_axis(plot, height, tr!("axis-time"), "s");
            let r = y_unit(plot, height, "%")
                .height(height)
                .include_y(0.0)
                .include_y(100.0)
                .label_formatter(readout.of_time(1, "%"))
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
            readout.show(ui, &r.response);
            cx.note("shares_plot", &r.response);
        });
    }
}
