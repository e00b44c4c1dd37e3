//! An edit of a disc typed in a field or a table cell: read, checked, and
//! applied, or refused with one short line that says why (the disc stays as
//! it was).

use super::command::EditPlace;
use super::{Note, Sandbox};
use crate::app::lang::{text as words, tr};
use crate::app::numbers::{disc_number, field, plain, Unread};
use glam::DVec2;
use impulse::scene::limits;
use impulse::Particle;

/// The selected disc's editable quantities, in the order an edit carries
/// them (their names are messages of `window.ftl`).
pub const FIELDS: [&str; 6] = [
    "quantity-mass",
    "quantity-radius",
    "quantity-vx",
    "quantity-vy",
    "quantity-x",
    "quantity-y",
];

/// The units of [`FIELDS`], which a typed value may carry ("3 kg").
const UNITS: [&str; 6] = ["kg", "m", "m/s", "m/s", "m", "m"];

/// An edit of a disc's quantities; `None` leaves one as it is.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DiscEdit {
    /// Mass (kg).
    pub mass: Option<f64>,
    /// Radius (m).
    pub radius: Option<f64>,
    /// Velocity, x (m/s).
    pub vx: Option<f64>,
    /// Velocity, y (m/s).
    pub vy: Option<f64>,
    /// Position, x (m).
    pub x: Option<f64>,
    /// Position, y (m).
    pub y: Option<f64>,
}

impl DiscEdit {
    /// Whether nothing would change.
    pub fn is_empty(&self) -> bool {
        *self == DiscEdit::default()
    }

    /// Writes the new values into `p`.
    pub fn apply(&self, p: &mut Particle) {
        p.mass = self.mass.unwrap_or(p.mass);
        p.radius = self.radius.unwrap_or(p.radius);
        p.vel.x = self.vx.unwrap_or(p.vel.x);
        p.vel.y = self.vy.unwrap_or(p.vel.y);
        p.pos.x = self.x.unwrap_or(p.pos.x);
        p.pos.y = self.y.unwrap_or(p.pos.y);
    }

    /// Whether it moves the disc.
    pub fn moves(&self) -> bool {
        self.x.is_some() || self.y.is_some()
    }
}

/// `text` read as a number for the field called `name` in `unit`, which
/// it may carry ("3 kg", "30°"), or the line that says why it was not:
/// "1,000" in English is asked about, not taken as 1.
fn typed_number(text: &str, name: &str, unit: &str) -> Result<f64, String> {
    let number = text.strip_suffix(unit).unwrap_or(text);
    crate::app::numbers::read(number).map_err(|unread| match unread {
        Unread::NotANumber => tr!("edit-not-a-number", name = name, text = text),
        Unread::Ambiguous { decimal, grouped } => tr!(
            "edit-ambiguous-number",
            name = name,
            text = text,
            decimal = field(decimal),
            grouped = field(grouped)
        ),
    })
}

/// Reads the fields the user changed (`None`: untouched, in [`FIELDS`]
/// order). Every value must be a finite number; mass and radius positive,
/// the radius at most `max_radius`, each in a scene file's range (so that a
/// saved scene opens again). The error is one short line.
pub fn parse_disc_edit(changed: [Option<&str>; 6], max_radius: f64) -> Result<DiscEdit, String> {
    let mut values = [None; 6];
    for (k, text) in changed.into_iter().enumerate() {
        let Some(text) = text else { continue };
        let name = words(FIELDS[k], &[]);
        let text = text.trim();
        if text.is_empty() {
            return Err(tr!("edit-type-a-number", name = name));
        }
        let v = typed_number(text, &name, UNITS[k])?;
        if !v.is_finite() {
            return Err(tr!("edit-not-finite", name = name));
        }
        if k < 2 && v <= 0.0 {
            return Err(tr!("edit-not-positive", name = name));
        }
        if k == 1 && v > max_radius {
            return Err(tr!("edit-radius-too-large", radius = field(max_radius)));
        }
        // A scene file's ranges: what is saved opens again.
        let ([lo, hi], [least, most]) = match k {
            0 => (limits::MASS, ["10⁻¹² kg", "10¹² kg"]),
            1 => (limits::LENGTH, ["10⁻⁹ m", "10⁹ m"]),
            2 | 3 => ([-limits::SPEED, limits::SPEED], ["−10⁸ m/s", "10⁸ m/s"]),
            _ => ([-limits::POSITION, limits::POSITION], ["−10¹² m", "10¹² m"]),
        };
        if !(lo..=hi).contains(&v) {
            return Err(tr!("edit-out-of-range", name = name, lo = least, hi = most));
        }
        values[k] = Some(v);
    }
    Ok(DiscEdit {
        mass: values[0],
        radius: values[1],
        vx: values[2],
        vy: values[3],
        x: values[4],
        y: values[5],
    })
}

/// A velocity from a speed and a direction typed into the *Selected disc*
/// fields (`None`: untouched), the other taken from `current`: the
/// direction in degrees counter-clockwise from the right (90 is up). A
/// student thinks "3 m/s at 30°" more than "v_x 2.598, v_y 1.5".
/// `Ok(None)` where neither was typed.
pub fn polar_velocity(
    speed: Option<&str>,
    direction: Option<&str>,
    current: DVec2,
) -> Result<Option<DVec2>, String> {
    if speed.is_none() && direction.is_none() {
        return Ok(None);
    }
    let read = |text: &str, id: &str, unit: &str| -> Result<f64, String> {
        let name = words(id, &[]);
        let text = text.trim();
        if text.is_empty() {
            return Err(tr!("edit-type-a-number", name = name));
        }
        let v = typed_number(text, &name, unit)?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(tr!("edit-not-finite", name = name))
        }
    };
    let speed = match speed {
        Some(text) => read(text, "quantity-speed", "m/s")?,
        None => current.length(),
    };
    if speed < 0.0 {
        return Err(tr!("edit-speed-negative"));
    }
    let degrees = match direction {
        Some(text) => read(text, "quantity-direction", "°")?,
        None => current.y.atan2(current.x).to_degrees(),
    };
    let (sin, cos) = degrees.to_radians().sin_cos();
    Ok(Some(DVec2::new(speed * cos, speed * sin)))
}

impl Sandbox {
    /// Applies an edit typed for `disc`, or keeps it and says what is wrong,
    /// where it was typed.
    pub(super) fn edit_disc(&mut self, disc: usize, text: &[Option<String>; 6], from: EditPlace) {
        if disc >= self.world.particles.len() {
            return;
        }
        let changed: [Option<&str>; 6] = std::array::from_fn(|k| text[k].as_deref());
        let max_radius = match from {
            EditPlace::Fields | EditPlace::Polar => self.biggest_radius(),
            EditPlace::Table => f64::INFINITY,
        };
        // What a scene file asks of the velocity as a whole.
        let velocity_kept = |e: DiscEdit| {
            let mut p = self.world.particles[disc];
            e.apply(&mut p);
            // The component across a one-dimensional world's line.
            let across = self.world.laws.constrain.map(|a| 1 - a.index());
            if p.vel.length() > limits::SPEED {
                Err(tr!("edit-too-fast"))
            } else if let Some(c) = across.filter(|&c| p.vel[c] != 0.0) {
                let name = words(FIELDS[2 + c], &[]);
                Err(tr!("edit-across-the-line", name = name))
            } else {
                Ok(e)
            }
        };
        let edit = parse_disc_edit(changed, max_radius)
            .and_then(velocity_kept)
            .and_then(|e| self.sized_edit(disc, e))
            .and_then(|e| self.placed_edit(disc, e));
        let note = match edit {
            Ok(edit) if edit.is_empty() => Note::ok(tr!("edit-nothing-changed")),
            Ok(edit) => {
                let p = &mut self.world.particles[disc];
                let before = *p;
                edit.apply(p);
                if *p != before {
                    self.record.totals.restart(&self.world);
                }
                let mut what = vec![
                    (edit.mass, FIELDS[0], " kg"),
                    (edit.radius, FIELDS[1], " m"),
                    (edit.vx, FIELDS[2], " m/s"),
                    (edit.vy, FIELDS[3], " m/s"),
                    (edit.x, FIELDS[4], " m"),
                    (edit.y, FIELDS[5], " m"),
                ];
                // As typed: "speed = 2.5 m/s; direction = 30°", not the
                // components it was sent as (v_x = 2.165064 m/s).
                if from == EditPlace::Polar {
                    let v = self.world.particles[disc].vel;
                    what.splice(
                        2..4,
                        [
                            (Some(v.length()), "quantity-speed", " m/s"),
                            (Some(v.y.atan2(v.x).to_degrees()), "quantity-direction", "°"),
                        ],
                    );
                }
                let said: Vec<String> = what
                    .iter()
                    .filter_map(|(v, name, unit)| {
                        v.map(|v| format!("{} = {}{unit}", words(name, &[]), field(v)))
                    })
                    .collect();
                let values = tr!(
                    "edit-applied-table",
                    disc = disc_number(disc),
                    values = said.join("; ")
                );
                // In the strip too, over what it said of the disc before
                // ("Disc 1 of 2 selected: 1.000 kg" beside a mass of 2).
                self.toast(values.clone());
                Note::ok(match from {
                    EditPlace::Fields | EditPlace::Polar => {
                        tr!("edit-applied", disc = disc_number(disc))
                    }
                    EditPlace::Table => values,
                })
            }
            Err(e) => Note::error(match from {
                EditPlace::Fields | EditPlace::Polar => e,
                EditPlace::Table => tr!("edit-refused-table", disc = disc_number(disc), error = e),
            }),
        };
        match from {
            // A refusal in the strip too: under the fields it was out of
            // sight in a projector's drawer, where the strip only said how
            // to give the keys back.
            EditPlace::Fields | EditPlace::Polar if note.error => {
                self.toast(note.text.clone());
                self.messages.fields = Some(note);
            }
            EditPlace::Fields | EditPlace::Polar => self.messages.fields = Some(note),
            // Also in the strip, and said: in a projector's short tab the
            // line above the table would take the row edited out of sight.
            EditPlace::Table => {
                self.toast(note.text.clone());
                self.messages.table = Some(note);
            }
        }
    }

    /// A disc moved by its typed position lands where it has room: inside
    /// the walls, on a one-dimensional world's line, clear of every other
    /// disc (with the edit's own radius); so is a disc made larger where
    /// it is. Otherwise refused, saying which.
    /// The keyboard's way to place a disc (a drag is the mouse's).
    pub fn placed_edit(&self, i: usize, edit: DiscEdit) -> Result<DiscEdit, String> {
        let w = &self.world;
        let Some(mut p) = w.particles.get(i).copied() else {
            return Ok(edit);
        };
        // A larger radius is placed too (a disc grown into its neighbour
        // had been taken; the step then shoved the two apart).
        let grows = edit.radius.is_some_and(|r| r > p.radius);
        if !edit.moves() && !grows {
            return Ok(edit);
        }
        let before = p.pos;
        edit.apply(&mut p);
        let at = crate::app::numbers::vector(p.pos, 3, "m");
        let radius = field(p.radius);
        if let Some(axis) = w.laws.constrain {
            let c = 1 - axis.index();
            if p.pos[c] != before[c] {
                let name = words(FIELDS[4 + c], &[]);
                return Err(tr!(
                    "edit-position-off-the-line",
                    name = name,
                    value = plain(before[c], 3)
                ));
            }
        }
        let l = &w.laws;
        if l.boundary == impulse::Boundary::Box
            && !l.boundary.admits(l.walls, l.size, p.pos, p.radius)
        {
            return Err(match edit.moves() {
                true => tr!("edit-position-crosses-wall", at = at),
                false => tr!("edit-radius-crosses-wall", radius = radius),
            });
        }
        let overlapped = w.particles.iter().enumerate().find(|&(j, q)| {
            j != i && l.boundary.separation(q.pos, p.pos, l.size).length() < p.radius + q.radius
        });
        if let Some((j, _)) = overlapped {
            return Err(match edit.moves() {
                true => tr!("edit-position-overlaps", at = at, disc = disc_number(j)),
                false => tr!(
                    "edit-radius-overlaps",
                    radius = radius,
                    disc = disc_number(j)
                ),
            });
        }
        Ok(edit)
    }

    /// Deletes the selected disc (its button and the Delete key).
    pub(super) fn delete_selected(&mut self) {
        if let Some(i) = self.selected.take() {
            if i < self.world.particles.len() {
                self.world.particles.remove(i);
                self.pointer.on_removed(i);
            }
        }
    }

    /// With "size follows mass", a new mass brings its radius, refused if
    /// the disc would then overlap another or cross a wall; otherwise the
    /// edit as it is.
    pub fn sized_edit(&self, i: usize, mut edit: DiscEdit) -> Result<DiscEdit, String> {
        let (Some(m), true) = (edit.mass, self.new_discs.size_follows_mass) else {
            return Ok(edit);
        };
        let r = super::gesture::radius_for_mass(m);
        let w = &self.world;
        let Some(p) = w.particles.get(i) else {
            return Ok(edit);
        };
        let size = plain(r, 2);
        let overlapped = w.particles.iter().enumerate().find(|&(j, q)| {
            j != i
                && w.laws
                    .boundary
                    .separation(q.pos, p.pos, w.laws.size)
                    .length()
                    < r + q.radius
        });
        if let Some((j, _)) = overlapped {
            return Err(tr!(
                "edit-mass-overlaps",
                mass = plain(m, 3),
                size = size.as_str(),
                disc = disc_number(j)
            ));
        }
        if !w.laws.boundary.admits(w.laws.walls, w.laws.size, p.pos, r) {
            return Err(tr!(
                "edit-mass-crosses-wall",
                mass = plain(m, 3),
                size = size
            ));
        }
        edit.radius = Some(r);
        Ok(edit)
    }
}

#[cfg(test)]
mod tests;
