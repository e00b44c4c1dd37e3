//! The top bar: what a class reads from the back row, on one line. The
//! scene's name, the simulated time and RUNNING or PAUSED (and in the π
//! blocks their count) are always there (not even Tab hides them); then,
//! as far as the line reaches, the total momentum (with a note while the
//! walls have changed it; the name is cut, and the buttons' and the state's
//! words give way, where that makes room for it) and energy, the impacts between discs and on
//! walls counted apart, and what the method cannot promise. What does not
//! fit is under "… more", on hover or when Tab gives it the keys. This
//! module says what the items are; [`line`] lays them out.

mod line;

use super::{Cx, View};
use crate::app::lang::tr;
use crate::app::model::lesson::{count_line, pi_decimals, pi_result, warning_text};
use crate::app::model::overlays::spin_shown;
use crate::app::numbers::{plain, quantity, vector, with_unit};
use egui::{Color32, RichText};
use line::Item;

/// The sign of a rewound run, beside its word or alone where the line is
/// too full for the word.
const REWOUND_SIGN: &str = "⏪";

/// The top bar (no state of its own).
pub struct TopBar;

impl View for TopBar {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let world = &model.world;
        let m = world.metrics();
        let spin = spin_shown(world);
        let dark = ui.visuals().dark_mode;
        let (running, paused) = if dark {
            (
                Color32::from_rgb(120, 230, 140),
                Color32::from_rgb(255, 200, 60),
            )
        } else {
            (Color32::from_rgb(0, 110, 30), Color32::from_rgb(170, 60, 0))
        };
        let name = model.scene_name();
        let mark = model.edited_mark();
        let method = model.method_in_use();
        let warnings = impulse::warnings::warnings(world, model.clock.dt);
        let stall = warnings
            .iter()
            .find(|w| w.code == impulse::warnings::STALL)
            .map(|w| warning_text(w, &method));
        // The state, and its sign alone for a line too full (the π blocks'
        // count at a projector's size).
        // Rewound, its own sign: alone at a projector (the line too full for
        // the word), the pause's sign had said only "paused".
        let (state, sign) = if model.record.history.cursor().is_some() {
            (
                RichText::new(format!("{REWOUND_SIGN} {}", tr!("state-rewound"))).color(paused),
                RichText::new(REWOUND_SIGN).color(paused),
            )
        } else if model.clock.paused {
            (
                RichText::new(format!("⏸ {}", tr!("state-paused"))).color(paused),
                RichText::new("⏸").color(paused),
            )
        } else if stall.is_some() {
            // Running, but the clock does not move: said where it is always
            // in sight, not only among the warnings "… more" may hold.
            (
                RichText::new(format!("⚠ {}", tr!("state-stalled"))).color(paused),
                RichText::new("⚠").color(paused),
            )
        } else {
            // The time scale only when it is not real time: a short line.
            let scale = model.clock.time_scale();
            let (text, sign) = if scale == 1.0 {
                (format!("▶ {}", tr!("state-running")), "▶".to_string())
            } else {
                let scale = crate::app::numbers::field(scale);
                (
                    format!("▶ {} ×{scale}", tr!("state-running")),
                    format!("▶ ×{scale}"),
                )
            };
            (
                RichText::new(text).color(running),
                RichText::new(sign).color(running),
            )
        };
        let sign = sign.strong();
        // Always shown, in this order.
        let mut essential = vec![
            Item::new(RichText::new(name).strong())
                // Short, a pencil: "*" read as "not saved", and stayed
                // after a save (it says the discs were edited since the
                // scene opened, so its caption may not hold).
                .kept_end(mark.map(|m| [RichText::new(m).strong(), RichText::new("✎").strong()])),
            Item::new(format!("t = {}", with_unit(world.time, 2, "s"))),
            match stall {
                Some(why) => Item::new(state.strong())
                    .named("run_state")
                    .hover(why)
                    .short(sign),
                None => Item::new(state.strong()).named("run_state").short(sign),
            },
        ];
        // Shown as far as the line reaches, in this order.
        let mut optional = Vec::new();
        if let Some(slow) = model.slow_note() {
            optional.push(Item::new(RichText::new(slow).color(paused)));
        }
        if let (Some(_), Some((oldest, newest))) =
            (model.record.history.cursor(), model.record.history.span())
        {
            // What was recorded, in the caption's words and figures (it said
            // "snapshot 117 of 120", its times to two decimals where the
            // caption has three); the time is the line's t.
            optional.push(Item::new(tr!(
                "rewound-line",
                oldest = plain(oldest, 3),
                newest = plain(newest, 3)
            )));
        }
        // What the method cannot promise comes before the numbers it affects.
        for warning in warnings {
            let text = warning_text(&warning, &method);
            optional.push(
                Item::new(RichText::new(format!("⚠ {text}")).color(paused))
                    .named(format!("warning_{}", warning.code)),
            );
        }
        // In the π blocks the count is the lesson: it is always there, after
        // the state (a projector's bar had kept it under "… more" until the
        // end), and the full line stays among the others.
        if pi_decimals(world).is_some() && pi_result(world).is_none() {
            let count = world.total_pair_collisions + world.total_wall_hits;
            essential.push(
                Item::new(RichText::new(tr!("pi-count", count = count)).strong())
                    .hover(tr!("count-hover"))
                    .named("pi_count"),
            );
        }
        let mut momentum = Item::new(format!("p = {}", vector(m.momentum, 3, "kg·m/s")))
            .hover(tr!("momentum-hover"))
            .named("momentum");
        if walls_pushed(cx) {
            momentum = Item::new(
                RichText::new(tr!(
                    "momentum-walls-push",
                    momentum = vector(m.momentum, 3, "kg·m/s")
                ))
                .color(paused),
            )
            .hover(tr!("momentum-walls-push-hover"))
            .named("walls_push")
            // Where the note does not fit, the momentum alone, its colour
            // and hover still saying the walls push.
            .short(RichText::new(format!("p = {}", vector(m.momentum, 3, "kg·m/s"))).color(paused));
        }
        optional.push(momentum.before_the_name());
        if spin {
            optional.push(
                Item::new(tr!(
                    "energy-with-turning",
                    moving = quantity(m.kinetic_energy, 3),
                    turning = quantity(m.rotational_energy, 3),
                    total = with_unit(m.kinetic_energy + m.rotational_energy, 3, "J")
                ))
                .hover(tr!("energy-with-turning-hover")),
            );
        } else {
            optional.push(
                Item::new(tr!(
                    "energy-line",
                    energy = with_unit(m.kinetic_energy, 3, "J")
                ))
                .hover(tr!("energy-hover")),
            );
        }
        optional.push(match pi_result(world) {
            Some(result) => Item::new(RichText::new(result).strong()),
            None => Item::new(count_line(world))
                .hover(tr!("count-hover"))
                .named("count"),
        });
        if model.overlays.com_view.is_some() {
            // The totals above are the box's; in the view's frame the
            // momentum is zero and less energy moves.
            let v = m.center_of_mass_velocity;
            let total_mass: f64 = world.particles.iter().map(|p| p.mass).sum();
            let relative_ke = m.kinetic_energy - 0.5 * total_mass * v.length_squared();
            optional.push(Item::new(
                RichText::new(tr!(
                    "com-view-line",
                    momentum = vector(glam::DVec2::ZERO, 3, "kg·m/s"),
                    energy = with_unit(relative_ke.max(0.0), 3, "J")
                ))
                .color(paused),
            ));
        }
        if world.laws.gravity != glam::DVec2::ZERO {
            // With gravity, kinetic energy alone seems to vanish in a fall.
            optional.push(
                Item::new(tr!(
                    "energy-with-height",
                    energy = with_unit(world.total_energy(), 3, "J")
                ))
                .hover(tr!("energy-with-height-hover")),
            );
        }
        if spin {
            optional.push(
                Item::new(format!(
                    "L = {}",
                    with_unit(m.angular_momentum, 3, "kg·m²/s")
                ))
                .hover(super::widgets::angular_momentum_tip(
                    tr!("angular-momentum-hover"),
                    world,
                )),
            );
        }
        if world.resting_contacts > 0 {
            optional.push(
                Item::new(tr!("resting-contacts", count = world.resting_contacts))
                    .hover(tr!("resting-contacts-hover")),
            );
        }
        self.line(ui, cx, essential, optional);
    }
}

/// Whether the walls have changed the discs' total momentum since the
/// record began (a box with walls, and a change beyond rounding).
fn walls_pushed(cx: &Cx) -> bool {
    let model = cx.model;
    let world = &model.world;
    if world.total_wall_hits == 0 {
        return false;
    }
    let Some(first) = model.record.totals.first() else {
        return false;
    };
    let scale: f64 = world
        .particles
        .iter()
        .map(|p| p.mass * p.vel.length())
        .sum::<f64>()
        .max(1e-300);
    (world.metrics().momentum - first.momentum).length() > 1e-9 * scale
}

/// The sound button's label, an icon (its name and key on hover, so that
/// the top bar keeps its room at a projector's scale): 🔊 on, 🔈 on but
/// silent now (paused, or faster than ×2), 🔇 off.
fn sound_label(cx: &Cx) -> String {
    let model = cx.model;
    let icon = match (
        model.session.sound.on,
        model.session.sound.active(&model.clock),
    ) {
        (true, true) => "🔊",
        (true, false) => "🔈",
        (false, _) => "🔇",
    };
    icon.to_string()
}

#[cfg(test)]
mod tests {
    use super::{TopBar, REWOUND_SIGN};
    use crate::app::model::tests::sandbox_with;
    use crate::app::model::Command;
    use crate::app::ui::widgets::texts_drawn;

    /// Where the momentum with its note ("walls push") does not fit, the
    /// momentum alone does: the whole item had gone under "… more".
    #[test]
    fn the_momentum_stays_in_a_line_too_short_for_its_note() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_with(dir.path(), "preset-2-heavy-hits-light.toml", false, 0.0);
        for k in 1..=300 {
            s.begin_frame(f64::from(k) / 60.0);
            s.tick(1.0 / 60.0, 1.0);
        }
        let (mut whole, mut alone) = (0, 0);
        for width in (300..1600).step_by(10) {
            let text = texts_drawn(&s, egui::vec2(width as f32, 40.0), &mut TopBar).concat();
            match (text.contains("p = ("), text.contains("walls push")) {
                (true, true) => whole += 1,
                (true, false) => alone += 1,
                _ => {}
            }
        }
        assert!(whole > 0, "the walls pushed: the note shows where it fits");
        assert!(alone > 0, "and the momentum alone where only it fits");
    }

    /// Rewound, the top bar shows a sign of its own, also where a
    /// projector's line has room for the sign alone: it showed the
    /// pause's, and only the caption said the run was rewound.
    #[test]
    fn a_rewound_run_has_its_own_sign_in_a_full_top_bar() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_with(dir.path(), "preset-1-head-on.toml", false, 0.0);
        for k in 1..=90 {
            s.begin_frame(f64::from(k) / 60.0);
            s.tick(1.0 / 60.0, 1.0);
        }
        s.apply(Command::Scrub(-3));
        assert!(s.record.history.cursor().is_some(), "rewound");
        for width in [400.0, 1400.0] {
            let text = texts_drawn(&s, egui::vec2(width, 40.0), &mut TopBar).concat();
            assert!(text.contains(REWOUND_SIGN), "{width}: {text}");
            assert!(!text.contains('⏸'), "{width}: {text}");
        }
        let fonts = egui::Context::default();
        crate::app::look::apply(&fonts, 1.0, crate::app::look::Theme::Dark);
        let _ = fonts.run(Default::default(), |_| {});
        let body = egui::FontId::proportional(14.0);
        assert!(fonts.fonts(|f| f.has_glyphs(&body, REWOUND_SIGN)));
    }
}
