//! Text readouts beside discs (v, |v|, p, m, KE): the selected disc's
//! always, every disc's only where readable: beside a disc big enough to
//! point at, on screen, overlapping no other readout. Backgrounds first,
//! then all text, so the labels cost two draw calls, not two each.

use super::camera::Camera;
use super::cull::{circle_on_screen, LabelPlacer, MIN_LABEL_DISC_PIXELS};
use super::draw::{Overlays, ReadoutScope};
use super::hud::screen_text;
use glam::DVec2;
use impulse::World;
use macroquad::prelude::*;

/// Readouts for "all discs" stop at this many labels.
const MAX_LABELS: usize = 250;

/// Readout lines for one disc.
pub fn readout_lines(p: &impulse::Particle) -> [String; 3] {
    let v = p.vel;
    let m = p.momentum();
    [
        format!("v = ({:.2}, {:.2}) m/s  |v| = {:.2}", v.x, v.y, v.length()),
        format!("p = ({:.2}, {:.2}) kg m/s", m.x, m.y),
        format!("m = {:.3} kg  KE = {:.3} J", p.mass, p.kinetic_energy()),
    ]
}

/// One label: top-left corner, size and lines.
struct Label {
    at: Vec2,
    size: Vec2,
    lines: Vec<String>,
}

/// Text readouts beside the selected disc or every readable disc.
pub fn draw_readouts(
    world: &World,
    camera: &Camera,
    overlays: &Overlays,
    selected: Option<usize>,
    font: f32,
) {
    let all = match overlays.readouts {
        ReadoutScope::Off => return,
        ReadoutScope::Selected => false,
        ReadoutScope::All => true,
    };
    let pad = 0.4 * font;
    let line_height = 1.15 * font;
    let height = 3.0 * line_height + 2.0 * pad;
    let mut placer = LabelPlacer::new(DVec2::new(20.0 * font as f64, height as f64));
    let mut labels = Vec::new();
    // The selected disc first, so its label is never crowded out.
    let others = (0..world.particles.len()).filter(|&i| all && Some(i) != selected);
    for i in selected.into_iter().chain(others) {
        if labels.len() >= MAX_LABELS {
            break;
        }
        let Some(p) = world.particles.get(i) else {
            continue;
        };
        let c = camera.world_to_screen(p.pos);
        let r = camera.length_in_pixels(p.radius);
        let chosen = Some(i) == selected;
        if !circle_on_screen(c, r, camera.viewport) || !(chosen || r >= MIN_LABEL_DISC_PIXELS) {
            continue;
        }
        let lines: Vec<String> = readout_lines(p).iter().map(|l| screen_text(l)).collect();
        let width = lines
            .iter()
            .map(|l| measure_text(l, None, font as u16, 1.0).width)
            .fold(0.0, f32::max);
        let at = vec2((c.x + r) as f32 + 6.0, (c.y - r) as f32);
        let size = vec2(width + 2.0 * pad, height);
        let rect = [at.x as f64, at.y as f64, size.x as f64, size.y as f64];
        if placer.try_place(rect) || chosen {
            labels.push(Label { at, size, lines });
        }
    }
    let background = Color::new(0.05, 0.06, 0.09, 0.55);
    for l in &labels {
        draw_rectangle(l.at.x, l.at.y, l.size.x, l.size.y, background);
    }
    for l in &labels {
        for (k, line) in l.lines.iter().enumerate() {
            let baseline = l.at.y + pad + line_height * (k as f32 + 0.8);
            draw_text(line, l.at.x + pad, baseline, font, WHITE);
        }
    }
}
