//! The top bar: what a class reads from the back row. The scene's name, the
//! simulated time, RUNNING or PAUSED (never hidden, not even by Tab), the
//! total momentum and kinetic energy with their units (when spin is shown
//! the KE of moving and of turning and their sum, and where there is room
//! the angular momentum L), the collision count, and, when it applies, that
//! the simulation runs slower than asked, that the view is a rewound
//! moment, or what the method cannot promise.

use super::numbers::{plain, vector, with_unit};
use crate::app::App;
use egui::{Color32, RichText};

/// The top bar names the angular momentum from this width (points) up.
const L_MIN_WIDTH: f32 = 1200.0;

impl App {
    /// Draws the top bar; returns its rectangle (points).
    pub(super) fn top_bar(&mut self, ctx: &egui::Context) -> egui::Rect {
        let m = self.world.metrics();
        let spin = crate::app::draw::spin_shown(&self.world);
        let dark = ctx.style().visuals.dark_mode;
        let (running, paused) = if dark {
            (
                Color32::from_rgb(120, 230, 140),
                Color32::from_rgb(255, 200, 60),
            )
        } else {
            (Color32::from_rgb(0, 110, 30), Color32::from_rgb(170, 60, 0))
        };
        let name = self.scene.name.clone().unwrap_or_else(|| "Sandbox".into());
        let panel = egui::TopBottomPanel::top("top_bar").show(ctx, |ui| {
            ui.horizontal_wrapped(|ui| {
                ui.spacing_mut().item_spacing.x = 18.0;
                // Each item stays whole; a narrow window moves it to the next line.
                ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
                ui.label(RichText::new(name).strong());
                ui.label(format!("t = {}", with_unit(self.world.time, 2, "s")));
                let state = if self.history.cursor().is_some() {
                    RichText::new("⏸ REWOUND").color(paused)
                } else if self.clock.paused {
                    RichText::new("⏸ PAUSED").color(paused)
                } else {
                    RichText::new(format!("▶ RUNNING ×{}", self.clock.time_scale())).color(running)
                };
                let state = ui.label(state.strong());
                self.ui
                    .note_widget("run_state", state.rect, super::px_per_point(ctx));
                if let Some(slow) = self.slow_note() {
                    ui.label(RichText::new(slow).color(paused));
                }
                ui.label(format!("p = {}", vector(m.momentum, 3, "kg·m/s")));
                if spin {
                    // One item, so that a 1024-pixel window keeps one line.
                    ui.label(format!(
                        "KE {} + rotational {} = {}",
                        plain(m.kinetic_energy, 3),
                        plain(m.rotational_energy, 3),
                        with_unit(m.kinetic_energy + m.rotational_energy, 3, "J")
                    ))
                    .on_hover_text(
                        "kinetic energy of moving, ½·m·v², plus of turning, ½·I·ω² with \
                         I = ½·m·r², summed over the discs",
                    );
                } else {
                    ui.label(format!("KE = {}", with_unit(m.kinetic_energy, 3, "J")));
                }
                if self.lesson.com_view.is_some() {
                    // The totals above are the box's; in the view's frame
                    // the momentum is zero and less energy moves.
                    let v = m.center_of_mass_velocity;
                    let total_mass: f64 = self.world.particles.iter().map(|p| p.mass).sum();
                    let relative_ke = m.kinetic_energy - 0.5 * total_mass * v.length_squared();
                    ui.label(
                        RichText::new(format!(
                            "centre-of-mass view: p = {}, KE = {}",
                            vector(glam::DVec2::ZERO, 3, "kg·m/s"),
                            with_unit(relative_ke.max(0.0), 3, "J")
                        ))
                        .color(paused),
                    );
                }
                let gravity = self.world.laws.gravity != glam::DVec2::ZERO;
                // L where the bar has room for it (at least 1200 points
                // wide); it is always in the Totals tab and the readouts.
                if spin && ctx.screen_rect().width() >= L_MIN_WIDTH {
                    ui.label(format!(
                        "L = {}",
                        with_unit(m.angular_momentum, 3, "kg·m²/s")
                    ))
                    .on_hover_text(
                        "angular momentum about the corner (0, 0), of moving and of turning: \
                         collisions between discs keep it, walls change it",
                    );
                }
                if gravity {
                    // With gravity, kinetic energy alone seems to vanish in a fall.
                    let (name, hover) = if spin {
                        (
                            "KE + rotational KE + PE",
                            "kinetic energy of moving and of turning, plus gravitational potential energy (zero at the bottom edge of the box)",
                        )
                    } else {
                        (
                            "KE + PE",
                            "kinetic plus gravitational potential energy (zero at the bottom edge of the box)",
                        )
                    };
                    ui.label(format!(
                        "{name} = {}",
                        with_unit(self.world.total_energy(), 3, "J")
                    ))
                    .on_hover_text(hover);
                }
                match crate::app::lesson::pi_result(&self.world) {
                    Some(result) => ui.label(RichText::new(result).strong()),
                    None => ui.label(format!(
                        "collisions: {}",
                        self.world.total_pair_collisions + self.world.total_wall_hits
                    )),
                };
                if self.world.resting_contacts > 0 {
                    ui.label(format!("resting contacts: {}", self.world.resting_contacts))
                        .on_hover_text(
                            "discs lying on each other or on a wall: not counted as collisions",
                        );
                }
                for warning in impulse::warnings::warnings(&self.world, self.clock.dt) {
                    let r = ui.label(RichText::new(format!("⚠ {}", warning.text)).color(paused));
                    self.ui.note_widget(
                        format!("warning_{}", warning.code),
                        r.rect,
                        super::px_per_point(ctx),
                    );
                }
                if !self.ui.docks_open {
                    // Tab's on-screen twin, for a touch screen.
                    if ui.button("Show panels").on_hover_text("Tab").clicked() {
                        self.ui.docks_open = true;
                    }
                }
                if let (Some(k), Some((oldest, newest))) =
                    (self.history.cursor(), self.history.span())
                {
                    ui.label(format!(
                        "rewound to snapshot {} of {} ({} to {} s): Space resumes",
                        k + 1,
                        self.history.len(),
                        plain(oldest, 2),
                        plain(newest, 2)
                    ));
                }
            });
        });
        panel.response.rect
    }
}
