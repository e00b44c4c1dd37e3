//! Resolution, the third stage: turn contacts into new velocities and positions.
//!
//! Velocities split along the contact normal n̂ and tangent t̂. Only the normal
//! parts change, by the one-dimensional collision law with restitution e:
//!
//! ```text
//! v'₁ₙ = ((m₁ − e·m₂)·v₁ₙ + (1 + e)·m₂·v₂ₙ) / (m₁ + m₂)
//! v'₂ₙ = ((m₂ − e·m₁)·v₂ₙ + (1 + e)·m₁·v₁ₙ) / (m₁ + m₂)
//! ```
//!
//! and only for pairs that approach (v₂ₙ − v₁ₙ < 0). A pair that already
//! separates is left alone, which is the cure for the seeds' "sticky problem"
//! (overlapping discs being bounced back into each other every frame).
//!
//! Overlap is then removed by moving the discs apart along n̂, each by a share
//! proportional to its inverse mass, so the centre of mass does not move.

use crate::narrow_phase::Contact;
use crate::particle::Particle;
use glam::DVec2;

/// What resolving one step's contacts did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ResolutionReport {
    /// Approaching pairs whose velocities were changed.
    pub collisions: usize,
    /// Deepest overlap found (m).
    pub max_overlap: f64,
}

/// Resolves `contacts` in order with particle restitution `restitution`.
pub fn resolve_contacts(
    particles: &mut [Particle],
    contacts: &[Contact],
    restitution: f64,
) -> ResolutionReport {
    let mut report = ResolutionReport::default();
    for c in contacts {
        let (a, b) = pair_mut(particles, c.i as usize, c.j as usize);
        if collide(a, b, c.normal, restitution) {
            report.collisions += 1;
        }
        push_apart(a, b, c.normal, c.depth);
        report.max_overlap = report.max_overlap.max(c.depth);
    }
    report
}

/// Applies the collision law along `normal` (from `a` to `b`) if the pair
/// approaches; returns whether it did.
pub fn collide(a: &mut Particle, b: &mut Particle, normal: DVec2, restitution: f64) -> bool {
    let (v1n, v2n) = (a.vel.dot(normal), b.vel.dot(normal));
    if v2n - v1n >= 0.0 {
        return false; // separating or resting: never re-resolved
    }
    let (m1, m2, e) = (a.mass, b.mass, restitution);
    let total = m1 + m2;
    let v1n_after = ((m1 - e * m2) * v1n + (1.0 + e) * m2 * v2n) / total;
    let v2n_after = ((m2 - e * m1) * v2n + (1.0 + e) * m1 * v1n) / total;
    // The tangential parts are untouched: only the normal components change.
    a.vel += (v1n_after - v1n) * normal;
    b.vel += (v2n_after - v2n) * normal;
    true
}

/// Moves `a` and `b` apart along `normal` by `depth` in total, split by
/// inverse mass so that m₁·Δx₁ + m₂·Δx₂ = 0.
pub fn push_apart(a: &mut Particle, b: &mut Particle, normal: DVec2, depth: f64) {
    let total = a.mass + b.mass;
    a.pos -= normal * (depth * b.mass / total);
    b.pos += normal * (depth * a.mass / total);
}

/// Two distinct mutable elements of a slice, `i < j`.
fn pair_mut(particles: &mut [Particle], i: usize, j: usize) -> (&mut Particle, &mut Particle) {
    debug_assert!(i < j, "pairs are ordered i < j");
    let (head, tail) = particles.split_at_mut(j);
    (&mut head[i], &mut tail[0])
}
