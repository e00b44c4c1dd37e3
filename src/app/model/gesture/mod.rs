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
//!   trajectory (metres per real second); let go over another disc, it goes
//!   to the nearest free spot.
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
        /// Where the press happened (world).
        pressed_at: DVec2,
        /// Moves shorter than this (m) are a click, which sets nothing.
        slop: f64,
        /// Whether the cursor has gone further than `slop` from `pressed_at`.
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

/// In a one-dimensional world, the axis across its line: a gesture moves
/// nothing across it (the step took a velocity across the line away, and
/// the kinetic energy shown fell with no collision).
fn across_line(world: &World) -> Option<usize> {
    world.laws.constrain.map(|axis| axis.locked())
}

/// `v` without its part across the line (`across`), if there is one.
fn along_line(across: Option<usize>, mut v: DVec2) -> DVec2 {
    if let Some(c) = across {
        v[c] = 0.0;
    }
    v
}

/// The free spot for a disc of `radius` nearest to `wanted`, or `None` in
/// a world too crowded; in one dimension on the line through `wanted`,
/// searched both ways along it.
fn free_spot(world: &World, wanted: DVec2, radius: f64, across: Option<usize>) -> Option<DVec2> {
    let Some(c) = across else {
        return world.free_spot_near(wanted, radius);
    };
    let along = 1 - c;
    let (step, length) = (0.05 * radius, world.laws.size[along]);
    let steps = (length / step).ceil().min(1e5) as usize;
    (0..=steps)
        .flat_map(|k| [1.0, -1.0].map(|sign| sign * k as f64 * step))
        .map(|shift| {
            let mut spot = wanted;
            spot[along] += shift;
            if world.laws.boundary == Boundary::Periodic {
                spot[along] = spot[along].rem_euclid(length);
            }
            spot
        })
        .find(|&spot| world.is_free(spot, radius))
}

/// Where a drag from `start` to `at` launches a disc of `radius`, and how
/// fast: the nearest free spot (`None`: no room), in one dimension on the
/// discs' line (off it, the disc moved along a line of its own and met
/// none of them) and along it. The preview drawn during the drag shows
/// this, so the disc comes where its ghost was.
pub fn planned_launch(
    world: &World,
    start: DVec2,
    at: DVec2,
    radius: f64,
) -> (Option<DVec2>, DVec2) {
    let across = across_line(world);
    let mut wanted = start;
    if let Some(c) = across {
        let middle = 0.5 * world.laws.size[c];
        wanted[c] = world.particles.first().map_or(middle, |p| p.pos[c]);
    }
    let spot = free_spot(world, wanted, radius, across);
    (spot, along_line(across, launch_velocity(start, at)))
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
    /// A press at `at` closer than `slop` (m) to where it is let go is a
    /// click: the velocity stays as it was.
    pub fn press_arrow_tip(
        &mut self,
        world: &World,
        index: usize,
        seconds: f64,
        (at, slop): (DVec2, f64),
    ) {
        let velocity_before = world.particles.get(index).map_or(DVec2::ZERO, |p| p.vel);
        *self = Gesture::Aiming {
            index,
            seconds,
            velocity_before,
            pressed_at: at,
            slop,
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
            pressed_at,
            slop,
            dragged,
            ..
        } = self
        {
            *dragged |= pressed_at.distance(at) > *slop;
            let across = across_line(world);
            if let (true, Some(p)) = (*dragged, world.particles.get_mut(*index)) {
                p.vel = along_line(across, (at - p.pos) / *seconds);
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
        let across = across_line(world);
        let velocity = along_line(across, trail_velocity(trail));
        if let Some(p) = world.particles.get_mut(*index) {
            let line = p.pos;
            p.pos = keep_inside(cursor + *offset, p.radius, size, edges);
            if let Some(c) = across {
                p.pos[c] = line[c]; // held on its line
            }
            p.vel = velocity;
        }
    }

    /// Ends the gesture at `at`.
    pub fn release(&mut self, world: &mut World, at: DVec2, new_disc: NewDisc) -> Released {
        let across = across_line(world);
        match std::mem::take(self) {
            Gesture::Idle => Released::Nothing,
            Gesture::Aiming {
                index,
                seconds,
                velocity_before,
                pressed_at,
                slop,
                dragged,
            } => match world.particles.get_mut(index) {
                Some(p) => {
                    if !(dragged || pressed_at.distance(at) > slop) {
                        p.vel = velocity_before; // taken and let go: nothing set
                        return Released::Clicked(index);
                    }
                    p.vel = along_line(across, (at - p.pos) / seconds);
                    Released::Aimed(index, p.vel)
                }
                None => Released::Nothing,
            },
            Gesture::Launching { start, slop } => {
                if start.distance(at) <= slop {
                    return Released::Nothing; // a click on empty space
                }
                let (spot, vel) = planned_launch(world, start, at, new_disc.radius);
                let Some(pos) = spot else {
                    return Released::NoRoom;
                };
                let color = Color::palette(world.particles.len());
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
                    let velocity = along_line(across, trail_velocity(&trail));
                    p.vel = velocity;
                    // Let go over another disc (easy while paused): to the
                    // nearest free spot, or back where it was picked up.
                    let mut held = world.particles.remove(index);
                    held.pos =
                        free_spot(world, held.pos, held.radius, across).unwrap_or(position_before);
                    world.particles.insert(index, held);
                    Released::Flung(index, velocity)
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
        if let Gesture::Holding { index, .. } | Gesture::Aiming { index, .. } = self {
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
mod tests;
