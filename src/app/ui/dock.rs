//! The bottom dock: a strip of tabs and the chosen one below it. *Totals*
//! plots p_x, p_y, the angular momentum L and KE against time (with spin
//! shown also the rotational KE and their sum); *Collisions* is the ledger;
//! *Discs* the table of every disc ([`super::discs_table`]); *Speeds* the
//! histogram against Maxwell–Boltzmann (with spin shown also the rim
//! speeds |ω|·r, and the shares of the energy in moving and turning over
//! time); *Momenta* every disc's momentum tip to tail and their sum. At the
//! projector's scale it starts folded to its tab strip.

use super::numbers::{plain, vector, with_unit};
use super::DockTab;
use crate::app::draw::spin_shown;
use crate::app::plot::{RimHistogram, SpeedHistogram, DIAGRAM_MAX_DISCS};
use crate::app::App;
use egui::{Color32, RichText};
use egui_plot::{
    Arrows, Bar, BarChart, Corner, HLine, Legend, Line, LineStyle, Plot, PlotPoints, Points,
};

/// Colours of the plotted totals (Okabe–Ito).
const PX_COLOR: Color32 = Color32::from_rgb(86, 180, 233); // sky blue
const PY_COLOR: Color32 = Color32::from_rgb(230, 159, 0); // orange
const KE_COLOR: Color32 = Color32::from_rgb(0, 158, 115); // bluish green
const ROT_COLOR: Color32 = Color32::from_rgb(213, 94, 0); // vermillion
const L_COLOR: Color32 = Color32::from_rgb(204, 121, 167); // reddish purple
const RIM_COLOR: Color32 = L_COLOR;
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
        let spin = spin_shown(&self.world);
        // A short dock (a laptop's browser) leaves the plots too low for a
        // legend box inside them, which then covered the line above: the
        // series are named in coloured words beside it instead (p in
        // kg·m/s, L in kg·m²/s, energies in J, as the line says), and the
        // line is put in symbols, so that both fit on one line.
        let compact = ui.available_height() < COMPACT_PLOT_HEIGHT + 24.0;
        let energy_name = match (compact, spin) {
            (true, _) => "ΔE",
            (false, true) => "energy",
            (false, false) => "kinetic energy",
        };
        let (p_name, l_name) = if compact {
            ("Δp", "ΔL")
        } else {
            ("momentum", "angular momentum L")
        };
        let drift = match (self.totals.drift(), samples.first(), samples.last()) {
            (Some(_), Some(a), Some(b)) => format!(
                "change since {}: {p_name} {}, {l_name} {}, {energy_name} {}",
                with_unit(a.time, 2, "s"),
                vector(b.momentum - a.momentum, 3, "kg·m/s"),
                with_unit(b.angular_momentum - a.angular_momentum, 3, "kg·m²/s"),
                with_unit(b.energy() - a.energy(), 3, "J")
            ),
            _ => "No record yet: run the simulation.".to_string(),
        };
        let total_color = ui.visuals().strong_text_color();
        // Each energy plotted: its name in the legend, in the compact line
        // of names, and its colour.
        let mut energies = vec![("KE", "KE", KE_COLOR)];
        if spin {
            energies.push(("rotational KE", "rotational KE", ROT_COLOR));
            energies.push(("KE + rotational KE", "sum", total_color));
        }
        ui.horizontal_wrapped(|ui| {
            ui.label(drift).on_hover_text(
                "p: momentum. L: angular momentum about the corner (0, 0) of the box; \
                 collisions between discs keep it, a wall's push can change it. \
                 E: kinetic energy, with spin KE + rotational KE.",
            );
            if compact {
                let names = [("p_x", PX_COLOR), ("p_y", PY_COLOR), ("L", L_COLOR)];
                let short = energies.iter().map(|&(_, name, color)| (name, color));
                for (name, color) in names.into_iter().chain(short) {
                    ui.label(RichText::new(format!("— {name}")).color(color).strong());
                }
            }
        });
        let height = ui.available_height();
        let legend = |corner| (!compact).then(|| Legend::default().position(corner));
        let series = |value: fn(&crate::app::plot::Sample) -> f64| -> Vec<[f64; 2]> {
            samples.iter().map(|s| [s.time, value(s)]).collect()
        };
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
        ui.columns(3, |columns| {
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
            let (lo, hi) = padded_range(l.iter().map(|p| p[1]));
            let plot = still_plot("angular_momentum_plot").height(height);
            let plot = match legend(Corner::RightBottom) {
                Some(l) => plot.legend(l),
                None => plot,
            };
            plot.x_axis_label("time (s)")
                .y_axis_label(if compact { "" } else { "L (kg·m²/s)" })
                .include_y(lo)
                .include_y(hi)
                .label_formatter(|name, v| {
                    format!("{name}\nt = {} s\n{} kg·m²/s", plain(v.x, 2), plain(v.y, 3))
                })
                .show(&mut columns[1], |plot| {
                    plot.line(
                        Line::new(PlotPoints::from(l))
                            .name("L")
                            .color(L_COLOR)
                            .width(2.5),
                    );
                });
            let shown = &energy_series[..energies.len()];
            let (lo, hi) = padded_range(shown.iter().flatten().map(|p| p[1]));
            let plot = still_plot("energy_plot").height(height);
            let plot = match legend(Corner::RightBottom) {
                Some(l) => plot.legend(l),
                None => plot,
            };
            plot.x_axis_label("time (s)")
                .y_axis_label(match (compact, spin) {
                    (true, _) => "",
                    (false, true) => "energy (J)",
                    (false, false) => "KE (J)",
                })
                .include_y(lo)
                .include_y(hi)
                .label_formatter(|name, v| {
                    format!("{name}\nt = {} s\n{} J", plain(v.x, 2), plain(v.y, 3))
                })
                .show(&mut columns[2], |plot| {
                    for ((name, _, color), points) in energies.iter().zip(shown) {
                        plot.line(
                            Line::new(PlotPoints::from(points.clone()))
                                .name(*name)
                                .color(*color)
                                .width(2.5),
                        );
                    }
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
        if !spin_shown(&self.world) {
            ui.label(format!(
                "Bars: the discs' speeds. Curve: Maxwell–Boltzmann at the same temperature, kT = KE/N = {}.",
                with_unit(h.kt, 3, "J")
            ));
            let height = ui.available_height();
            speed_plot(ui, &h, None, height, true);
            return;
        }
        // Rough discs: the rim speeds beside the speeds, and how the energy
        // is shared between moving and turning. Each plot is named by a
        // line of coloured words above it, not a legend box, which in a
        // short dock covered the bars.
        let rims = RimHistogram::of(&self.world, &h);
        let samples: Vec<_> = self.totals.samples().copied().collect();
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
                named(ui, "■ rim speeds |ω|·r", RIM_COLOR).on_hover_text(&meaning);
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
                .y_axis_label("%")
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

/// The speed histogram against Maxwell–Boltzmann; with `rims`, each bin's
/// rim-speed bar beside its speed bar, and the rim speeds' law.
fn speed_plot(
    ui: &mut egui::Ui,
    h: &SpeedHistogram,
    rims: Option<&RimHistogram>,
    height: f32,
    legend: bool,
) {
    // Side by side within a bin when both are drawn.
    let (offset, width) = if rims.is_some() {
        (0.28, 0.42)
    } else {
        (0.5, 0.9)
    };
    let bars: Vec<Bar> = h
        .density
        .iter()
        .enumerate()
        .map(|(k, &d)| Bar::new((k as f64 + offset) * h.bin_width, d).width(h.bin_width * width))
        .collect();
    let top = h.bin_width * h.density.len() as f64;
    let curve = |law: &dyn Fn(f64) -> f64| -> Vec<[f64; 2]> {
        (0..=200)
            .map(|k| top * k as f64 / 200.0)
            .map(|v| [v, law(v)])
            .collect()
    };
    let law = curve(&|v| h.law(v));
    let rim = rims.map(|r| {
        let bars: Vec<Bar> = r
            .density
            .iter()
            .enumerate()
            .map(|(k, &d)| {
                Bar::new((k as f64 + 1.0 - offset) * h.bin_width, d).width(h.bin_width * width)
            })
            .collect();
        (bars, curve(&|u| r.law(u)))
    });
    let (x_label, speed_name) = if rim.is_some() {
        ("speed, rim speed (m/s)", "speeds |v|")
    } else {
        ("speed (m/s)", "discs")
    };
    let plot = still_plot("speeds_plot").height(height);
    let plot = if legend {
        plot.legend(Legend::default().position(Corner::RightTop))
    } else {
        plot
    };
    plot.x_axis_label(x_label)
        .y_axis_label("per m/s")
        .include_y(0.0)
        .label_formatter(|_, v| format!("{} m/s\n{} per m/s", plain(v.x, 2), plain(v.y, 3)))
        .show(ui, |plot| {
            plot.bar_chart(BarChart::new(bars).name(speed_name).color(PX_COLOR));
            plot.line(
                Line::new(PlotPoints::from(law))
                    .name("Maxwell–Boltzmann")
                    .color(PY_COLOR)
                    .width(3.0),
            );
            if let Some((bars, law)) = rim {
                plot.bar_chart(
                    BarChart::new(bars)
                        .name("rim speeds |ω|·r")
                        .color(RIM_COLOR),
                );
                plot.line(
                    Line::new(PlotPoints::from(law))
                        .name("rim speeds, shared equally")
                        .color(RIM_COLOR)
                        .style(LineStyle::dashed_loose())
                        .width(3.0),
                );
            }
        });
}

/// A plot's series named in its colour, in the line above the plot.
fn named(ui: &mut egui::Ui, name: &str, color: Color32) -> egui::Response {
    ui.label(RichText::new(name).color(color).strong())
}

/// A plot that holds still: no scrolling, dragging or zooming, which in a
/// live plot would only lose the view (hover still reads values).
fn still_plot(id: &str) -> Plot<'static> {
    Plot::new(id)
        // Never taller than the dock leaves it (egui_plot's least is 64
        // points, which grew a short dock over the world).
        .min_size(egui::vec2(40.0, 16.0))
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
