//! Exact event times: when two discs touch, when a coordinate under
//! constant acceleration reaches a value. Written to avoid cancellation.

use glam::DVec2;

/// Time until two discs at separation `d` with relative velocity `dv`
/// touch (distance `sigma`), if they approach; zero if they already overlap
/// and approach; infinity if they never touch. Computed without branches
/// (the prediction loop runs it for every neighbour, and whether a pair
/// approaches is a coin toss a branch predictor cannot learn).
#[inline]
pub(super) fn pair_time(d: DVec2, dv: DVec2, sigma: f64) -> f64 {
    let b = d.dot(dv);
    let gap = d.length_squared() - sigma * sigma;
    let disc = b * b - dv.length_squared() * gap;
    let overlapping = gap <= 0.0;
    let meets = b < 0.0 && (overlapping | (disc > 0.0));
    let t = if overlapping {
        0.0
    } else {
        gap / (-b + disc.max(0.0).sqrt())
    };
    if meets {
        t
    } else {
        f64::INFINITY
    }
}

/// First time ≥ 0 at which a coordinate `p` moving at `v` with acceleration
/// `g` reaches `target` while moving in the direction `sign` (−1 down, +1 up).
pub(super) fn first_crossing(p: f64, v: f64, g: f64, target: f64, sign: f64) -> Option<f64> {
    let beyond = sign * (p - target) >= 0.0;
    if beyond && (sign * v > 0.0 || (v == 0.0 && sign * g > 0.0)) {
        return Some(0.0);
    }
    if g == 0.0 {
        if sign * v <= 0.0 {
            return None;
        }
        let tau = (target - p) / v;
        return (tau >= 0.0).then_some(tau);
    }
    let disc = v * v - 2.0 * g * (p - target);
    if disc < 0.0 {
        return None;
    }
    let root_velocity = sign * disc.sqrt(); // velocity at the crossing
    let tau = if root_velocity * v > 0.0 {
        2.0 * (p - target) / (-v - root_velocity)
    } else {
        (root_velocity - v) / g
    };
    // Zero here is a disc on the line at rest, or turning there, with
    // gravity pulling it back: it does not cross (the crossings at once
    // were answered above). Taking it for one sent a disc at rest on a cell
    // border to and fro between the two cells forever.
    (tau > 0.0 && tau.is_finite()).then_some(tau)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_disc_at_rest_on_a_line_crosses_it_only_the_way_gravity_pulls() {
        let g = -9.81;
        // Downward crossing of the line it sits on: at once.
        assert_eq!(first_crossing(2.0, 0.0, g, 2.0, -1.0), Some(0.0));
        // Upward: never (it was crossed back at t = 0 and looped forever).
        assert_eq!(first_crossing(2.0, 0.0, g, 2.0, 1.0), None);
        // Thrown up from the line: back down through it after 2v/g.
        let t = first_crossing(2.0, 3.0, g, 2.0, -1.0).unwrap();
        assert!((t - 6.0 / 9.81).abs() < 1e-12, "{t}");
    }

    #[test]
    pub(super) fn pair_time_matches_straight_line_contact() {
        // Discs 10 apart, closing at 2: touch when 1 apart, after 4.5.
        let t = pair_time(DVec2::new(10.0, 0.0), DVec2::new(-2.0, 0.0), 1.0);
        assert!((t - 4.5).abs() < 1e-12);
        let never = f64::INFINITY;
        assert_eq!(
            pair_time(DVec2::new(10.0, 0.0), DVec2::new(2.0, 0.0), 1.0),
            never,
            "receding"
        );
        assert_eq!(
            pair_time(DVec2::new(10.0, 5.0), DVec2::new(-2.0, 0.0), 1.0),
            never,
            "miss"
        );
        assert_eq!(
            pair_time(DVec2::new(10.0, 1.0), DVec2::new(-2.0, 0.0), 1.0),
            never,
            "grazing"
        );
        assert_eq!(
            pair_time(DVec2::new(0.5, 0.0), DVec2::new(-1.0, 0.0), 1.0),
            0.0,
            "overlapping and approaching"
        );
        assert_eq!(
            pair_time(DVec2::new(0.5, 0.0), DVec2::new(1.0, 0.0), 1.0),
            never,
            "overlapping and separating"
        );
    }

    #[test]
    fn crossing_times_under_gravity() {
        // Dropped from 5 onto a floor contact at 1: t = sqrt(2·4/9.81).
        let t = first_crossing(5.0, 0.0, -9.81, 1.0, -1.0).unwrap();
        assert!((t - (8.0f64 / 9.81).sqrt()).abs() < 1e-12);
        // Thrown up at 3 from the floor: back after 2·3/9.81, not at once.
        let t = first_crossing(1.0, 3.0, -9.81, 1.0, -1.0).unwrap();
        assert!((t - 6.0 / 9.81).abs() < 1e-12);
        // Reaching a ceiling it cannot reach.
        assert_eq!(first_crossing(1.0, 3.0, -9.81, 10.0, 1.0), None);
        // Small time to a nearby border, no cancellation.
        let t = first_crossing(0.0, 1e3, -9.81, 1e-9, 1.0).unwrap();
        assert!((t - 1e-12).abs() < 1e-20);
    }
}
