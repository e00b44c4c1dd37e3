//! Scenes built in code, for sizes no hand-written file reaches: the gas the
//! benchmarks, the accuracy lab and the tests share.

use crate::boundary::Boundary;
use crate::broad_phase::BroadPhaseKind;
use crate::method::{Method, Setting};
use crate::particle::{Color, Particle};
use crate::world::World;
use glam::DVec2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A gas of equal discs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gas {
    /// Number of discs.
    pub count: usize,
    /// Fraction of the area the discs cover (0.3 is a dense gas).
    pub area_fraction: f64,
    /// Largest disc radius (m).
    pub radius: f64,
    /// Largest over smallest radius: 1 for equal discs; otherwise radii are
    /// spread log-uniformly down to `radius / radius_ratio` (same density,
    /// so mass grows with area).
    pub radius_ratio: f64,
    /// Root-mean-square speed (m/s); directions are uniform.
    pub speed: f64,
    /// Random seed.
    pub seed: u64,
    /// Edges of the box.
    pub boundary: Boundary,
}

impl Default for Gas {
    fn default() -> Self {
        Gas {
            count: 1000,
            area_fraction: 0.3,
            radius: 0.5,
            radius_ratio: 1.0,
            speed: 1.0,
            seed: 1,
            boundary: Boundary::Periodic,
        }
    }
}

impl Gas {
    /// [`Gas::build`] with the method and broad phase fixed and one
    /// substep, as the benchmarks measure it.
    pub fn build_fixed(&self, method: Method, broad: BroadPhaseKind) -> World {
        let mut world = self.build();
        world.method = Setting::Fixed(method);
        world.broad_phase = Setting::Fixed(broad);
        world.substeps = Setting::Fixed(1);
        world
    }

    /// The world: discs on a jittered square lattice filling a square box,
    /// so no two overlap and building a million takes a fraction of a second.
    /// Total momentum is removed, so the gas as a whole is at rest.
    pub fn build(&self) -> World {
        let n = self.count.max(1);
        let spacing =
            self.radius * (std::f64::consts::PI / self.area_fraction.clamp(1e-6, 0.75)).sqrt();
        let per_row = (n as f64).sqrt().ceil() as usize;
        let side = per_row as f64 * spacing;
        let jitter = (0.5 * (spacing - 2.0 * self.radius)).max(0.0) * 0.999;
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let mut world = World::new(DVec2::splat(side));
        world.laws.boundary = self.boundary;
        world.particles = (0..self.count)
            .map(|k| {
                let cell = DVec2::new((k % per_row) as f64 + 0.5, (k / per_row) as f64 + 0.5);
                let offset = DVec2::new(rng.random_range(-1.0..=1.0), rng.random_range(-1.0..=1.0));
                let angle = rng.random_range(0.0..std::f64::consts::TAU);
                let pos = cell * spacing + offset * jitter;
                let vel = self.speed * crate::math::unit(angle);
                let radius = if self.radius_ratio > 1.0 {
                    self.radius * crate::math::pow(self.radius_ratio, -rng.random_range(0.0..=1.0))
                } else {
                    self.radius
                };
                let mass = (radius / self.radius) * (radius / self.radius);
                Particle::new(pos, vel, mass, radius, Color::palette(k))
            })
            .collect();
        let drift = world.metrics().center_of_mass_velocity;
        for p in &mut world.particles {
            p.vel -= drift;
        }
        world
    }
}
