//! Conservation, shown: a live plot of the totals (momentum components and
//! kinetic energy) against time with their drift, the centre of mass with
//! its velocity, and a momentum diagram (every disc's momentum tip to tail,
//! and their sum) like PhET's.

use super::camera::Camera;
use super::hud::screen_text;
use glam::DVec2;
use impulse::{Metrics, World};
use macroquad::prelude::*;
use std::collections::VecDeque;

/// Samples the plot keeps (one per frame: about 10 s at 60 fps).
const MAX_SAMPLES: usize = 600;
/// The momentum diagram is drawn for at most this many discs.
pub const DIAGRAM_MAX_DISCS: usize = 24;

/// One frame's totals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Simulated time (s).
    pub time: f64,
    /// Total momentum (kg·m/s).
    pub momentum: DVec2,
    /// Total kinetic energy (J).
    pub kinetic_energy: f64,
}

/// The recent totals, and the values they started from.
#[derive(Clone, Debug, Default)]
pub struct Totals {
    samples: VecDeque<Sample>,
    first: Option<Sample>,
    /// Σ m·|v| when recording began: the momentum scale drift is quoted in.
    momentum_scale: f64,
}

impl Totals {
    /// Adds the world's totals now (a jump back in time starts afresh).
    pub fn push(&mut self, world: &World, metrics: &Metrics) {
        let sample = Sample {
            time: world.time,
            momentum: metrics.momentum,
            kinetic_energy: metrics.kinetic_energy,
        };
        if self.samples.back().is_some_and(|s| s.time > sample.time) {
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

    /// Starts afresh (a new scene, an edit, a rewind).
    pub fn clear(&mut self) {
        self.samples.clear();
        self.first = None;
    }

    /// Drift since recording began: (|Δp| / Σm|v|, ΔKE / KE₀), or `None`
    /// with nothing recorded. A zero scale gives zero drift.
    pub fn drift(&self) -> Option<(f64, f64)> {
        let (first, last) = (self.first?, *self.samples.back()?);
        let relative = |change: f64, scale: f64| if scale > 0.0 { change / scale } else { 0.0 };
        Some((
            relative(
                (last.momentum - first.momentum).length(),
                self.momentum_scale,
            ),
            relative(
                last.kinetic_energy - first.kinetic_energy,
                first.kinetic_energy,
            ),
        ))
    }

    /// The samples, oldest first.
    pub fn samples(&self) -> impl Iterator<Item = &Sample> {
        self.samples.iter()
    }
}

/// A plotted total: its label, colour and value.
type Series = (&'static str, Color, fn(&Sample) -> f64);

/// The dark backdrop every plot here sits on.
fn backdrop(rect: Rect) {
    draw_rectangle(
        rect.x,
        rect.y,
        rect.w,
        rect.h,
        Color::new(0.05, 0.06, 0.09, 0.8),
    );
}

const PX_COLOR: Color = Color::new(0.34, 0.71, 0.91, 1.0); // sky blue
const PY_COLOR: Color = Color::new(0.90, 0.62, 0.0, 1.0); // orange
const KE_COLOR: Color = Color::new(0.0, 0.62, 0.45, 1.0); // bluish green
const COM_COLOR: Color = Color::new(0.94, 0.89, 0.26, 1.0); // yellow

/// The plot in `rect` (screen pixels): p_x, p_y and KE against time, each
/// scaled to its own range (so a flat line means conserved), with the
/// drift written underneath.
pub fn draw_totals(totals: &Totals, rect: Rect, font: f32) {
    backdrop(rect);
    let samples: Vec<Sample> = totals.samples().copied().collect();
    let title = match totals.drift() {
        Some((dp, dke)) => format!("totals   drift: |dp| {dp:.1e}   dKE {dke:+.1e}"),
        None => "totals".to_string(),
    };
    draw_text(
        screen_text(&title),
        rect.x + 6.0,
        rect.y + font,
        font,
        WHITE,
    );
    if samples.len() < 2 {
        return;
    }
    let plot = Rect::new(
        rect.x + 6.0,
        rect.y + 1.4 * font,
        rect.w - 12.0,
        rect.h - 2.4 * font,
    );
    let (t0, t1) = (samples[0].time, samples[samples.len() - 1].time);
    let series: [Series; 3] = [
        ("px", PX_COLOR, |s| s.momentum.x),
        ("py", PY_COLOR, |s| s.momentum.y),
        ("KE", KE_COLOR, |s| s.kinetic_energy),
    ];
    for (k, (label, color, value)) in series.iter().enumerate() {
        let values: Vec<f64> = samples.iter().map(value).collect();
        let (lo, hi) = values
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                (lo.min(v), hi.max(v))
            });
        // Each total gets a band of its own; a conserved one is a flat line
        // through the band's middle.
        let mid = 0.5 * (lo + hi);
        let half = (0.5 * (hi - lo)).max(1e-9 * mid.abs().max(1e-12));
        let band = plot.h / 3.0;
        let centre = plot.y + band * (k as f32 + 0.5);
        let to_screen = |t: f64, v: f64| {
            let x = plot.x + ((t - t0) / (t1 - t0).max(1e-12)) as f32 * plot.w;
            let y = centre - 0.4 * band * ((v - mid) / half) as f32;
            vec2(x, y)
        };
        for pair in samples.windows(2).zip(values.windows(2)) {
            let (s, v) = pair;
            let (a, b) = (to_screen(s[0].time, v[0]), to_screen(s[1].time, v[1]));
            draw_line(a.x, a.y, b.x, b.y, 2.0, *color);
        }
        let now = values[values.len() - 1];
        let label = format!("{label} {now:+.3}");
        draw_text(
            &label,
            rect.x + 6.0 + k as f32 * rect.w / 3.0,
            rect.y + rect.h - 0.3 * font,
            0.9 * font,
            *color,
        );
    }
}

/// The centre of mass as a cross in a circle, with its velocity arrow.
pub fn draw_center_of_mass(world: &World, camera: &Camera, arrow_seconds: f64) {
    if world.particles.is_empty() {
        return;
    }
    let m = world.metrics();
    let c = camera.world_to_screen(m.center_of_mass);
    let (x, y) = (c.x as f32, c.y as f32);
    draw_circle_lines(x, y, 9.0, 2.0, COM_COLOR);
    draw_line(x - 12.0, y, x + 12.0, y, 2.0, COM_COLOR);
    draw_line(x, y - 12.0, x, y + 12.0, 2.0, COM_COLOR);
    let tip = c + camera.vector_to_screen(m.center_of_mass_velocity * arrow_seconds);
    draw_line(x, y, tip.x as f32, tip.y as f32, 3.0, COM_COLOR);
}

/// Every disc's momentum tip to tail from the corner of `rect`, and their
/// sum from the same start: the sum's arrow ends where the chain ends.
pub fn draw_momentum_diagram(world: &World, rect: Rect, font: f32) {
    backdrop(rect);
    draw_text(
        "momentum, tip to tail",
        rect.x + 6.0,
        rect.y + font,
        font,
        WHITE,
    );
    let ps = &world.particles;
    if ps.is_empty() || ps.len() > DIAGRAM_MAX_DISCS {
        let why = if ps.is_empty() {
            "no discs"
        } else {
            "too many discs to draw"
        };
        draw_text(why, rect.x + 6.0, rect.y + 2.2 * font, font, GRAY);
        return;
    }
    // The chain's extent fixes the scale.
    let mut at = DVec2::ZERO;
    let (mut lo, mut hi) = (DVec2::ZERO, DVec2::ZERO);
    for p in ps {
        at += p.momentum();
        lo = lo.min(at);
        hi = hi.max(at);
    }
    let span = (hi - lo).max_element().max(1e-12);
    let area = Rect::new(
        rect.x + 10.0,
        rect.y + 1.5 * font,
        rect.w - 20.0,
        rect.h - 2.0 * font,
    );
    let scale = f64::from(area.w.min(area.h)) / span;
    let origin =
        DVec2::new(f64::from(area.x), f64::from(area.y + area.h)) + DVec2::new(-lo.x, lo.y) * scale;
    let to_screen = |v: DVec2| {
        vec2(
            (origin.x + v.x * scale) as f32,
            (origin.y - v.y * scale) as f32,
        )
    };
    let mut at = DVec2::ZERO;
    for p in ps {
        let (a, b) = (to_screen(at), to_screen(at + p.momentum()));
        let c = p.color;
        let color = Color::from_rgba(c.r, c.g, c.b, 255);
        draw_line(a.x, a.y, b.x, b.y, 3.0, color);
        draw_circle(b.x, b.y, 3.0, color);
        at += p.momentum();
    }
    let (a, b) = (to_screen(DVec2::ZERO), to_screen(at));
    draw_line(a.x, a.y, b.x, b.y, 2.0, WHITE);
    draw_circle_lines(b.x, b.y, 5.0, 2.0, WHITE);
    draw_text(
        format!("sum ({:+.3}, {:+.3}) kg m/s", at.x, at.y),
        rect.x + 6.0,
        rect.y + rect.h - 0.3 * font,
        0.9 * font,
        WHITE,
    );
}

/// Speed bins of the histogram.
const BINS: usize = 20;

/// The discs' speeds as a histogram against the 2D Maxwell–Boltzmann law
/// at the same temperature, f(v) = (v/σ²)·exp(−v²/2σ²) with σ² = kT/m and
/// kT = KE/N (two degrees of freedom per disc; the mean mass stands in for
/// mixed masses), with the temperature written above.
pub fn draw_speed_histogram(world: &World, rect: Rect, font: f32) {
    backdrop(rect);
    let n = world.particles.len();
    if n < 2 {
        draw_text(
            "speed histogram: too few discs",
            rect.x + 6.0,
            rect.y + font,
            font,
            GRAY,
        );
        return;
    }
    let kt = world.metrics().kinetic_energy / n as f64;
    let mean_mass = world.particles.iter().map(|p| p.mass).sum::<f64>() / n as f64;
    let sigma2 = kt / mean_mass;
    let top = 4.0 * sigma2.sqrt().max(1e-12);
    let width = top / BINS as f64;
    let mut counts = [0usize; BINS];
    for p in &world.particles {
        let k = (p.vel.length() / width) as usize;
        if k < BINS {
            counts[k] += 1;
        }
    }
    draw_text(
        format!("speeds vs Maxwell-Boltzmann   kT = KE/N = {kt:.3} J"),
        rect.x + 6.0,
        rect.y + font,
        font,
        WHITE,
    );
    let area = Rect::new(
        rect.x + 6.0,
        rect.y + 1.4 * font,
        rect.w - 12.0,
        rect.h - 2.6 * font,
    );
    let density = |v: f64| v / sigma2 * (-v * v / (2.0 * sigma2)).exp();
    let peak = density(sigma2.sqrt());
    let tallest = counts
        .iter()
        .map(|&c| c as f64 / (n as f64 * width))
        .fold(peak, f64::max);
    let y_of = |d: f64| area.y + area.h * (1.0 - (d / tallest) as f32);
    let bar = area.w / BINS as f32;
    for (k, &c) in counts.iter().enumerate() {
        let d = c as f64 / (n as f64 * width);
        let y = y_of(d);
        draw_rectangle(
            area.x + k as f32 * bar + 1.0,
            y,
            bar - 2.0,
            area.y + area.h - y,
            PX_COLOR,
        );
    }
    let mut last = None;
    for k in 0..=100 {
        let v = top * k as f64 / 100.0;
        let point = vec2(area.x + area.w * k as f32 / 100.0, y_of(density(v)));
        if let Some(a) = last {
            let a: Vec2 = a;
            draw_line(a.x, a.y, point.x, point.y, 2.0, PY_COLOR);
        }
        last = Some(point);
    }
    draw_text(
        format!("0 to {top:.2} m/s; curve: the law at this temperature"),
        rect.x + 6.0,
        rect.y + rect.h - 0.3 * font,
        0.9 * font,
        GRAY,
    );
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
}
