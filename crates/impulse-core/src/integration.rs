//! Integration, the fourth stage: advance velocities and positions by `dt`.
//!
//! Semi-implicit (symplectic) Euler: v ← v + g·dt, then x ← x + v·dt. Without
//! gravity it moves discs in exact straight lines; with gravity its energy
//! error stays bounded instead of growing. Each disc turns by ω·dt.

use crate::particle::Particle;
use glam::DVec2;

/// Advances every disc by one step of length `dt` under uniform `gravity`.
pub fn integrate(particles: &mut [Particle], gravity: DVec2, dt: f64) {
    let dv = gravity * dt;
    for p in particles {
        p.vel += dv;
        p.pos += p.vel * dt;
        p.angle += p.spin * dt;
    }
}
