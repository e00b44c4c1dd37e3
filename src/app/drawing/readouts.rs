//! Text in the world: the per-disc readouts (v, |v|, p, m, KE; when spin
//! is shown also the spin ω, rotational KE and angular momentum L) and the
//! launch preview's speed, in the bundled DejaVu Sans (it has π, °, ² and
//! the middle dot of kg·m/s). A readout goes where it covers no disc, no
//! arrow and no other readout ([`super::cull::place_label`]): the selected
//! disc's always (moved out on a leader line when crowded, over its
//! neighbours when there is no room at all), every other disc's only where
//! there is room. Backgrounds first, then all text.

use super::cull::{
    circle_on_screen, place_label, LabelPlacer, Obstacles, Placement, ScreenRect, MIN_ARROW_PIXELS,
    MIN_LABEL_DISC_PIXELS,
};
use crate::app::lang::tr;
use crate::app::look::{color, Look, MIN_TEXT_POINTS};
use crate::app::model::camera::Camera;
use crate::app::model::overlays::{spin_shown, Overlays, ReadoutScope, ARROW_SECONDS};
use crate::app::numbers::{disc_number, vector, with_unit};
use glam::DVec2;
use impulse::World;
use macroquad::prelude::*;
use std::cell::Cell;

/// Readouts for "every disc" stop at this many labels.
const MAX_LABELS: usize = 250;
/// Obstacles are collected for at most this many discs on screen; beyond,
/// "every disc" shows no labels (they could not be read anyway).
const MAX_OBSTACLE_DISCS: usize = 20_000;

/// The world's font and the smallest size drawn with it this frame.
pub struct WorldText {
    font: Font,
    smallest: Cell<f32>,
}

impl WorldText {
    /// Loads the bundled font (needs the window).
    pub fn new() -> Self {
        let font = load_ttf_font_from_bytes(crate::app::look::DEJAVU_SANS)
            .expect("the bundled DejaVu Sans loads");
        WorldText {
            font,
            smallest: Cell::new(f32::INFINITY),
        }
    }

    /// Starts a frame's count of the smallest text.
    pub fn begin_frame(&self) {
        self.smallest.set(f32::INFINITY);
    }

    /// The smallest font size drawn since [`Self::begin_frame`] (px), if any.
    pub fn smallest(&self) -> Option<f32> {
        let s = self.smallest.get();
        s.is_finite().then_some(s)
    }

    /// Width and height of `text` at `size` px.
    pub fn measure(&self, text: &str, size: f32) -> Vec2 {
        let d = measure_text(text, Some(&self.font), size.round() as u16, 1.0);
        vec2(d.width, size * 1.25)
    }

    /// Draws `text` with its top-left corner at `at`.
    pub fn draw(&self, text: &str, at: Vec2, size: f32, c: Color) {
        let size = size.round();
        self.smallest.set(self.smallest.get().min(size));
        draw_text_ex(
            text,
            at.x,
            at.y + 0.95 * size,
            TextParams {
                font: Some(&self.font),
                font_size: size as u16,
                color: c,
                ..Default::default()
            },
        );
    }
}

/// Readout lines for disc `i`: its name (as the ledger gives it), mass
/// and KE; its velocity and speed; its momentum. With `spin`, two more:
/// its spin and rotational KE, and its angular momentum about the origin.
/// The name, with the disc's colour down the label's edge, tells whose
/// values a label holds: at a projector's size two discs' labels, each
/// far from its disc, had nothing to tell them apart. (Four shorter lines
/// were tried: too tall to fit above or below a disc in a projector's
/// world, they were not drawn at all.)
pub fn readout_lines(p: &impulse::Particle, i: usize, spin: bool) -> Vec<String> {
    let v = p.vel;
    let mut lines = vec![
        format!(
            "{}  m = {}   {} = {}",
            // "disque 3 :" in French, the space before the colon kept.
            tr!(
                "readout-disc",
                disc = tr!("disc-numbered", disc = disc_number(i))
            ),
            with_unit(p.mass, 3, "kg"),
            tr!("symbol-ke"),
            with_unit(p.kinetic_energy(), 3, "J")
        ),
        format!(
            "v = {}   |v| = {}",
            vector(v, 2, "m/s"),
            with_unit(v.length(), 2, "m/s")
        ),
        format!("p = {}", vector(p.momentum(), 2, "kg·m/s")),
    ];
    if spin {
        lines.push(tr!(
            "readout-spin",
            spin = with_unit(p.spin, 2, "rad/s"),
            energy = with_unit(p.rotational_energy(), 3, "J")
        ));
        lines.push(tr!(
            "readout-angular-momentum",
            angular = with_unit(p.angular_momentum(), 3, "kg·m²/s")
        ));
    }
    lines
}

/// What the readouts showed this frame.
#[derive(Clone, Copy, Debug, Default)]
pub struct Shown {
    /// Discs with their values beside them.
    pub shown: usize,
    /// Discs on screen that were to have them (the world says so when
    /// fewer were shown).
    pub wanted: usize,
    /// Where the selected disc's label went (px: x, y, width, height).
    pub selected_at: Option<[f64; 4]>,
}

/// One placed label.
struct Label {
    rect: [f64; 4],
    leader: Option<(DVec2, DVec2)>,
    lines: Vec<String>,
    /// Its text's size (points): smaller than the others' where the
    /// selected disc's values fit beside the open drawer only so.
    size: f32,
    /// The disc's colour, down the label's left edge.
    color: Color,
}

/// How far the selected disc's values may shrink to stay clear of the open
/// drawer, never below the text size 1's: at a projector's text size 2 at
/// 1024×768 they were 614 px wide in a world of 604 beside the drawer, and
/// went under its edge.
const SHRINK_TO_FIT: f32 = 0.8;

/// What labels must keep clear of: every disc on screen and every arrow drawn.
fn obstacles(world: &World, camera: &Camera, overlays: &Overlays, cell: f64) -> Option<Obstacles> {
    let rect = camera.screen_rect();
    let mut o = Obstacles::new(cell);
    let mut on_screen = 0;
    let mean_mass = mean_mass(world);
    for p in &world.particles {
        let c = camera.world_to_screen(p.pos);
        let r = camera.length_in_pixels(p.radius).max(1.0);
        if !circle_on_screen(c, r, rect) {
            continue;
        }
        on_screen += 1;
        if on_screen > MAX_OBSTACLE_DISCS {
            return None;
        }
        add_disc(&mut o, p, mean_mass, camera, overlays);
    }
    Some(o)
}

/// The mass the momentum arrows are drawn against (as velocities).
fn mean_mass(world: &World) -> f64 {
    world.particles.iter().map(|p| p.mass).sum::<f64>() / world.particles.len().max(1) as f64
}

/// Disc `p` and the arrows drawn on it (momenta against `mean_mass`), as
/// obstacles to labels.
fn add_disc(
    o: &mut Obstacles,
    p: &impulse::Particle,
    mean_mass: f64,
    camera: &Camera,
    overlays: &Overlays,
) {
    let half = 4.0 * 2.4; // the momentum arrow's half width, in px
    let c = camera.world_to_screen(p.pos);
    let r = camera.length_in_pixels(p.radius).max(1.0);
    o.add_circle(c, r + 2.0);
    for (on, v) in [
        (overlays.velocity, p.vel),
        (overlays.momentum, p.momentum() / mean_mass),
    ] {
        let tip = c + camera.vector_to_screen(v * ARROW_SECONDS);
        if on && c.distance(tip) >= MIN_ARROW_PIXELS {
            o.add_segment(c, tip, half);
        }
    }
}

/// Text readouts beside the selected disc or every readable disc.
/// Returns how many discs got their values and how many on screen were to
/// have them; where not all could, it says so in the world's corner.
///
/// `visible` is the part of the world's rectangle in sight: less than the
/// camera's where the open drawer covers its right end, whose labels went
/// under the drawer.
pub fn draw_readouts(
    world: &World,
    camera: &Camera,
    visible: ScreenRect,
    overlays: &Overlays,
    selected: Option<usize>,
    look: Look,
    text: &WorldText,
) -> Shown {
    let all = match overlays.readouts {
        ReadoutScope::Off => return Shown::default(),
        ReadoutScope::Selected => false,
        ReadoutScope::All => true,
    };
    if world.particles.is_empty() {
        return Shown::default();
    }
    let size = MIN_TEXT_POINTS * look.text_scale;
    let pad = 0.35 * size;
    let line_height = 1.25 * size;
    let spin = spin_shown(world);
    let rows = if spin { 5.0 } else { 3.0 };
    let height = f64::from(rows * line_height + 2.0 * pad);
    // The disc's colour down the left edge, then the text.
    let stripe = 0.35 * size;
    let typical = DVec2::new(f64::from(22.0 * size), height);
    // Past MAX_OBSTACLE_DISCS discs on screen, only the selected disc's values.
    let (obstacles, all) = match obstacles(world, camera, overlays, typical.y) {
        Some(o) => (o, all),
        None if selected.is_some() => (Obstacles::new(typical.y), false),
        None => return Shown::default(),
    };
    let mut placer = LabelPlacer::new(typical);
    let gaps = [6.0, 30.0, 80.0].map(|g| g * f64::from(look.text_scale));
    let mut labels = Vec::new();
    let mut wanted = 0;
    let mut selected_at = None;
    // The selected disc first, so its label is never crowded out.
    let others = (0..world.particles.len()).filter(|&i| all && Some(i) != selected);
    for i in selected.into_iter().chain(others) {
        let Some(p) = world.particles.get(i) else {
            continue;
        };
        let c = camera.world_to_screen(p.pos);
        let r = camera.length_in_pixels(p.radius);
        let chosen = Some(i) == selected;
        if !circle_on_screen(c, r, visible) {
            continue;
        }
        wanted += 1;
        if labels.len() >= MAX_LABELS || !(chosen || r >= MIN_LABEL_DISC_PIXELS) {
            continue;
        }
        let lines = readout_lines(p, i, spin);
        let width_at = |fitted: f32| {
            let text_width = lines
                .iter()
                .map(|l| text.measure(l, fitted).x)
                .fold(0.0, f32::max);
            // The stripe and the padding grow with the text.
            text_width + (stripe + 2.0 * pad) * fitted / size
        };
        let room = (visible.1.x - visible.0.x) as f32 - 2.0 * gaps[0] as f32;
        let whole = width_at(size);
        let mut fitted = size;
        if chosen && whole > room {
            let least = (size * SHRINK_TO_FIT).max(MIN_TEXT_POINTS).min(size);
            fitted = (size * room / whole).clamp(least, size);
        }
        let scale = fitted / size;
        let label_size = DVec2::new(f64::from(width_at(fitted)), height * f64::from(scale));
        let gaps: &[f64] = if chosen { &gaps } else { &gaps[..1] };
        let place_in = |room: ScreenRect| {
            place_label(c, r, label_size, gaps, room, &obstacles, &placer).or_else(|| {
                // Crowded all round: the selected disc's values go beside
                // it all the same, over its neighbours (a teacher chose
                // this disc; a notice instead would cover more of them).
                chosen
                    .then(|| {
                        let scene = (world, camera, overlays);
                        place_over_others(p, scene, (label_size, room), gaps, &placer)
                    })
                    .flatten()
            })
        };
        // Clear of the open drawer where there is room; the selected disc's
        // values, where there is none (a projector's world beside the
        // drawer is narrower than they are), partly under its edge rather
        // than not at all.
        let full = camera.screen_rect();
        let placed = place_in(visible).or_else(|| {
            (chosen && visible != full)
                .then(|| place_in(full))
                .flatten()
        });
        if let Some(at) = placed {
            placer.try_place(at.rect);
            if chosen {
                selected_at = Some(at.rect);
            }
            let c = overlays.disc_color(world, i);
            labels.push(Label {
                rect: at.rect,
                leader: at.leader,
                lines,
                size: fitted,
                color: Color::from_rgba(c.r, c.g, c.b, 255),
            });
        }
    }
    let background = color(look.colors.label_background);
    let leader = color(look.colors.leader);
    for l in &labels {
        if let Some((a, b)) = l.leader {
            draw_line(a.x as f32, a.y as f32, b.x as f32, b.y as f32, 1.5, leader);
        }
        let r = l.rect.map(|v| v as f32);
        draw_rectangle(r[0], r[1], r[2], r[3], background);
        draw_rectangle(r[0], r[1], stripe * l.size / size, r[3], l.color);
    }
    let ink = color(look.colors.text);
    for l in &labels {
        let scale = l.size / size;
        for (k, line) in l.lines.iter().enumerate() {
            let at = vec2(
                l.rect[0] as f32 + (stripe + pad) * scale,
                l.rect[1] as f32 + (pad + line_height * k as f32) * scale,
            );
            text.draw(line, at, l.size, ink);
        }
    }
    if labels.len() < wanted {
        // Never silently fewer: say how many, in the world's corner.
        // Wrapped to the world's width: at a projector's text size one line
        // ran off the right edge.
        let note = tr!("readouts-culled", shown = labels.len(), wanted = wanted);
        let (lo, hi) = visible;
        let room = (hi.x - lo.x) as f32 - 16.0;
        let lines = wrap_words(&note, room, |line| text.measure(line, size).x);
        let line_height = text.measure(&note, size).y;
        let top = hi.y as f32 - 8.0 - line_height * lines.len() as f32;
        for (k, line) in lines.iter().enumerate() {
            let at = vec2(lo.x as f32 + 8.0, top + line_height * k as f32);
            let width = text.measure(line, size).x;
            draw_rectangle(at.x - 4.0, at.y, width + 8.0, line_height, background);
            text.draw(line, at, size, ink);
        }
    }
    Shown {
        shown: labels.len(),
        wanted,
        selected_at,
    }
}

/// Where the selected disc's label goes when every place beside it covers
/// something: the nearest one that covers only other discs and arrows,
/// never the disc itself, its own arrows (a review's student, having just
/// typed its v_x, found the label over its velocity arrow) or another
/// label; where its arrows leave no such place, one clear of the disc.
fn place_over_others(
    p: &impulse::Particle,
    (world, camera, overlays): (&World, &Camera, &Overlays),
    (size, screen): (DVec2, ScreenRect),
    gaps: &[f64],
    placed: &LabelPlacer,
) -> Option<Placement> {
    let center = camera.world_to_screen(p.pos);
    let radius = camera.length_in_pixels(p.radius);
    let mut itself = Obstacles::new(size.y);
    add_disc(&mut itself, p, mean_mass(world), camera, overlays);
    let mut disc = Obstacles::new(size.y);
    disc.add_circle(center, radius + 2.0);
    place_label(center, radius, size, gaps, screen, &itself, placed)
        .or_else(|| place_label(center, radius, size, gaps, screen, &disc, placed))
}

/// `text` cut into lines no wider than `width` (as `measure` finds them),
/// breaking between words; a word wider than that gets a line of its own.
fn wrap_words(text: &str, width: f32, measure: impl Fn(&str) -> f32) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(line) if measure(&format!("{line} {word}")) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// The launch preview's label: the speed, or that there is no room.
pub fn launch_label(text: &WorldText, label: &str, tip: Vec2, look: Look) {
    let size = MIN_TEXT_POINTS * look.text_scale;
    let extent = text.measure(label, size);
    let at = tip + vec2(8.0, -8.0 - extent.y);
    draw_rectangle(
        at.x - 4.0,
        at.y,
        extent.x + 8.0,
        extent.y,
        color(look.colors.label_background),
    );
    text.draw(label, at, size, color(look.colors.text));
}

#[cfg(test)]
mod tests;
