//! Mouse gestures on the world: drag-to-launch, and grab-and-fling.
//!
//! Pure logic over world coordinates (the window converts the mouse through
//! the camera first), so it is tested without a window.
//!
//! - Press on empty space and drag: a new disc is launched from the press
//!   point with velocity `LAUNCH_GAIN × drag` (drag in metres), placed on the
//!   nearest free spot so it never starts overlapping another disc.
//! - Press on a disc: it is held at the same offset from the cursor, kept
//!   inside the walls, and on release keeps the velocity of the recent mouse
//!   trajectory (metres per real second).
//! - A click (press and release without moving more than a few pixels) only
//!   selects: on empty space it launches nothing, on a disc it gives the disc
//!   back the velocity it had, so selecting a disc to read it never stops it.

use glam::DVec2;
use impulse::{Boundary, Color, Particle, Walls, World};
use std::collections::VecDeque;

/// Launch speed per metre of drag (1/s): a 2 m drag launches at 3 m/s.
pub const LAUNCH_GAIN: f64 = 1.5;
/// How much recent mouse history sets a fling's velocity (s); at a low
/// frame rate, three frames' worth, so a few samples always remain.
pub const TRAIL_SECONDS: f64 = 0.08;

/// What a newly launched disc looks like.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewDisc {
    /// Radius (m).
    pub radius: f64,
    /// Mass (kg).
    pub mass: f64,
}

/// With "size follows mass": the radius of a disc of `mass` kg at one
/// areal density for all, 1/(π·0.4²) ≈ 1.99 kg/m², so a 1 kg disc is 0.4 m
/// in radius and the radius grows as √m.
pub fn radius_for_mass(mass: f64) -> f64 {
    0.4 * mass.sqrt()
}

/// The gesture in progress.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Gesture {
    /// Nothing held.
    #[default]
    Idle,
    /// Dragging out a new disc from `start`.
    Launching {
        /// Where the press happened (world).
        start: DVec2,
        /// Drags shorter than this (m) are clicks.
        slop: f64,
    },
    /// Holding disc `index`, which sits at `cursor + offset`.
    Holding {
        /// The held disc.
        index: usize,
        /// Disc centre minus the grab point.
        offset: DVec2,
        /// Recent (real time, cursor world position) samples.
        trail: VecDeque<(f64, DVec2)>,
        /// The disc's velocity when it was grabbed.
        velocity_before: DVec2,
        /// Its position when it was grabbed.
        position_before: DVec2,
        /// Where the press happened (world).
        pressed_at: DVec2,
        /// Whether the cursor has gone further than `slop` from `pressed_at`.
        dragged: bool,
        /// Drags shorter than this (m) are clicks.
        slop: f64,
    },
    /// Dragging the tip of disc `index`'s velocity arrow: its velocity is
    /// (tip − centre) / `seconds`, the arrow's time scale.
    Aiming {
        /// The disc.
        index: usize,
        /// Seconds of travel the arrow shows.
        seconds: f64,
        /// Its velocity before; kept if the tip is let go where it was taken.
        velocity_before: DVec2,
        /// Whether the tip has been dragged at all.
        dragged: bool,
    },
}

/// What a release did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Released {
    /// Nothing was in progress.
    Nothing,
    /// A disc was launched; its index.
    Launched(usize),
    /// There was no free room for the new disc.
    NoRoom,
    /// A held disc was let go with this velocity.
    Flung(usize, DVec2),
    /// A disc was pressed and let go without moving: it is selected, and
    /// left exactly as it was.
    Clicked(usize),
    /// A disc's velocity was set by its arrow's tip.
    Aimed(usize, DVec2),
}

/// Launch velocity for a drag from `start` to `end` (world).
pub fn launch_velocity(start: DVec2, end: DVec2) -> DVec2 {
    (end - start) * LAUNCH_GAIN
}

/// Velocity of the cursor over the last `TRAIL_SECONDS` of samples.
pub fn trail_velocity(trail: &VecDeque<(f64, DVec2)>) -> DVec2 {
    let (Some(&(t1, p1)), Some(&(t0, p0))) = (trail.back(), trail.front()) else {
        return DVec2::ZERO;
    };
    let span = t1 - t0;
    if span > 1e-3 {
        (p1 - p0) / span
    } else {
        DVec2::ZERO
    }
}

impl Gesture {
    /// Starts a gesture at world point `at`; returns the disc grabbed, if any.
    /// Moves shorter than `slop` (m) count as a click.
    pub fn press(&mut self, world: &World, at: DVec2, now: f64, slop: f64) -> Option<usize> {
        match world.particle_at(at) {
            Some(index) => {
                let p = &world.particles[index];
                *self = Gesture::Holding {
                    index,
                    offset: p.pos - at,
                    trail: VecDeque::from([(now, at)]),
                    velocity_before: p.vel,
                    position_before: p.pos,
                    pressed_at: at,
                    dragged: false,
                    slop,
                };
                Some(index)
            }
            None => {
                *self = Gesture::Launching { start: at, slop };
                None
            }
        }
    }

    /// Starts dragging the tip of disc `index`'s velocity arrow (drawn
    /// `seconds` long).
    pub fn press_arrow_tip(&mut self, world: &World, index: usize, seconds: f64) {
        let velocity_before = world.particles.get(index).map_or(DVec2::ZERO, |p| p.vel);
        *self = Gesture::Aiming {
            index,
            seconds,
            velocity_before,
            dragged: false,
        };
    }

    /// Whether screen point `cursor` is within `reach` pixels of the tip of
    /// the velocity arrow of a disc at `centre` with velocity `tip_offset`
    /// (both already in screen pixels).
    pub fn near_tip(cursor: DVec2, centre: DVec2, tip_offset: DVec2, reach: f64) -> bool {
        tip_offset.length() > reach && cursor.distance(centre + tip_offset) <= reach
    }

    /// Follows the cursor; a held disc moves with it (inside the walls).
    pub fn drag(&mut self, world: &mut World, at: DVec2, now: f64) {
        if let Gesture::Aiming {
            index,
            seconds,
            dragged,
            ..
        } = self
        {
            if let Some(p) = world.particles.get_mut(*index) {
                let vel = (at - p.pos) / *seconds;
                *dragged |= vel != p.vel;
                p.vel = vel;
            }
            return;
        }
        if let Gesture::Holding {
            trail,
            pressed_at,
            dragged,
            slop,
            ..
        } = self
        {
            *dragged |= pressed_at.distance(at) > *slop;
            let frame_gap = trail.back().map_or(0.0, |&(t, _)| now - t);
            let window = TRAIL_SECONDS.max(3.0 * frame_gap);
            trail.push_back((now, at));
            while trail.len() > 2 && trail.front().is_some_and(|&(t, _)| now - t > window) {
                trail.pop_front();
            }
        }
        self.pin_held(world);
    }

    /// Puts a held disc back under the cursor with the cursor's velocity
    /// (after physics steps have moved it).
    pub fn pin_held(&self, world: &mut World) {
        let Gesture::Holding {
            index,
            offset,
            trail,
            ..
        } = self
        else {
            return;
        };
        let (Some(&(_, cursor)), size, edges) = (
            trail.back(),
            world.laws.size,
            (world.laws.boundary, world.laws.walls),
        ) else {
            return;
        };
        let velocity = trail_velocity(trail);
        if let Some(p) = world.particles.get_mut(*index) {
            p.pos = keep_inside(cursor + *offset, p.radius, size, edges);
            p.vel = velocity;
        }
    }

    /// Ends the gesture at `at`.
    pub fn release(&mut self, world: &mut World, at: DVec2, new_disc: NewDisc) -> Released {
        match std::mem::take(self) {
            Gesture::Idle => Released::Nothing,
            Gesture::Aiming {
                index,
                seconds,
                velocity_before,
                dragged,
            } => match world.particles.get_mut(index) {
                Some(p) => {
                    let vel = (at - p.pos) / seconds;
                    if !dragged && (vel - velocity_before).length() * seconds < 1e-9 {
                        p.vel = velocity_before; // taken and let go: nothing set
                        return Released::Nothing;
                    }
                    p.vel = vel;
                    Released::Aimed(index, p.vel)
                }
                None => Released::Nothing,
            },
            Gesture::Launching { start, slop } => {
                if start.distance(at) <= slop {
                    return Released::Nothing; // a click on empty space
                }
                let Some(pos) = world.free_spot_near(start, new_disc.radius) else {
                    return Released::NoRoom;
                };
                let color = Color::palette(world.particles.len());
                let vel = launch_velocity(start, at);
                world.particles.push(Particle::new(
                    pos,
                    vel,
                    new_disc.mass,
                    new_disc.radius,
                    color,
                ));
                Released::Launched(world.particles.len() - 1)
            }
            Gesture::Holding {
                index,
                trail,
                velocity_before,
                position_before,
                dragged,
                ..
            } => {
                let Some(p) = world.particles.get_mut(index) else {
                    return Released::Nothing;
                };
                if dragged {
                    p.vel = trail_velocity(&trail);
                    Released::Flung(index, p.vel)
                } else {
                    // A click selects; it neither stops nor moves the disc.
                    p.vel = velocity_before;
                    p.pos = position_before;
                    Released::Clicked(index)
                }
            }
        }
    }

    /// The held disc, if any.
    pub fn held(&self) -> Option<usize> {
        match self {
            Gesture::Holding { index, .. } => Some(*index),
            _ => None,
        }
    }

    /// Keeps indices right after disc `removed` was deleted.
    pub fn on_removed(&mut self, removed: usize) {
        if let Gesture::Holding { index, .. } = self {
            if *index == removed {
                *self = Gesture::Idle;
            } else if *index > removed {
                *index -= 1;
            }
        }
    }
}

/// Clamps a disc centre inside the box's walls (open sides and other
/// boundaries have none).
fn keep_inside(
    pos: DVec2,
    radius: f64,
    size: DVec2,
    (boundary, walls): (Boundary, Walls),
) -> DVec2 {
    match boundary {
        Boundary::Box => {
            let lo = DVec2::splat(radius).min(0.5 * size);
            let hi = size - lo;
            let mut out = pos;
            for axis in 0..2 {
                if walls.at(axis, false) {
                    out[axis] = out[axis].max(lo[axis]);
                }
                if walls.at(axis, true) {
                    out[axis] = out[axis].min(hi[axis]);
                }
            }
            out
        }
        Boundary::Periodic => pos.rem_euclid(size),
        Boundary::Open => pos,
    }
}

#[cfg(test)]
mod tests {
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
        g.press_arrow_tip(&w, 0, 0.5);
        g.drag(&mut w, centre + DVec2::new(1.0, 0.0), 0.0);
        assert_eq!(w.particles[0].vel, DVec2::new(2.0, 0.0));
        let r = g.release(&mut w, centre + DVec2::new(0.5, 0.5), NEW);
        assert_eq!(r, Released::Aimed(0, DVec2::new(1.0, 1.0)));
        assert_eq!(w.particles[0].vel, DVec2::new(1.0, 1.0));
        assert_eq!(w.particles[0].pos, centre, "aiming moves nothing");
        // Taken and let go where it was: nothing is set.
        let before = w.particles[0].vel;
        g.press_arrow_tip(&w, 0, 0.5);
        let r = g.release(&mut w, centre + before * 0.5, NEW);
        assert_eq!(r, Released::Nothing);
        assert_eq!(w.particles[0].vel, before);
    }
}
