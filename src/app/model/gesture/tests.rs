//! Gestures on a world without a window.

use super::*;

const NEW: NewDisc = NewDisc {
    radius: 0.5,
    mass: 1.0,
};
const SLOP: f64 = 0.02;

fn world() -> World {
    let mut w = World::new(DVec2::new(10.0, 10.0));
    w.particles.push(Particle::new(
        DVec2::new(5.0, 5.0),
        DVec2::ZERO,
        2.0,
        1.0,
        Color::palette(0),
    ));
    w
}

#[test]
fn drag_on_empty_space_launches_along_the_drag() {
    let mut w = world();
    let mut g = Gesture::default();
    assert_eq!(g.press(&w, DVec2::new(2.0, 2.0), 0.0, SLOP), None);
    g.drag(&mut w, DVec2::new(3.0, 4.0), 0.1);
    let r = g.release(&mut w, DVec2::new(3.0, 4.0), NEW);
    assert_eq!(r, Released::Launched(1));
    let p = w.particles[1];
    assert_eq!(p.pos, DVec2::new(2.0, 2.0));
    assert_eq!(p.vel, DVec2::new(1.0, 2.0) * LAUNCH_GAIN);
}

#[test]
fn a_launch_never_overlaps_another_disc() {
    let mut w = world();
    let mut g = Gesture::default();
    // Just outside the big disc: a new disc here would overlap it.
    g.press(&w, DVec2::new(6.2, 5.0), 0.0, SLOP);
    assert_eq!(
        g.release(&mut w, DVec2::new(6.3, 5.0), NEW),
        Released::Launched(1)
    );
    let (a, b) = (w.particles[0], w.particles[1]);
    assert!(a.pos.distance(b.pos) >= a.radius + b.radius);
    assert!(b.pos.distance(DVec2::new(6.2, 5.0)) < 0.5, "placed nearby");
}

#[test]
fn no_room_is_reported_not_forced() {
    let mut w = World::new(DVec2::new(1.0, 1.0));
    w.particles.push(Particle::new(
        DVec2::splat(0.5),
        DVec2::ZERO,
        1.0,
        0.5,
        Color::palette(0),
    ));
    let mut g = Gesture::default();
    g.press(&w, DVec2::new(0.05, 0.05), 0.0, SLOP);
    assert_eq!(
        g.release(&mut w, DVec2::new(0.1, 0.05), NEW),
        Released::NoRoom
    );
    assert_eq!(w.particles.len(), 1);
}

#[test]
fn a_grab_keeps_its_offset_and_a_fling_keeps_the_trajectory_velocity() {
    let mut w = world();
    let mut g = Gesture::default();
    assert_eq!(g.press(&w, DVec2::new(5.5, 5.0), 0.0, SLOP), Some(0));
    for k in 1..=10 {
        let t = k as f64 * 0.01;
        g.drag(&mut w, DVec2::new(5.5 + 2.0 * t, 5.0 - 1.0 * t), t);
    }
    let p = w.particles[0];
    assert!(
        (p.pos - DVec2::new(5.7 - 0.5, 4.9)).length() < 1e-12,
        "offset kept: {}",
        p.pos
    );
    match g.release(&mut w, DVec2::new(5.7, 4.9), NEW) {
        Released::Flung(0, v) => assert!((v - DVec2::new(2.0, -1.0)).length() < 1e-9, "{v}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_held_disc_stays_inside_the_walls() {
    let mut w = world();
    let mut g = Gesture::default();
    g.press(&w, DVec2::new(5.0, 5.0), 0.0, SLOP);
    g.drag(&mut w, DVec2::new(-30.0, 50.0), 0.05);
    let p = w.particles[0];
    assert_eq!(p.pos, DVec2::new(1.0, 9.0));
}

#[test]
fn a_still_cursor_drops_the_disc_at_rest() {
    let mut w = world();
    let mut g = Gesture::default();
    g.press(&w, DVec2::new(5.0, 5.0), 0.0, SLOP);
    g.drag(&mut w, DVec2::new(6.0, 5.0), 0.05);
    g.drag(&mut w, DVec2::new(6.0, 5.0), 0.5);
    g.drag(&mut w, DVec2::new(6.0, 5.0), 0.6);
    assert_eq!(
        g.release(&mut w, DVec2::new(6.0, 5.0), NEW),
        Released::Flung(0, DVec2::ZERO)
    );
}

#[test]
fn a_fling_at_a_low_frame_rate_keeps_its_velocity() {
    // Five frames a second: the cursor moved until the last frame.
    let mut w = world();
    let mut g = Gesture::default();
    g.press(&w, DVec2::new(5.0, 5.0), 0.0, SLOP);
    for k in 1..=3 {
        let t = 0.2 * k as f64;
        g.drag(&mut w, DVec2::new(5.0 + t, 5.0), t);
    }
    g.drag(&mut w, DVec2::new(5.6, 5.0), 0.8);
    match g.release(&mut w, DVec2::new(5.6, 5.0), NEW) {
        Released::Flung(0, v) => assert!(v.x > 0.4, "{v}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_click_selects_without_launching_or_stopping() {
    let mut w = world();
    w.particles[0].vel = DVec2::new(1.0, -2.0);
    let mut g = Gesture::default();
    g.press(&w, DVec2::new(2.0, 2.0), 0.0, SLOP);
    assert_eq!(
        g.release(&mut w, DVec2::new(2.01, 2.0), NEW),
        Released::Nothing
    );
    assert_eq!(
        w.particles.len(),
        1,
        "a click on empty space launches nothing"
    );
    assert_eq!(g.press(&w, DVec2::new(5.2, 5.0), 0.0, SLOP), Some(0));
    g.drag(&mut w, DVec2::new(5.21, 5.0), 0.2);
    let r = g.release(&mut w, DVec2::new(5.21, 5.0), NEW);
    assert_eq!(r, Released::Clicked(0), "a click is a click");
    assert_eq!(
        w.particles[0].vel,
        DVec2::new(1.0, -2.0),
        "it keeps the velocity"
    );
    assert_eq!(w.particles[0].pos, DVec2::new(5.0, 5.0), "and the place");
}

#[test]
fn dragging_the_arrow_tip_sets_the_velocity_it_draws() {
    let mut w = world();
    let centre = w.particles[0].pos;
    // The tip is hit only near it, and only on an arrow longer than the reach.
    let tip = DVec2::new(40.0, 0.0);
    assert!(Gesture::near_tip(
        DVec2::new(105.0, 3.0),
        DVec2::new(60.0, 0.0),
        tip,
        10.0
    ));
    assert!(!Gesture::near_tip(
        DVec2::new(80.0, 0.0),
        DVec2::new(60.0, 0.0),
        tip,
        10.0
    ));
    assert!(!Gesture::near_tip(
        DVec2::ZERO,
        DVec2::ZERO,
        DVec2::new(5.0, 0.0),
        10.0
    ));
    let mut g = Gesture::default();
    g.press_arrow_tip(&w, 0, 0.5, (centre, SLOP));
    g.drag(&mut w, centre + DVec2::new(1.0, 0.0), 0.0);
    assert_eq!(w.particles[0].vel, DVec2::new(2.0, 0.0));
    let r = g.release(&mut w, centre + DVec2::new(0.5, 0.5), NEW);
    assert_eq!(r, Released::Aimed(0, DVec2::new(1.0, 1.0)));
    assert_eq!(w.particles[0].vel, DVec2::new(1.0, 1.0));
    assert_eq!(w.particles[0].pos, centre, "aiming moves nothing");
    // Taken near the tip and let go there: nothing is set, even off the
    // tip by a few pixels.
    let before = w.particles[0].vel;
    let near = centre + before * 0.5 + DVec2::new(0.01, 0.0);
    g.press_arrow_tip(&w, 0, 0.5, (near, SLOP));
    g.drag(&mut w, near, 0.1);
    let r = g.release(&mut w, near, NEW);
    assert_eq!(r, Released::Clicked(0));
    assert_eq!(w.particles[0].vel, before);
}

/// In a one-dimensional world (along x) no gesture moves a disc across the
/// line, nor gives it a velocity across it: a launch goes onto the discs'
/// line, a held disc slides along it, a fling and an aimed arrow keep v_y
/// at 0 (the step took it away, and the kinetic energy shown fell).
#[test]
fn in_one_dimension_gestures_keep_to_the_line() {
    let mut w = world();
    w.laws.constrain = Some(impulse::Axis::X);
    let mut g = Gesture::default();
    g.press(&w, DVec2::new(1.5, 3.0), 0.0, SLOP);
    let r = g.release(&mut w, DVec2::new(2.5, 4.0), NEW);
    assert_eq!(r, Released::Launched(1));
    let p = w.particles[1];
    assert_eq!(p.pos, DVec2::new(1.5, 5.0), "on the first disc's line");
    assert_eq!(p.vel, DVec2::new(1.0, 0.0) * LAUNCH_GAIN);
    // Held and flung diagonally.
    assert_eq!(g.press(&w, DVec2::new(5.0, 5.0), 0.0, SLOP), Some(0));
    for k in 1..=5 {
        let t = 0.02 * f64::from(k);
        g.drag(&mut w, DVec2::new(5.0 + t, 5.0 + 2.0 * t), t);
        assert_eq!(w.particles[0].pos.y, 5.0, "held on its line");
    }
    let r = g.release(&mut w, DVec2::new(5.1, 5.2), NEW);
    let Released::Flung(0, v) = r else {
        panic!("{r:?}")
    };
    assert!(v.x > 0.0 && v.y == 0.0, "{v}");
    // Its arrow's tip dragged up and right.
    let centre = w.particles[0].pos;
    g.press_arrow_tip(&w, 0, 0.5, (centre, SLOP));
    g.drag(&mut w, centre + DVec2::new(1.0, 1.0), 0.2);
    assert_eq!(w.particles[0].vel.y, 0.0);
    let r = g.release(&mut w, centre + DVec2::new(1.0, 1.0), NEW);
    assert_eq!(r, Released::Aimed(0, DVec2::new(2.0, 0.0)));
}

/// A disc let go over another (paused, nothing pushes them apart) goes to
/// the nearest free spot: the next step had shoved the two apart, out of
/// nothing, and a student read the energy it made.
#[test]
fn a_disc_let_go_over_another_goes_to_the_nearest_free_spot() {
    for line in [false, true] {
        let mut w = world();
        w.particles.push(Particle::new(
            DVec2::new(2.0, 5.0),
            DVec2::ZERO,
            1.0,
            0.5,
            Color::palette(1),
        ));
        if line {
            w.laws.constrain = Some(impulse::Axis::X);
        }
        let mut g = Gesture::default();
        assert_eq!(g.press(&w, DVec2::new(2.0, 5.0), 0.0, SLOP), Some(1));
        // Onto the big disc's centre, a little above it.
        g.drag(&mut w, DVec2::new(4.8, 5.2), 0.1);
        g.drag(&mut w, DVec2::new(4.8, 5.2), 0.3);
        assert!(matches!(
            g.release(&mut w, DVec2::new(4.8, 5.2), NEW),
            Released::Flung(1, _)
        ));
        let (big, small) = (w.particles[0], w.particles[1]);
        let gap = big.pos.distance(small.pos) - (big.radius + small.radius);
        assert!((0.0..0.2).contains(&gap), "line {line}: gap {gap}");
        if line {
            assert_eq!(small.pos.y, 5.0, "on its line");
            assert!(
                small.pos.x < 5.0,
                "on the side it came from: {}",
                small.pos.x
            );
        }
    }
}

/// The ghost drawn during a drag is the disc the release launches, where
/// it comes and how fast: on a one-dimensional world's line it had been
/// drawn off the line with a slanting arrow ("3.86 m/s"), and came on the
/// line at 3.46 m/s.
#[test]
fn the_launch_planned_during_a_drag_is_the_one_released() {
    for line in [false, true] {
        let mut w = world();
        if line {
            w.laws.constrain = Some(impulse::Axis::X);
        }
        let (start, end) = (DVec2::new(2.0, 7.0), DVec2::new(0.5, 8.0));
        let (spot, velocity) = planned_launch(&w, start, end, NEW.radius);
        let mut g = Gesture::default();
        g.press(&w, start, 0.0, SLOP);
        g.drag(&mut w, end, 0.1);
        assert_eq!(g.release(&mut w, end, NEW), Released::Launched(1));
        let p = w.particles[1];
        assert_eq!((Some(p.pos), p.vel), (spot, velocity), "line {line}");
        if line {
            assert_eq!((p.pos.y, p.vel.y), (5.0, 0.0), "on the line, along it");
        }
    }
}
