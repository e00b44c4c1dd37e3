//! The physical laws of a world as the methods see them: copied out of the
//! [`crate::world::World`] for one step, so the methods depend on this and
//! not on the world.

use crate::boundary::{Boundary, Walls};
use glam::DVec2;

/// The physical laws of a world, copied out for the methods.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Laws {
    /// World size (m).
    pub size: DVec2,
    /// Gravity (m/s²).
    pub gravity: DVec2,
    /// Restitution between discs.
    pub restitution: f64,
    /// Restitution at walls.
    pub wall_restitution: f64,
    /// Edge behaviour.
    pub boundary: Boundary,
    /// Which sides of a box have walls.
    pub walls: Walls,
}
