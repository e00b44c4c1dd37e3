//! Integration, the fourth stage: advance velocities and positions by `dt`.
//!
//! Semi-implicit (symplectic) Euler: v ← v + g·dt, then x ← x + v·dt. Without
//! gravity it moves discs in exact straight lines; with gravity its energy
//! error stays bounded instead of growing. Each disc turns by ω·dt.
//!
//! It also measures the largest distance a disc moved, in its own radii: a
//! disc that moves more than its radius in one (sub)step can pass through
//! another unseen, which [`crate::warnings`] says.

use crate::particle::Particle;
use glam::DVec2;

/// Advances every disc by one step of length `dt` under uniform `gravity`;
/// returns the largest distance a disc moved, in its own radii.
pub fn integrate(particles: &mut [Particle], gravity: DVec2, dt: f64) -> f64 {
    let dv = gravity * dt;
    let step = |p: &mut Particle| {
        p.vel += dv;
        p.pos += p.vel * dt;
        p.angle += p.spin * dt;
        p.vel.length_squared() / (p.radius * p.radius)
    };
    // The largest |v|²/r², on four independent running maxima so that the
    // comparisons do not wait on each other.
    let mut worst = [0.0f64; 4];
    let mut quads = particles.chunks_exact_mut(4);
    for quad in &mut quads {
        for (w, p) in worst.iter_mut().zip(quad) {
            *w = w.max(step(p));
        }
    }
    for p in quads.into_remainder() {
        worst[0] = worst[0].max(step(p));
    }
    let worst = worst[0].max(worst[1]).max(worst[2].max(worst[3]));
    worst.sqrt() * dt
}
