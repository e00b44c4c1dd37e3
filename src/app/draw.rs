//! Drawing the world: walls, discs (batched, [`super::discs`]), velocity and
//! momentum arrows (only readable ones, [`super::cull`]) and the launch
//! preview; the readouts are in [`super::readouts`]. Everything goes through
//! the camera.

use super::camera::Camera;
use super::cull::{arrow_readable, circle_on_screen, MIN_DISC_PIXELS};
use super::discs::{self, DiscBatch};
use super::interaction::{launch_velocity, NewDisc};
use glam::DVec2;
use impulse::{Boundary, World};
use macroquad::prelude::*;

/// Arrows show where a disc will be this many seconds from now.
pub const ARROW_SECONDS: f64 = 0.5;

/// Which discs carry a text readout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReadoutScope {
    /// None.
    Off,
    /// Only the selected disc.
    Selected,
    /// Every disc on screen.
    All,
}

impl ReadoutScope {
    /// Off → Selected → All → Off.
    pub fn next(self) -> Self {
        match self {
            ReadoutScope::Off => ReadoutScope::Selected,
            ReadoutScope::Selected => ReadoutScope::All,
            ReadoutScope::All => ReadoutScope::Off,
        }
    }

    /// "off", "selected" or "all".
    pub fn name(self) -> &'static str {
        match self {
            ReadoutScope::Off => "off",
            ReadoutScope::Selected => "selected",
            ReadoutScope::All => "all",
        }
    }
}

/// The overlay toggles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Overlays {
    /// Velocity arrows.
    pub velocity: bool,
    /// Momentum arrows.
    pub momentum: bool,
    /// Text readouts.
    pub readouts: ReadoutScope,
    /// The totals panel.
    pub hud: bool,
    /// The key list.
    pub help: bool,
    /// The preset menu.
    pub presets: bool,
    /// Projector mode: thick lines (the fonts grow too).
    pub thick: bool,
    /// Colour discs by the colour-blind-safe palette, not the scene's colours.
    pub safe_palette: bool,
}

impl Default for Overlays {
    fn default() -> Self {
        Overlays {
            velocity: true,
            momentum: false,
            readouts: ReadoutScope::Selected,
            hud: true,
            help: false,
            presets: false,
            thick: false,
            safe_palette: false,
        }
    }
}

pub const VELOCITY_COLOR: Color = Color::new(1.0, 1.0, 1.0, 0.9);
pub const MOMENTUM_COLOR: Color = Color::new(1.0, 0.35, 0.75, 0.95);
const WALL_COLOR: Color = Color::new(0.85, 0.88, 0.95, 1.0);
const SELECTED_COLOR: Color = Color::new(1.0, 1.0, 1.0, 1.0);

fn px(v: DVec2) -> Vec2 {
    vec2(v.x as f32, v.y as f32)
}

/// The walls (solid for a box, dashed for periodic, faint for open space).
pub fn draw_boundary(world: &World, camera: &Camera) {
    let a = px(camera.world_to_screen(DVec2::new(0.0, world.size.y)));
    let b = px(camera.world_to_screen(DVec2::new(world.size.x, 0.0)));
    let (w, h) = (b.x - a.x, b.y - a.y);
    draw_rectangle(a.x, a.y, w, h, Color::new(1.0, 1.0, 1.0, 0.03));
    match world.boundary {
        Boundary::Box => draw_rectangle_lines(a.x, a.y, w, h, 3.0, WALL_COLOR),
        Boundary::Periodic | Boundary::Open => {
            let color = Color::new(0.85, 0.88, 0.95, 0.35);
            let corners = [a, vec2(b.x, a.y), b, vec2(a.x, b.y), a];
            for edge in corners.windows(2) {
                dashed_line(edge[0], edge[1], 12.0, color);
            }
        }
    }
}

fn dashed_line(from: Vec2, to: Vec2, dash: f32, color: Color) {
    let length = from.distance(to);
    let dashes = ((length / dash) as usize).min(2000);
    for k in (0..dashes).step_by(2) {
        let s = from.lerp(to, k as f32 / dashes as f32);
        let e = from.lerp(to, (k + 1) as f32 / dashes as f32);
        draw_line(s.x, s.y, e.x, e.y, 2.0, color);
    }
}

/// Every disc in one instanced draw call (see [`super::discs`]), with a ring
/// round the selected one.
pub fn draw_discs(
    world: &World,
    camera: &Camera,
    selected: Option<usize>,
    overlays: &Overlays,
    batch: &mut DiscBatch,
) {
    let color = |i: usize| {
        if overlays.safe_palette {
            impulse::Color::palette(i)
        } else {
            world.particles[i].color
        }
    };
    discs::instances(world, camera, color, &mut batch.instances);
    batch.draw();
    let Some(p) = selected.and_then(|i| world.particles.get(i)) else {
        return;
    };
    let c = camera.world_to_screen(p.pos);
    let r = camera.length_in_pixels(p.radius).max(MIN_DISC_PIXELS);
    if circle_on_screen(c, r + 3.0, camera.viewport) {
        let sides = (r * 0.8).clamp(12.0, 90.0) as u8;
        let width = if overlays.thick { 5.0 } else { 2.5 };
        let c = px(c);
        draw_poly_lines(c.x, c.y, sides, r as f32 + 3.0, 0.0, width, SELECTED_COLOR);
    }
}

/// An arrow between two screen points; nothing if shorter than a pixel.
pub fn arrow(from: Vec2, to: Vec2, thickness: f32, color: Color) {
    let d = to - from;
    let len = d.length();
    if len < 1.0 {
        return;
    }
    let dir = d / len;
    let head = (4.0 * thickness).min(0.5 * len).max(4.0);
    let base = to - dir * head;
    let side = vec2(-dir.y, dir.x) * head * 0.5;
    draw_line(from.x, from.y, base.x, base.y, thickness, color);
    draw_triangle(to, base + side, base - side, color);
}

/// Velocity and momentum arrows, as toggled; only those long enough to read
/// ([`super::cull::MIN_ARROW_PIXELS`]) and crossing the screen.
pub fn draw_arrows(world: &World, camera: &Camera, overlays: &Overlays) {
    if !(overlays.velocity || overlays.momentum) || world.particles.is_empty() {
        return;
    }
    // Momentum arrows share the velocity scale for a disc of average mass.
    let mean_mass =
        world.particles.iter().map(|p| p.mass).sum::<f64>() / world.particles.len() as f64;
    let thickness = if overlays.thick { 2.0 } else { 1.0 };
    for p in &world.particles {
        let c = camera.world_to_screen(p.pos);
        if overlays.velocity {
            let tip = c + camera.vector_to_screen(p.vel * ARROW_SECONDS);
            if arrow_readable(c, tip, camera.viewport) {
                arrow(px(c), px(tip), 2.0 * thickness, VELOCITY_COLOR);
            }
        }
        if overlays.momentum {
            let tip = c + camera.vector_to_screen(p.momentum() / mean_mass * ARROW_SECONDS);
            if arrow_readable(c, tip, camera.viewport) {
                arrow(px(c), px(tip), 3.0 * thickness, MOMENTUM_COLOR);
            }
        }
    }
}

/// The disc about to be launched, its arrow and speed.
pub fn draw_launch_preview(
    world: &World,
    camera: &Camera,
    start: DVec2,
    cursor: DVec2,
    new_disc: NewDisc,
    font: f32,
) {
    let spot = world.free_spot_near(start, new_disc.radius);
    let at = px(camera.world_to_screen(spot.unwrap_or(start)));
    let r = camera.length_in_pixels(new_disc.radius).max(1.0) as f32;
    let ghost = if spot.is_some() {
        Color::new(1.0, 1.0, 1.0, 0.35)
    } else {
        Color::new(1.0, 0.2, 0.2, 0.5)
    };
    draw_poly(at.x, at.y, 40, r, 0.0, ghost);
    let velocity = launch_velocity(start, cursor);
    let tip = camera.world_to_screen(start) + camera.vector_to_screen(velocity * ARROW_SECONDS);
    arrow(at, px(tip), 3.0, Color::new(1.0, 0.9, 0.3, 1.0));
    let label = match spot {
        Some(_) => format!("{:.2} m/s", velocity.length()),
        None => "no room here".to_string(),
    };
    draw_text(&label, tip.x as f32 + 8.0, tip.y as f32 - 8.0, font, WHITE);
}
