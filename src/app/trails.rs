//! Trails: each disc's recent path, drawn fading, so a class can see where
//! the discs came from and how a collision bent their paths.

use super::camera::Camera;
use glam::DVec2;
use impulse::World;
use macroquad::prelude::*;
use std::collections::VecDeque;

/// Points kept per disc (one per frame: about 1 s at 60 fps).
const POINTS: usize = 60;
/// Above this many discs trails are not drawn (they would be a blur).
pub const MAX_DISCS: usize = 2000;

/// Recent positions of every disc, when trails are on.
#[derive(Clone, Debug, Default)]
pub struct Trails {
    /// Whether trails are recorded and drawn.
    pub on: bool,
    paths: Vec<(impulse::Color, VecDeque<DVec2>)>,
    last_time: f64,
}

impl Trails {
    /// Adds the discs' positions now; starts afresh when the discs changed
    /// (added, removed) or time went back (a rewind, a new scene).
    pub fn record(&mut self, world: &World) {
        if !self.on || world.particles.len() > MAX_DISCS {
            self.paths.clear();
            return;
        }
        if world.particles.len() != self.paths.len() || world.time < self.last_time {
            self.paths = world
                .particles
                .iter()
                .map(|p| (p.color, VecDeque::with_capacity(POINTS)))
                .collect();
        }
        self.last_time = world.time;
        for ((_, path), p) in self.paths.iter_mut().zip(&world.particles) {
            // A jump (a periodic wrap, a drag) breaks the line.
            if path
                .back()
                .is_some_and(|&q| (q - p.pos).length() > 4.0 * p.radius)
            {
                path.clear();
            }
            if path.len() == POINTS {
                path.pop_front();
            }
            path.push_back(p.pos);
        }
    }

    /// Fading lines, oldest faintest.
    pub fn draw(&self, camera: &Camera, scale: f32) {
        if !self.on {
            return;
        }
        let width = 1.5 * scale;
        for (color, path) in &self.paths {
            let n = path.len();
            for (k, pair) in path.iter().zip(path.iter().skip(1)).enumerate() {
                let (a, b) = (
                    camera.world_to_screen(*pair.0),
                    camera.world_to_screen(*pair.1),
                );
                let alpha = 0.7 * (k + 1) as f32 / n as f32;
                let c = Color::from_rgba(color.r, color.g, color.b, (alpha * 255.0) as u8);
                draw_line(a.x as f32, a.y as f32, b.x as f32, b.y as f32, width, c);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_capped_and_restart_on_a_rewind() {
        let mut world = impulse::presets::Gas {
            count: 3,
            ..Default::default()
        }
        .build();
        let mut trails = Trails {
            on: true,
            ..Default::default()
        };
        for _ in 0..(POINTS + 10) {
            world.step(0.001);
            trails.record(&world);
        }
        assert!(trails.paths.iter().all(|(_, p)| p.len() == POINTS));
        world.time = 0.0;
        trails.record(&world);
        assert!(trails.paths.iter().all(|(_, p)| p.len() == 1));
    }
}
