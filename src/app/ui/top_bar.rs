//! The top bar: what a class reads from the back row, on one line. The
//! scene's name, the simulated time and RUNNING or PAUSED are always there
//! (not even Tab hides them); then, as far as the line reaches, the total
//! momentum (with a note while the walls have changed it) and energy, the
//! impacts between discs and on walls counted apart, and what the method
//! cannot promise. What does not fit is under "… more", on hover or when
//! Tab gives it the keys.

use super::{Cx, View};
use crate::app::lang::tr;
use crate::app::model::lesson::{count_line, pi_result, warning_text};
use crate::app::model::overlays::spin_shown;
use crate::app::model::Command;
use crate::app::numbers::{plain, quantity, vector, with_unit};
use crate::app::ui::tip::Tip;
use egui::{Color32, RichText, WidgetText};
use std::sync::Arc;

/// The top bar (no state of its own).
pub struct TopBar;

/// One item of the line: its text, what hovering it says, and its name in
/// the state dump.
struct Item {
    text: RichText,
    hover: Option<String>,
    name: Option<String>,
}

impl Item {
    fn new(text: impl Into<RichText>) -> Self {
        Item {
            text: text.into(),
            hover: None,
            name: None,
        }
    }

    fn hover(mut self, text: impl Into<String>) -> Self {
        self.hover = Some(text.into());
        self
    }

    fn named(mut self, name: impl Into<String>) -> Self {
        self.name = Some(name.into());
        self
    }
}

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
        let method = model.method_in_use();
        let warnings = impulse::warnings::warnings(world, model.clock.dt);
        let stall = warnings
            .iter()
            .find(|w| w.code == impulse::warnings::STALL)
            .map(|w| warning_text(w, &method));
        let state = if model.record.history.cursor().is_some() {
            RichText::new(format!("⏸ {}", tr!("state-rewound"))).color(paused)
        } else if model.clock.paused {
            RichText::new(format!("⏸ {}", tr!("state-paused"))).color(paused)
        } else if stall.is_some() {
            // Running, but the clock does not move: said where it is always
            // in sight, not only among the warnings "… more" may hold.
            RichText::new(format!("⚠ {}", tr!("state-stalled"))).color(paused)
        } else {
            // The time scale only when it is not real time: a short line.
            let scale = model.clock.time_scale();
            let text = if scale == 1.0 {
                format!("▶ {}", tr!("state-running"))
            } else {
                format!(
                    "▶ {} ×{}",
                    tr!("state-running"),
                    crate::app::numbers::field(scale)
                )
            };
            RichText::new(text).color(running)
        };
        // Always shown, in this order.
        let essential = [
            Item::new(RichText::new(name).strong()),
            Item::new(format!("t = {}", with_unit(world.time, 2, "s"))),
            match stall {
                Some(why) => Item::new(state.strong()).named("run_state").hover(why),
                None => Item::new(state.strong()).named("run_state"),
            },
        ];
        // Shown as far as the line reaches, in this order.
        let mut optional = Vec::new();
        if let Some(slow) = model.slow_note() {
            optional.push(Item::new(RichText::new(slow).color(paused)));
        }
        if let (Some(k), Some((oldest, newest))) =
            (model.record.history.cursor(), model.record.history.span())
        {
            optional.push(Item::new(tr!(
                "rewound-line",
                snapshot = k + 1,
                snapshots = model.record.history.len(),
                oldest = plain(oldest, 2),
                newest = plain(newest, 2)
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
        let mut momentum = Item::new(format!("p = {}", vector(m.momentum, 3, "kg·m/s")))
            .hover(tr!("momentum-hover"));
        if walls_pushed(cx) {
            momentum = Item::new(
                RichText::new(tr!(
                    "momentum-walls-push",
                    momentum = vector(m.momentum, 3, "kg·m/s")
                ))
                .color(paused),
            )
            .hover(tr!("momentum-walls-push-hover"))
            .named("walls_push");
        }
        optional.push(momentum);
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

impl TopBar {
    /// Lays the items out on one line: the essential ones, then the others
    /// while they fit, then "⋯ more" with the rest on hover, and the
    /// buttons at the right end.
    fn line(&self, ui: &mut egui::Ui, cx: &mut Cx, essential: [Item; 3], optional: Vec<Item>) {
        // Less room between items where the bar is narrow.
        let spacing = if ui.available_width() < 700.0 {
            12.0
        } else {
            18.0
        };
        let label = |c: &Command| crate::app::model::bindings::label(c).unwrap_or_default();
        let sound = sound_label(cx);
        let mut buttons: Vec<(String, Command, &str)> =
            vec![(label(&Command::ShowStart), Command::ShowStart, "start")];
        buttons.push((sound, Command::ToggleSound, "sound"));
        if cx.drawer && cx.model.panels.docks_open {
            let toggle = Command::ToggleDrawer;
            buttons.push((label(&toggle), toggle, "drawer_toggle"));
        }
        if !cx.model.panels.docks_open {
            buttons.push((tr!("show-panels"), Command::ToggleDocks, "show_panels"));
        }
        let more = RichText::new(tr!("top-bar-more"));
        let more_width = galley(ui, &more).size().x + spacing;
        let [_, time, state] = &essential;
        let fixed =
            galley(ui, &time.text).size().x + galley(ui, &state.text).size().x + 2.0 * spacing;
        // Where the buttons' words would leave the time and the state no
        // room (long words at a projector's scale), the buttons that have
        // an icon show only it, their words on hover.
        let padding = ui.spacing().button_padding.x * 2.0 + 8.0;
        let buttons_width: f32 = buttons
            .iter()
            .map(|(l, _, _)| galley(ui, &RichText::new(l.as_str())).size().x + padding)
            .sum();
        if ui.available_width() - buttons_width < fixed + more_width + 40.0 + 2.0 * spacing {
            for (label, _, _) in &mut buttons {
                if let Some(icon) = label
                    .split_whitespace()
                    .next()
                    .filter(|w| !w.chars().any(char::is_alphanumeric))
                {
                    *label = icon.to_string();
                }
            }
        }
        // The line first and the buttons after it, at the right, so that Tab
        // meets everything in reading order (egui's Tab follows the order
        // controls are made). The buttons' group is as wide as it was last
        // frame; the line gets what it leaves.
        let group = ui.id().with("top_bar_buttons");
        let width = ui
            .data(|d| d.get_temp::<f32>(group))
            .unwrap_or(buttons_width);
        ui.with_layout(egui::Layout::left_to_right(egui::Align::Center), |ui| {
            let line = egui::vec2(
                (ui.available_width() - width - spacing).max(0.0),
                ui.available_height(),
            );
            ui.allocate_ui_with_layout(
                line,
                egui::Layout::left_to_right(egui::Align::Center),
                |ui| {
                    let words = Words {
                        essential,
                        optional,
                        more,
                        spacing,
                        more_width,
                        fixed,
                    };
                    items(ui, cx, words);
                },
            );
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                button_group(ui, cx, buttons, (group, width));
            });
        });
    }
}

/// What the line says: the essential items, the others while they fit,
/// "… more" for the rest, and the room between items (points); with the
/// widths [`TopBar::line`] measured: "… more" and the room after it, and
/// the time and the state with theirs.
struct Words {
    essential: [Item; 3],
    optional: Vec<Item>,
    more: RichText,
    spacing: f32,
    more_width: f32,
    fixed: f32,
}

/// `text` in one line of body text.
fn galley(ui: &egui::Ui, text: &RichText) -> Arc<egui::Galley> {
    WidgetText::from(text.clone()).into_galley(
        ui,
        Some(egui::TextWrapMode::Extend),
        f32::INFINITY,
        egui::TextStyle::Body,
    )
}

/// The line's items in the room `ui` has: the scene's name (cut first,
/// whole on hover), the time and the state, then the others in order while
/// they fit, then "… more" with the rest.
fn items(ui: &mut egui::Ui, cx: &mut Cx, words: Words) {
    let Words {
        essential: [name, time, state],
        optional,
        more,
        spacing,
        more_width,
        fixed,
    } = words;
    // What the name and the other items may take, "… more" kept room for.
    let free = ui.available_width() - more_width - fixed;
    let full_name = galley(ui, &name.text).size().x;
    let name_width = full_name.min((0.6 * free).max(40.0));
    // The other items that fit beside the name at that width, in order (the
    // last may use the room kept for "… more")...
    let galleys: Vec<_> = optional.iter().map(|item| galley(ui, &item.text)).collect();
    // (`free` has the room between items: `fixed` the two after the name
    // and the time, `more_width` the one before "… more", each item's its
    // own before it.)
    let (mut room, mut used, mut shown) = (free - name_width, 0.0, 0);
    for (k, g) in galleys.iter().enumerate() {
        let last = k + 1 == galleys.len();
        let need = g.size().x + spacing - if last { more_width } else { 0.0 };
        if need > room {
            break;
        }
        room -= g.size().x + spacing;
        used += g.size().x + spacing;
        shown += 1;
    }
    // ... and the room they leave goes back to the name, so that it is cut
    // only where the line is really full.
    let name_width = full_name.min((free - used).max(name_width));
    ui.spacing_mut().item_spacing.x = spacing;
    ui.set_clip_rect(ui.max_rect().intersect(ui.clip_rect()));
    let height = ui.available_height();
    let r = ui.add_sized([name_width, height], |ui: &mut egui::Ui| {
        super::widgets::one_line(ui, name.text, None)
    });
    cx.note("scene_name", &r);
    if name_width + 0.5 < full_name {
        cx.marks.cut.insert("scene_name".into());
    }
    let said = [time, state].into_iter().map(|item| (item, None));
    let others = optional
        .into_iter()
        .zip(galleys)
        .map(|(item, g)| (item, Some(g)));
    let mut hidden = Vec::new();
    for (k, (item, g)) in said.chain(others).enumerate() {
        if k >= 2 + shown {
            hidden.push(item.text.text().to_string());
            continue;
        }
        let r = match g {
            Some(g) => ui.label(g),
            None => ui.label(item.text),
        };
        let r = match item.hover {
            Some(h) => r.tip(h),
            None => r,
        };
        if let Some(name) = item.name {
            cx.note(name, &r);
        }
    }
    if !hidden.is_empty() {
        more_label(ui, cx, more, hidden.join("\n"));
    }
}

/// "… more", with `hidden` on hover, while it has the keys (Tab reaches
/// it), or from a click until the next click elsewhere or Esc: a touch
/// screen (a classroom's board) has no hover.
fn more_label(ui: &mut egui::Ui, cx: &mut Cx, more: RichText, hidden: String) {
    let r = ui.add(egui::Label::new(more).sense(egui::Sense::click()));
    let pinned_id = r.id.with("pinned");
    let mut pinned = ui.data(|d| d.get_temp::<bool>(pinned_id)).unwrap_or(false);
    if r.clicked() {
        pinned = !pinned;
    } else if ui.input(|i| i.pointer.any_pressed()) && !r.hovered() {
        pinned = false;
    }
    // Esc lets go of it, as of any popup; and it gives way to the key list
    // and the start screen, which it would cover.
    let panels = &cx.model.panels;
    if ui.input(|i| i.key_pressed(egui::Key::Escape)) || panels.help_open || panels.start_open {
        pinned = false;
    }
    ui.data_mut(|d| d.insert_temp(pinned_id, pinned));
    let r = if r.has_focus() || pinned {
        r.tip_now(hidden);
        r
    } else {
        r.tip(hidden)
    };
    cx.note("top_bar_more", &r);
}

/// The buttons at the bar's right end, in a group as wide as it was last
/// frame (`group` keeps the width); a change of width lays the frame out
/// again.
fn button_group(
    ui: &mut egui::Ui,
    cx: &mut Cx,
    buttons: Vec<(String, Command, &str)>,
    (group, width): (egui::Id, f32),
) {
    let size = egui::vec2(width, ui.available_height());
    let used = ui
        .allocate_ui_with_layout(
            size,
            egui::Layout::left_to_right(egui::Align::Center),
            |ui| {
                ui.spacing_mut().item_spacing.x = 8.0;
                for (label, command, name) in buttons.into_iter().rev() {
                    super::widgets::labelled_button(ui, cx, label, command, Some(name));
                }
                ui.min_rect().width()
            },
        )
        .inner;
    if (used - width).abs() > 0.5 {
        ui.data_mut(|d| d.insert_temp(group, used));
        ui.ctx()
            .request_discard("the top bar's buttons changed width");
    }
}
