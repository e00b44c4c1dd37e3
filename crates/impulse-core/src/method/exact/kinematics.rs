//! Exact event times: when two discs touch, when a coordinate under
//! constant acceleration reaches a value. Written to avoid cancellation.

use glam::DVec2;

/// Closing speed (m/s) below which two discs in contact are taken as not
/// approaching: a pair that creeps together at 10⁻¹² m/s would need a
/// million years to close a micrometre.
pub(super) const CREEP: f64 = 1e-12;

/// Time until two discs at separation `d` with relative velocity `dv`
/// touch (distance `sigma`), if they approach; zero if they already overlap
/// and approach; infinity if they never touch.
#[inline]
pub(super) fn pair_time(d: DVec2, dv: DVec2, sigma: f64) -> f64 {
    let terms = PairTerms::of(d, dv, sigma);
    if terms.meets() {
        terms.time()
    } else {
        f64::INFINITY
    }
}

/// What [`pair_time`] is made of, for a caller that skips the square root
/// and the division of a pair that never meets (most neighbours).
#[derive(Clone, Copy)]
pub(super) struct PairTerms {
    /// d·dv: negative while they approach.
    b: f64,
    /// |d|² − σ²: negative when they overlap.
    gap: f64,
    /// The quadratic's discriminant, b² − |dv|²·gap.
    disc: f64,
    sigma: f64,
}

impl PairTerms {
    #[inline]
    pub(super) fn of(d: DVec2, dv: DVec2, sigma: f64) -> Self {
        let b = d.dot(dv);
        let gap = d.length_squared() - sigma * sigma;
        let disc = b * b - dv.length_squared() * gap;
        PairTerms {
            b,
            gap,
            disc,
            sigma,
        }
    }

    /// Whether they touch while approaching. Without branches: whether a
    /// pair approaches is a coin toss a branch predictor cannot learn.
    #[inline]
    pub(super) fn meets(&self) -> bool {
        let overlapping = self.gap <= 0.0;
        // In contact, a pair closing slower than CREEP is not approaching
        // (round-off in a pile falling together would collide it forever).
        (self.b < 0.0)
            & (!overlapping | (self.b < -CREEP * self.sigma))
            & (overlapping | (self.disc > 0.0))
    }

    /// When they touch, if they [meet](PairTerms::meets): the smaller
    /// root, written without cancellation; zero if they overlap already.
    #[inline]
    pub(super) fn time(&self) -> f64 {
        if self.gap <= 0.0 {
            0.0
        } else {
            self.gap / (-self.b + self.disc.max(0.0).sqrt())
        }
    }
}

/// Time until two discs touch (distance `sigma`) when their separation
/// moves as `d + dv·t + ½·a·t²`: one disc falls while the other lies still
/// (asleep, see `sleep`), so their relative motion is a parabola and the
/// touching time a root of a quartic. Zero if they touch or overlap and
/// approach now; infinity if they never meet approaching.
///
/// The squared distance minus σ², f(t), is monotone between the roots of
/// its derivative (a cubic, solved in closed form and polished); the answer
/// is the start of the first falling stretch that begins in contact, or
/// the root inside the first falling stretch that ends in it (bisection,
/// to the last bit).
pub(super) fn accelerating_pair_time(d: DVec2, dv: DVec2, a: DVec2, sigma: f64) -> f64 {
    let c4 = 0.25 * a.length_squared();
    if c4 == 0.0 {
        return pair_time(d, dv, sigma);
    }
    let (c3, c2, c1) = (dv.dot(a), dv.length_squared() + d.dot(a), 2.0 * d.dot(dv));
    let c0 = d.length_squared() - sigma * sigma;
    let f = |t: f64| (((c4 * t + c3) * t + c2) * t + c1) * t + c0;
    let slope = |t: f64| ((4.0 * c4 * t + 3.0 * c3) * t + 2.0 * c2) * t + c1;
    let mut ends = [0.0; 5];
    let mut count = 1;
    for r in cubic_roots(3.0 * c3 / (4.0 * c4), c2 / (2.0 * c4), c1 / (4.0 * c4)) {
        if r > 0.0 && r.is_finite() {
            ends[count] = r;
            count += 1;
        }
    }
    ends[1..count].sort_unstable_by(f64::total_cmp);
    // The last stretch, to infinity, rises (c4 > 0): no contact begins there.
    for k in 0..count - 1 {
        let (lo, hi) = (ends[k], ends[k + 1]);
        if slope(0.5 * (lo + hi)) >= 0.0 {
            continue;
        }
        if f(lo) <= 0.0 {
            // In contact already and turning in: the contact begins when
            // they close at CREEP (f′ = −2σ·CREEP), found on the part of
            // the stretch where f′ still falls (up to the root of f″);
            // touching and never closing that fast, they only graze.
            let least = -2.0 * sigma * CREEP;
            if slope(lo) <= least {
                return lo;
            }
            let curve = |t: f64| (12.0 * c4 * t + 6.0 * c3) * t + 2.0 * c2;
            let mut deepest = hi;
            let (qa, qb, qc) = (12.0 * c4, 6.0 * c3, 2.0 * c2);
            let q = qb * qb - 4.0 * qa * qc;
            if q >= 0.0 {
                for r in [(-qb - q.sqrt()) / (2.0 * qa), (-qb + q.sqrt()) / (2.0 * qa)] {
                    if r > lo && r < deepest && curve(0.5 * (lo + r)) < 0.0 {
                        deepest = r;
                    }
                }
            }
            if slope(deepest) > least {
                continue;
            }
            return falling_root(|t| slope(t) - least, curve, lo, deepest).1;
        }
        if f(hi) < 0.0 {
            return falling_root(f, slope, lo, hi).0;
        }
    }
    f64::INFINITY
}

/// Where `g`, falling on [lo, hi] with g(lo) > 0 ≥ g(hi), crosses zero:
/// the last time found above it and the first at or below it, a bit or two
/// apart. Newton's method (`dg` is g′) inside the bracket, bisection where
/// a Newton step would leave it: about five evaluations instead of sixty.
fn falling_root(g: impl Fn(f64) -> f64, dg: impl Fn(f64) -> f64, lo: f64, hi: f64) -> (f64, f64) {
    let (mut above, mut below) = (lo, hi);
    let mut t = 0.5 * (lo + hi);
    for _ in 0..200 {
        if t <= above || t >= below {
            t = 0.5 * (above + below);
            if t <= above || t >= below {
                break; // the bracket is two neighbouring numbers
            }
        }
        let value = g(t);
        if value > 0.0 {
            above = t;
        } else {
            below = t;
        }
        let step = value / dg(t);
        let next = t - step;
        t = if step.is_finite() && next > above && next < below {
            next
        } else {
            0.5 * (above + below)
        };
    }
    (above, below)
}

/// The real roots of t³ + b·t² + c·t + d (one or three; NaN fills the
/// slots of missing ones), each polished by Newton's method.
fn cubic_roots(b: f64, c: f64, d: f64) -> [f64; 3] {
    let shift = b / 3.0;
    let p = c - b * shift;
    let q = 2.0 * shift * shift * shift - c * shift + d;
    let half_q = 0.5 * q;
    let third_p = p / 3.0;
    let disc = half_q * half_q + third_p * third_p * third_p;
    let mut roots = if disc > 0.0 {
        // One real root; the sum of two cube roots, the smaller found from
        // the larger so that nothing cancels.
        let u = crate::math::cbrt(-half_q - half_q.signum() * disc.sqrt());
        let x = if u == 0.0 { 0.0 } else { u - third_p / u };
        [x - shift, f64::NAN, f64::NAN]
    } else if p == 0.0 {
        [-shift, f64::NAN, f64::NAN]
    } else {
        let r = (-third_p).sqrt();
        let cos3 = (half_q / (third_p * r)).clamp(-1.0, 1.0);
        let phi = crate::math::acos(cos3) / 3.0;
        let third = 2.0 * std::f64::consts::PI / 3.0;
        [0.0, 1.0, 2.0].map(|k| 2.0 * r * crate::math::cos(phi - k * third) - shift)
    };
    for x in roots.iter_mut().filter(|x| x.is_finite()) {
        for _ in 0..3 {
            let value = ((*x + b) * *x + c) * *x + d;
            let slope = (3.0 * *x + 2.0 * b) * *x + c;
            if slope == 0.0 {
                break;
            }
            let next = *x - value / slope;
            if !next.is_finite() {
                break;
            }
            *x = next;
        }
    }
    roots
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
    fn cubic_roots_are_found_for_one_and_three_real_roots() {
        // (t − 1)(t − 2)(t − 3) = t³ − 6t² + 11t − 6.
        let mut r = cubic_roots(-6.0, 11.0, -6.0);
        r.sort_by(f64::total_cmp);
        for (got, want) in r.iter().zip([1.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-12, "{r:?}");
        }
        // (t − 2)(t² + 1): one real root.
        let r = cubic_roots(-2.0, 1.0, -2.0);
        assert!((r[0] - 2.0).abs() < 1e-12 && r[1].is_nan(), "{r:?}");
    }

    #[test]
    fn a_disc_dropped_onto_a_still_one_meets_it_when_the_fall_says() {
        let g = DVec2::new(0.0, -9.81);
        // Centre 3 above a still disc, both radius 0.5: it falls 2 m.
        let d = DVec2::new(0.0, -3.0); // from the falling disc to the still one
        let t = accelerating_pair_time(d, DVec2::ZERO, -g, 1.0);
        assert!((t - (4.0f64 / 9.81).sqrt()).abs() < 1e-12, "{t}");
        // Thrown sideways past it, high enough to clear it: never.
        let t = accelerating_pair_time(DVec2::new(-5.0, -0.5), DVec2::new(-100.0, 0.0), -g, 1.0);
        assert_eq!(t, f64::INFINITY);
        // Thrown up off its top: back down on it after 2v/g.
        let t = accelerating_pair_time(DVec2::new(0.0, -1.0), DVec2::new(0.0, -2.0), -g, 1.0);
        assert!((t - 4.0 / 9.81).abs() < 1e-9, "{t}");
        // Resting on it, a hair inside: as soon as it closes at CREEP.
        let t = accelerating_pair_time(DVec2::new(0.0, -(1.0 - 1e-15)), DVec2::ZERO, -g, 1.0);
        assert!((0.0..=2.0 * CREEP / 9.81).contains(&t), "{t}");
        // Grazing a still disc's side (touching, moving along it, pressed
        // on by nothing): never.
        let t = accelerating_pair_time(
            DVec2::new(-1.0, 0.0),
            DVec2::new(0.0, 0.0),
            DVec2::ZERO,
            1.0,
        );
        assert_eq!(t, f64::INFINITY);
        // A hair inside and rising too slowly to get out: the moment it turns.
        let t = accelerating_pair_time(
            DVec2::new(0.0, -(1.0 - 1e-9)),
            DVec2::new(0.0, -1e-6),
            -g,
            1.0,
        );
        assert!((t - 1e-6 / 9.81).abs() < 1e-12, "{t}");
    }

    #[test]
    fn the_quartic_time_agrees_with_stepping_the_fall() {
        // A disc thrown at an angle past a still one: the first instant the
        // centres come within σ, found by fine steps, and the formula's.
        let g = DVec2::new(0.0, -9.81);
        for (k, v) in [(1.0, 2.0), (2.0, 0.5), (-1.0, 3.0), (0.3, 0.0)]
            .into_iter()
            .enumerate()
        {
            let d = DVec2::new(1.5, -1.2 - 0.1 * k as f64);
            let dv = -DVec2::new(v.0, v.1);
            let t = accelerating_pair_time(d, dv, -g, 1.0);
            let h = 1e-6;
            let at = |t: f64| (d + dv * t - 0.5 * g * t * t).length();
            let stepped = (0..4_000_000)
                .map(|s| s as f64 * h)
                .find(|&s| at(s) <= 1.0)
                .unwrap_or(f64::INFINITY);
            if stepped.is_finite() {
                assert!((t - stepped).abs() <= h, "{k}: {t} vs {stepped}");
            } else {
                assert_eq!(t, f64::INFINITY, "{k}");
            }
        }
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
