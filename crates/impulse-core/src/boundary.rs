//! Boundaries, the last stage of a step: closed box, open space, or periodic.
//!
//! The box walls reflect a disc that has crossed them, scaled by the wall
//! restitution, and put it back inside. Moving a disc back inside changes its
//! height, so under gravity the wall also takes the potential energy that move
//! gains out of the disc's speed along that axis: a bounce never creates
//! energy. (A disc pushed into the floor while at rest has no speed to pay
//! with; lifting it back costs at most m·g·depth, and it ends at rest.)
//!
//! A box may leave sides open ([`Walls`]): a disc crosses an open side and
//! flies on, as in open space.

use crate::particle::Particle;
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// What happens at the edges of the world rectangle (0,0)–`size`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Boundary {
    /// Four walls; discs bounce off them.
    #[default]
    Box,
    /// No walls: discs fly away freely (total momentum is conserved).
    Open,
    /// A torus: a disc leaving one side re-enters on the other, and discs
    /// interact across the seam (total momentum is conserved).
    Periodic,
}

/// Which sides of a box have walls; the rest are open. All four by default.
///
/// In a scene file: `walls = ["left"]` (any of "left", "right", "bottom",
/// "top"; y is up, so "bottom" is the floor).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Walls {
    /// The side x = 0.
    pub left: bool,
    /// The side x = width.
    pub right: bool,
    /// The side y = 0 (the floor under gravity pointing down).
    pub bottom: bool,
    /// The side y = height.
    pub top: bool,
}

impl Default for Walls {
    fn default() -> Self {
        Walls::ALL
    }
}

impl Walls {
    /// All four sides closed.
    pub const ALL: Walls = Walls {
        left: true,
        right: true,
        bottom: true,
        top: true,
    };
    /// No walls.
    pub const NONE: Walls = Walls {
        left: false,
        right: false,
        bottom: false,
        top: false,
    };
    /// The side names, in the order of [`Walls::sides`].
    pub const NAMES: [&'static str; 4] = ["left", "right", "bottom", "top"];

    /// Whether all four sides have walls.
    pub fn all(self) -> bool {
        self == Walls::ALL
    }

    /// Whether the wall at the lower (`upper = false`) or upper end of an
    /// axis (0: x, 1: y) is there.
    pub fn at(self, axis: usize, upper: bool) -> bool {
        match (axis, upper) {
            (0, false) => self.left,
            (0, true) => self.right,
            (_, false) => self.bottom,
            (_, true) => self.top,
        }
    }

    /// The four flags as left, right, bottom, top.
    pub fn sides(self) -> [bool; 4] {
        [self.left, self.right, self.bottom, self.top]
    }

    /// The walls named in `names`; an error names an unknown side.
    pub fn from_names<S: AsRef<str>>(names: &[S]) -> Result<Walls, String> {
        let mut w = Walls::NONE;
        for name in names {
            match name.as_ref() {
                "left" => w.left = true,
                "right" => w.right = true,
                "bottom" => w.bottom = true,
                "top" => w.top = true,
                other => {
                    return Err(format!(
                        "{other:?} is not a side: use \"left\", \"right\", \"bottom\" or \"top\""
                    ))
                }
            }
        }
        Ok(w)
    }

    /// The names of the sides that have walls.
    pub fn names(self) -> Vec<&'static str> {
        Walls::NAMES
            .into_iter()
            .zip(self.sides())
            .filter_map(|(n, on)| on.then_some(n))
            .collect()
    }
}

impl Serialize for Walls {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.names().serialize(s)
    }
}

impl<'de> Deserialize<'de> for Walls {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let names = Vec::<String>::deserialize(d)?;
        Walls::from_names(&names).map_err(serde::de::Error::custom)
    }
}

/// A one-dimensional world: discs move along one axis only; the other
/// velocity component is held at zero in every method (`constrain = "x"`
/// in a scene's `[world]`: motion along x, as on a track).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Axis {
    /// Along x (the y velocity is locked at zero).
    X,
    /// Along y (the x velocity is locked at zero).
    Y,
}

impl Axis {
    /// The index of the axis discs move along (0: x, 1: y).
    pub fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
        }
    }

    /// The index of the locked axis.
    pub fn locked(self) -> usize {
        1 - self.index()
    }
}

impl Boundary {
    /// All variants, in the order the UI cycles through them.
    pub const ALL: [Boundary; 3] = [Boundary::Box, Boundary::Open, Boundary::Periodic];

    /// The lowercase name used in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Boundary::Box => "box",
            Boundary::Open => "open",
            Boundary::Periodic => "periodic",
        }
    }

    /// The vector from `a` to `b`; across the seam (minimum image) when periodic.
    pub fn separation(self, a: DVec2, b: DVec2, size: DVec2) -> DVec2 {
        let d = b - a;
        match self {
            Boundary::Periodic => DVec2::new(wrap(d.x, size.x), wrap(d.y, size.y)),
            Boundary::Box | Boundary::Open => d,
        }
    }

    /// Whether a disc of `radius` at `pos` lies where this boundary lets
    /// it be: inside every wall of a box (an open side lets it out).
    pub fn admits(self, walls: Walls, size: DVec2, pos: DVec2, radius: f64) -> bool {
        match self {
            Boundary::Box => (0..2).all(|axis| {
                (!walls.at(axis, false) || pos[axis] >= radius)
                    && (!walls.at(axis, true) || pos[axis] <= size[axis] - radius)
            }),
            Boundary::Periodic => pos.cmpge(DVec2::ZERO).all() && pos.cmplt(size).all(),
            Boundary::Open => true,
        }
    }

    /// Applies the boundary to every disc; a bounce faster than
    /// `impact_speed` (see [`crate::impact`]) is a hit, a slower one a
    /// resting contact.
    pub fn apply(
        self,
        particles: &mut [Particle],
        (size, walls): (DVec2, Walls),
        gravity: DVec2,
        (wall_restitution, rough): (f64, crate::rough::Tangential),
        impact_speed: f64,
    ) -> WallReport {
        match self {
            Boundary::Open => WallReport::default(),
            Boundary::Periodic => {
                for p in particles {
                    // Most discs are inside already; rem_euclid is a slow fmod.
                    let inside = p.pos.cmpge(DVec2::ZERO).all() && p.pos.cmplt(size).all();
                    if !inside {
                        p.pos = p.pos.rem_euclid(size);
                    }
                }
                WallReport::default()
            }
            Boundary::Box => {
                let (mut hits, mut resting) = (0, 0);
                let mut impulse = 0.0;
                for p in particles {
                    let before = p.vel;
                    let mut count = |bounced: bool, speed: f64| {
                        if bounced {
                            if crate::impact::is_impact(speed.abs(), impact_speed) {
                                hits += 1;
                            } else {
                                resting += 1;
                            }
                        }
                    };
                    // A rough wall turns the disc's slip along it into spin.
                    let rub = |p: &mut Particle, axis: usize, was: f64| {
                        let law = if crate::impact::is_impact(was.abs(), impact_speed) {
                            Some(rough)
                        } else {
                            rough.resting()
                        };
                        let Some(law) = law else { return };
                        let mut into = DVec2::ZERO;
                        into[axis] = if was < 0.0 { -1.0 } else { 1.0 };
                        let impulse = p.mass * (p.vel[axis] - was).abs();
                        let side = crate::rough::Side {
                            mass: p.mass,
                            radius: p.radius,
                            vel: p.vel,
                            spin: p.spin,
                        };
                        if let Some(after) = law.wall(into, impulse, side) {
                            (p.vel, p.spin) = (after.vel, after.spin);
                        }
                    };
                    let (x, y) = (&mut p.pos.x, &mut p.pos.y);
                    let bounced = bounce_axis(
                        x,
                        &mut p.vel.x,
                        p.radius,
                        (size.x, [walls.left, walls.right]),
                        gravity.x,
                        wall_restitution,
                    );
                    count(bounced, before.x);
                    let bounced_x = bounced;
                    let bounced = bounce_axis(
                        y,
                        &mut p.vel.y,
                        p.radius,
                        (size.y, [walls.bottom, walls.top]),
                        gravity.y,
                        wall_restitution,
                    );
                    count(bounced, before.y);
                    if !rough.is_smooth() {
                        for (axis, hit) in [(0, bounced_x), (1, bounced)] {
                            if hit {
                                rub(p, axis, before[axis]);
                            }
                        }
                    }
                    impulse += p.mass * (p.vel - before).abs().element_sum();
                }
                WallReport {
                    hits,
                    resting,
                    impulse,
                }
            }
        }
    }
}

/// What the walls did in one boundary stage.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WallReport {
    /// Discs that hit a wall (impacts).
    pub hits: usize,
    /// Discs that met a wall slower than an impact (resting on it).
    pub resting: usize,
    /// Momentum the walls gave the discs, Σ m·|Δv| (kg·m/s): over time and
    /// wall length, the pressure.
    pub impulse: f64,
}

/// The shortest signed distance along one axis of a torus of length `len`
/// (exact for |d| < 1.5·len, which holds for positions kept inside the box).
fn wrap(d: f64, len: f64) -> f64 {
    let half = 0.5 * len;
    if d > half {
        let w = d - len;
        if w > half {
            d - len * (d / len).round()
        } else {
            w
        }
    } else if d < -half {
        let w = d + len;
        if w < -half {
            d - len * (d / len).round()
        } else {
            w
        }
    } else {
        d
    }
}

/// Keeps one coordinate of a disc within `[radius, extent − radius]`, at
/// the ends that have walls (`sides`: lower, upper).
///
/// Returns whether the disc bounced (was moving into the wall it touched).
fn bounce_axis(
    pos: &mut f64,
    vel: &mut f64,
    radius: f64,
    (extent, [lower, upper]): (f64, [bool; 2]),
    gravity: f64,
    restitution: f64,
) -> bool {
    let (lo, hi) = (radius, extent - radius);
    if lo > hi && lower && upper {
        // A disc wider than the box: keep it centred, at rest along this axis.
        *pos = 0.5 * extent;
        *vel = 0.0;
        return false;
    }
    let (target, into_wall) = if *pos < lo && lower {
        (lo, *vel < 0.0)
    } else if *pos > hi && upper {
        (hi, *vel > 0.0)
    } else {
        return false;
    };
    if into_wall {
        *vel *= -restitution;
    }
    // Moving the disc by `shift` against gravity costs −g·shift per unit mass.
    let shift = target - *pos;
    *pos = target;
    let potential_gain = -gravity * shift;
    if potential_gain > 0.0 {
        let speed_sq = (*vel * *vel - 2.0 * potential_gain).max(0.0);
        *vel = speed_sq.sqrt().copysign(*vel);
    }
    into_wall
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::particle::Color;

    #[test]
    fn periodic_separation_takes_the_short_way_round() {
        let size = DVec2::new(10.0, 10.0);
        let d = Boundary::Periodic.separation(DVec2::new(0.5, 5.0), DVec2::new(9.5, 5.0), size);
        assert!((d - DVec2::new(-1.0, 0.0)).length() < 1e-12);
        let d = Boundary::Box.separation(DVec2::new(0.5, 5.0), DVec2::new(9.5, 5.0), size);
        assert!((d - DVec2::new(9.0, 0.0)).length() < 1e-12);
    }

    #[test]
    fn an_open_side_lets_a_disc_through_and_a_wall_does_not() {
        let size = DVec2::new(10.0, 10.0);
        let walls = Walls::from_names(&["left"]).unwrap();
        let mut discs = [
            Particle::new(
                DVec2::new(9.9, 5.0),
                DVec2::new(2.0, 0.0),
                1.0,
                0.5,
                Color::palette(0),
            ),
            Particle::new(
                DVec2::new(0.1, 5.0),
                DVec2::new(-2.0, 0.0),
                1.0,
                0.5,
                Color::palette(0),
            ),
            Particle::new(
                DVec2::new(5.0, 0.1),
                DVec2::new(0.0, -2.0),
                1.0,
                0.5,
                Color::palette(0),
            ),
        ];
        let report = Boundary::Box.apply(
            &mut discs,
            (size, walls),
            DVec2::ZERO,
            (1.0, crate::rough::Tangential::SMOOTH),
            0.0,
        );
        assert_eq!(report.hits, 1);
        assert_eq!(discs[0].vel.x, 2.0, "no right wall");
        assert_eq!(discs[0].pos.x, 9.9);
        assert_eq!(discs[1].vel.x, 2.0, "the left wall reflects");
        assert_eq!(discs[1].pos.x, 0.5);
        assert_eq!(discs[2].vel.y, -2.0, "no floor");
        assert!(!Boundary::Box.admits(walls, size, DVec2::new(0.2, 5.0), 0.5));
        assert!(Boundary::Box.admits(walls, size, DVec2::new(30.0, -4.0), 0.5));
    }

    #[test]
    fn walls_read_and_write_as_side_names() {
        let w = Walls::from_names(&["top", "left"]).unwrap();
        assert_eq!(w.names(), ["left", "top"]);
        assert!(w.at(0, false) && w.at(1, true) && !w.at(0, true) && !w.at(1, false));
        assert_eq!(Walls::from_names(&Walls::NAMES).unwrap(), Walls::ALL);
        let err = Walls::from_names(&["floor"]).unwrap_err();
        assert!(err.contains("floor") && err.contains("bottom"), "{err}");
    }

    #[test]
    fn floor_bounce_under_gravity_never_gains_energy() {
        let g = -9.81;
        for depth in [0.0, 1e-6, 0.01, 0.3] {
            for v in [-3.0, -0.01, 0.0, 0.5] {
                let (mut pos, mut vel) = (0.5 - depth, v);
                let before = 0.5 * v * v - g * pos;
                bounce_axis(&mut pos, &mut vel, 0.5, (10.0, [true, true]), g, 1.0);
                let after = 0.5 * vel * vel - g * pos;
                assert!(pos >= 0.5, "disc left inside the floor");
                // Never more than before, unless the disc had too little
                // speed to pay for the lift, and then it ends at rest.
                let at_rest_on_floor = -g * 0.5;
                assert!(
                    after <= before.max(at_rest_on_floor) + 1e-12,
                    "energy {before} -> {after}"
                );
                if after > before + 1e-12 {
                    assert_eq!(vel, 0.0);
                }
            }
        }
    }
}
