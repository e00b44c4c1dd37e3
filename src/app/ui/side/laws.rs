//! The *Collisions* section: restitution between discs and at the walls,
//! gravity, the edges and the time scale; and under *More*, the rough-disc
//! laws (roughness and friction). A slider sends its value as a command;
//! the model keeps it in range and remembers it for undo.

use super::super::widgets::{pick, slider, Reading};
use super::Cx;
use crate::app::lang::tr;
use crate::app::model::clock::TIME_SCALES;
use crate::app::model::command::Law;
use crate::app::model::overlays::spin_shown;
use crate::app::model::Command;
use crate::app::ui::tip::Tip;
use egui::Ui;
use impulse::Boundary;

use crate::app::model::apply::EARTH_GRAVITY;

/// The gravity slider's track's value: tenths, sticking to Earth's within
/// 0.15.
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
    let (r, changed) = slider(ui, label, &mut value, lo..=hi, Reading::new(2, ""));
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
    cx.note(name, &r.tip(hover));
}

/// Restitution, gravity, edges, time scale; with rough discs (a scene
/// whose discs spin) also roughness and friction, which it needs.
pub fn laws(ui: &mut Ui, cx: &mut Cx) {
    // What 1 and 0 mean beside the name; in the drawer, on hover: at a
    // projector's size the name took six lines there and pushed the slider
    // under the drawer's edge.
    let (name, scale, hover) = (
        tr!("restitution-label"),
        tr!("restitution-scale"),
        tr!("restitution-hover"),
    );
    let (label, hover) = if cx.drawer {
        (name, format!("{scale}. {hover}"))
    } else {
        (format!("{name} ({scale})"), hover)
    };
    coefficient(ui, cx, Law::Restitution, (&label, "restitution", &hover));
    coefficient(
        ui,
        cx,
        Law::WallRestitution,
        (
            &tr!("wall-restitution-label"),
            "wall_restitution",
            &tr!("wall-restitution-hover"),
        ),
    );
    // The slider shows |g| and sets it pointing down; a scene's sideways
    // gravity is only replaced once the slider is moved.
    let mut g = cx.model.world.laws.gravity.length();
    let (lo, hi) = impulse::laws::GRAVITY_RANGE.control;
    let (r, changed) = slider(
        ui,
        &tr!("gravity-label"),
        &mut g,
        lo..=hi,
        Reading::new(2, " m/s²").magnitude(),
    );
    if changed {
        // The track snaps (a drag cannot land on 9.81); a number typed or
        // dragged in the box is taken as it is.
        let g = if r.changed() { snap_gravity(g) } else { g };
        cx.send(Command::SetGravity(g));
    }
    let tip = crate::app::model::bindings::tooltip(&Command::ToggleGravity);
    cx.note(
        "gravity",
        &r.tip(format!(
            "{}\n{tip}",
            tr!(
                "gravity-hover",
                gravity = crate::app::numbers::plain(EARTH_GRAVITY, 2)
            )
        )),
    );
    let boundary = cx.model.world.laws.boundary;
    let edge_name = |b: Boundary| match b {
        Boundary::Box => tr!("edges-box"),
        Boundary::Open => tr!("edges-open"),
        Boundary::Periodic => tr!("edges-periodic"),
    };
    let names = Boundary::ALL.map(edge_name);
    let at = Boundary::ALL.iter().position(|&b| b == boundary);
    let words = (&*tr!("edges-label"), &*tr!("edges-hover"), "edges");
    if let Some(k) = pick(ui, cx, words, &names, at, &edge_name(boundary)) {
        if Boundary::ALL[k] != boundary {
            cx.send(Command::SetBoundary(Boundary::ALL[k]));
        }
    }
    let scales = TIME_SCALES.map(|s| format!("×{}", crate::app::numbers::field(s)));
    let index = cx.model.clock.time_scale_index();
    let words = (
        &*tr!("time-scale-label"),
        &*tr!("time-scale-hover"),
        "time_scale",
    );
    if let Some(k) = pick(ui, cx, words, &scales, Some(index), &scales[index]) {
        cx.send(Command::SetTimeScale(k));
    }
    if spin_shown(&cx.model.world) {
        ui.separator();
        advanced(ui, cx);
    }
}

/// Roughness β between discs and at the walls, and friction μ (off: no
/// limit): for discs that spin.
pub fn advanced(ui: &mut Ui, cx: &mut Cx) {
    let rough = tr!("roughness-hover");
    coefficient(
        ui,
        cx,
        Law::Roughness,
        (&tr!("roughness-label"), "tangential_restitution", &rough),
    );
    coefficient(
        ui,
        cx,
        Law::WallRoughness,
        (
            &tr!("wall-roughness-label"),
            "wall_tangential_restitution",
            &rough,
        ),
    );
    // μ is off (no limit) or a number: a tick turns it on at the slider's
    // value, kept in the side dock while it is off.
    let friction = cx.model.world.laws.friction;
    let mut on = friction.is_some();
    let r = ui
        .checkbox(&mut on, tr!("friction-on-label"))
        .tip(tr!("friction-hover"));
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
            slider(
                ui,
                &tr!("friction-label"),
                &mut mu,
                lo..=hi,
                Reading::new(2, ""),
            )
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
