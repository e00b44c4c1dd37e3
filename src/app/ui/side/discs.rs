//! *New discs* (radius and mass of the next launch, or radius from mass)
//! and *Selected disc* (its mass, radius, position, and velocity as v_x and
//! v_y and as speed and direction, in text fields that follow the disc
//! until typed in; Apply or Enter sends the edit).

use super::super::widgets::{command_button, select_all_on_focus, show_note, slider, Reading};
use super::Cx;
use crate::app::lang::tr;
use crate::app::model::bindings::tooltip;
use crate::app::model::command::{Dir, EditPlace};
use crate::app::model::edit::{polar_velocity, FIELDS};
use crate::app::model::gesture::radius_for_mass;
use crate::app::model::Command;
use crate::app::numbers::{field, field_reading, with_unit};
use crate::app::ui::tip::Tip;
use egui::Ui;

/// The selected disc's text fields.
#[derive(Default)]
pub struct DiscFields {
    /// Which disc they were filled from.
    disc: Option<usize>,
    /// What the fields hold.
    text: [String; 8],
    /// What the disc had when a field was last filled: a field whose text
    /// differs has been edited and stops following the disc.
    shown: [String; 8],
    /// An edit was sent: once the model has answered, fields that it
    /// took follow the disc again.
    sent: bool,
    /// Why the speed and direction typed could not be read.
    polar_error: Option<String>,
    /// The fields the model refused in the last edit, with their text
    /// then: until typed in again, each has its name in red (in amber,
    /// with "not applied yet", it read as if Enter had not been pressed,
    /// and a later edit of another field was refused for it without a
    /// sign why).
    refused: Option<([String; 8], [bool; 8])>,
    /// The edit sent was sent with Enter, while it is answered.
    sent_with_enter: bool,
    /// The field to give the keyboard back to: after Enter, a refused
    /// field kept it (egui's field let it go, and a keyboard user had to
    /// Tab back to mend the number).
    refocus: Option<usize>,
}

/// Each field's name (a message of `window.ftl`): the model's six (mass,
/// radius, v_x, v_y, x, y), then the speed and the direction, which are
/// sent as v_x and v_y.
const FIELD_NAMES: [&str; 8] = [
    FIELDS[0],
    FIELDS[1],
    FIELDS[2],
    FIELDS[3],
    FIELDS[4],
    FIELDS[5],
    "quantity-speed",
    "quantity-direction",
];
/// Each field's unit, after its name.
const FIELD_UNITS: [&str; 8] = ["kg", "m", "m/s", "m/s", "m", "m", "m/s", "°"];
const FIELD_KEYS: [&str; 8] = [
    "disc_mass",
    "disc_radius",
    "disc_vx",
    "disc_vy",
    "disc_x",
    "disc_y",
    "disc_speed",
    "disc_direction",
];
/// A field's width (points): a number of seven characters whole.
const FIELD_WIDTH: f32 = 80.0;
/// The fields top to bottom: where it is, then how it moves.
const SHOWN_IN_ORDER: [usize; 8] = [0, 1, 4, 5, 2, 3, 6, 7];
/// The direction's field (its label explains the angle).
const DIRECTION: usize = 7;

/// Radius and mass of the next disc launched.
pub fn new_discs(ui: &mut Ui, cx: &mut Cx) {
    ui.label(tr!("new-discs-line"));
    let follows = cx.model.new_discs.size_follows_mass;
    let mut on = follows;
    let r = ui
        .checkbox(&mut on, tr!("size-follows-mass"))
        .tip(tr!("size-follows-mass-hover"));
    cx.note("size_follows_mass", &r);
    if r.changed() {
        cx.send(Command::SizeFollowsMass(on));
    }
    let biggest = cx.model.biggest_radius();
    let disc = cx.model.new_discs.disc;
    if follows {
        let r = radius_for_mass(disc.mass).min(biggest);
        ui.label(tr!("radius-from-mass", radius = with_unit(r, 2, "m")));
    } else {
        let mut r = disc.radius;
        let (track, changed) = slider(
            ui,
            &tr!("radius-label"),
            &mut r,
            0.05..=2.0f64.min(biggest).max(0.06),
            Reading::new(2, " m").log(),
        );
        if changed {
            cx.send(Command::SetNewRadius(r));
        }
        let tip = tooltip(&Command::StepNewRadius(Dir::Up));
        cx.note("new_radius", &track.tip(tip));
    }
    let mut m = disc.mass;
    let (track, changed) = slider(
        ui,
        &tr!("mass-label"),
        &mut m,
        0.01..=100.0,
        Reading::new(2, " kg").log(),
    );
    if changed {
        cx.send(Command::SetNewMass(m));
    }
    // Why the slider stops at 100 kg while the table takes any mass.
    let tip = format!(
        "{}\n{}",
        tr!("new-mass-hover"),
        tooltip(&Command::StepNewMass(Dir::Up))
    );
    cx.note("new_mass", &track.tip(tip));
}

impl DiscFields {
    /// The selected disc's fields, Apply and Delete.
    pub fn ui(&mut self, ui: &mut Ui, cx: &mut Cx) {
        let Some(i) = cx.model.selected_disc() else {
            self.disc = None;
            ui.label(tr!("selected-none"));
            return;
        };
        let p = cx.model.world.particles[i];
        if self.disc != Some(i) {
            *self = DiscFields {
                disc: Some(i),
                ..DiscFields::default()
            };
        }
        // The model took the last edit: every field follows the disc again.
        if std::mem::take(&mut self.sent) {
            let entered = std::mem::take(&mut self.sent_with_enter);
            match cx.model.messages.fields.as_ref().map(|n| n.error) {
                Some(false) => {
                    self.shown = self.text.clone();
                    self.refused = None;
                }
                Some(true) => {
                    let culprits = self.culprits(cx);
                    self.refused = Some((self.text.clone(), culprits));
                    self.refocus = SHOWN_IN_ORDER
                        .into_iter()
                        .find(|&k| culprits[k])
                        .filter(|_| entered);
                }
                None => {}
            }
        }
        let refused = self.refused_fields();
        // Untouched fields follow the disc as it moves.
        let direction = p.vel.y.atan2(p.vel.x).to_degrees();
        // The mass and the radius as typed, every digit (a mass of
        // 0.0125 kg); what moves to three decimals, whole in the field.
        let live = [
            field(p.mass),
            field(p.radius),
            field_reading(p.vel.x),
            field_reading(p.vel.y),
            field_reading(p.pos.x),
            field_reading(p.pos.y),
            field_reading(p.vel.length()),
            field_reading(direction),
        ];
        for (k, value) in live.into_iter().enumerate() {
            if self.text[k] == self.shown[k] {
                self.text[k] = value.clone();
                self.shown[k] = value;
            }
        }
        let mut enter = false;
        egui::Grid::new("selected_fields")
            .num_columns(2)
            .show(ui, |ui| {
                for k in SHOWN_IN_ORDER {
                    // Wide enough for "13,457" and "−84,29" whole: the grid
                    // had squeezed the fields to four characters, and a
                    // teacher read 13,4 for 13,457.
                    let field = egui::TextEdit::singleline(&mut self.text[k])
                        .desired_width(FIELD_WIDTH)
                        .min_size(egui::vec2(FIELD_WIDTH, 0.0));
                    let r = ui.add(field);
                    if self.refocus == Some(k) {
                        self.refocus = None;
                        r.request_focus();
                    }
                    select_all_on_focus(ui, &r, &self.text[k]);
                    cx.marks.text_field(&r);
                    cx.note(FIELD_KEYS[k], &r);
                    if r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                        enter = true;
                    }
                    // Esc takes back what was typed; and a refused number
                    // goes once the clock runs: "1e30" stayed in red
                    // beside a disc moving at 2 m/s, and a student read it.
                    let esc = r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Escape));
                    let running = !cx.model.clock.paused;
                    if esc || (running && refused[k] && !r.has_focus()) {
                        self.text[k] = self.shown[k].clone();
                    }
                    let name = crate::app::lang::text(FIELD_NAMES[k], &[]);
                    let mut label = egui::RichText::new(format!("{name} ({})", FIELD_UNITS[k]));
                    // Typed and not yet applied: its name in amber;
                    // refused, in red.
                    if refused[k] {
                        label = label.color(ui.visuals().error_fg_color);
                    } else if self.text[k] != self.shown[k] {
                        label = label.color(ui.visuals().warn_fg_color);
                    }
                    // Wrapped where the dock is narrow: "speed |v| (m/s)"
                    // ran past its edge at text size 1.5.
                    let label = ui.add(egui::Label::new(label).wrap());
                    cx.marks
                        .note(format!("{}_label", FIELD_KEYS[k]), label.rect);
                    if refused[k] {
                        cx.marks
                            .note(format!("{}_refused", FIELD_KEYS[k]), label.rect);
                    }
                    if k == DIRECTION {
                        label.tip(tr!("direction-hover"));
                    }
                    ui.end_row();
                }
            });
        // Nothing typed takes effect before Enter or Apply (a teacher who
        // moved on with Tab saw the disc unchanged and nothing saying why).
        let pending = (0..FIELD_NAMES.len()).any(|k| self.text[k] != self.shown[k] && !refused[k]);
        if pending && !self.sent {
            let r = ui
                .label(egui::RichText::new(tr!("edit-pending")).color(ui.visuals().warn_fg_color));
            cx.note("edit_pending", &r);
        }
        ui.horizontal(|ui| {
            let r = ui.button(tr!("apply")).tip(tr!("apply-hover"));
            cx.note("apply", &r);
            if r.clicked() || enter {
                self.sent_with_enter = enter && !r.clicked();
                self.apply(cx, i);
            }
            command_button(ui, cx, Command::DeleteSelected, Some("delete"));
        });
        if let Some(error) = &self.polar_error {
            show_note(ui, &crate::app::model::Note::error(error.clone()));
        } else if let Some(note) = &cx.model.messages.fields {
            show_note(ui, note);
        }
    }

    /// Which of the fields sent the model refused, decided once as the
    /// refusal comes: those that cannot be taken on their own, else (a disc
    /// that would overlap, a velocity too fast as a whole) every field sent.
    fn culprits(&self, cx: &Cx) -> [bool; 8] {
        let sent: [bool; 8] = std::array::from_fn(|k| self.text[k] != self.shown[k]);
        let biggest = cx.model.biggest_radius();
        let alone_refused: [bool; 8] = std::array::from_fn(|k| {
            let mut one = [None; 6];
            let Some(slot) = one.get_mut(k) else {
                return false; // speed and direction: said under the fields
            };
            *slot = Some(self.text[k].as_str());
            sent[k] && crate::app::model::edit::parse_disc_edit(one, biggest).is_err()
        });
        match alone_refused.contains(&true) {
            true => alone_refused,
            false => sent,
        }
    }

    /// The refused fields still as they were when refused.
    fn refused_fields(&self) -> [bool; 8] {
        let Some((was, culprits)) = &self.refused else {
            return [false; 8];
        };
        std::array::from_fn(|k| culprits[k] && self.text[k] == was[k])
    }

    /// Sends the edited fields as an edit of disc `i`; the model reads
    /// them and answers under the fields.
    /// A speed or direction typed is sent as v_x and v_y (to a
    /// picometre per second, so that 90° has no v_x of 6·10⁻¹⁷); one that
    /// cannot be read is said under the fields, and nothing is sent.
    fn apply(&mut self, cx: &mut Cx, i: usize) {
        let edited = |k: usize| (self.text[k] != self.shown[k]).then(|| self.text[k].clone());
        let mut text: [Option<String>; 6] = std::array::from_fn(edited);
        let (speed, direction) = (edited(6), edited(DIRECTION));
        let current = cx.model.world.particles[i].vel;
        let mut from = EditPlace::Fields;
        match polar_velocity(speed.as_deref(), direction.as_deref(), current) {
            Ok(Some(v)) => {
                from = EditPlace::Polar;
                // (+ 0.0 writes −0, a rounded −6·10⁻¹⁷, as 0.)
                let v = (v * 1e12).round() / 1e12;
                text[2] = Some(format!("{}", v.x + 0.0));
                text[3] = Some(format!("{}", v.y + 0.0));
            }
            Ok(None) => {}
            Err(error) => {
                self.polar_error = Some(error);
                // The one typed in of the two (the speed if both were).
                let typed = if speed.is_some() { 6 } else { DIRECTION };
                self.refocus = std::mem::take(&mut self.sent_with_enter).then_some(typed);
                return;
            }
        }
        self.polar_error = None;
        self.sent = true;
        cx.send(Command::EditDisc {
            disc: i,
            text,
            from,
        });
    }
}
