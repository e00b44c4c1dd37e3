//! Drawing the world: walls, discs (batched, [`super::discs`]), velocity and
//! momentum arrows (only readable ones, [`super::cull`]) and the launch
//! preview; the readouts are in [`super::readouts`]. Everything goes through
//! the camera.

use super::camera::Camera;
use super::cull::{arrow_readable, circle_on_screen, MIN_DISC_PIXELS};
use super::discs::{self, DiscBatch};
use super::interaction::{launch_velocity, NewDisc};
use super::ui::theme::WorldColors;
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
    /// For a moment after each collision, each disc's change of momentum.
    pub delta_p: bool,
    /// Text readouts.
    pub readouts: ReadoutScope,
    /// Colour discs by the colour-blind-safe palette, not the scene's colours.
    pub safe_palette: bool,
}

impl Default for Overlays {
    fn default() -> Self {
        Overlays {
            velocity: true,
            momentum: false,
            delta_p: true,
            readouts: ReadoutScope::Selected,
            safe_palette: false,
        }
    }
}

/// Whether spin is worth showing: a disc spins, or the laws can make one
/// spin (a roughness β above −1 between discs or at the walls, or friction,
/// which rubs resting discs). Only then do discs carry their spin line and
/// the readouts, the Discs table, the top bar and the Speeds tab their spin
/// values, so the smooth presets look as they always did.
pub fn spin_shown(world: &World) -> bool {
    let laws = &world.laws;
    laws.tangential_restitution > -1.0
        || laws.wall_tangential_restitution > -1.0
        || laws.friction.is_some()
        || world.particles.iter().any(|p| p.spin != 0.0)
}

/// How the world is drawn this frame: the theme's colours and the UI scale
/// (line widths and text grow with it).
#[derive(Clone, Copy, Debug)]
pub struct Look {
    pub colors: WorldColors,
    pub scale: f32,
}

/// A theme colour as macroquad's.
pub fn color(c: [f32; 4]) -> Color {
    Color::new(c[0], c[1], c[2], c[3])
}

fn px(v: DVec2) -> Vec2 {
    vec2(v.x as f32, v.y as f32)
}

/// The walls (solid for a box, dashed for periodic, faint for open space).
pub fn draw_boundary(world: &World, camera: &Camera, look: Look) {
    let a = px(camera.world_to_screen(DVec2::new(0.0, world.laws.size.y)));
    let b = px(camera.world_to_screen(DVec2::new(world.laws.size.x, 0.0)));
    let (w, h) = (b.x - a.x, b.y - a.y);
    draw_rectangle(a.x, a.y, w, h, color(look.colors.inside));
    let wall = color(look.colors.wall);
    let faint = Color { a: 0.45, ..wall };
    // Sides in the order left, right, bottom, top (screen y grows down).
    let sides = [
        (a, vec2(a.x, b.y)),
        (vec2(b.x, a.y), b),
        (vec2(a.x, b.y), b),
        (a, vec2(b.x, a.y)),
    ];
    let walled = match world.laws.boundary {
        Boundary::Box => world.laws.walls.sides(),
        Boundary::Periodic | Boundary::Open => [false; 4],
    };
    // One dimension: a rail through the discs' line (drawn under them, like
    // beads on a wire), and only the walls at its ends (the sides along it
    // play no part).
    let mut skip = [false; 4];
    if let (Some(axis), Some(first)) = (world.laws.constrain, world.particles.first()) {
        let along = axis.index();
        let at = first.pos;
        let mut from = at;
        from[along] = 0.0;
        let mut to = at;
        to[along] = world.laws.size[along];
        let (a, b) = (
            px(camera.world_to_screen(from)),
            px(camera.world_to_screen(to)),
        );
        draw_line(a.x, a.y, b.x, b.y, 3.0 * look.scale, wall);
        skip = if along == 0 {
            [false, false, true, true]
        } else {
            [true, true, false, false]
        };
    }
    for (((from, to), solid), skipped) in sides.into_iter().zip(walled).zip(skip) {
        if skipped {
            continue;
        }
        if solid {
            draw_line(from.x, from.y, to.x, to.y, 3.0 * look.scale, wall);
        } else {
            dashed_line(from, to, 12.0, 2.0 * look.scale, faint);
        }
    }
}

fn dashed_line(from: Vec2, to: Vec2, dash: f32, width: f32, color: Color) {
    let length = from.distance(to);
    let dashes = ((length / dash) as usize).min(2000);
    for k in (0..dashes).step_by(2) {
        let s = from.lerp(to, k as f32 / dashes as f32);
        let e = from.lerp(to, (k + 1) as f32 / dashes as f32);
        draw_line(s.x, s.y, e.x, e.y, width, color);
    }
}

/// Every disc in one instanced draw call (see [`super::discs`]), each with
/// its spin line when spin is shown ([`spin_shown`]), and a ring round the
/// selected one.
pub fn draw_discs(
    world: &World,
    camera: &Camera,
    selected: Option<usize>,
    overlays: &Overlays,
    batch: &mut DiscBatch,
    look: Look,
) {
    let disc_color = |i: usize| {
        if overlays.safe_palette {
            impulse::Color::palette(i)
        } else {
            world.particles[i].color
        }
    };
    discs::instances(world, camera, disc_color, &mut batch.instances);
    batch.spin_line = if spin_shown(world) { look.scale } else { 0.0 };
    batch.draw();
    let Some(p) = selected.and_then(|i| world.particles.get(i)) else {
        return;
    };
    let c = camera.world_to_screen(p.pos);
    let r = camera.length_in_pixels(p.radius).max(MIN_DISC_PIXELS);
    if circle_on_screen(c, r + 3.0, camera.screen_rect()) {
        let sides = (r * 0.8).clamp(12.0, 90.0) as u8;
        let width = 2.5 * look.scale;
        let c = px(c);
        draw_poly_lines(
            c.x,
            c.y,
            sides,
            r as f32 + 3.0,
            0.0,
            width,
            color(look.colors.selected),
        );
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

/// The outline of a wide arrow between two screen points (a shaft
/// `2 × half_width` wide and a head), drawn hollow so that a thin arrow
/// drawn along it stays visible: the momentum arrow under the velocity arrow
/// of a disc of average mass, where the two coincide exactly.
pub fn hollow_arrow(from: Vec2, to: Vec2, half_width: f32, line: f32, color: Color) {
    let d = to - from;
    let len = d.length();
    if len < 1.0 {
        return;
    }
    let dir = d / len;
    let side = vec2(-dir.y, dir.x);
    let head = (5.0 * half_width).min(0.6 * len);
    let base = to - dir * head;
    let outline = [
        from + side * half_width,
        base + side * half_width,
        base + side * 2.4 * half_width,
        to,
        base - side * 2.4 * half_width,
        base - side * half_width,
        from - side * half_width,
        from + side * half_width,
    ];
    for edge in outline.windows(2) {
        draw_line(edge[0].x, edge[0].y, edge[1].x, edge[1].y, line, color);
    }
}

/// Velocity and momentum arrows, as toggled; only those long enough to read
/// ([`super::cull::MIN_ARROW_PIXELS`]) and crossing the world's rectangle.
/// Momentum arrows are wide and hollow and drawn first, so a velocity arrow
/// lying along one shows inside it.
pub fn draw_arrows(world: &World, camera: &Camera, overlays: &Overlays, look: Look) {
    if !(overlays.velocity || overlays.momentum) || world.particles.is_empty() {
        return;
    }
    // Momentum arrows share the velocity scale for a disc of average mass.
    let mean_mass =
        world.particles.iter().map(|p| p.mass).sum::<f64>() / world.particles.len() as f64;
    let s = look.scale;
    let rect = camera.screen_rect();
    if overlays.momentum {
        let pink = color(look.colors.momentum);
        for p in &world.particles {
            let c = camera.world_to_screen(p.pos);
            let tip = c + camera.vector_to_screen(p.momentum() / mean_mass * ARROW_SECONDS);
            if arrow_readable(c, tip, rect) {
                hollow_arrow(px(c), px(tip), 4.0 * s, 2.0 * s, pink);
            }
        }
    }
    if overlays.delta_p {
        draw_momentum_changes(world, camera, mean_mass, look);
    }
    if overlays.velocity {
        let white = color(look.colors.velocity);
        for p in &world.particles {
            let c = camera.world_to_screen(p.pos);
            let tip = c + camera.vector_to_screen(p.vel * ARROW_SECONDS);
            if arrow_readable(c, tip, rect) {
                arrow(px(c), px(tip), 2.0 * s, white);
            }
        }
    }
}

/// How long a collision's Δp arrows stay (simulated seconds).
pub const DELTA_P_SECONDS: f64 = 1.0;

/// For [`DELTA_P_SECONDS`] after each recorded collision, each of its two
/// discs carries its change of momentum m·(v′ − v), fading, on the momentum
/// arrows' scale.
fn draw_momentum_changes(world: &World, camera: &Camera, mean_mass: f64, look: Look) {
    let s = look.scale;
    for c in world.ledger.entries() {
        let age = world.time - c.time;
        if !(0.0..=DELTA_P_SECONDS).contains(&age) {
            continue;
        }
        let mut amber = color(look.colors.delta_p);
        amber.a *= (1.0 - 0.7 * age / DELTA_P_SECONDS) as f32;
        for k in 0..2 {
            let Some(p) = world.particles.get(c.discs[k]) else {
                continue;
            };
            let dp = c.masses[k] * (c.after[k] - c.before[k]);
            let from = camera.world_to_screen(p.pos);
            let tip = from + camera.vector_to_screen(dp / mean_mass * ARROW_SECONDS);
            if from.distance(tip) >= 4.0 {
                arrow(px(from), px(tip), 4.0 * s, amber);
            }
        }
    }
}

/// The centre of mass as a cross in a circle, with its velocity arrow.
pub fn draw_center_of_mass(world: &World, camera: &Camera, arrow_seconds: f64, scale: f32) {
    if world.particles.is_empty() {
        return;
    }
    const COM_COLOR: Color = Color::new(0.94, 0.89, 0.26, 1.0); // yellow
    let m = world.metrics();
    let c = camera.world_to_screen(m.center_of_mass);
    let (x, y, s) = (c.x as f32, c.y as f32, scale);
    draw_circle_lines(x, y, 9.0 * s, 2.0 * s, COM_COLOR);
    draw_line(x - 12.0 * s, y, x + 12.0 * s, y, 2.0 * s, COM_COLOR);
    draw_line(x, y - 12.0 * s, x, y + 12.0 * s, 2.0 * s, COM_COLOR);
    let tip = c + camera.vector_to_screen(m.center_of_mass_velocity * arrow_seconds);
    arrow(vec2(x, y), px(tip), 3.0 * s, COM_COLOR);
}

/// The disc about to be launched, its arrow and speed.
pub fn draw_launch_preview(
    world: &World,
    camera: &Camera,
    start: DVec2,
    cursor: DVec2,
    new_disc: NewDisc,
    look: Look,
    text: &super::readouts::WorldText,
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
    arrow(
        at,
        px(tip),
        3.0 * look.scale,
        Color::new(1.0, 0.75, 0.0, 1.0),
    );
    let label = match spot {
        Some(_) => super::ui::numbers::with_unit(velocity.length(), 2, "m/s"),
        None => "no room here".to_string(),
    };
    super::readouts::launch_label(text, &label, px(tip), look);
}
