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
//!
//! The wall stage can also hand each hit to the ledger as a
//! [`crate::ledger::WallHit`]; the pipeline does when the ledger is on.

use crate::ledger::{Wall, WallHit};
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
        edges: (DVec2, Walls),
        gravity: DVec2,
        wall_law: (f64, crate::rough::Tangential),
        impact_speed: f64,
    ) -> WallReport {
        let contact = WallContact {
            impact_speed,
            rewind: 0.0,
        };
        self.apply_recording(particles, edges, gravity, wall_law, contact, None)
    }

    /// [`Boundary::apply`], which with `record` = (`hits`, `time`) also
    /// adds each hit to `hits` as a [`WallHit`] at `time`, its disc an
    /// index into `particles`; see [`record_hits`] for a disc that meets
    /// two walls at once.
    pub(crate) fn apply_recording(
        self,
        particles: &mut [Particle],
        (size, walls): (DVec2, Walls),
        gravity: DVec2,
        (wall_restitution, rough): (f64, crate::rough::Tangential),
        contact: WallContact,
        mut record: Option<(&mut Vec<WallHit>, f64)>,
    ) -> WallReport {
        let impact_speed = contact.impact_speed;
        match self {
            Boundary::Open => WallReport::default(),
            Boundary::Periodic => {
                for p in particles {
                    // Most discs are inside already; rem_euclid is a slow fmod.
                    let inside = p.pos.cmpge(DVec2::ZERO).all() && p.pos.cmplt(size).all();
                    if !inside {
                        wrap_into(&mut p.pos, size);
                    }
                }
                WallReport::default()
            }
            Boundary::Box => {
                let mut report = WallReport::default();
                for (k, p) in particles.iter_mut().enumerate() {
                    let (before, spin_before) = (p.vel, p.spin);
                    let (x, y) = (&mut p.pos.x, &mut p.pos.y);
                    let (bounced_x, ago_x) = bounce_axis(
                        (x, &mut p.vel.x),
                        p.radius,
                        (size.x, [walls.left, walls.right]),
                        gravity.x,
                        wall_restitution,
                        contact,
                    );
                    let after_x = p.vel;
                    let (bounced_y, ago_y) = bounce_axis(
                        (y, &mut p.vel.y),
                        p.radius,
                        (size.y, [walls.bottom, walls.top]),
                        gravity.y,
                        wall_restitution,
                        contact,
                    );
                    let bounced = [bounced_x, bounced_y];
                    let ago = [ago_x, ago_y];
                    let hit = [0, 1].map(|axis| {
                        bounced[axis] && crate::impact::is_impact(before[axis].abs(), impact_speed)
                    });
                    for axis in 0..2 {
                        report.hits += usize::from(hit[axis]);
                        report.resting += usize::from(bounced[axis] && !hit[axis]);
                    }
                    // What each wall did: its bounce, then its rub.
                    let mut change = [(after_x - before, 0.0), (p.vel - after_x, 0.0)];
                    if !rough.is_smooth() {
                        for axis in 0..2 {
                            if bounced[axis] {
                                let (vel, spin) = (p.vel, p.spin);
                                rub(p, axis, before[axis], hit[axis], rough);
                                // On from the touch with the rub's change too.
                                p.pos += (p.vel - vel) * ago[axis];
                                change[axis].0 += p.vel - vel;
                                change[axis].1 += p.spin - spin;
                            }
                        }
                    }
                    report.impulse += p.mass * (p.vel - before).abs().element_sum();
                    if let Some((hits, time)) = record.as_mut() {
                        if hit[0] || hit[1] {
                            let start = (before, spin_before);
                            record_hits(hits, (*time, k), p, start, hit, change);
                        }
                    }
                }
                report
            }
        }
    }
}

/// A rough wall turns the disc's slip along it into spin: the tangential
/// law after the bounce of `axis`, where the disc came in at `was` along
/// it (an impact if `impact`, else resting).
fn rub(p: &mut Particle, axis: usize, was: f64, impact: bool, rough: crate::rough::Tangential) {
    let law = if impact { Some(rough) } else { rough.resting() };
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
}

/// Adds disc `k`'s wall hits of one boundary stage to `hits`, at `time`.
/// `start` is its velocity and spin before the stage, `p` the disc after
/// it, and `change` what each axis's wall did (velocity, spin); `hit` says
/// which of them were impacts.
///
/// Each entry carries exactly its own wall's change, so its
/// [`WallHit::wall_impulse`] is that wall's; the last one ends at the
/// disc's state after the stage. What a wall that was not hit did (a
/// resting contact, a disc put back inside) goes into the first entry's
/// "before". A disc in a corner makes two entries, x then y, the second
/// starting where the first ended. The stage bounces off both walls before
/// either rubs, so with rough walls that start is a velocity the disc never
/// had: it holds the x wall's rub, which is along y, and the second
/// entry's closing speed is off by it (its impulse is not).
fn record_hits(
    hits: &mut Vec<WallHit>,
    (time, k): (f64, usize),
    p: &Particle,
    (came_in, spin_before): (DVec2, f64),
    hit: [bool; 2],
    change: [(DVec2, f64); 2],
) {
    let (mut vel, mut spin) = (came_in, spin_before);
    for axis in 0..2 {
        let (dv, dw) = change[axis];
        if !hit[axis] && (dv != DVec2::ZERO || dw != 0.0) {
            (vel, spin) = (vel + dv, spin + dw);
        }
    }
    let last = if hit[1] { 1 } else { 0 };
    for axis in (0..2).filter(|&axis| hit[axis]) {
        let (dv, dw) = change[axis];
        let (after, spin_after) = if axis == last {
            (p.vel, p.spin)
        } else {
            (vel + dv, spin + dw)
        };
        hits.push(WallHit {
            time,
            disc: k,
            // Came in moving up the axis: the upper wall.
            wall: Wall::at(axis, came_in[axis] > 0.0),
            mass: p.mass,
            radius: p.radius,
            before: vel,
            after,
            spin_before: spin,
            spin_after,
        });
        (vel, spin) = (after, spin_after);
    }
}

/// How the walls meet a disc: which bounces are impacts, and how far back
/// an impact may be rewound to the moment the disc touched the wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallContact {
    /// Speed into the wall above which a bounce is an impact (see
    /// [`crate::impact`]).
    pub impact_speed: f64,
    /// The substep's length (s) for the impulse method, which places a
    /// bouncing disc where it would be had it turned at the touch (the
    /// mirror of its overshoot, shortened by the restitution); 0 for the
    /// others, which put it at the wall.
    pub rewind: f64,
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

/// `pos` brought into the periodic box `[0, size)`. Out of line, so that
/// a compiler vectorizing the loop around it for wide vector units
/// (`-C target-cpu=native` with AVX-512) does not take the slow `fmod`
/// for every disc instead of the few outside: that made the periodic
/// boundary 5× slower there.
#[cold]
#[inline(never)]
fn wrap_into(pos: &mut DVec2, size: DVec2) {
    *pos = pos.rem_euclid(size);
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
/// Returns whether the disc bounced (was moving into the wall it touched),
/// and how long ago it touched the wall if it was placed as from that
/// moment (0 if it was put at the wall).
fn bounce_axis(
    (pos, vel): (&mut f64, &mut f64),
    radius: f64,
    (extent, [lower, upper]): (f64, [bool; 2]),
    gravity: f64,
    restitution: f64,
    contact: WallContact,
) -> (bool, f64) {
    let (lo, hi) = (radius, extent - radius);
    if lo > hi && lower && upper {
        // A disc wider than the box: keep it centred, at rest along this axis.
        *pos = 0.5 * extent;
        *vel = 0.0;
        return (false, 0.0);
    }
    let (target, into_wall) = if *pos < lo && lower {
        (lo, *vel < 0.0)
    } else if *pos > hi && upper {
        (hi, *vel > 0.0)
    } else {
        return (false, 0.0);
    };
    // An impact within the substep: it touched overshoot / speed ago.
    let impact = into_wall && crate::impact::is_impact(vel.abs(), contact.impact_speed);
    let ago = if impact {
        let ago = (target - *pos).abs() / vel.abs();
        if ago <= contact.rewind {
            ago
        } else {
            0.0
        }
    } else {
        0.0
    };
    if into_wall {
        *vel *= -restitution;
    }
    let place = target + *vel * ago;
    let (place, ago) = if (lo..=hi).contains(&place) {
        (place, ago)
    } else {
        (target, 0.0)
    };
    // Moving the disc by `shift` against gravity costs −g·shift per unit mass.
    let shift = place - *pos;
    *pos = place;
    let potential_gain = -gravity * shift;
    if potential_gain > 0.0 {
        let speed_sq = (*vel * *vel - 2.0 * potential_gain).max(0.0);
        *vel = speed_sq.sqrt().copysign(*vel);
    }
    (into_wall, ago)
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
    fn the_ledgers_walls_are_named_as_the_sides() {
        assert_eq!(Wall::ALL.map(Wall::name), Walls::NAMES);
        for w in Wall::ALL {
            let only = Walls::from_names(&[w.name()]).unwrap();
            assert!(only.at(w.axis(), w.is_upper()));
        }
    }

    #[test]
    fn a_disc_in_a_corner_records_each_walls_own_impulse() {
        // Past the bottom-right corner, moving out through both walls:
        // two hits, each wall giving (1 + e)·m·vₙ along its normal, and
        // with rough walls the two entries still add up to the whole change.
        let size = DVec2::new(10.0, 10.0);
        for beta in [-1.0, 1.0] {
            let rough = crate::rough::Tangential {
                beta,
                friction: None,
            };
            let (v0, w0, m, e) = (DVec2::new(3.0, -2.0), 1.5, 2.0, 0.5);
            let mut discs = [Particle::new(
                DVec2::new(9.6, 0.4),
                v0,
                m,
                0.5,
                Color::palette(0),
            )];
            discs[0].spin = w0;
            let mut hits = Vec::new();
            let report = Boundary::Box.apply_recording(
                &mut discs,
                (size, Walls::ALL),
                DVec2::ZERO,
                (e, rough),
                WallContact {
                    impact_speed: 0.0,
                    rewind: 0.0,
                },
                Some((&mut hits, 7.0)),
            );
            assert_eq!(report.hits, 2);
            let [x, y] = hits[..] else {
                panic!("two entries: {hits:?}")
            };
            assert_eq!((x.wall, y.wall), (Wall::Right, Wall::Bottom));
            assert_eq!((x.time, x.disc), (7.0, 0));
            assert_eq!((x.before, x.spin_before), (v0, w0));
            assert_eq!((y.before, y.spin_before), (x.after, x.spin_after));
            assert_eq!((y.after, y.spin_after), (discs[0].vel, discs[0].spin));
            for (h, came_in) in [(x, v0.x), (y, -v0.y)] {
                let along_normal = h.wall_impulse().dot(h.normal());
                let expected = (1.0 + e) * m * came_in;
                assert!((along_normal - expected).abs() < 1e-12, "{h:?}");
            }
            let total = x.wall_impulse() + y.wall_impulse();
            assert!((total - m * (discs[0].vel - v0)).length() < 1e-12);
            if beta == -1.0 {
                assert_eq!(x.after, DVec2::new(-1.5, -2.0), "smooth: x only");
            }
        }
    }

    #[test]
    fn floor_bounce_under_gravity_never_gains_energy() {
        let g = -9.81;
        // Put at the floor, and (impulse) placed as from the touch.
        let h = 1.0 / 240.0;
        let contacts = [0.0, h].map(|rewind| WallContact {
            impact_speed: crate::impact::threshold(DVec2::new(0.0, g), h),
            rewind,
        });
        for (depth, v, contact) in [0.0, 1e-6, 0.01, 0.3]
            .into_iter()
            .flat_map(|d| [-3.0, -0.01, 0.0, 0.5].map(|v| (d, v)))
            .flat_map(|(d, v)| contacts.map(|c| (d, v, c)))
        {
            {
                let (mut pos, mut vel) = (0.5 - depth, v);
                let before = 0.5 * v * v - g * pos;
                let at = (10.0, [true, true]);
                bounce_axis((&mut pos, &mut vel), 0.5, at, g, 1.0, contact);
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
