//! A disc: position, velocity, spin, mass, radius and display colour (SI
//! units).

use glam::DVec2;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// A solid uniform disc (moment of inertia ½·m·r²). Units: metres, metres
/// per second, radians, kilograms.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Particle {
    /// Centre, in world coordinates (y up).
    pub pos: DVec2,
    /// Velocity.
    pub vel: DVec2,
    /// Mass (> 0).
    pub mass: f64,
    /// Radius (> 0).
    pub radius: f64,
    /// Display colour; the physics ignores it.
    pub color: Color,
    /// Angular velocity ω (rad/s), counter-clockwise positive. Only rough
    /// contacts change it (see [`crate::rough`]).
    #[serde(default)]
    pub spin: f64,
    /// How far the disc has turned (rad, counter-clockwise): drawn as a
    /// radius line; the physics never reads it.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub angle: f64,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

impl Particle {
    /// A disc at `pos` moving at `vel`.
    pub fn new(pos: DVec2, vel: DVec2, mass: f64, radius: f64, color: Color) -> Self {
        Self {
            pos,
            vel,
            mass,
            radius,
            color,
            spin: 0.0,
            angle: 0.0,
        }
    }

    /// Moment of inertia about the centre, ½·m·r² (kg·m²).
    pub fn moment_of_inertia(&self) -> f64 {
        0.5 * self.mass * self.radius * self.radius
    }

    /// Rotational kinetic energy ½·I·ω².
    pub fn rotational_energy(&self) -> f64 {
        0.5 * self.moment_of_inertia() * self.spin * self.spin
    }

    /// Angular momentum about the origin: orbital m·(x × v) plus spin I·ω
    /// (counter-clockwise positive).
    pub fn angular_momentum(&self) -> f64 {
        self.mass * (self.pos.x * self.vel.y - self.pos.y * self.vel.x)
            + self.moment_of_inertia() * self.spin
    }

    /// Momentum m·v.
    pub fn momentum(&self) -> DVec2 {
        self.vel * self.mass
    }

    /// Kinetic energy ½·m·|v|².
    pub fn kinetic_energy(&self) -> f64 {
        0.5 * self.mass * self.vel.length_squared()
    }

    /// Whether a world point lies on the disc (edge included).
    pub fn contains(&self, point: DVec2) -> bool {
        self.pos.distance_squared(point) <= self.radius * self.radius
    }
}

/// An sRGB colour, written `"#rrggbb"` in scene files.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub struct Color {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
}

impl Color {
    /// A colour from its components.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Self {
        Self { r, g, b }
    }

    /// The `i`-th colour of a palette that stays distinguishable on a projector
    /// and for the common forms of colour blindness (Okabe–Ito).
    pub fn palette(i: usize) -> Self {
        const OKABE_ITO: [Color; 7] = [
            Color::rgb(230, 159, 0),
            Color::rgb(86, 180, 233),
            Color::rgb(0, 158, 115),
            Color::rgb(240, 228, 66),
            Color::rgb(0, 114, 178),
            Color::rgb(213, 94, 0),
            Color::rgb(204, 121, 167),
        ];
        OKABE_ITO[i % OKABE_ITO.len()]
    }
}

impl fmt::Display for Color {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{:02x}{:02x}{:02x}", self.r, self.g, self.b)
    }
}

impl FromStr for Color {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let hex = s
            .strip_prefix('#')
            .filter(|h| h.len() == 6 && h.is_ascii())
            .ok_or_else(|| format!("colour {s:?} is not of the form \"#rrggbb\""))?;
        let channel = |i: usize| {
            u8::from_str_radix(&hex[i..i + 2], 16)
                .map_err(|_| format!("colour {s:?} has a non-hexadecimal digit"))
        };
        Ok(Color::rgb(channel(0)?, channel(2)?, channel(4)?))
    }
}

impl TryFrom<String> for Color {
    type Error = String;
    fn try_from(s: String) -> Result<Self, Self::Error> {
        s.parse()
    }
}

impl From<Color> for String {
    fn from(c: Color) -> String {
        c.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_round_trips_through_hex() {
        let c = Color::rgb(1, 171, 255);
        assert_eq!(c.to_string(), "#01abff");
        assert_eq!("#01abff".parse::<Color>(), Ok(c));
    }

    #[test]
    fn bad_colours_are_refused_with_a_reason() {
        for bad in ["01abff", "#01abf", "#01abfg", "#ééé", ""] {
            let err = bad.parse::<Color>().unwrap_err();
            assert!(err.contains("colour"), "{bad}: {err}");
        }
    }
}
