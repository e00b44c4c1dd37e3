//! The physical laws of a world, declared once: the [`crate::world::World`]
//! holds them, a scene file's `[world]` table is them (serde), and the
//! methods read a copy for each step ([`Laws::in_effect`]), so they depend
//! on this and not on the world.

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
