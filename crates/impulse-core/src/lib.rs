//! Impulse's physics core: 2D discs in a box, stepped at a fixed time step.
//!
//! The core is window-free (it never imports macroquad) so that every property
//! of the physics can be tested headlessly. One call to [`World::step`] runs the
//! pipeline, one module per stage:
//!
//! 1. [`broad_phase`]: which pairs *might* touch (brute force, grid, sort and
//!    sweep, or quadtree);
//! 2. [`narrow_phase`]: which of them overlap, with normal and depth;
//! 3. [`resolution`]: elastic/inelastic impulses for approaching pairs, then an
//!    inverse-mass push-apart that leaves the centre of mass where it was
//!    (large contact lists band by band, on several threads);
//! 4. [`integration`]: semi-implicit Euler under gravity;
//! 5. [`boundary`]: walls (reflection without creating energy), open space, or
//!    a periodic torus.
//!
//! For large scenes the order-free stages run on several threads ([`parallel`]),
//! with results that do not depend on how many.
//!
//! [`method`] holds the methods that run these stages (`seed`, `impulse`,
//! `verlet`) and the event-driven `exact`, which keeps its own cells and
//! event calendar; [`auto`] chooses among them. [`metrics`] measures the
//! conserved quantities, [`stats`] what a step did and
//! how long each stage took, [`warnings`] what a method cannot promise, and
//! [`scene`] turns TOML scene files into worlds.
#![warn(missing_docs)]

pub mod alloc_count;
pub mod auto;
pub mod boundary;
pub mod broad_phase;
pub mod catalogue;
pub mod clock;
pub mod fingerprint;
pub mod history;
pub mod impact;
pub mod integration;
pub mod laws;
pub mod ledger;
pub mod math;
pub mod method;
pub mod metrics;
pub mod narrow_phase;
pub mod parallel;
pub mod particle;
pub(crate) mod pipeline;
pub mod presets;
pub mod resolution;
pub mod rough;
pub mod scene;
pub mod stats;
pub mod stress;
pub mod warnings;
pub mod world;

pub use boundary::{Axis, Boundary, Walls};
pub use glam::DVec2;
pub use metrics::Metrics;
pub use particle::{Color, Particle};
pub use scene::{Scene, SceneError};
pub use stats::StepStats;
pub use world::World;
