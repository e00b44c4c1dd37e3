//! The panel's first four sections, which set what the simulation does:
//! World (restitution, gravity, boundary, time scale), Method (step method,
//! broad phase, substeps), New discs (size and mass of discs drawn on empty
//! space) and Overlays (arrows, totals, per-disc readouts). Each writes
//! straight into the app as its widgets move; nothing waits for a button.
//!
//! The sliders' scales and rounding live here with the sections that use
//! them.

use super::selected::field_text;
use super::widgets::{checkbox, combo, SliderScale};
use super::{Action, ROW};
use crate::app::clock::TIME_SCALES;
use crate::app::draw::ReadoutScope;
use crate::app::input::{BROAD_PHASES, METHODS, SUBSTEPS};
use crate::app::App;
use glam::DVec2;
use impulse::Boundary;
use macroquad::prelude::*;
use macroquad::ui::{hash, Ui};
use std::fmt::Display;

/// Earth's gravity, where the gravity slider sticks (m/s²).
const EARTH_GRAVITY: f64 = 9.81;

pub(super) const RESTITUTION: SliderScale = SliderScale::linear(0.0, 1.0);
const GRAVITY: SliderScale = SliderScale::linear(0.0, 20.0);
const NEW_RADIUS: SliderScale = SliderScale::log(0.05, 2.0);
pub(super) const NEW_MASS: SliderScale = SliderScale::log(0.01, 100.0);

/// `v` rounded to a multiple of `step`.
pub fn round_to_step(v: f64, step: f64) -> f64 {
    (v / step).round() * step
}

/// `v` rounded to `digits` significant digits (0 and non-finite unchanged).
pub fn round_significant(v: f64, digits: i32) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let scale = 10f64.powi(digits - 1 - v.abs().log10().floor() as i32);
    (v * scale).round() / scale
}

/// The gravity slider's value: tenths, sticking to 9.81 within 0.15.
pub fn snap_gravity(g: f64) -> f64 {
    if (g - EARTH_GRAVITY).abs() < 0.15 {
        EARTH_GRAVITY
    } else {
        round_to_step(g, 0.1)
    }
}

/// The labels of `list` for a combo box and the index of `current`; a
/// current value that is not in the list (a scene file may ask for 3
/// substeps) is added at the end, so the box always shows the truth.
pub fn choices<T: Copy + PartialEq + Display>(list: &[T], current: T) -> (Vec<String>, usize) {
    let mut labels: Vec<String> = list.iter().map(ToString::to_string).collect();
    let index = match list.iter().position(|&x| x == current) {
        Some(k) => k,
        None => {
            labels.push(current.to_string());
            labels.len() - 1
        }
    };
    (labels, index)
}

impl App {
    pub(super) fn world_section(&mut self, ui: &mut Ui) {
        let panel = &mut self.panel;
        let r = panel.row(ui, ROW);
        panel.styled(
            ui,
            |s| &s.header,
            |panel, ui| {
                panel.label(ui, vec2(r.x, r.y + 1.0), "Controls   (L hides, H: keys)");
            },
        );
        panel.header(ui, "World");
        let w = &mut self.world;
        if let Some(e) = panel.slider(
            ui,
            "restitution",
            w.restitution,
            RESTITUTION,
            |v| round_to_step(v, 0.01),
            |v| format!("{v:.2} e disc-disc"),
        ) {
            w.restitution = e;
        }
        if let Some(e) = panel.slider(
            ui,
            "wall_restitution",
            w.wall_restitution,
            RESTITUTION,
            |v| round_to_step(v, 0.01),
            |v| format!("{v:.2} e disc-wall"),
        ) {
            w.wall_restitution = e;
        }
        // The slider shows |g| and sets it pointing down; a scene's sideways
        // gravity is only replaced once the slider is moved.
        if let Some(g) = panel.slider(
            ui,
            "gravity",
            w.gravity.length(),
            GRAVITY,
            snap_gravity,
            |v| {
                if v == 0.0 {
                    "gravity off".to_string()
                } else {
                    format!("g {v:.2} m/s^2")
                }
            },
        ) {
            w.gravity = DVec2::new(0.0, -g);
        }
        let (labels, index) = choices(&Boundary::ALL.map(Boundary::name), w.boundary.name());
        if let Some(k) = combo(ui, hash!(), "boundary", &labels, index) {
            w.boundary = Boundary::ALL[k];
        }
        let scales = TIME_SCALES.map(|s| format!("x{s}"));
        let index = self.clock.time_scale_index();
        if let Some(k) = combo(ui, hash!(), "time scale", &scales, index) {
            self.clock.set_time_scale_index(k);
        }
    }

    pub(super) fn method_section(&mut self, ui: &mut Ui) {
        self.panel.header(ui, "Method");
        let w = &mut self.world;
        let (labels, index) = choices(&METHODS, w.method);
        if let Some(k) = combo(ui, hash!(), "method", &labels, index) {
            w.method = METHODS[k];
        }
        let (labels, index) = choices(&BROAD_PHASES, w.broad_phase);
        if let Some(k) = combo(ui, hash!(), "broad phase", &labels, index) {
            w.broad_phase = BROAD_PHASES[k];
        }
        let (labels, index) = choices(&SUBSTEPS, w.substeps);
        if let Some(k) = combo(ui, hash!(), "substeps", &labels, index) {
            w.substeps = SUBSTEPS[k];
        }
    }

    pub(super) fn new_disc_section(&mut self, ui: &mut Ui) {
        let panel = &mut self.panel;
        panel.header(ui, "New discs (drag on empty space)");
        let biggest = 0.45 * self.world.size.min_element();
        if let Some(r) = panel.slider(
            ui,
            "new_radius",
            self.new_disc.radius,
            NEW_RADIUS,
            |v| round_significant(v, 2),
            |v| format!("radius {v:.2} m"),
        ) {
            self.new_disc.radius = r.min(biggest);
        }
        if let Some(m) = panel.slider(
            ui,
            "new_mass",
            self.new_disc.mass,
            NEW_MASS,
            |v| round_significant(v, 2),
            |v| format!("mass {} kg", field_text(v)),
        ) {
            self.new_disc.mass = m;
        }
    }

    pub(super) fn overlay_section(&mut self, ui: &mut Ui, actions: &mut Vec<Action>) {
        self.panel.header(ui, "Overlays");
        let o = &mut self.overlays;
        checkbox(ui, hash!(), "velocity arrows", &mut o.velocity);
        checkbox(ui, hash!(), "momentum arrows", &mut o.momentum);
        checkbox(ui, hash!(), "totals (HUD)", &mut o.hud);
        let l = &mut self.lesson;
        checkbox(ui, hash!(), "totals plot (T)", &mut l.totals);
        checkbox(ui, hash!(), "centre of mass (O)", &mut l.center_of_mass);
        checkbox(ui, hash!(), "p diagram (D)", &mut l.diagram);
        checkbox(ui, hash!(), "ledger (U)", &mut l.ledger);
        checkbox(ui, hash!(), "histogram (F4)", &mut l.histogram);
        checkbox(ui, hash!(), "trails (A)", &mut self.trails.on);
        let o = &mut self.overlays;
        const SCOPES: [ReadoutScope; 3] =
            [ReadoutScope::Off, ReadoutScope::Selected, ReadoutScope::All];
        let labels = ["off", "selected", "all"].map(String::from);
        let index = SCOPES.iter().position(|&s| s == o.readouts).unwrap_or(0);
        if let Some(k) = combo(ui, hash!(), "readouts", &labels, index) {
            o.readouts = SCOPES[k];
        }
        let r = self.panel.row(ui, ROW + 2.0);
        let at = Rect::new(r.x, r.y, 240.0, r.h);
        if self
            .panel
            .button(ui, "com-frame", at, "Centre-of-mass frame (Z)")
        {
            actions.push(Action::CenterOfMassFrame);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use impulse::method::Setting;

    #[test]
    fn sliders_round_and_gravity_sticks_to_earth() {
        assert_eq!(round_to_step(0.456, 0.01), 0.46);
        assert_eq!(round_significant(0.04137, 2), 0.041);
        assert_eq!(round_significant(1234.0, 2), 1200.0);
        assert_eq!(round_significant(0.0, 2), 0.0);
        assert_eq!(snap_gravity(9.7), EARTH_GRAVITY);
        assert_eq!(snap_gravity(9.9), EARTH_GRAVITY);
        assert!((snap_gravity(3.04) - 3.0).abs() < 1e-12);
        assert_eq!(snap_gravity(0.02), 0.0, "the left end switches gravity off");
    }

    #[test]
    fn combo_lists_show_values_that_are_not_among_the_choices() {
        assert_eq!(
            choices(&SUBSTEPS, Setting::Fixed(4)),
            (
                ["auto", "1", "2", "4", "8", "16"]
                    .map(String::from)
                    .to_vec(),
                3
            )
        );
        let (labels, index) = choices(&SUBSTEPS, Setting::Fixed(3));
        assert_eq!((labels.len(), index, labels[index].as_str()), (7, 6, "3"));
        assert_eq!(choices(&METHODS, Setting::Auto).1, 0);
        assert_eq!(choices(&BROAD_PHASES, BROAD_PHASES[4]).1, 4);
    }
}
