//! What counts as a collision. An *impact* is a contact that closes faster
//! than [`threshold`]; slower ones are *resting contacts*: discs lying on
//! each other or on a wall, held up against gravity step after step. Every
//! method, the wall stage and the ledger ask this module, so the counters
//! count impacts and a pile at rest does not run up a count.
//!
//! Under gravity g a disc resting on a support gains g·h of speed towards it
//! in a (sub)step of h seconds and loses it again at the contact; anything
//! closing at a few times that came from a fall or a throw. Without gravity
//! nothing rests, and every approaching contact is an impact.

use glam::DVec2;

/// Closing speed, in units of g·h, below which a contact is resting.
pub const RESTING_SPEED: f64 = 4.0;

/// The closing speed (m/s) above which a contact is an impact, under
/// `gravity` with (sub)steps of `h` seconds.
pub fn threshold(gravity: DVec2, h: f64) -> f64 {
    RESTING_SPEED * gravity.length() * h
}

/// Whether a contact closing at `closing_speed` (m/s, positive when the
/// discs approach) is an impact, given the [`threshold`].
pub fn is_impact(closing_speed: f64, threshold: f64) -> bool {
    closing_speed > threshold
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn without_gravity_every_approach_is_an_impact() {
        let t = threshold(DVec2::ZERO, 0.01);
        assert_eq!(t, 0.0);
        assert!(is_impact(1e-12, t));
        assert!(!is_impact(0.0, t), "touching without closing is no impact");
    }

    #[test]
    fn under_gravity_a_fall_is_an_impact_and_a_steps_worth_of_speed_is_not() {
        let (g, h) = (DVec2::new(0.0, -9.81), 1.0 / 240.0);
        let t = threshold(g, h);
        assert!(!is_impact(9.81 * h, t), "one step of free fall: resting");
        // A fall from 1 cm: v = √(2·g·0.01) ≈ 0.44 m/s.
        assert!(is_impact((2.0 * 9.81 * 0.01f64).sqrt(), t));
    }
}
