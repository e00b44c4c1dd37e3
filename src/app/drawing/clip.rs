//! Cutting what is drawn at the box: an arrow may not run out through a
//! wall. Pure screen geometry, tested without a window.

use glam::DVec2;

/// The part of the segment from `a` to `b` inside the rectangle `lo`–`hi`
/// (Liang–Barsky), or `None` when none of it is. An end inside is returned
/// as it was, bit for bit.
pub fn clip_segment(a: DVec2, b: DVec2, lo: DVec2, hi: DVec2) -> Option<(DVec2, DVec2)> {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x - lo.x),
        (d.x, hi.x - a.x),
        (-d.y, a.y - lo.y),
        (d.y, hi.y - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    if t0 > t1 || t0.is_nan() || t1.is_nan() {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            a + d * t
        }
    };
    Some((at(t0), at(t1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_is_cut_at_the_rectangle_and_kept_whole_inside() {
        let (lo, hi) = (DVec2::ZERO, DVec2::new(10.0, 10.0));
        let inside = (DVec2::new(1.0, 1.0), DVec2::new(9.0, 3.0));
        assert_eq!(clip_segment(inside.0, inside.1, lo, hi), Some(inside));
        let (p, q) = clip_segment(DVec2::new(5.0, 5.0), DVec2::new(15.0, 5.0), lo, hi).unwrap();
        assert_eq!(p, DVec2::new(5.0, 5.0));
        assert!((q - DVec2::new(10.0, 5.0)).length() < 1e-12, "{q}");
        assert_eq!(
            clip_segment(DVec2::new(11.0, 1.0), DVec2::new(20.0, 1.0), lo, hi),
            None
        );
        let (p, q) = clip_segment(DVec2::new(-5.0, 5.0), DVec2::new(15.0, 5.0), lo, hi).unwrap();
        assert!((p.x - 0.0).abs() < 1e-12 && (q.x - 10.0).abs() < 1e-12);
    }
}
