//! Drawing the world, from the model: walls, discs (batched, [`discs`]),
//! velocity and momentum arrows (only readable ones, [`cull`]), the trails,
//! the centre of mass, the contact at an impact and the launch preview; the
//! readouts are in [`readouts`]. Everything goes through the camera. Lines
//! keep their width in screen pixels whatever the UI scale (which enlarges
//! text and controls, not arrows); colours come from the theme
//! ([`crate::app::look`]), but for the contact's normal (orange) and tangent
//! (blue), which read on both.

mod clip;
pub mod cull;
pub mod discs;
pub mod readouts;
mod trails;

use crate::app::look::{color, Look};
use crate::app::model::camera::Camera;
use crate::app::model::gesture::{planned_launch, Gesture, NewDisc};
use crate::app::model::overlays::{
    momentum_changes, spin_shown, MomentumChange, Overlays, ARROW_SECONDS, DELTA_P_MAX_DISCS,
};
use crate::app::model::Sandbox;
use cull::{arrow_readable, circle_on_screen, MIN_DISC_PIXELS};
use discs::DiscBatch;
use glam::DVec2;
use impulse::{Boundary, World};
use macroquad::prelude::*;
use readouts::WorldText;

/// What drawing keeps between frames: the discs' GPU batch and the world's
/// font, made at the first frame (they need the window).
#[derive(Default)]
pub struct Painter {
    batch: Option<DiscBatch>,
    text: Option<WorldText>,
    /// What the readouts showed last frame.
    pub readouts: readouts::Shown,
}

impl Painter {
    /// The smallest text drawn in the world this frame (px), if any.
    pub fn smallest_text(&self) -> Option<f32> {
        self.text.as_ref().and_then(WorldText::smallest)
    }

    /// Draws the world as the model has it, the pointer at `mouse`.
    pub fn draw(&mut self, model: &Sandbox, mouse: DVec2) {
        let look = Look::of(model.panels.theme, model.panels.scale);
        // The centre-of-mass view draws a copy with relative velocities.
        let seen = model.world_as_seen();
        let world = seen.as_ref().unwrap_or(&model.world);
        let camera = &model.view.camera;
        clear_background(color(look.colors.background));
        let text = self.text.get_or_insert_with(WorldText::new);
        text.begin_frame();
        draw_boundary(world, camera, look);
        let disc_color = |i| model.overlays.disc_color(&model.world, i);
        trails::draw_trails(&model.record.trails, camera, disc_color);
        let batch = self.batch.get_or_insert_with(DiscBatch::new);
        draw_discs(world, camera, model.selected, &model.overlays, batch, look);
        draw_arrows(
            world,
            camera,
            &model.overlays,
            model.record.totals.edited_at(),
            look,
        );
        if model.overlays.center_of_mass {
            draw_center_of_mass(world, camera, ARROW_SECONDS, look);
        }
        if model.overlays.contact {
            if let Some(impact) = model.world.ledger.last_impact() {
                if (model.world.time - impact.time()).abs() < 1e-9 {
                    draw_contact(impact, world, camera);
                }
            }
        }
        let Some(text) = self.text.as_ref() else {
            return;
        };
        // The labels keep out from under the open drawer.
        let (lo, hi) = camera.screen_rect();
        let visible = (lo, hi - DVec2::new(model.view.covered, 0.0));
        let (overlays, selected) = (&model.overlays, model.selected);
        self.readouts =
            readouts::draw_readouts(world, camera, visible, overlays, selected, look, text);
        if let Gesture::Launching { start, .. } = model.pointer.gesture {
            let cursor = camera.screen_to_world(mouse);
            let disc = model.new_disc_now();
            draw_launch_preview(&model.world, camera, start, cursor, disc, look, text);
        }
    }
}

/// At the instant of impact: the line of impact (orange) and the line
/// across it (blue) through the point of contact, between two discs or
/// where a disc meets a wall.
fn draw_contact(impact: &impulse::ledger::Impact, world: &World, camera: &Camera) {
    use impulse::ledger::Impact;
    let (contact, normal, reach) = match impact {
        Impact::Pair(c) => {
            let (Some(a), Some(b)) = (
                world.particles.get(c.discs[0]),
                world.particles.get(c.discs[1]),
            ) else {
                return;
            };
            (
                a.pos + c.normal * a.radius,
                c.normal,
                1.5 * a.radius.max(b.radius),
            )
        }
        Impact::Wall(w) => {
            let Some(p) = world.particles.get(w.disc) else {
                return;
            };
            let n = w.normal();
            (p.pos - n * p.radius, n, 1.5 * p.radius)
        }
    };
    let line = |dir: DVec2, color: Color| {
        let (p, q) = (
            camera.world_to_screen(contact - dir * reach),
            camera.world_to_screen(contact + dir * reach),
        );
        draw_line(p.x as f32, p.y as f32, q.x as f32, q.y as f32, 3.0, color);
    };
    line(normal, Color::new(0.84, 0.37, 0.0, 1.0));
    line(normal.perp(), Color::new(0.34, 0.71, 0.91, 1.0));
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
        draw_line(a.x, a.y, b.x, b.y, 3.0, color(look.colors.rail));
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
            draw_line(from.x, from.y, to.x, to.y, 3.0, wall);
        } else {
            dashed_line(from, to, 12.0, 2.0, faint);
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

/// Every disc in one instanced draw call (see [`discs`]), each with
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
    let disc_color = |i: usize| overlays.disc_color(world, i);
    discs::instances(world, camera, disc_color, &mut batch.instances);
    batch.spin_line = if spin_shown(world) { 1.0 } else { 0.0 };
    batch.draw();
    let Some(p) = selected.and_then(|i| world.particles.get(i)) else {
        return;
    };
    let c = camera.world_to_screen(p.pos);
    let r = camera.length_in_pixels(p.radius).max(MIN_DISC_PIXELS);
    if circle_on_screen(c, r + 3.0, camera.screen_rect()) {
        let sides = (r * 0.8).clamp(12.0, 90.0) as u8;
        let width = 2.5;
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

/// Where arrows are cut: the box's rectangle on screen, for a box with
/// four walls (an arrow may not run out through a wall); elsewhere none.
fn arrow_clip(world: &World, camera: &Camera) -> Option<(DVec2, DVec2)> {
    let walled = world.laws.boundary == Boundary::Box && world.laws.walls.all();
    walled.then(|| {
        let a = camera.world_to_screen(DVec2::new(0.0, world.laws.size.y));
        let b = camera.world_to_screen(DVec2::new(world.laws.size.x, 0.0));
        (a.min(b), a.max(b))
    })
}

/// The part of the arrow from `a` to `b` inside `clip` (all of it without
/// one), and whether its tip is inside (only then is the head drawn).
fn clipped(a: DVec2, b: DVec2, clip: Option<(DVec2, DVec2)>) -> Option<(DVec2, DVec2, bool)> {
    match clip {
        None => Some((a, b, true)),
        Some((lo, hi)) => {
            let (p, q) = clip::clip_segment(a, b, lo, hi)?;
            Some((p, q, q == b))
        }
    }
}

/// An arrow between two screen points, its head only if `head`; nothing if
/// shorter than a pixel.
pub fn arrow(from: Vec2, to: Vec2, thickness: f32, color: Color, head: bool) {
    let d = to - from;
    let len = d.length();
    if len < 1.0 {
        return;
    }
    let dir = d / len;
    if !head {
        draw_line(from.x, from.y, to.x, to.y, thickness, color);
        return;
    }
    let size = (4.0 * thickness).min(0.5 * len).max(4.0);
    let base = to - dir * size;
    let side = vec2(-dir.y, dir.x) * size * 0.5;
    draw_line(from.x, from.y, base.x, base.y, thickness, color);
    draw_triangle(to, base + side, base - side, color);
}

/// The outline of [`arrow`]`(from, to, thickness, …)`, `line` wide all
/// round, drawn under it.
fn arrow_outline(from: Vec2, to: Vec2, thickness: f32, line: f32, color: Color, head: bool) {
    let d = to - from;
    let len = d.length();
    if len < 1.0 {
        return;
    }
    let dir = d / len;
    let back = from - dir * line;
    if !head {
        let end = to + dir * line;
        draw_line(back.x, back.y, end.x, end.y, thickness + 2.0 * line, color);
        return;
    }
    let size = (4.0 * thickness).min(0.5 * len).max(4.0);
    let base = to - dir * size;
    let side = vec2(-dir.y, dir.x);
    draw_line(
        back.x,
        back.y,
        base.x,
        base.y,
        thickness + 2.0 * line,
        color,
    );
    let grow = 2.2 * line;
    draw_triangle(
        to + dir * grow,
        base - dir * line + side * (size * 0.5 + grow),
        base - dir * line - side * (size * 0.5 + grow),
        color,
    );
}

/// The outline of a wide arrow between two screen points (a shaft
/// `2 × half_width` wide and a head), drawn hollow so that a thin arrow
/// drawn along it stays visible: the momentum arrow under the velocity arrow
/// of a disc of average mass, where the two coincide exactly.
pub fn hollow_arrow(from: Vec2, to: Vec2, half_width: f32, line: f32, color: Color, head: bool) {
    let d = to - from;
    let len = d.length();
    if len < 1.0 {
        return;
    }
    let dir = d / len;
    let side = vec2(-dir.y, dir.x);
    if !head {
        for k in [-1.0, 1.0] {
            let (a, b) = (from + side * k * half_width, to + side * k * half_width);
            draw_line(a.x, a.y, b.x, b.y, line, color);
        }
        return;
    }
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
/// ([`cull::MIN_ARROW_PIXELS`]) and crossing the world's rectangle.
/// Momentum arrows are wide and hollow and drawn first, so a velocity arrow
/// lying along one shows inside it.
pub fn draw_arrows(
    world: &World,
    camera: &Camera,
    overlays: &Overlays,
    edited_at: Option<f64>,
    look: Look,
) {
    if !(overlays.velocity || overlays.momentum) || world.particles.is_empty() {
        return;
    }
    // Momentum arrows share the velocity scale for a disc of average mass.
    let mean_mass =
        world.particles.iter().map(|p| p.mass).sum::<f64>() / world.particles.len() as f64;
    let rect = camera.screen_rect();
    let clip = arrow_clip(world, camera);
    // As thick as the text is large: at a projector's size 2 the velocity
    // arrows were lines of 2 px a class could not see.
    let thick = look.text_scale.max(1.0);
    if overlays.momentum {
        let pink = color(look.colors.momentum);
        for p in &world.particles {
            let c = camera.world_to_screen(p.pos);
            let tip = c + camera.vector_to_screen(p.momentum() / mean_mass * ARROW_SECONDS);
            if arrow_readable(c, tip, rect) {
                if let Some((a, b, whole)) = clipped(c, tip, clip) {
                    hollow_arrow(px(a), px(b), 4.0 * thick, 2.0 * thick, pink, whole);
                }
            }
        }
    }
    if overlays.delta_p && world.particles.len() <= DELTA_P_MAX_DISCS {
        let changes = momentum_changes(world, edited_at);
        draw_momentum_changes(&changes, world, camera, mean_mass, look, clip);
    }
    if overlays.velocity {
        let white = color(look.colors.velocity);
        for p in &world.particles {
            let c = camera.world_to_screen(p.pos);
            let tip = c + camera.vector_to_screen(p.vel * ARROW_SECONDS);
            if arrow_readable(c, tip, rect) {
                if let Some((a, b, whole)) = clipped(c, tip, clip) {
                    arrow(px(a), px(b), 2.0 * thick, white, whole);
                }
            }
        }
    }
}

/// Each disc's change of momentum in a recent collision
/// ([`momentum_changes`]), fading, on the momentum arrows' scale.
fn draw_momentum_changes(
    changes: &[MomentumChange],
    world: &World,
    camera: &Camera,
    mean_mass: f64,
    look: Look,
    clip: Option<(DVec2, DVec2)>,
) {
    let mut outline = color(look.colors.outline);
    for change in changes {
        let Some(p) = world.particles.get(change.disc) else {
            continue;
        };
        let mut amber = color(look.colors.delta_p);
        amber.a *= change.fade;
        outline.a = change.fade;
        let from = camera.world_to_screen(p.pos);
        let tip = from + camera.vector_to_screen(change.change / mean_mass * ARROW_SECONDS);
        if from.distance(tip) >= 4.0 {
            if let Some((a, b, whole)) = clipped(from, tip, clip) {
                // An outline under it, so it reads on an orange disc too.
                arrow_outline(px(a), px(b), 4.0, 2.0, outline, whole);
                arrow(px(a), px(b), 4.0, amber, whole);
            }
        }
    }
}

/// The centre of mass as a cross in a circle, with its velocity arrow.
pub fn draw_center_of_mass(world: &World, camera: &Camera, arrow_seconds: f64, look: Look) {
    if world.particles.is_empty() {
        return;
    }
    let com_color = color(look.colors.center_of_mass);
    let m = world.metrics();
    let c = camera.world_to_screen(m.center_of_mass);
    let (x, y, s) = (c.x as f32, c.y as f32, 1.0);
    draw_circle_lines(x, y, 9.0 * s, 2.0 * s, com_color);
    draw_line(x - 12.0 * s, y, x + 12.0 * s, y, 2.0 * s, com_color);
    draw_line(x, y - 12.0 * s, x, y + 12.0 * s, 2.0 * s, com_color);
    let tip = c + camera.vector_to_screen(m.center_of_mass_velocity * arrow_seconds);
    arrow(vec2(x, y), px(tip), 3.0 * s, com_color, true);
}

/// The disc about to be launched, its arrow and speed.
pub fn draw_launch_preview(
    world: &World,
    camera: &Camera,
    start: DVec2,
    cursor: DVec2,
    new_disc: NewDisc,
    look: Look,
    text: &WorldText,
) {
    let (spot, velocity) = planned_launch(world, start, cursor, new_disc.radius);
    let from = spot.unwrap_or(start);
    let at = px(camera.world_to_screen(from));
    let r = camera.length_in_pixels(new_disc.radius).max(1.0) as f32;
    let ghost = if spot.is_some() {
        color(look.colors.ghost)
    } else {
        Color::new(1.0, 0.2, 0.2, 0.5)
    };
    draw_poly(at.x, at.y, 40, r, 0.0, ghost);
    let tip = camera.world_to_screen(from) + camera.vector_to_screen(velocity * ARROW_SECONDS);
    arrow(at, px(tip), 3.0, Color::new(1.0, 0.75, 0.0, 1.0), true);
    let label = match spot {
        Some(_) => crate::app::numbers::with_unit(velocity.length(), 2, "m/s"),
        None => crate::app::lang::tr!("launch-no-room"),
    };
    readouts::launch_label(text, &label, px(tip), look);
}
