//! Trails: each disc's recent path, drawn fading, so a class can see where
//! the discs came from and how a collision bent their paths, with a dot
//! every [`DOT_SECONDS`] of simulated time: the spacing of the dots reads
//! as the speed (PhET's path traces). Recorded here; drawn by the world's drawing.

use glam::DVec2;
use impulse::World;
use std::collections::VecDeque;

/// Points kept per disc (one per frame: about 3 s at 60 fps).
const POINTS: usize = 180;
/// A dot on the path every this many simulated seconds.
pub const DOT_SECONDS: f64 = 0.1;
/// Dots kept per disc.
const DOTS: usize = 40;
/// Above this many discs trails are not drawn (they would be a blur).
pub const MAX_DISCS: usize = 2000;

/// Recent positions of every disc, when trails are on.
#[derive(Clone, Debug, Default)]
pub struct Trails {
    /// Whether trails are recorded and drawn.
    pub on: bool,
    paths: Vec<VecDeque<DVec2>>,
    /// Where each disc was at each whole multiple of [`DOT_SECONDS`].
    dots: Vec<VecDeque<DVec2>>,
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
            self.paths = vec![VecDeque::with_capacity(POINTS); world.particles.len()];
            self.dots = vec![VecDeque::with_capacity(DOTS); world.particles.len()];
        }
        let (t0, t1) = (self.last_time, world.time);
        self.last_time = t1;
        // The multiples of DOT_SECONDS passed since the last frame.
        let first = (t0 / DOT_SECONDS).floor() as i64 + 1;
        let last = (t1 / DOT_SECONDS).floor() as i64;
        let discs = self
            .paths
            .iter_mut()
            .zip(&mut self.dots)
            .zip(&world.particles);
        for ((path, dots), p) in discs {
            // A jump (a periodic wrap, a drag) breaks the line.
            if path
                .back()
                .is_some_and(|&q| (q - p.pos).length() > 4.0 * p.radius)
            {
                path.clear();
                dots.clear();
            }
            // A dot where the disc was at each multiple, between the last
            // frame's position and this one (straight flight in between).
            if let Some(&q) = path.back().filter(|_| t1 > t0) {
                for k in first..=last.min(first + 100) {
                    let f = (k as f64 * DOT_SECONDS - t0) / (t1 - t0);
                    if dots.len() == DOTS {
                        dots.pop_front();
                    }
                    dots.push_back(q + (p.pos - q) * f);
                }
            }
            if path.len() == POINTS {
                path.pop_front();
            }
            path.push_back(p.pos);
        }
    }

    /// Each disc's recent path (its colour, oldest point first) and its
    /// dots, for drawing.
    pub fn paths(&self) -> impl Iterator<Item = (&VecDeque<DVec2>, &VecDeque<DVec2>)> {
        self.paths.iter().zip(&self.dots)
    }

    /// The dots of disc `k`, oldest first.
    #[cfg(test)]
    pub fn dots(&self, k: usize) -> impl Iterator<Item = &DVec2> {
        self.dots.get(k).into_iter().flatten()
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
        assert!(trails.paths.iter().all(|p| p.len() == POINTS));
        world.time = 0.0;
        trails.record(&world);
        assert!(trails.paths.iter().all(|p| p.len() == 1));
    }

    #[test]
    fn dots_fall_every_tenth_of_a_second_so_their_spacing_is_the_speed() {
        let mut world = World::new(DVec2::new(100.0, 10.0));
        world.particles.push(impulse::Particle::new(
            DVec2::new(1.0, 5.0),
            DVec2::new(3.0, 0.0),
            1.0,
            0.5,
            impulse::Color::palette(0),
        ));
        let mut trails = Trails {
            on: true,
            ..Default::default()
        };
        trails.record(&world);
        // Frames of an awkward length, not a divisor of the dot period.
        for _ in 0..20 {
            world.step(0.037);
            trails.record(&world);
        }
        let dots: Vec<DVec2> = trails.dots(0).copied().collect();
        assert_eq!(dots.len(), (20.0 * 0.037 / DOT_SECONDS) as usize);
        for pair in dots.windows(2) {
            let gap = (pair[1] - pair[0]).length();
            assert!((gap - 3.0 * DOT_SECONDS).abs() < 1e-9, "{gap}");
        }
        assert!((dots[0].x - (1.0 + 3.0 * DOT_SECONDS)).abs() < 1e-9);
    }
}
