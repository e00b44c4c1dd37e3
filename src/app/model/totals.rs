//! The data behind the bottom dock's plots, kept apart from drawing: the
//! recent totals (momentum, angular momentum and the energies of moving and
//! of turning against time, with their drift), the speed histogram against
//! Maxwell–Boltzmann, and the rim speeds |ω|·r beside it.

use glam::DVec2;
use impulse::{Metrics, World};
use std::collections::VecDeque;

/// Samples the plot keeps (one per frame, and two per step with a
/// collision in small scenes: about 10 s at 60 fps).
const MAX_SAMPLES: usize = 600;
/// Wall impacts the momentum plot marks at most.
const MAX_WALL_MARKS: usize = 200;
/// Scenes up to this many discs are also sampled just before and after
/// each step with a collision, so a loss shows as a drop at its instant.
pub const SAMPLE_COLLISIONS_MAX_DISCS: usize = 64;
/// The momentum diagram is drawn for at most this many discs.
pub const DIAGRAM_MAX_DISCS: usize = 24;

/// One frame's totals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Simulated time (s).
    pub time: f64,
    /// Total momentum (kg·m/s).
    pub momentum: DVec2,
    /// Total kinetic energy of translation (J).
    pub kinetic_energy: f64,
    /// Total kinetic energy of rotation (J).
    pub rotational_energy: f64,
    /// Total angular momentum about the origin (kg·m²/s).
    pub angular_momentum: f64,
}

impl Sample {
    /// Kinetic energy of moving and of turning together (J).
    pub fn energy(&self) -> f64 {
        self.kinetic_energy + self.rotational_energy
    }

    /// The share of that energy in turning (0 to 1; 0 with no energy).
    pub fn rotation_share(&self) -> f64 {
        let e = self.energy();
        if e > 0.0 {
            self.rotational_energy / e
        } else {
            0.0
        }
    }
}

/// The recent totals, and the values they started from.
#[derive(Clone, Debug, Default)]
pub struct Totals {
    samples: VecDeque<Sample>,
    first: Option<Sample>,
    /// Σ m·|v| when recording began: the momentum scale drift is quoted in.
    momentum_scale: f64,
    /// When walls pushed the discs (s), in small scenes.
    walls: VecDeque<f64>,
    /// When the person last changed the discs' totals (s): the collisions
    /// before it no longer describe these discs.
    edited_at: Option<f64>,
}

impl Totals {
    /// Adds the world's totals now. A jump back in time (a rewind) drops
    /// the samples after it: the plot shows what led up to this moment.
    pub fn push(&mut self, world: &World, metrics: &Metrics) {
        self.push_at(world.time, world, metrics);
    }

    /// Adds totals measured at `time` (s).
    pub fn push_at(&mut self, time: f64, world: &World, metrics: &Metrics) {
        let sample = Sample {
            time,
            momentum: metrics.momentum,
            kinetic_energy: metrics.kinetic_energy,
            rotational_energy: metrics.rotational_energy,
            angular_momentum: metrics.angular_momentum,
        };
        if self.edited_at.is_some_and(|at| at > sample.time) {
            // Back before the change: the discs are as they were then.
            self.edited_at = None;
        }
        while self.samples.back().is_some_and(|s| s.time > sample.time) {
            self.samples.pop_back();
        }
        if self.first.is_some_and(|f| f.time > sample.time) {
            self.clear();
        }
        if self.first.is_none() {
            self.first = Some(sample);
            self.momentum_scale = Metrics::momentum_scale(&world.particles);
        }
        if self.samples.back().is_some_and(|s| s.time == sample.time) {
            self.samples.pop_back();
        }
        self.samples.push_back(sample);
        if self.samples.len() > MAX_SAMPLES {
            self.samples.pop_front();
        }
    }

    /// Forgets the samples and wall marks from `time` on (an undo back to
    /// a moment of this run).
    pub fn keep_before(&mut self, time: f64) {
        while self.samples.back().is_some_and(|s| s.time >= time) {
            self.samples.pop_back();
        }
        while self.walls.back().is_some_and(|&t| t >= time) {
            self.walls.pop_back();
        }
        if self.edited_at.is_some_and(|at| at >= time) {
            self.edited_at = None;
        }
        if self.samples.is_empty() {
            self.clear();
        }
    }

    /// Starts afresh from `world` as it is now (a new scene, the person's
    /// edit): the change is then counted from this instant ("since t =
    /// 0.00 s" for a scene just opened, not from the first frame's step).
    pub fn restart(&mut self, world: &World) {
        self.clear();
        self.push(world, &world.metrics());
        self.edited_at = Some(world.time);
    }

    /// When the discs' totals were last set afresh (a scene opened, the
    /// person's edit), unless a rewind or an undo has gone back before it.
    pub fn edited_at(&self) -> Option<f64> {
        self.edited_at
    }

    /// Forgets every sample (a rewind to another run).
    pub fn clear(&mut self) {
        self.samples.clear();
        self.walls.clear();
        self.first = None;
    }

    /// Drift since recording began: (|Δp| / Σm|v|, ΔE / E₀) with E the
    /// kinetic energy of moving and turning, or `None` with nothing
    /// recorded. A zero scale gives zero drift.
    pub fn drift(&self) -> Option<(f64, f64)> {
        let (first, last) = (self.first?, *self.samples.back()?);
        let relative = |change: f64, scale: f64| if scale > 0.0 { change / scale } else { 0.0 };
        Some((
            relative(
                (last.momentum - first.momentum).length(),
                self.momentum_scale,
            ),
            relative(last.energy() - first.energy(), first.energy()),
        ))
    }

    /// The totals just `before` a step with an impact (its start time and
    /// totals) and `now` after it, and the walls' push marked if `walls`
    /// hit: in small scenes the plot then drops at the impact's instant.
    pub fn around_impact(
        &mut self,
        before: (f64, &Metrics),
        world: &World,
        now: &Metrics,
        walls: bool,
    ) {
        self.push_at(before.0, world, before.1);
        self.push(world, now);
        if walls {
            self.mark_wall(world.time);
        }
    }

    /// Notes that walls pushed the discs at `time` (s): the momentum plot
    /// marks it, since only there does the total momentum change.
    pub fn mark_wall(&mut self, time: f64) {
        while self.walls.back().is_some_and(|&t| t > time) {
            self.walls.pop_back();
        }
        if self.walls.len() == MAX_WALL_MARKS {
            self.walls.pop_front();
        }
        self.walls.push_back(time);
    }

    /// When walls pushed the discs, oldest first (within the samples' span).
    pub fn wall_marks(&self) -> impl Iterator<Item = f64> + '_ {
        let from = self.samples.front().map_or(f64::INFINITY, |s| s.time);
        self.walls.iter().copied().filter(move |&t| t >= from)
    }

    /// The first sample since recording began.
    pub fn first(&self) -> Option<&Sample> {
        self.first.as_ref()
    }

    /// The samples, oldest first.
    pub fn samples(&self) -> impl Iterator<Item = &Sample> {
        self.samples.iter()
    }
}

/// The discs' speeds against the 2D Maxwell–Boltzmann law at the same
/// temperature, f(v) = (v/σ²)·exp(−v²/2σ²) with σ² = kT/m and kT = KE/N (two
/// degrees of freedom per disc; the mean mass stands in for mixed masses).
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedHistogram {
    /// kT = KE/N (J).
    pub kt: f64,
    /// σ² = kT / mean mass (m²/s²).
    pub sigma2: f64,
    /// Width of a bin (m/s); the bins start at 0.
    pub bin_width: f64,
    /// Share of the discs per m/s in each bin: a probability density, so
    /// the bars and the law share one axis.
    pub density: Vec<f64>,
    /// How many discs the histogram counts (moving or not).
    pub discs: usize,
}

/// Speed bins of the histogram.
pub const BINS: usize = 20;

/// Whether every disc lies and moves on one horizontal line, with nothing
/// pulling it off (the head-on lessons, the cradle, the π blocks). There
/// L about the origin is −y·p_x, the momentum's plot again: the Totals tab
/// leaves it out rather than show a number a student cannot place.
pub fn on_one_line(world: &World) -> bool {
    let Some(first) = world.particles.first() else {
        return false;
    };
    world.laws.gravity.y == 0.0
        && world
            .particles
            .iter()
            .all(|p| p.pos.y == first.pos.y && p.vel.y == 0.0 && p.spin == 0.0)
}

/// Discs from which the Speeds tab draws Maxwell–Boltzmann: the law of a
/// gas, not of two discs in a lesson (a review read the curve over a
/// head-on hit's two bars as something they should follow).
pub const GAS_AT_LEAST: usize = 20;

impl SpeedHistogram {
    /// Whether enough discs are counted for a gas's law to mean anything
    /// ([`GAS_AT_LEAST`]).
    pub fn is_a_gas(&self) -> bool {
        self.discs >= GAS_AT_LEAST
    }
}

/// The discs' rim speeds |ω|·r, on the speed histogram's bins, and where
/// they settle when the energy is shared equally among the two ways of
/// moving and the one of turning: ω is then normal with variance kT/I, so
/// for a uniform disc (I = ½·m·r²) the rim speed is half-normal with
/// variance 2σ², f(u) = exp(−u²/4σ²) / (σ·√π).
#[derive(Clone, Debug, PartialEq)]
pub struct RimHistogram {
    /// Share of the discs per m/s in each bin (the speed histogram's bins).
    pub density: Vec<f64>,
    /// σ² of the speed histogram (m²/s²).
    pub sigma2: f64,
}

impl RimHistogram {
    /// The rim speeds of `world` on `speeds`' bins.
    pub fn of(world: &World, speeds: &SpeedHistogram) -> Self {
        let n = world.particles.len().max(1);
        let mut counts = [0usize; BINS];
        for p in &world.particles {
            let k = (p.spin.abs() * p.radius / speeds.bin_width) as usize;
            if k < BINS {
                counts[k] += 1;
            }
        }
        let density = counts
            .iter()
            .map(|&c| c as f64 / (n as f64 * speeds.bin_width))
            .collect();
        RimHistogram {
            density,
            sigma2: speeds.sigma2,
        }
    }

    /// The equal-sharing law's density at rim speed `u` (per m/s).
    pub fn law(&self, u: f64) -> f64 {
        (-u * u / (4.0 * self.sigma2)).exp() / (self.sigma2 * std::f64::consts::PI).sqrt()
    }
}

impl SpeedHistogram {
    /// The histogram of `world`'s speeds up to 4σ, or `None` for fewer than
    /// two discs or none moving.
    pub fn of(world: &World) -> Option<Self> {
        let n = world.particles.len();
        if n < 2 {
            return None;
        }
        let kt = world.metrics().kinetic_energy / n as f64;
        let mean_mass = world.particles.iter().map(|p| p.mass).sum::<f64>() / n as f64;
        let sigma2 = kt / mean_mass;
        if !(sigma2 > 0.0 && sigma2.is_finite()) {
            return None;
        }
        let bin_width = 4.0 * sigma2.sqrt() / BINS as f64;
        let mut counts = [0usize; BINS];
        for p in &world.particles {
            let k = (p.vel.length() / bin_width) as usize;
            if k < BINS {
                counts[k] += 1;
            }
        }
        let density = counts
            .iter()
            .map(|&c| c as f64 / (n as f64 * bin_width))
            .collect();
        Some(SpeedHistogram {
            kt,
            sigma2,
            bin_width,
            density,
            discs: n,
        })
    }

    /// A density times this is a number of discs in one bin: what a bar
    /// shows, and what the law expects there.
    pub fn discs_per_density(&self) -> f64 {
        self.discs as f64 * self.bin_width
    }

    /// The law's density at speed `v` (per m/s).
    pub fn law(&self, v: f64) -> f64 {
        v / self.sigma2 * (-v * v / (2.0 * self.sigma2)).exp()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use impulse::presets::Gas;

    #[test]
    fn drift_is_zero_for_a_conserving_run_and_a_rewind_starts_afresh() {
        let mut world = Gas {
            count: 40,
            boundary: impulse::Boundary::Periodic,
            ..Gas::default()
        }
        .build();
        world.method = impulse::method::Setting::Fixed(impulse::method::Method::Exact);
        let mut totals = Totals::default();
        for _ in 0..50 {
            world.step(0.02);
            totals.push(&world, &world.metrics());
        }
        let (dp, dke) = totals.drift().unwrap();
        assert!(dp < 1e-12 && dke.abs() < 1e-12, "{dp} {dke}");
        assert_eq!(totals.samples().count(), 50);
        world.time = 0.01; // a rewind
        totals.push(&world, &world.metrics());
        assert_eq!(totals.samples().count(), 1);
    }

    #[test]
    fn the_histogram_is_a_density_and_the_law_integrates_to_one() {
        let world = Gas {
            count: 400,
            ..Gas::default()
        }
        .build();
        let h = SpeedHistogram::of(&world).unwrap();
        let n = world.particles.len() as f64;
        let below: usize = world
            .particles
            .iter()
            .filter(|p| p.vel.length() < 4.0 * h.sigma2.sqrt())
            .count();
        let area: f64 = h.density.iter().sum::<f64>() * h.bin_width;
        assert!((area - below as f64 / n).abs() < 1e-12, "{area}");
        let (mut integral, dv) = (0.0, 1e-3 * h.sigma2.sqrt());
        for k in 0..20_000 {
            integral += h.law((k as f64 + 0.5) * dv) * dv;
        }
        assert!((integral - 1.0).abs() < 1e-6, "{integral}");
        assert!((h.kt - world.metrics().kinetic_energy / n).abs() < 1e-12);
        // What the plot draws: each bar the discs in its bin, counted here
        // afresh.
        for (k, &d) in h.density.iter().enumerate() {
            let (lo, hi) = (k as f64 * h.bin_width, (k + 1) as f64 * h.bin_width);
            let inside = world.particles.iter().map(|p| p.vel.length());
            let inside = inside.filter(|v| (lo..hi).contains(v)).count();
            assert!(
                (d * h.discs_per_density() - inside as f64).abs() < 1e-9,
                "bin {k}"
            );
        }
    }

    #[test]
    fn rim_speeds_share_the_bins_and_their_law_integrates_to_one() {
        let mut world = Gas {
            count: 100,
            ..Gas::default()
        }
        .build();
        let speeds = SpeedHistogram::of(&world).unwrap();
        // Half the discs turn their rims at 1.5 bins' width, half at 5.5
        // (backwards): bins 1 and 5, half the discs each.
        let w = speeds.bin_width;
        for (k, p) in world.particles.iter_mut().enumerate() {
            p.spin = if k % 2 == 0 { 1.5 * w } else { -5.5 * w } / p.radius;
        }
        let rims = RimHistogram::of(&world, &speeds);
        let share = |k: usize| rims.density[k] * w;
        assert!((share(1) - 0.5).abs() < 1e-12 && (share(5) - 0.5).abs() < 1e-12);
        let (mut integral, du) = (0.0, 1e-3 * speeds.sigma2.sqrt());
        for k in 0..40_000 {
            integral += rims.law((k as f64 + 0.5) * du) * du;
        }
        assert!((integral - 1.0).abs() < 1e-6, "{integral}");
    }
}
