//! The *Totals* tab: the total momentum (p_x, p_y), the angular momentum L
//! and the energy against time, each in its own plot, with the change since
//! the record began above them.

use super::super::widgets::{angular_momentum_tip, cut_label};
use super::super::{Cx, View};
use super::plots::*;
use crate::app::lang::tr;
use crate::app::model::overlays::spin_shown;
use crate::app::model::totals::on_one_line;
use crate::app::numbers::{vector, with_unit};
use crate::app::ui::tip::Tip;
use egui::text::LayoutJob;
use egui::{Align, FontSelection, RichText};
use egui_plot::{Corner, Legend, Line, LineStyle, PlotPoints, VLine};

/// The tab (no state of its own).
pub struct Totals;

impl View for Totals {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let samples: Vec<_> = model.record.totals.samples().copied().collect();
        let spin = spin_shown(&model.world);
        // Discs on one line: no L, which there is −y·p_x again.
        let line = on_one_line(&model.world);
        // A short dock (a laptop's browser) leaves the plots too low for a
        // legend box inside them, which then covered the line above: the
        // series are named in coloured words beside it instead (p in
        // kg·m/s, L in kg·m²/s, energies in J, as the line says), and the
        // line is put in symbols, so that both fit on one line.
        // So does a narrow one: in a laptop's third of the dock the legend
        // box ("walls push", p_y, p_x) covered most of the momentum plot.
        let columns: f32 = if line { 2.0 } else { 3.0 };
        let narrow = ui.available_width() / columns < LEGEND_NEEDS_WIDTH;
        let compact = ui.available_height() < COMPACT_PLOT_HEIGHT + 24.0 || narrow;
        let energy_name = match (compact, spin) {
            (true, _) => "ΔE".to_string(),
            (false, true) => tr!("totals-energy"),
            (false, false) => tr!("totals-kinetic-energy"),
        };
        let (p_name, l_name) = if compact {
            ("Δp".to_string(), "ΔL".to_string())
        } else {
            (tr!("totals-momentum"), tr!("totals-angular-momentum"))
        };
        // Across a wrapping edge a disc's position about (0, 0) jumps, and
        // L with it: its change is no measure of the collisions there.
        let wrapping = model.world.laws.boundary == impulse::Boundary::Periodic;
        let change = if wrapping {
            "totals-change-wrapping" // says why instead of L's change
        } else if line {
            "totals-change-line"
        } else {
            "totals-change"
        };
        let drift = match (model.record.totals.drift(), samples.first(), samples.last()) {
            (Some(_), Some(a), Some(b)) => tr!(
                change,
                since = unit_kept(with_unit(a.time, 2, "s")),
                p_name = p_name,
                momentum = unit_kept(vector(b.momentum - a.momentum, 3, "kg·m/s")),
                l_name = l_name,
                angular = unit_kept(with_unit(
                    b.angular_momentum - a.angular_momentum,
                    3,
                    "kg·m²/s"
                )),
                e_name = energy_name,
                energy = unit_kept(with_unit(b.energy() - a.energy(), 3, "J"))
            ),
            _ => tr!("totals-none"),
        };
        let total_color = ui.visuals().strong_text_color();
        // Each energy plotted: its name in the legend, in the compact line
        // of names, and its colour.
        let ke = tr!("symbol-ke");
        let mut energies = vec![(ke.clone(), ke, KE_COLOR)];
        if spin {
            let rotational = tr!("totals-rotational-ke");
            energies.push((rotational.clone(), rotational, ROT_COLOR));
            energies.push((tr!("totals-ke-sum"), tr!("totals-sum"), total_color));
        }
        let hover = angular_momentum_tip(tr!("totals-hover"), &model.world);
        if compact {
            let names = [("p_x", PX_COLOR), ("p_y", PY_COLOR), ("L", L_COLOR)];
            let names = &names[..if line { 2 } else { 3 }];
            let short = energies
                .iter()
                .map(|(_, name, color)| (name.as_str(), *color));
            change_and_names(ui, drift, names.iter().copied().chain(short), hover);
        } else {
            ui.label(drift).tip(hover);
        }
        let height = ui.available_height();
        let start = samples.first().map_or(model.world.time, |s| s.time);
        let series = |value: fn(&crate::app::model::totals::Sample) -> f64| -> Vec<[f64; 2]> {
            samples.iter().map(|s| [s.time, value(s)]).collect()
        };
        let walls: Vec<f64> = model.record.totals.wall_marks().collect();
        let (px, py, l) = (
            series(|s| s.momentum.x),
            series(|s| s.momentum.y),
            series(|s| s.angular_momentum),
        );
        let energy_series = [
            series(|s| s.kinetic_energy),
            series(|s| s.rotational_energy),
            series(|s| s.energy()),
        ];
        let plots = TimePlots {
            start,
            height,
            compact,
        };
        plot_columns(ui, if line { 2 } else { 3 }, |columns| {
            let momentum = [("p_x", PX_COLOR, px), ("p_y", PY_COLOR, py)];
            let shown = plots.show(
                &mut columns[0],
                ("momentum_plot", "p (kg·m/s)".into(), "kg·m/s"),
                momentum.map(|(name, color, points)| (name.to_string(), color, points)),
                |plot| {
                    // Where walls pushed: the only places the total moves.
                    for (k, &t) in walls.iter().enumerate() {
                        let mark = VLine::new(t)
                            .color(WALL_COLOR)
                            .style(LineStyle::dashed_dense())
                            .width(1.0);
                        plot.vline(if k == 0 {
                            mark.name(tr!("totals-walls-push"))
                        } else {
                            mark
                        });
                    }
                },
            );
            cx.note("momentum_plot", &shown);
            // The energy in the last column: the third, or the second
            // where there is no L.
            let last = if line { 1 } else { 2 };
            if !line {
                let shown = plots.show(
                    &mut columns[1],
                    ("angular_momentum_plot", "L (kg·m²/s)".into(), "kg·m²/s"),
                    [("L".to_string(), L_COLOR, l)],
                    |_| {},
                );
                cx.note("angular_momentum_plot", &shown);
            }
            let y_name = if spin {
                tr!("axis-energy")
            } else {
                format!("{} (J)", tr!("symbol-ke"))
            };
            let lines = energies
                .iter()
                .zip(energy_series)
                .map(|((name, _, color), points)| (name.clone(), *color, points));
            let shown = plots.show(
                &mut columns[last],
                ("energy_plot", y_name, "J"),
                lines,
                |_| {},
            );
            cx.note("energy_plot", &shown);
        });
    }
}

/// The least width (points) of a plot's column for a legend box inside it:
/// narrower, the series are named on the line above.
const LEGEND_NEEDS_WIDTH: f32 = 280.0;

/// What the tab's plots against time share: where their time axis starts,
/// their height, and whether the dock is too low for legends and axis names.
struct TimePlots {
    start: f64,
    height: f32,
    compact: bool,
}

impl TimePlots {
    /// A plot (its id, the name of its value axis and the unit of its
    /// readout) of `lines` (name, colour, points), each numbered on its
    /// own value axis ([`value_axis`]), with `under` drawn first.
    fn show(
        &self,
        ui: &mut egui::Ui,
        (id, y_name, unit): (&str, String, &'static str),
        lines: impl IntoIterator<Item = (String, egui::Color32, Vec<[f64; 2]>)>,
        under: impl FnOnce(&mut egui_plot::PlotUi),
    ) -> egui::Response {
        let lines: Vec<_> = lines.into_iter().collect();
        let height = self.height;
        let plot = from_start(still_plot(id), self.start).height(height);
        let series: Vec<&[[f64; 2]]> = lines.iter().map(|(_, _, points)| &points[..]).collect();
        let plot = value_axis(plot, &series, height);
        let plot = if self.compact {
            plot
        } else {
            plot.legend(Legend::default().position(Corner::RightBottom))
        };
        let readout = Readout::default();
        let shown = x_axis(plot, height, tr!("axis-time"), "s")
            // Too low for a rotated name: the line above gives the units.
            .y_axis_label(if self.compact { String::new() } else { y_name })
            .label_formatter(readout.of_time(3, unit))
            .show(ui, |plot| {
                under(plot);
                for (name, color, points) in lines {
                    plot.line(
                        Line::new(PlotPoints::from(points))
                            .name(name)
                            .color(color)
                            .width(2.5),
                    );
                }
            });
        readout.show(ui, &shown.response);
        shown.response
    }
}

/// A quantity whose unit stays on its number's line where the change
/// wraps (a German line ended "ΔE 0,000" with "J" alone below it).
fn unit_kept(quantity: String) -> String {
    match quantity.rsplit_once(' ') {
        Some((number, unit)) => format!("{number}\u{a0}{unit}"),
        None => quantity,
    }
}

/// The change since the record began, whole on as many lines as it needs,
/// then the plots' series named in their colours after it, on two lines at
/// most or the change's last, cut with "…" where that is full: then the
/// hover, `more`, ends with them all. Wrapped onto lines of their own, the
/// six names of rough discs took a projector's plots down to strips 35 px
/// high; kept to the change's one line, the names of a 1280-px projector's
/// plots were cut to "— p_…".
fn change_and_names<'a>(
    ui: &mut egui::Ui,
    change: String,
    names: impl Iterator<Item = (&'a str, egui::Color32)>,
    more: String,
) -> egui::Response {
    let (galley, all) = change_and_names_galley(ui, change, names);
    let more = if galley.elided {
        format!("{more}\n\n{all}")
    } else {
        more
    };
    cut_label(ui, egui::Label::new(galley), Some(more))
}

/// [`change_and_names`]'s text laid out to `ui`'s width, and every name.
fn change_and_names_galley<'a>(
    ui: &egui::Ui,
    change: String,
    names: impl Iterator<Item = (&'a str, egui::Color32)>,
) -> (std::sync::Arc<egui::Galley>, String) {
    let style = ui.style().clone();
    let append = |job: &mut LayoutJob, text: RichText| {
        text.append_to(job, &style, FontSelection::Default, Align::Center)
    };
    let mut job = LayoutJob::default();
    append(&mut job, RichText::new(change));
    job.wrap.max_width = ui.available_width();
    let rows = ui.fonts(|f| f.layout_job(job.clone())).rows.len();
    let mut all = Vec::new();
    for (name, color) in names {
        all.push(format!("— {name}"));
        // A breakable gap before each name, none inside it: never "—" on
        // one line and its name on the next.
        let name = format!("—\u{a0}{}", name.replace(' ', "\u{a0}"));
        append(&mut job, RichText::new("  "));
        append(&mut job, RichText::new(name).color(color).strong());
    }
    job.wrap.max_rows = rows.max(2);
    job.wrap.overflow_character = Some('…');
    (ui.fonts(|f| f.layout_job(job)), all.join("   "))
}

#[cfg(test)]
mod tests {
    use super::{change_and_names_galley, unit_kept};
    use crate::app::ui::widgets::headless;
    use egui::Color32;

    /// The galley for a line `width` points wide, laid out by egui without
    /// a window.
    fn galley(width: f32, change: &str, names: &[&str]) -> std::sync::Arc<egui::Galley> {
        let mut out = None;
        headless(egui::vec2(width, 100.0), |ui| {
            let names = names.iter().map(|n| (*n, Color32::WHITE));
            out = Some(change_and_names_galley(ui, change.into(), names).0);
        });
        out.unwrap()
    }

    #[test]
    fn a_unit_stays_on_its_numbers_line() {
        assert_eq!(unit_kept("0,000 J".into()), "0,000\u{a0}J");
        assert_eq!(
            unit_kept("(1,000; −2,000) kg·m/s".into()),
            "(1,000; −2,000)\u{a0}kg·m/s",
            "the vector may still break after its separator"
        );
    }

    #[test]
    fn the_change_stays_whole_and_the_names_take_two_lines_at_most() {
        let change = "Change since t = 0.00 s: Δp (−11.360, −0.058) kg·m/s, ΔL 80.799 kg·m²/s, \
                      ΔE 0.000 J";
        let rough = ["p_x", "p_y", "L", "KE", "rotational KE", "sum"];
        // Wide enough for the change on one line: the names go on to a
        // second (kept to the first, they were cut to "— p_…").
        let wide = galley(700.0, change, &rough[..4]);
        assert!(!wide.elided && wide.rows.len() == 2, "{}", wide.text());
        // The change on two lines: the names fill the rest of the second
        // and are cut there, never a third line; the change stays whole.
        let narrow = galley(420.0, change, &rough);
        assert_eq!(narrow.rows.len(), 2, "{}", narrow.text());
        assert!(
            narrow.elided && narrow.text().starts_with(change),
            "{}",
            narrow.text()
        );
        // A change longer than two lines keeps all its lines.
        let tall = galley(200.0, change, &rough);
        assert!(
            tall.rows.len() >= 3 && tall.text().starts_with(change),
            "{}",
            tall.text()
        );
    }

    /// A laptop's narrow dock names the series on the line above, not in
    /// legend boxes inside plots a third of it wide (one covered most of
    /// the momentum plot); a wide one keeps the boxes and the words.
    #[test]
    fn a_narrow_dock_names_its_series_above_the_plots() {
        use crate::app::model::tests::sandbox_with;
        use crate::app::ui::widgets::texts_drawn;
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_with(dir.path(), "preset-4-glancing.toml", false, 0.0);
        for k in 1..=30 {
            s.begin_frame(f64::from(k) / 60.0);
            s.tick(1.0 / 60.0, 1.0);
        }
        let at = |width: f32| texts_drawn(&s, egui::vec2(width, 240.0), &mut super::Totals);
        let narrow = at(760.0).join(" | ");
        assert!(narrow.contains("Δp ("), "{narrow}");
        let wide = at(1400.0).join(" | ");
        assert!(wide.contains("momentum ("), "{wide}");
    }

    /// On one line L is −y·p_x, the momentum's plot again, as a number a
    /// student cannot place: the head-on lesson's Totals leave it out (its
    /// plot, its name, its change); the glancing hit keeps it.
    #[test]
    fn discs_on_one_line_get_no_angular_momentum_in_the_totals() {
        use crate::app::model::tests::sandbox_with;
        use crate::app::model::totals::on_one_line;
        use crate::app::ui::widgets::texts_drawn;
        let dir = tempfile::tempdir().unwrap();
        let shown = |file: &str| {
            let s = sandbox_with(dir.path(), file, true, 0.0);
            let text = texts_drawn(&s, egui::vec2(900.0, 200.0), &mut super::Totals).join(" | ");
            (on_one_line(&s.world), text)
        };
        let (line, text) = shown("preset-1-head-on.toml");
        assert!(line, "the head-on discs");
        let names_l = |t: &str| {
            t.split(" | ")
                .any(|w| w == "L" || w.starts_with("L (") || w.contains("ΔL"))
        };
        assert!(!names_l(&text), "{text}");
        assert!(
            text.contains("p_x") || text.contains("Δp") || text.contains("p ("),
            "{text}"
        );
        let (line, text) = shown("preset-4-glancing.toml");
        assert!(!line, "the glancing hit");
        assert!(names_l(&text), "{text}");
    }
}
