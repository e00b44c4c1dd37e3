//! Collisions at the same instant: a disc that meets two others at once.
//!
//! Resolving such contacts one after the other gives an answer that depends
//! on the order and breaks mirror symmetry (a disc arriving exactly between
//! two touching discs leaves them with different speeds: 81 % of the
//! arrival speed of asymmetry in the stress suite). Instead, each contact's
//! impulse is computed as if it were alone, from the velocities before any
//! of them, and all are applied together scaled by one factor λ chosen so
//! that the kinetic energy changes by exactly the sum of the pairwise
//! losses ½·μ·(1 − e²)·u² (none for e = 1). Impulses are equal and opposite,
//! so momentum is kept; the rule is symmetric because nothing in it depends
//! on order; and for a single contact λ = 1, the ordinary collision law.

use glam::DVec2;

/// A contact between bodies `a` and `b` with unit `normal` from a to b.
#[derive(Clone, Copy, Debug)]
pub(super) struct Touch {
    pub a: usize,
    pub b: usize,
    pub normal: DVec2,
}

/// New velocities for bodies with `masses` and `velocities` after the
/// simultaneous collisions `touches` with restitution `e`. Contacts that do
/// not approach get no impulse.
pub(super) fn simultaneous_velocities(
    masses: &[f64],
    velocities: &[DVec2],
    touches: &[Touch],
    e: f64,
) -> Vec<DVec2> {
    let mut change = vec![DVec2::ZERO; velocities.len()];
    let mut loss = 0.0;
    for t in touches {
        let u = (velocities[t.b] - velocities[t.a]).dot(t.normal);
        if u >= 0.0 {
            continue;
        }
        let (ma, mb) = (masses[t.a], masses[t.b]);
        let reduced = ma * mb / (ma + mb);
        let impulse = (1.0 + e) * reduced * -u;
        change[t.a] -= t.normal * (impulse / ma);
        change[t.b] += t.normal * (impulse / mb);
        loss += 0.5 * reduced * (1.0 - e * e) * u * u;
    }
    // KE(λ) − KE₀ = λ·linear + λ²·quadratic; solve for −loss.
    let (mut linear, mut quadratic) = (0.0, 0.0);
    for ((&m, v), w) in masses.iter().zip(velocities).zip(&change) {
        linear += m * v.dot(*w);
        quadratic += 0.5 * m * w.length_squared();
    }
    let lambda = if quadratic > 0.0 {
        let discriminant = linear * linear - 4.0 * quadratic * loss;
        if discriminant >= 0.0 {
            (-linear + discriminant.sqrt()) / (2.0 * quadratic)
        } else {
            -linear / (2.0 * quadratic) // the most the impulses can take out
        }
    } else {
        0.0
    };
    velocities
        .iter()
        .zip(&change)
        .map(|(v, w)| *v + lambda * *w)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::resolution::collision_velocities;

    fn energy(m: &[f64], v: &[DVec2]) -> f64 {
        m.iter()
            .zip(v)
            .map(|(m, v)| 0.5 * m * v.length_squared())
            .sum()
    }

    fn momentum(m: &[f64], v: &[DVec2]) -> DVec2 {
        m.iter().zip(v).map(|(m, v)| *m * *v).sum()
    }

    #[test]
    fn one_contact_is_the_ordinary_collision_law() {
        let (m, v) = ([1.0, 3.0], [DVec2::new(2.0, 0.5), DVec2::new(-1.0, 0.2)]);
        let n = DVec2::new(0.8, 0.6);
        for e in [1.0, 0.5, 0.0] {
            let out = simultaneous_velocities(
                &m,
                &v,
                &[Touch {
                    a: 0,
                    b: 1,
                    normal: n,
                }],
                e,
            );
            let (va, vb) = collision_velocities(m[0], m[1], v[0], v[1], n, e);
            assert!((out[0] - va).length() < 1e-12 && (out[1] - vb).length() < 1e-12);
        }
    }

    #[test]
    fn a_disc_between_two_leaves_them_mirrored_keeping_momentum_and_energy() {
        // A arrives along x between B (above) and C (below).
        let s = 0.75f64.sqrt();
        let (m, v) = ([1.0, 1.0, 1.0], [DVec2::X, DVec2::ZERO, DVec2::ZERO]);
        let touches = [
            Touch {
                a: 0,
                b: 1,
                normal: DVec2::new(s, 0.5),
            },
            Touch {
                a: 0,
                b: 2,
                normal: DVec2::new(s, -0.5),
            },
        ];
        for e in [1.0, 0.5] {
            let out = simultaneous_velocities(&m, &v, &touches, e);
            assert!(out[0].y.abs() < 1e-15);
            assert!((out[1].x - out[2].x).abs() < 1e-15 && (out[1].y + out[2].y).abs() < 1e-15);
            assert!((momentum(&m, &out) - momentum(&m, &v)).length() < 1e-15);
            // Energy falls by exactly the two pairwise losses.
            let u = s; // approach speed along each normal
            let loss = 2.0 * 0.5 * 0.5 * (1.0 - e * e) * u * u;
            assert!((energy(&m, &v) - energy(&m, &out) - loss).abs() < 1e-12);
            // Nobody keeps approaching.
            for t in &touches {
                assert!((out[t.b] - out[t.a]).dot(t.normal) >= -1e-12);
            }
        }
    }
}
