//! Boundaries, the last stage of a step: closed box, open space, or periodic.
//!
//! The box walls reflect a disc that has crossed them, scaled by the wall
//! restitution, and put it back inside. Moving a disc back inside changes its
//! height, so under gravity the wall also takes the potential energy that move
//! gains out of the disc's speed along that axis: a bounce never creates
//! energy. (A disc pushed into the floor while at rest has no speed to pay
//! with; lifting it back costs at most m·g·depth, and it ends at rest.)

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

    /// Applies the boundary to every disc.
    pub fn apply(
        self,
        particles: &mut [Particle],
        size: DVec2,
        gravity: DVec2,
        wall_restitution: f64,
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
                let mut hits = 0;
                let mut impulse = 0.0;
                for p in particles {
                    let before = p.vel;
                    let (x, y) = (&mut p.pos.x, &mut p.pos.y);
                    hits += usize::from(bounce_axis(
                        x,
                        &mut p.vel.x,
                        p.radius,
                        size.x,
                        gravity.x,
                        wall_restitution,
                    ));
                    hits += usize::from(bounce_axis(
                        y,
                        &mut p.vel.y,
                        p.radius,
                        size.y,
                        gravity.y,
                        wall_restitution,
                    ));
                    impulse += p.mass * (p.vel - before).abs().element_sum();
                }
                WallReport { hits, impulse }
            }
        }
    }
}

/// What the walls did in one boundary stage.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WallReport {
    /// Discs that bounced.
    pub hits: usize,
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

/// Keeps one coordinate of a disc within `[radius, extent − radius]`.
///
/// Returns whether the disc bounced (was moving into the wall it touched).
fn bounce_axis(
    pos: &mut f64,
    vel: &mut f64,
    radius: f64,
    extent: f64,
    gravity: f64,
    restitution: f64,
) -> bool {
    let (lo, hi) = (radius, extent - radius);
    if lo > hi {
        // A disc wider than the box: keep it centred, at rest along this axis.
        *pos = 0.5 * extent;
        *vel = 0.0;
        return false;
    }
    let (target, into_wall) = if *pos < lo {
        (lo, *vel < 0.0)
    } else if *pos > hi {
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

    #[test]
    fn periodic_separation_takes_the_short_way_round() {
        let size = DVec2::new(10.0, 10.0);
        let d = Boundary::Periodic.separation(DVec2::new(0.5, 5.0), DVec2::new(9.5, 5.0), size);
        assert!((d - DVec2::new(-1.0, 0.0)).length() < 1e-12);
        let d = Boundary::Box.separation(DVec2::new(0.5, 5.0), DVec2::new(9.5, 5.0), size);
        assert!((d - DVec2::new(9.0, 0.0)).length() < 1e-12);
    }

    #[test]
    fn floor_bounce_under_gravity_never_gains_energy() {
        let g = -9.81;
        for depth in [0.0, 1e-6, 0.01, 0.3] {
            for v in [-3.0, -0.01, 0.0, 0.5] {
                let (mut pos, mut vel) = (0.5 - depth, v);
                let before = 0.5 * v * v - g * pos;
                bounce_axis(&mut pos, &mut vel, 0.5, 10.0, g, 1.0);
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
