//! Metrics: the conserved quantities a teacher points at, summed over discs.

use crate::particle::Particle;
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// Totals over all discs at one instant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Metrics {
    /// Number of discs.
    pub count: usize,
    /// Total mass (kg).
    pub mass: f64,
    /// Total momentum Σ m·v (kg·m/s).
    pub momentum: DVec2,
    /// Total kinetic energy of translation Σ ½·m·|v|² (J).
    pub kinetic_energy: f64,
    /// Total kinetic energy of rotation Σ ½·I·ω² (J), I = ½·m·r².
    #[serde(default)]
    pub rotational_energy: f64,
    /// Total angular momentum about the origin, orbital Σ m·(x × v) plus
    /// spin Σ I·ω (kg·m²/s, counter-clockwise positive).
    #[serde(default)]
    pub angular_momentum: f64,
    /// Centre of mass Σ m·x / Σ m (m); zero when there are no discs.
    pub center_of_mass: DVec2,
    /// Velocity of the centre of mass, total momentum / total mass (m/s).
    pub center_of_mass_velocity: DVec2,
}

impl Metrics {
    /// Measures `particles`.
    pub fn measure(particles: &[Particle]) -> Self {
        let mut m = Metrics {
            count: particles.len(),
            ..Metrics::default()
        };
        let mut weighted_pos = DVec2::ZERO;
        for p in particles {
            m.mass += p.mass;
            m.momentum += p.momentum();
            m.kinetic_energy += p.kinetic_energy();
            m.rotational_energy += p.rotational_energy();
            m.angular_momentum += p.angular_momentum();
            weighted_pos += p.pos * p.mass;
        }
        if m.mass > 0.0 {
            m.center_of_mass = weighted_pos / m.mass;
            m.center_of_mass_velocity = m.momentum / m.mass;
        }
        m
    }

    /// Σ |m·v|: the scale against which a change of total momentum is small.
    pub fn momentum_scale(particles: &[Particle]) -> f64 {
        particles.iter().map(|p| p.momentum().length()).sum()
    }

    /// Gravitational potential energy −Σ m·g·x, zero at the origin (J).
    pub fn potential_energy(particles: &[Particle], gravity: DVec2) -> f64 {
        -particles
            .iter()
            .map(|p| p.mass * gravity.dot(p.pos))
            .sum::<f64>()
    }
}
