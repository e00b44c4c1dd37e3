//! The *Collisions* section's laws: restitution, roughness and friction,
//! gravity, the edges and the time scale.

use super::controls::{setting_combo, slider, snap_gravity};
use crate::app::clock::TIME_SCALES;
use crate::app::App;
use egui::{ComboBox, Ui};
use glam::DVec2;
use impulse::laws::Laws;
use impulse::Boundary;

impl App {
    /// A slider for the coefficient `field` of the laws, in `range`, kept
    /// to hundredths; `name` is its widget's name in the state dump.
    fn coefficient(
        &mut self,
        ui: &mut Ui,
        (label, name, hover): (&str, &str, &str),
        range: std::ops::RangeInclusive<f64>,
        field: fn(&mut Laws) -> &mut f64,
    ) {
        let mut value = *field(&mut self.world.laws);
        let (r, changed) = slider(ui, label, &mut value, range, false, 2, "");
        if changed {
            *field(&mut self.world.laws) = (value * 100.0).round() / 100.0;
        }
        self.widget(ui, name, &r.on_hover_text(hover));
    }

    pub(super) fn laws_section(&mut self, ui: &mut Ui) {
        let restitution = "Restitution e between discs (1: elastic, 0: they stick)";
        self.coefficient(
            ui,
            (restitution, "restitution", "E / Shift+E: ±0.1"),
            0.0..=1.0,
            |l| &mut l.restitution,
        );
        self.coefficient(
            ui,
            (
                "Restitution e at the walls",
                "wall_restitution",
                "W / Shift+W: ±0.1",
            ),
            0.0..=1.0,
            |l| &mut l.wall_restitution,
        );
        self.roughness_sliders(ui);
        // The slider shows |g| and sets it pointing down; a scene's sideways
        // gravity is only replaced once the slider is moved.
        let w = &mut self.world;
        let mut g = w.laws.gravity.length();
        let (r, changed) = slider(
            ui,
            "Gravity, pointing down",
            &mut g,
            0.0..=20.0,
            false,
            2,
            " m/s²",
        );
        if changed {
            w.laws.gravity = DVec2::new(0.0, -snap_gravity(g));
        }
        self.widget(ui, "gravity", &r.on_hover_text("G: 9.81 m/s² down, or off"));
        let w = &mut self.world;
        if let Some(b) = setting_combo(
            ui,
            "edges",
            &Boundary::ALL.map(Boundary::name),
            w.laws.boundary.name(),
        ) {
            if let Some(&k) = Boundary::ALL.iter().find(|k| k.name() == b) {
                w.laws.boundary = k;
            }
        }
        let scales = TIME_SCALES.map(|s| format!("×{s}"));
        let index = self.clock.time_scale_index();
        ComboBox::from_label("time scale")
            .selected_text(scales[index].clone())
            .show_ui(ui, |ui| {
                for (k, label) in scales.iter().enumerate() {
                    if ui.selectable_label(k == index, label).clicked() {
                        self.clock.set_time_scale_index(k);
                    }
                }
            });
    }

    /// Roughness β between discs and at the walls, and friction μ (off:
    /// no limit), beside restitution; changes are undone like restitution's.
    fn roughness_sliders(&mut self, ui: &mut Ui) {
        const ROUGH: &str = "How the touching edges grip in a collision: −1 smooth \
            (no spin given or taken), 0 their slipping stops, 1 perfectly rough (the \
            slipping reverses and no energy is lost)";
        let between = "Roughness β between discs (−1 smooth … 1 rough)";
        self.coefficient(
            ui,
            (between, "tangential_restitution", ROUGH),
            -1.0..=1.0,
            |l| &mut l.tangential_restitution,
        );
        self.coefficient(
            ui,
            (
                "Roughness β at the walls",
                "wall_tangential_restitution",
                ROUGH,
            ),
            -1.0..=1.0,
            |l| &mut l.wall_tangential_restitution,
        );
        // μ is off (no limit) or a number: a tick turns it on at the
        // slider's value, which is kept while it is off.
        let w = &mut self.world;
        let mut on = w.laws.friction.is_some();
        let r = ui
            .checkbox(&mut on, "Friction μ limits the grip")
            .on_hover_text(
                "Coulomb friction: the sideways push at a contact is at most μ times the \
                 head-on push, so fast slipping is only slowed; it also makes discs \
                 lying on each other rub. Off: no limit.",
            );
        self.widget(ui, "friction_on", &r);
        if r.changed() {
            self.world.laws.friction = on.then_some(self.ui.friction);
        }
        let mut mu = self.world.laws.friction.unwrap_or(self.ui.friction);
        let (r, changed) = ui
            .add_enabled_ui(on, |ui| {
                slider(ui, "Friction μ", &mut mu, 0.0..=2.0, false, 2, "")
            })
            .inner;
        if changed && on {
            let mu = (mu * 100.0).round() / 100.0;
            self.ui.friction = mu;
            self.world.laws.friction = Some(mu);
        }
        self.widget(ui, "friction", &r);
    }
}
