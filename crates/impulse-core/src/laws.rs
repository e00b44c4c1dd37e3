//! The physical laws of a world, declared once: the [`crate::world::World`]
//! holds them, a scene file's `[world]` table is them (serde), and the
//! methods read a copy for each step ([`Laws::in_effect`]), so they depend
//! on this and not on the world. Beside them, each law's ranges
//! ([`LawRange`]): what a scene file may hold, read by validation, and what
//! a control offers, read by the window's sliders and keys.

use crate::boundary::{Axis, Boundary, Walls};
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// The size of a world and the laws its discs obey.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Laws {
    /// Width and height of the world rectangle (0,0)–`size` (m).
    pub size: DVec2,
    /// Uniform gravitational acceleration (m/s²); y is up.
    #[serde(default)]
    pub gravity: DVec2,
    /// Coefficient of restitution e between discs, 0 (sticky) to 1 (elastic).
    #[serde(default = "one")]
    pub restitution: f64,
    /// Coefficient of restitution at the walls.
    #[serde(default = "one")]
    pub wall_restitution: f64,
    /// Tangential restitution β between discs, −1 (smooth: no spin is
    /// given or taken, the default) to 1 (perfectly rough): the relative
    /// velocity of the touching points along the contact becomes −β times
    /// itself (see [`crate::rough`]).
    #[serde(default = "minus_one", skip_serializing_if = "is_smooth")]
    pub tangential_restitution: f64,
    /// Tangential restitution at the walls.
    #[serde(default = "minus_one", skip_serializing_if = "is_smooth")]
    pub wall_tangential_restitution: f64,
    /// Coulomb friction coefficient μ ≥ 0: the tangential impulse of a
    /// contact is at most μ times its normal impulse, and resting contacts
    /// under gravity rub with it. Absent: no limit at impacts, and resting
    /// contacts smooth.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<f64>,
    /// What the edges do.
    #[serde(default)]
    pub boundary: Boundary,
    /// The sides of a box that have walls (all four when absent).
    #[serde(default, skip_serializing_if = "all_walls")]
    pub walls: Walls,
    /// A one-dimensional world: the only axis discs move along ("x" or "y").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub constrain: Option<Axis>,
}

fn one() -> f64 {
    1.0
}

fn minus_one() -> f64 {
    -1.0
}

fn is_smooth(beta: &f64) -> bool {
    *beta == -1.0
}

fn all_walls(walls: &Walls) -> bool {
    walls.all()
}

impl Laws {
    /// A closed box of the given size: no gravity, elastic everywhere, two
    /// dimensions.
    pub fn new(size: DVec2) -> Self {
        Laws {
            size,
            gravity: DVec2::ZERO,
            restitution: 1.0,
            wall_restitution: 1.0,
            tangential_restitution: -1.0,
            wall_tangential_restitution: -1.0,
            friction: None,
            boundary: Boundary::Box,
            walls: Walls::ALL,
            constrain: None,
        }
    }

    /// The tangential law between discs.
    pub fn rough(&self) -> crate::rough::Tangential {
        crate::rough::Tangential {
            beta: self.tangential_restitution,
            friction: self.friction,
        }
    }

    /// The tangential law at the walls.
    pub fn wall_rough(&self) -> crate::rough::Tangential {
        crate::rough::Tangential {
            beta: self.wall_tangential_restitution,
            friction: self.friction,
        }
    }

    /// The laws as a step applies them: in one dimension, gravity across
    /// the line is held by the line and drops out.
    pub fn in_effect(&self) -> Laws {
        let mut laws = *self;
        if let Some(axis) = self.constrain {
            laws.gravity[axis.locked()] = 0.0;
        }
        laws
    }
}

/// A law's two ranges, which differ on purpose: what a scene file may hold
/// (`valid`), and what the window's controls offer (`control`; gravity up to
/// 10⁶ m/s² in a file, 0–20 on the slider).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LawRange {
    /// What a scene file may hold, both ends included.
    pub valid: (f64, f64),
    /// What the window's controls offer.
    pub control: (f64, f64),
}

impl LawRange {
    /// Whether `x` is a value a scene file may hold (false for NaN).
    pub fn admits(self, x: f64) -> bool {
        (self.valid.0..=self.valid.1).contains(&x)
    }
}

/// |g| (m/s²), pointing anywhere in a file, down on the slider.
pub const GRAVITY_RANGE: LawRange = LawRange {
    valid: (0.0, 1e6),
    control: (0.0, 20.0),
};

/// Friction μ: any finite number from 0 in a file, 0–2 on the slider.
pub const FRICTION_RANGE: LawRange = LawRange {
    valid: (0.0, f64::MAX),
    control: (0.0, 2.0),
};

/// A coefficient of the collision law, one number each.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Law {
    /// Restitution e between discs.
    Restitution,
    /// Restitution at the walls.
    WallRestitution,
    /// Tangential restitution (roughness) β between discs.
    Roughness,
    /// Tangential restitution at the walls.
    WallRoughness,
}

impl Law {
    /// Every coefficient, in the `[world]` table's order.
    pub const ALL: [Law; 4] = [
        Law::Restitution,
        Law::WallRestitution,
        Law::Roughness,
        Law::WallRoughness,
    ];

    /// Its value in `laws`.
    pub fn of(self, laws: &Laws) -> f64 {
        match self {
            Law::Restitution => laws.restitution,
            Law::WallRestitution => laws.wall_restitution,
            Law::Roughness => laws.tangential_restitution,
            Law::WallRoughness => laws.wall_tangential_restitution,
        }
    }

    /// Its value in `laws`, to change.
    pub fn of_mut(self, laws: &mut Laws) -> &mut f64 {
        match self {
            Law::Restitution => &mut laws.restitution,
            Law::WallRestitution => &mut laws.wall_restitution,
            Law::Roughness => &mut laws.tangential_restitution,
            Law::WallRoughness => &mut laws.wall_tangential_restitution,
        }
    }

    /// Its key in a scene file's `[world]` table.
    pub fn field(self) -> &'static str {
        match self {
            Law::Restitution => "restitution",
            Law::WallRestitution => "wall_restitution",
            Law::Roughness => "tangential_restitution",
            Law::WallRoughness => "wall_tangential_restitution",
        }
    }

    /// Its ranges: restitution 0 (no bounce) to 1 (elastic), roughness −1
    /// (smooth) to 1 (perfectly rough), in a file and on a control alike.
    pub fn range(self) -> LawRange {
        match self {
            Law::Restitution | Law::WallRestitution => LawRange {
                valid: (0.0, 1.0),
                control: (0.0, 1.0),
            },
            Law::Roughness | Law::WallRoughness => LawRange {
                valid: (-1.0, 1.0),
                control: (-1.0, 1.0),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;

    fn scene_with(line: &str) -> Result<Scene, String> {
        let text = format!("[world]\nsize = [4.0, 4.0]\n{line}\n");
        Scene::parse(&text, "test").map_err(|e| e.to_string())
    }

    #[test]
    fn validation_reads_each_laws_range_and_the_controls_stay_inside_it() {
        for law in Law::ALL {
            let range = law.range();
            let (lo, hi) = range.valid;
            for ok in [lo, hi] {
                let scene = scene_with(&format!("{} = {ok:?}", law.field()));
                assert!(scene.is_ok(), "{law:?} = {ok}: {scene:?}");
                assert_eq!(law.of(&scene.unwrap().world), ok);
            }
            let error = scene_with(&format!("{} = {:?}", law.field(), hi + 0.01)).unwrap_err();
            assert!(error.contains(&format!("world.{}", law.field())), "{error}");
            let (clo, chi) = range.control;
            assert!(
                lo <= clo && chi <= hi,
                "{law:?}: a control offers only what a file may hold"
            );
        }
        for r in [GRAVITY_RANGE, FRICTION_RANGE] {
            assert!(r.valid.0 <= r.control.0 && r.control.1 <= r.valid.1);
        }
        assert!(scene_with("gravity = [0.0, -1e6]").is_ok());
        assert!(scene_with("gravity = [0.0, -1.1e6]")
            .unwrap_err()
            .contains("world.gravity"));
        assert!(scene_with("friction = -0.1")
            .unwrap_err()
            .contains("world.friction"));
    }
}
