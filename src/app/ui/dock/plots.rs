//! What the dock's plots share: the series' colours (Okabe–Ito), a plot
//! that holds still, a y range that shows a conserved total as a flat line,
//! the speed histogram, axes that give way in a short dock, and series
//! named in their colours on one line.

use crate::app::lang::tr;
use crate::app::model::totals::{RimHistogram, SpeedHistogram};
use crate::app::numbers::{plain, quantity};
use crate::app::ui::widgets::one_line;
use egui::{Color32, RichText};
mod readout;
mod values;
use readout::bar_hover;
pub use readout::{on_a_line, Readout};
pub use values::value_axis;
use values::value_steps;

use egui_plot::{
    Bar, BarChart, Corner, Legend, Line, LineStyle, Plot, PlotItem, PlotPoint, PlotPoints,
};

/// Colours of the plotted totals (Okabe–Ito).
pub const PX_COLOR: Color32 = Color32::from_rgb(86, 180, 233); // sky blue
pub const PY_COLOR: Color32 = Color32::from_rgb(230, 159, 0); // orange
pub const KE_COLOR: Color32 = Color32::from_rgb(0, 158, 115); // bluish green
pub const ROT_COLOR: Color32 = Color32::from_rgb(213, 94, 0); // vermillion
pub const L_COLOR: Color32 = Color32::from_rgb(204, 121, 167); // reddish purple
pub const RIM_COLOR: Color32 = L_COLOR;
/// From this height (points) a plot has room for its rotated axis name.
pub const ROOMY_PLOT: f32 = 140.0;
/// The marks where walls pushed the discs.
pub const WALL_COLOR: Color32 = Color32::from_rgb(150, 150, 150);
/// Below this height (points) a plot has no room for a legend box of three
/// names (p_x, p_y and the walls' marks; or the three energies) above its
/// time axis: at 110 the box grew over the line above the plots.
pub const COMPACT_PLOT_HEIGHT: f32 = 130.0;

/// The speed histogram against Maxwell–Boltzmann; with `rims`, each bin's
/// rim-speed bar beside its speed bar, and the rim speeds' law. A bar is
/// the number of discs in its bin and a curve the number the law expects
/// there: "how many discs" needs no unit, where a density (per m/s) beside
/// a short plot, with no room for the axis's name, was a bare "0.5".
pub fn speed_plot(
    ui: &mut egui::Ui,
    h: &SpeedHistogram,
    rims: Option<&RimHistogram>,
    height: f32,
    legend: bool,
) -> egui::Response {
    // Side by side within a bin when both are drawn.
    let (offset, width) = if rims.is_some() {
        (0.28, 0.42)
    } else {
        (0.5, 0.9)
    };
    let discs = h.discs_per_density();
    let bars: Vec<Bar> = h
        .density
        .iter()
        .enumerate()
        .map(|(k, &d)| {
            Bar::new((k as f64 + offset) * h.bin_width, d * discs).width(h.bin_width * width)
        })
        .collect();
    let top = h.bin_width * h.density.len() as f64;
    let curve = |law: &dyn Fn(f64) -> f64| -> Vec<[f64; 2]> {
        (0..=200)
            .map(|k| top * k as f64 / 200.0)
            .map(|v| [v, law(v) * discs])
            .collect()
    };
    let law = curve(&|v| h.law(v));
    let rim = rims.map(|r| {
        let bars: Vec<Bar> = r
            .density
            .iter()
            .enumerate()
            .map(|(k, &d)| {
                Bar::new((k as f64 + 1.0 - offset) * h.bin_width, d * discs)
                    .width(h.bin_width * width)
            })
            .collect();
        (bars, curve(&|u| r.law(u)))
    });
    let (x_label, speed_name) = if rim.is_some() {
        (tr!("speeds-axis-rim"), tr!("speeds-name"))
    } else {
        (tr!("speeds-axis"), tr!("speeds-discs"))
    };
    let count = tr!("speeds-count");
    let discs_word = tr!("speeds-discs");
    let plot = still_plot("speeds_plot").height(height);
    let plot = if legend {
        plot.legend(Legend::default().position(Corner::RightTop))
    } else {
        plot
    };
    let readout = Readout::default();
    let shown = x_axis(plot, height, x_label, "m/s")
        // Rotated beside a short plot, the name would run past it.
        .y_axis_label(if height >= ROOMY_PLOT {
            count
        } else {
            String::new()
        })
        .include_y(0.0)
        .y_axis_formatter(|mark, _| whole_count(mark))
        .label_formatter(readout.keeping(move |name: &str, v: &PlotPoint| {
            on_a_line(name, || {
                format!("{} m/s\n{} {discs_word}", plain(v.x, 2), plain(v.y, 1))
            })
        }))
        .show(ui, |plot| {
            let bin_width = h.bin_width;
            let two = rims.is_some();
            let hover = || {
                readout.keeping(move |bar: &Bar, chart: &BarChart| {
                    bar_hover(two.then(|| chart.name()), bar, bin_width)
                })
            };
            plot.bar_chart(
                BarChart::new(bars)
                    .name(speed_name)
                    .color(PX_COLOR)
                    .element_formatter(Box::new(hover())),
            );
            // A gas's law only for a gas.
            if h.is_a_gas() {
                plot.line(
                    Line::new(PlotPoints::from(law))
                        .name(tr!("maxwell-boltzmann"))
                        .color(PY_COLOR)
                        .width(3.0),
                );
            }
            if let Some((bars, law)) = rim {
                plot.bar_chart(
                    BarChart::new(bars)
                        .name(tr!("rim-speeds"))
                        .color(RIM_COLOR)
                        .element_formatter(Box::new(hover())),
                );
                plot.line(
                    Line::new(PlotPoints::from(law))
                        .name(tr!("rim-speeds-equal"))
                        .color(RIM_COLOR)
                        .style(LineStyle::dashed_loose())
                        .width(3.0),
                );
            }
        })
        .response;
    readout.show(ui, &shown);
    shown
}

/// The x axis's name under a plot with room for it; under a shorter one
/// the unit goes on each number instead ("2 m/s"). egui_plot keeps a line
/// for the name even when it is empty, and in a projector's dock that line
/// and the numbers took two thirds of the plot's height.
pub fn x_axis(plot: Plot<'static>, height: f32, name: String, unit: &'static str) -> Plot<'static> {
    if height >= ROOMY_PLOT {
        return plot.x_axis_label(name);
    }
    plot.x_axis_label(RichText::new("").size(1.0))
        .x_axis_formatter(move |mark, _| format!("{} {unit}", tick(mark)))
}

/// The y axis's unit beside a plot with room for it; beside a shorter one
/// (no name, see [`x_axis`]) on each number instead ("100 %").
pub fn y_unit(plot: Plot<'static>, height: f32, unit: &'static str) -> Plot<'static> {
    if height >= ROOMY_PLOT {
        return plot.y_axis_label(unit);
    }
    plot.y_axis_formatter(move |mark, _| beside_frame(format!("{} {unit}", tick(mark))))
}

/// A count axis's number: only whole ones (a histogram of two discs was
/// numbered 0.5 and 1.5 discs), with [`beside_frame`]'s space.
fn whole_count(mark: egui_plot::GridMark) -> String {
    if mark.value.fract() == 0.0 {
        beside_frame(plain(mark.value, 0))
    } else {
        String::new()
    }
}

/// A value axis's number with a space after it: egui_plot sets it flush
/// against the plot's frame ("−200" touched it).
fn beside_frame(number: String) -> String {
    number + "\u{a0}"
}

/// An axis's number, with as many decimals as its step needs and the
/// language's decimal separator.
fn tick(mark: egui_plot::GridMark) -> String {
    let (v, step) = (mark.value, mark.step_size);
    if v.abs() >= 1e6 {
        // 8×10¹¹, not 800000000000: a number that wide squeezed a
        // projector's plot to a sliver. As many decimals as the step needs.
        let digits = v.abs().log10().floor() - step.log10().floor();
        return quantity(v, digits.clamp(0.0, 3.0) as usize);
    }
    plain(v, decimals_of(step))
}

/// The decimals that write every multiple of `step` exactly: 1 for 0.5,
/// 2 for 0.25 (from the step's power of ten alone, a mark of 0.25 read
/// "−0.8" at −0.75), at most 6.
fn decimals_of(step: f64) -> usize {
    let exact = |d: i32| {
        let scaled = step.abs() * 10f64.powi(d);
        (scaled - scaled.round()).abs() < 1e-6 * scaled.max(1.0)
    };
    (0..=6).find(|&d| exact(d)).unwrap_or(6) as usize
}

/// A plot's series named in their colours on one line above it, after a
/// plain `lead` word if given; cut with "…" where the column is narrow, and
/// hovered, `more` (what the names mean). Names wrapped onto a second line
/// took a projector's short plot down to a strip.
pub fn names_line(
    ui: &mut egui::Ui,
    lead: Option<String>,
    names: &[(String, Color32)],
    more: String,
) -> egui::Response {
    let style = ui.style().clone();
    let mut job = egui::text::LayoutJob::default();
    let parts = lead.map(RichText::new);
    let names = names
        .iter()
        .map(|(name, color)| RichText::new(name).color(*color).strong());
    for (k, part) in parts.into_iter().chain(names).enumerate() {
        if k > 0 {
            RichText::new("  ").append_to(
                &mut job,
                &style,
                Default::default(),
                egui::Align::Center,
            );
        }
        part.append_to(&mut job, &style, Default::default(), egui::Align::Center);
    }
    one_line(ui, job, Some(more))
}

/// Room kept right of plots side by side for half of a number on the time
/// axis: the last column's plot ends at the dock's edge, which cut a "1 s"
/// standing at the plot's end in half (and 12 points, a "2.5 s").
const EDGE_ROOM: f32 = 18.0;

/// `ui.columns(n, add)` for plots, short of the dock's right edge by
/// [`EDGE_ROOM`].
pub fn plot_columns<R>(ui: &mut egui::Ui, n: usize, add: impl FnOnce(&mut [egui::Ui]) -> R) -> R {
    let mut room = ui.available_rect_before_wrap();
    room.max.x -= EDGE_ROOM.min(0.5 * room.width());
    ui.scope_builder(egui::UiBuilder::new().max_rect(room), |ui| {
        ui.columns(n, add)
    })
    .inner
}

/// A plot that holds still: no scrolling, dragging or zooming, which in a
/// live plot would only lose the view (hover still reads values); nor a
/// Tab stop, as it does nothing with the keyboard.
pub fn still_plot(id: &str) -> Plot<'static> {
    // The axes' numbers with the language's decimal separator.
    let axis = |mark: egui_plot::GridMark, _: &std::ops::RangeInclusive<f64>| tick(mark);
    // egui_plot hides the x axis's numbers closer than 60 points, sized for
    // long numbers: a projector's 120-point plot of 9 s then numbered only
    // "0 s". Ours are short ("5 s"), and one too wide is still left out.
    let spaced = egui_plot::AxisHints::new_x().label_spacing(40.0..=55.0);
    // And the value axis's numbers wherever they fit (see `value_steps`).
    let values = egui_plot::AxisHints::new_y().label_spacing(14.0..=16.0);
    Plot::new(id)
        .custom_x_axes(vec![spaced])
        .custom_y_axes(vec![values])
        .x_axis_formatter(axis)
        .y_axis_formatter(|mark, _| beside_frame(tick(mark)))
        .x_grid_spacer(egui_plot::uniform_grid_spacer(steps_of_one_two_or_five_ten))
        .y_grid_spacer(egui_plot::uniform_grid_spacer(value_steps))
        // Never taller than the dock leaves it (egui_plot's least is 64
        // points, which grew a short dock over the world).
        .min_size(egui::vec2(40.0, 16.0))
        .allow_scroll(false)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_boxed_zoom(false)
        .sense(egui::Sense::hover())
}

/// A plot against time that starts where its samples start and spans a
/// second at least: with one sample, egui_plot centred it on a time axis from
/// −10 to 10 s.
pub fn from_start(plot: Plot<'static>, start: f64) -> Plot<'static> {
    plot.include_x(start).include_x(start + 1.0)
}

/// The grid's steps: the smallest power of ten the plot has room for, the
/// smallest of two or five of it far enough apart to be numbered, and ten
/// of it. egui_plot's own steps go up by tens, so that a plot of 0 to 9 s,
/// too narrow to number every second, numbered only 0 s; and with five
/// always, a projector's plot of the first 4.7 s still did.
fn steps_of_one_two_or_five_ten(input: egui_plot::GridInput) -> [f64; 3] {
    let least = input.base_step_size.abs().max(f64::MIN_POSITIVE);
    let unit = 10f64.powf(least.log10().ceil());
    // The time axis numbers marks from 40 points apart (`still_plot`),
    // five of egui_plot's least grid spacing.
    let numbered = least * 40.0 / BASE_STEP_POINTS;
    let middle = if 2.0 * unit >= numbered { 2.0 } else { 5.0 };
    [unit, middle * unit, 10.0 * unit]
}

/// egui_plot's `base_step_size` is the value of this many points (its
/// least grid spacing).
const BASE_STEP_POINTS: f64 = 8.0;

#[cfg(test)]
mod readout_tests;
#[cfg(test)]
mod tests;
