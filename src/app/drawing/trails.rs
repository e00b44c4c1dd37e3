//! The path traces: each disc's recent path as a fading line, with a dot
//! every 0.1 s of simulated time.

use crate::app::model::camera::Camera;
use macroquad::prelude::*;

/// Fading lines, oldest faintest, and a dot every 0.1 s, each disc's in
/// the colour `disc_color` gives it.
pub fn draw_trails(
    trails: &crate::app::model::trails::Trails,
    camera: &Camera,
    disc_color: impl Fn(usize) -> impulse::Color,
) {
    if !trails.on {
        return;
    }
    for (i, (path, dots)) in trails.paths().enumerate() {
        let c = disc_color(i);
        let n = path.len();
        for (k, pair) in path.iter().zip(path.iter().skip(1)).enumerate() {
            let (a, b) = (
                camera.world_to_screen(*pair.0),
                camera.world_to_screen(*pair.1),
            );
            let alpha = 0.7 * (k + 1) as f32 / n as f32;
            let line = Color::from_rgba(c.r, c.g, c.b, (alpha * 255.0) as u8);
            draw_line(a.x as f32, a.y as f32, b.x as f32, b.y as f32, 1.5, line);
        }
        let dot = Color::from_rgba(c.r, c.g, c.b, 230);
        for d in dots {
            let at = camera.world_to_screen(*d);
            draw_circle(at.x as f32, at.y as f32, 2.5, dot);
        }
    }
}
