//! Rough contacts: what an impact does along the contact, and so to spin.
//!
//! The standard rough-sphere model for uniform discs (I = ½·m·r²): besides
//! the normal restitution e, the relative velocity of the touching points
//! along the contact, g_t, becomes −β·g_t, with the tangential restitution
//! β from −1 (smooth: nothing changes, today's discs) to +1 (perfectly
//! rough: g_t reverses, energy kept). With a Coulomb coefficient μ the
//! tangential impulse is at most μ times the normal one (Walton's model),
//! which for uniform discs makes the effective β = min(β, −1 + 3μ(1+e)|g_n|/|g_t|).
//!
//! With n the unit normal from disc a to disc b and t = n rotated by +90°,
//! the touching points move apart along t at
//! g_t = (v_a − v_b)·t + ω_a·r_a + ω_b·r_b; an impulse P·t on a (and −P·t
//! on b, at the same point) changes g_t by P·(3/m_a + 3/m_b) (1/m for the
//! centre and r²/I = 2/m for the spin). Equal and opposite at one point, it
//! keeps the momentum and the angular momentum (orbital plus spin) exactly.
//! A wall is a disc of infinite mass at rest.
//!
//! Pure arithmetic on numbers and vectors: every method calls it with its
//! own storage.

use glam::DVec2;

/// The tangential law of a contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tangential {
    /// Tangential restitution β in [−1, 1]; −1 is smooth.
    pub beta: f64,
    /// Coulomb coefficient μ ≥ 0: |tangential impulse| ≤ μ·normal impulse.
    pub friction: Option<f64>,
}

/// One disc's side of a contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Side {
    /// Mass (kg).
    pub mass: f64,
    /// Radius (m).
    pub radius: f64,
    /// Velocity (m/s).
    pub vel: DVec2,
    /// Angular velocity (rad/s, counter-clockwise).
    pub spin: f64,
}

impl Tangential {
    /// Smooth discs: impacts change no spin and no tangential velocity.
    pub const SMOOTH: Tangential = Tangential {
        beta: -1.0,
        friction: None,
    };

    /// Whether impacts leave the tangential motion alone.
    pub fn is_smooth(&self) -> bool {
        self.beta == -1.0
    }

    /// The law of a resting contact: Coulomb friction, which drives the
    /// touching points to rest against each other (β = 0) with at most μ
    /// times the normal impulse; none without μ.
    pub fn resting(&self) -> Option<Tangential> {
        self.friction.map(|mu| Tangential {
            beta: 0.0,
            friction: Some(mu),
        })
    }

    /// The tangential impulse on disc a (along t) for the touching points
    /// moving apart at `g_t` along t, with `inverse_mass` the change of g_t
    /// per unit impulse (3/m_a + 3/m_b) and `normal_impulse` (≥ 0) the
    /// normal impulse of the same contact.
    pub fn impulse(&self, g_t: f64, inverse_mass: f64, normal_impulse: f64) -> f64 {
        let wanted = -(1.0 + self.beta) * g_t / inverse_mass;
        match self.friction {
            Some(mu) => wanted.clamp(-mu * normal_impulse, mu * normal_impulse),
            None => wanted,
        }
    }

    /// A pair contact with normal `n` (unit, from a to b) that took
    /// `normal_impulse` (≥ 0): the sides after the tangential impulse, or
    /// `None` where the law changes nothing.
    pub fn pair(&self, n: DVec2, normal_impulse: f64, a: Side, b: Side) -> Option<(Side, Side)> {
        if self.is_smooth() {
            return None;
        }
        let t = tangent(n);
        let g_t = (a.vel - b.vel).dot(t) + a.spin * a.radius + b.spin * b.radius;
        let p = self.impulse(g_t, 3.0 / a.mass + 3.0 / b.mass, normal_impulse);
        if p == 0.0 {
            return None;
        }
        // b is pushed by −p·t at its point −r_b·n: torque (−r_b·n) × (−p·t),
        // the same sign as a's.
        Some((kick(a, t, p, p), kick(b, t, -p, p)))
    }

    /// A disc against a still wall (or any immovable support) whose
    /// normal `n` points from the disc into it: the side after the
    /// tangential impulse, or `None` where the law changes nothing.
    pub fn wall(&self, n: DVec2, normal_impulse: f64, a: Side) -> Option<Side> {
        if self.is_smooth() {
            return None;
        }
        let t = tangent(n);
        let g_t = a.vel.dot(t) + a.spin * a.radius;
        let p = self.impulse(g_t, 3.0 / a.mass, normal_impulse);
        (p != 0.0).then(|| kick(a, t, p, p))
    }
}

/// The unit normal `n` turned a quarter counter-clockwise.
pub fn tangent(n: DVec2) -> DVec2 {
    n.perp()
}

/// Disc `a` after the impulse `p`·`t` at its point of contact, whose
/// torque is r·`turn` (I = ½·m·r², so ω changes by 2·turn/(m·r)).
fn kick(a: Side, t: DVec2, p: f64, turn: f64) -> Side {
    Side {
        vel: a.vel + t * (p / a.mass),
        spin: a.spin + 2.0 * turn / (a.mass * a.radius),
        ..a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn side(mass: f64, radius: f64, vel: [f64; 2], spin: f64) -> Side {
        Side {
            mass,
            radius,
            vel: DVec2::from(vel),
            spin,
        }
    }

    fn g_t(n: DVec2, a: Side, b: Side) -> f64 {
        (a.vel - b.vel).dot(tangent(n)) + a.spin * a.radius + b.spin * b.radius
    }

    #[test]
    fn the_touching_points_end_at_minus_beta_times_their_slip() {
        let n = DVec2::new(0.6, 0.8);
        let (a, b) = (
            side(2.0, 0.3, [1.0, -2.0], 3.0),
            side(0.5, 0.2, [-1.0, 0.5], -7.0),
        );
        for beta in [-0.5, 0.0, 0.4, 1.0] {
            let law = Tangential {
                beta,
                friction: None,
            };
            let (a2, b2) = law.pair(n, 1.0, a, b).unwrap();
            assert!((g_t(n, a2, b2) + beta * g_t(n, a, b)).abs() < 1e-12);
            // Momentum and angular momentum about the contact point kept.
            let p = a.mass * a.vel + b.mass * b.vel;
            let p2 = a2.mass * a2.vel + b2.mass * b2.vel;
            assert!((p - p2).length() < 1e-12);
            // Angular momentum about the origin, with a at the origin and
            // b at (r_a + r_b)·n: orbital plus spin.
            let xb = (a.radius + b.radius) * n;
            let l = |a: Side, b: Side| {
                let inertia = |s: Side| 0.5 * s.mass * s.radius * s.radius;
                b.mass * xb.perp_dot(b.vel) + inertia(a) * a.spin + inertia(b) * b.spin
            };
            assert!((l(a, b) - l(a2, b2)).abs() < 1e-12, "β = {beta}");
        }
    }

    #[test]
    fn coulomb_caps_the_tangential_impulse_at_mu_times_the_normal_one() {
        let law = Tangential {
            beta: 1.0,
            friction: Some(0.2),
        };
        let a = side(1.0, 1.0, [5.0, 0.0], 0.0);
        let out = law.wall(DVec2::new(0.0, -1.0), 2.0, a).unwrap();
        // The wall's tangent for n = −y is +x: the impulse opposes the slip.
        assert!((out.vel.x - (5.0 - 0.2 * 2.0)).abs() < 1e-12);
        assert!((out.spin - 2.0 * (-0.4)).abs() < 1e-12);
    }

    #[test]
    fn smooth_discs_are_left_alone() {
        let a = side(1.0, 1.0, [5.0, 1.0], 2.0);
        assert_eq!(Tangential::SMOOTH.wall(DVec2::X, 3.0, a), None);
        assert_eq!(Tangential::SMOOTH.pair(DVec2::X, 3.0, a, a), None);
        assert_eq!(Tangential::SMOOTH.resting(), None);
    }
}
