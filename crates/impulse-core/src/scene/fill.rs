//! Seeded random fill: discs placed where they overlap nothing (or no more
//! than the fill allows), and the hash grid of discs by cell that the fill
//! and the loader's overlap check share.

use super::FillSpec;
use crate::boundary::Boundary;
use crate::particle::{Color, Particle};
use crate::world::World;
use glam::DVec2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Adds `fill.count` seeded random discs that overlap nothing already there
/// (or no more than `fill.overlap` of the smaller diameter).
///
/// The discs already placed are kept in a hash grid of cells at least a
/// diameter of the largest disc wide, so each try looks at the 3×3 cells
/// around it: placing n discs costs O(n), not O(n²). The answer of each try
/// is the same as testing every disc, so a seed gives the same discs.
pub(super) fn add_fill(world: &mut World, fill: &FillSpec) -> Result<(), String> {
    let mut rng = ChaCha8Rng::seed_from_u64(fill.seed);
    let first = world.particles.len();
    let attempts_per_disc = 2000;
    let largest = world
        .particles
        .iter()
        .map(|p| p.radius)
        .fold(fill.radius[1], f64::max);
    let mut cells = DiscCells::new(world.laws.size, 2.0 * largest, world.laws.boundary);
    for (k, p) in world.particles.iter().enumerate() {
        cells.insert(p.pos, k);
    }
    for k in 0..fill.count {
        let radius = rng.random_range(fill.radius[0]..=fill.radius[1]);
        let speed = rng.random_range(fill.speed[0]..=fill.speed[1]);
        let heading = rng.random_range(0.0..std::f64::consts::TAU);
        let spot = (0..attempts_per_disc).find_map(|_| {
            let pos = DVec2::new(
                rng.random_range(radius..=world.laws.size.x - radius),
                rng.random_range(radius..=world.laws.size.y - radius),
            );
            let mut near = cells.near(pos).map(|i| &world.particles[i]);
            let free = if fill.overlap > 0.0 {
                near.all(|q| {
                    let allowed = fill.overlap * 2.0 * radius.min(q.radius);
                    (q.pos - pos).length() >= radius + q.radius - allowed
                })
            } else {
                let inside = world.laws.boundary != Boundary::Box
                    || (pos.cmpge(DVec2::splat(radius)).all()
                        && pos.cmple(world.laws.size - DVec2::splat(radius)).all());
                inside
                    && near.all(|q| {
                        world
                            .laws
                            .boundary
                            .separation(q.pos, pos, world.laws.size)
                            .length()
                            >= q.radius + radius
                    })
            };
            free.then_some(pos)
        });
        let Some(pos) = spot else {
            return Err(format!(
                "placed only {k} of {} discs without overlap: the box is too full",
                fill.count
            ));
        };
        let mass = fill.density * std::f64::consts::PI * radius * radius;
        let vel = speed * crate::math::unit(heading);
        let color = Color::palette(first + k);
        cells.insert(pos, world.particles.len());
        world
            .particles
            .push(Particle::new(pos, vel, mass, radius, color));
    }
    Ok(())
}

/// Discs by cell, for the overlap tests of [`super::Scene::validate`] and
/// [`add_fill`].
pub(super) struct DiscCells {
    /// Cell width and height (m), at least the widest diameter.
    width: DVec2,
    /// Cells per axis (at least 1); an axis with fewer than three is one cell.
    count: [i64; 2],
    /// Whether the cells wrap around (periodic boundary).
    wrap: bool,
    /// Disc indices by cell.
    map: std::collections::HashMap<[i64; 2], Vec<usize>>,
}

impl DiscCells {
    /// Most cells along one axis (the map is sparse, so this only bounds the
    /// integer arithmetic).
    const MAX_PER_AXIS: f64 = (1u64 << 30) as f64;

    pub(super) fn new(size: DVec2, diameter: f64, boundary: Boundary) -> Self {
        let per_axis = |length: f64| {
            let n = (length / diameter).floor().clamp(1.0, Self::MAX_PER_AXIS);
            if n < 3.0 {
                1
            } else {
                n as i64
            }
        };
        let count = [per_axis(size.x), per_axis(size.y)];
        DiscCells {
            width: DVec2::new(size.x / count[0] as f64, size.y / count[1] as f64),
            count,
            wrap: boundary == Boundary::Periodic,
            map: std::collections::HashMap::new(),
        }
    }

    /// The cell of `pos`; points outside the box go to the border cells,
    /// which are nearer to them than any other cell.
    fn cell(&self, pos: DVec2) -> [i64; 2] {
        let along = |x: f64, w: f64, n: i64| ((x / w).floor().clamp(0.0, (n - 1) as f64)) as i64;
        [
            along(pos.x, self.width.x, self.count[0]),
            along(pos.y, self.width.y, self.count[1]),
        ]
    }

    pub(super) fn insert(&mut self, pos: DVec2, index: usize) {
        let cell = self.cell(pos);
        self.map.entry(cell).or_default().push(index);
    }

    /// Every disc in the 3×3 cells around `pos` (each cell once).
    pub(super) fn near(&self, pos: DVec2) -> impl Iterator<Item = usize> + '_ {
        let [cx, cy] = self.cell(pos);
        let axis = |c: i64, n: i64| -> Vec<i64> {
            let mut cells: Vec<i64> = (c - 1..=c + 1)
                .filter_map(|k| {
                    if self.wrap {
                        Some(k.rem_euclid(n))
                    } else {
                        (0..n).contains(&k).then_some(k)
                    }
                })
                .collect();
            cells.sort_unstable();
            cells.dedup();
            cells
        };
        let (xs, ys) = (axis(cx, self.count[0]), axis(cy, self.count[1]));
        xs.into_iter()
            .flat_map(move |x| ys.clone().into_iter().map(move |y| [x, y]))
            .filter_map(|cell| self.map.get(&cell))
            .flatten()
            .copied()
    }
}
