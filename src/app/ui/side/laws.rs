//! The *Collisions* section: restitution between discs and at the walls,
//! gravity, the edges and the time scale; and under *More*, the rough-disc
//! laws (roughness and friction). A slider sends its value as a command;
//! the model keeps it in range and remembers it for undo.

use super::super::widgets::{setting_combo, slider};
use super::Cx;
use crate::app::model::clock::TIME_SCALES;
use crate::app::model::command::Law;
use crate::app::model::overlays::spin_shown;
use crate::app::model::Command;
use egui::{ComboBox, Ui};
use impulse::Boundary;

use crate::app::model::apply::EARTH_GRAVITY;

/// The gravity slider's value: tenths, sticking to Earth's within 0.15.
pub fn snap_gravity(g: f64) -> f64 {
    if (g - EARTH_GRAVITY).abs() < 0.15 {
        EARTH_GRAVITY
    } else {
        (g * 10.0).round() / 10.0
    }
}

/// A slider for `law`; `name` is its widget's name in the state dump.
fn coefficient(ui: &mut Ui, cx: &mut Cx, law: Law, (label, name, hover): (&str, &str, &str)) {
    let mut value = law.of(&cx.model.world.laws);
    let (lo, hi) = law.range().control;
    let (r, changed) = slider(ui, label, &mut value, lo..=hi, false, 2, "");
    if changed {
        cx.send(Command::SetLaw(law, value));
    }
    let keys = crate::app::model::bindings::tooltip(&Command::NudgeLaw(
        law,
        crate::app::model::command::Dir::Up,
    ));
    let hover = if keys.is_empty() {
        hover.to_string()
    } else {
        format!("{hover}\n{keys}")
    };
    cx.note(name, &r.on_hover_text(hover));
}

/// Restitution, gravity, edges, time scale; with rough discs (a scene
/// whose discs spin) also roughness and friction, which it needs.
pub fn laws(ui: &mut Ui, cx: &mut Cx) {
    coefficient(
        ui,
        cx,
        Law::Restitution,
        (
            "Bounce between discs, restitution e (1: they bounce back fully, 0: they move on together along the line of impact)",
            "restitution",
            "How much of their approach speed two discs keep, going apart, along the line through their centres: 1 all of it, 0 none (sideways motion is kept)",
        ),
    );
    coefficient(
        ui,
        cx,
        Law::WallRestitution,
        (
            "Bounce at the walls, restitution e",
            "wall_restitution",
            "How much of its speed into a wall a disc keeps, going away from it: 1 all of it, 0 none",
        ),
    );
    // The slider shows |g| and sets it pointing down; a scene's sideways
    // gravity is only replaced once the slider is moved.
    let mut g = cx.model.world.laws.gravity.length();
    let (lo, hi) = impulse::laws::GRAVITY_RANGE.control;
    let (r, changed) = slider(
        ui,
        "Gravity, pointing down",
        &mut g,
        lo..=hi,
        false,
        2,
        " m/s²",
    );
    if changed {
        cx.send(Command::SetGravity(snap_gravity(g)));
    }
    let tip = crate::app::model::bindings::tooltip(&Command::ToggleGravity);
    cx.note(
        "gravity",
        &r.on_hover_text(format!(
            "how hard the discs are pulled down; 9.81 m/s² on Earth\n{tip}"
        )),
    );
    let boundary = cx.model.world.laws.boundary;
    if let Some(b) = setting_combo(
        ui,
        (
            "edges",
            "What the sides of the box do: box, walls the discs bounce off; open, no walls \
             (discs fly away); periodic, a disc leaving on one side comes back on the other",
        ),
        &Boundary::ALL.map(Boundary::name),
        boundary.name(),
    ) {
        if let Some(&k) = Boundary::ALL.iter().find(|k| k.name() == b) {
            cx.send(Command::SetBoundary(k));
        }
    }
    let scales = TIME_SCALES.map(|s| format!("×{s}"));
    let index = cx.model.clock.time_scale_index();
    ComboBox::from_label("time scale")
        .selected_text(scales[index].clone())
        .show_ui(ui, |ui| {
            for (k, label) in scales.iter().enumerate() {
                if ui.selectable_label(k == index, label).clicked() {
                    cx.send(Command::SetTimeScale(k));
                }
            }
        })
        .response
        .on_hover_text("simulated seconds per real second: below 1 is slow motion");
    if spin_shown(&cx.model.world) {
        ui.separator();
        advanced(ui, cx);
    }
}

/// Roughness β between discs and at the walls, and friction μ (off: no
/// limit): for discs that spin.
pub fn advanced(ui: &mut Ui, cx: &mut Cx) {
    const ROUGH: &str = "How the touching edges grip in a collision, so that discs start or stop \
        spinning: −1 smooth (no grip, no spin given), 0 their sliding stops, 1 perfectly rough \
        (the sliding reverses and no energy is lost)";
    coefficient(
        ui,
        cx,
        Law::Roughness,
        (
            "Grip between discs, roughness β (−1 smooth … 1 rough)",
            "tangential_restitution",
            ROUGH,
        ),
    );
    coefficient(
        ui,
        cx,
        Law::WallRoughness,
        (
            "Grip at the walls, roughness β",
            "wall_tangential_restitution",
            ROUGH,
        ),
    );
    // μ is off (no limit) or a number: a tick turns it on at the slider's
    // value, kept in the side dock while it is off.
    let friction = cx.model.world.laws.friction;
    let mut on = friction.is_some();
    let r = ui
        .checkbox(&mut on, "Friction μ limits the grip")
        .on_hover_text(
            "Friction: the sideways push where discs touch is at most μ times the \
             head-on push, so fast sliding is only slowed; it also makes discs \
             lying on each other rub. Off: no limit.",
        );
    cx.note("friction_on", &r);
    let kept = ui
        .ctx()
        .data(|d| d.get_temp::<f64>(egui::Id::new("friction_kept")))
        .unwrap_or(0.5);
    if r.changed() {
        cx.send(Command::SetFriction(on.then_some(kept)));
    }
    let mut mu = friction.unwrap_or(kept);
    let (r, changed) = ui
        .add_enabled_ui(on, |ui| {
            let (lo, hi) = impulse::laws::FRICTION_RANGE.control;
            slider(ui, "Friction μ", &mut mu, lo..=hi, false, 2, "")
        })
        .inner;
    if changed && on {
        let mu = (mu * 100.0).round() / 100.0;
        ui.ctx()
            .data_mut(|d| d.insert_temp(egui::Id::new("friction_kept"), mu));
        cx.send(Command::SetFriction(Some(mu)));
    }
    cx.note("friction", &r);
}
