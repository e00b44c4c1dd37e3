//! The classroom layer over the sandbox: conservation shown (totals plot,
//! centre of mass, momentum diagram, centre-of-mass frame), the collision
//! ledger with "run to the next collision", rewind, and data export.
//!
//! Keys: T totals plot, O centre of mass, D momentum diagram, U ledger,
//! Z centre-of-mass frame, J run to the next collision, `,` / `.` rewind
//! and forward (Shift: ten times as far), X export CSV files, A trails,
//! F2 projector mode, F3 colour-blind-safe palette, F4 speed histogram,
//! F12 screenshot into the output folder.

use super::hud::{screen_text, text_panel};
use super::{export, plot, scenes, App};
use glam::DVec2;
use impulse::ledger::Collision;
use macroquad::prelude::*;

/// Collisions the window keeps in the ledger.
pub const LEDGER_KEEP: usize = 50;
/// Collisions the ledger panel lists.
const LEDGER_LINES: usize = 6;
/// How far "run to the next collision" looks ahead (simulated seconds).
const NEXT_COLLISION_LIMIT: f64 = 60.0;

/// Which classroom overlays are on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LessonOverlays {
    /// The live plot of the totals.
    pub totals: bool,
    /// The centre of mass and its velocity.
    pub center_of_mass: bool,
    /// The momentum diagram.
    pub diagram: bool,
    /// The collision ledger.
    pub ledger: bool,
    /// The speed histogram against Maxwell–Boltzmann.
    pub histogram: bool,
}

impl App {
    /// Keys of the classroom layer (after the typing guard).
    pub(super) fn handle_lesson_keys(&mut self) {
        let shift = is_key_down(KeyCode::LeftShift) || is_key_down(KeyCode::RightShift);
        let l = &mut self.lesson;
        if is_key_pressed(KeyCode::T) {
            l.totals = !l.totals;
        }
        if is_key_pressed(KeyCode::O) {
            l.center_of_mass = !l.center_of_mass;
        }
        if is_key_pressed(KeyCode::D) {
            l.diagram = !l.diagram;
        }
        if is_key_pressed(KeyCode::U) {
            l.ledger = !l.ledger;
        }
        if is_key_pressed(KeyCode::Z) {
            self.center_of_mass_frame();
        }
        if is_key_pressed(KeyCode::J) {
            self.run_to_next_collision();
        }
        let reach = if shift { 10 } else { 1 };
        if is_key_pressed(KeyCode::Comma) {
            self.scrub(-reach);
        }
        if is_key_pressed(KeyCode::Period) {
            self.scrub(reach);
        }
        if is_key_pressed(KeyCode::X) {
            self.export_data();
        }
        if is_key_pressed(KeyCode::A) {
            self.trails.on = !self.trails.on;
        }
        if is_key_pressed(KeyCode::F2) {
            self.overlays.thick = !self.overlays.thick;
            self.font = if self.overlays.thick { 30.0 } else { 20.0 };
            let mode = if self.overlays.thick { "on" } else { "off" };
            self.toast(format!("Projector mode {mode}"));
        }
        if is_key_pressed(KeyCode::F3) {
            self.overlays.safe_palette = !self.overlays.safe_palette;
            let which = if self.overlays.safe_palette {
                "colour-blind-safe palette (Okabe-Ito, by disc number)"
            } else {
                "the scene's colours"
            };
            self.toast(format!("Discs in {which}"));
        }
        if is_key_pressed(KeyCode::F4) {
            self.lesson.histogram = !self.lesson.histogram;
        }
        if is_key_pressed(KeyCode::F12) {
            let stem = scenes::slug(self.scene.name.as_deref().unwrap_or("scene"));
            self.screenshot_request = Some(scenes::free_file(&self.options.out, &stem, "png"));
        }
    }

    /// After the frame's steps: keep the ledger on, sample the totals and
    /// record the moment for rewinding. A world that went back in time (a
    /// new scene, a reset) starts its history afresh.
    pub(super) fn after_steps(&mut self, steps: u32) {
        if !self.world.ledger.is_on() {
            self.world.ledger.keep(LEDGER_KEEP);
        }
        let newest = self.history.span().map(|(_, t)| t);
        if self.history.cursor().is_none() && newest.is_some_and(|t| t > self.world.time) {
            self.history.clear();
        }
        let metrics = self.world.metrics();
        self.totals.push(&self.world, &metrics);
        self.trails.record(&self.world);
        if steps > 0 || self.history.is_empty() {
            self.history.record(&self.world);
        }
    }

    /// Forgets the recorded past (a new scene, a reset, a cleared box): a
    /// rewind must never bring back discs of another scene.
    pub(super) fn forget_past(&mut self) {
        self.history.clear();
        self.totals.clear();
        self.world.ledger.clear();
    }

    /// Every disc's velocity less the centre of mass's: total momentum 0.
    pub(super) fn center_of_mass_frame(&mut self) {
        let drift = self.world.metrics().center_of_mass_velocity;
        for p in &mut self.world.particles {
            p.vel -= drift;
        }
        self.totals.clear();
        self.toast(format!(
            "Centre-of-mass frame: subtracted ({:+.3}, {:+.3}) m/s from every disc",
            drift.x, drift.y
        ));
    }

    /// Runs to the next pair collision and pauses there, the ledger open.
    fn run_to_next_collision(&mut self) {
        self.clock.paused = true;
        let found = self
            .world
            .run_to_next_collision(self.clock.dt, NEXT_COLLISION_LIMIT);
        self.history.record(&self.world);
        self.lesson.ledger = true;
        match found {
            Some(c) => {
                let (dp, dke) = c.total_change();
                self.toast(format!(
                    "Collision of discs {} and {} at t = {:.4} s: change of total p = ({:+.1e}, {:+.1e}), KE {:+.4} J",
                    c.discs[0], c.discs[1], c.time, dp.x, dp.y, dke
                ));
            }
            None => self.toast(format!("No collision within {NEXT_COLLISION_LIMIT:.0} s")),
        }
    }

    /// Shows an earlier (or later) recorded moment; pauses.
    fn scrub(&mut self, delta: isize) {
        self.clock.paused = true;
        self.gesture = Default::default();
        match self.history.scrub(&mut self.world, delta) {
            Some(t) => {
                self.world.ledger.clear();
                let (oldest, newest) = self.history.span().unwrap_or((t, t));
                self.toast(format!(
                    "Rewind: t = {t:.3} s of {oldest:.3} to {newest:.3} s; Space resumes from here"
                ));
            }
            None => self.toast("Nothing recorded yet"),
        }
    }

    /// Writes the totals, the discs and the ledger as CSV files.
    fn export_data(&mut self) {
        let stem = scenes::slug(self.scene.name.as_deref().unwrap_or("scene"));
        let samples: Vec<plot::Sample> = self.totals.samples().copied().collect();
        let dir = self.options.out.clone();
        match export::export_all(&dir, &stem, &samples, &self.world) {
            Ok(files) => {
                eprintln!(
                    "impulse: exported {} files to {}",
                    files.len(),
                    dir.display()
                );
                self.toast(format!(
                    "Exported totals, discs and collisions to {}/",
                    dir.display()
                ));
            }
            Err(e) => self.report(format!("Not exported to {}: {e}", dir.display())),
        }
    }

    /// The classroom overlays, in the part of the window left of the panel.
    pub(super) fn draw_lesson(&self, free: Vec2) {
        let font = self.font * 0.8;
        if self.lesson.center_of_mass {
            plot::draw_center_of_mass(&self.world, &self.camera, super::draw::ARROW_SECONDS);
        }
        if self.lesson.ledger {
            if let Some(c) = self.world.ledger.last() {
                if (self.world.time - c.time).abs() < 1e-9 {
                    draw_contact(c, &self.world, &self.camera);
                }
            }
            let lines = ledger_lines(&self.world);
            // Bottom left, above the scale bar and the caption.
            let height = 1.15 * font * lines.len() as f32 + 0.8 * font;
            text_panel(10.0, free.y - height - 3.5 * font, &lines, font, 0.8);
        }
        let (w, h) = (340.0f32.min(free.x * 0.45), 150.0f32);
        if self.lesson.totals {
            let rect = Rect::new(free.x - w - 10.0, free.y - h - 3.0 * font, w, h);
            plot::draw_totals(&self.totals, rect, font);
        }
        if self.lesson.histogram {
            let rect = Rect::new(free.x - w - 10.0, free.y - 2.0 * h - 4.0 * font, w, h);
            plot::draw_speed_histogram(&self.world, rect, font);
        }
        if self.lesson.diagram {
            let side = 220.0f32.min(free.y * 0.4);
            let rect = Rect::new(free.x - side - 10.0, 10.0, side, side);
            plot::draw_momentum_diagram(&self.world, rect, font);
        }
        if let (Some(k), Some((oldest, newest))) = (self.history.cursor(), self.history.span()) {
            let line = format!(
                "REWIND  t = {:.3} s  [{oldest:.2} .. {newest:.2} s]  snapshot {} of {}  (, . scrub, Space resumes)",
                self.world.time,
                k + 1,
                self.history.len()
            );
            let width = measure_text(&line, None, font as u16, 1.0).width;
            text_panel(
                ((free.x - width) * 0.5).max(10.0),
                free.y - 5.0 * font,
                &[line],
                font,
                0.9,
            );
        }
    }
}

/// The ledger as text: the newest collisions, then the newest one in full.
fn ledger_lines(world: &impulse::World) -> Vec<String> {
    let mut lines = vec![format!(
        "Collision ledger ({} so far)   J: run to the next",
        world.ledger.recorded
    )];
    let recent: Vec<&Collision> = world.ledger.entries().rev().take(LEDGER_LINES).collect();
    for c in &recent {
        let (dp, dke) = c.total_change();
        lines.push(format!(
            "t {:8.3} s  discs {}-{}  dp ({:+.1e}, {:+.1e})  dKE {:+.4} J",
            c.time, c.discs[0], c.discs[1], dp.x, dp.y, dke
        ));
    }
    if let Some(c) = recent.first() {
        lines.push(String::new());
        for k in 0..2 {
            let (p0, p1) = c.momentum(k);
            let (e0, e1) = c.kinetic_energy(k);
            let ((n0, t0), (n1, t1)) = c.components(k);
            lines.push(format!(
                "disc {}: p ({:+.3}, {:+.3}) -> ({:+.3}, {:+.3})  KE {:.3} -> {:.3} J",
                c.discs[k], p0.x, p0.y, p1.x, p1.y, e0, e1
            ));
            lines.push(format!(
                "        v normal {n0:+.3} -> {n1:+.3}   v tangent {t0:+.3} -> {t1:+.3} m/s"
            ));
        }
    }
    lines.into_iter().map(|l| screen_text(&l)).collect()
}

/// At the instant of impact: the normal (orange) and tangent (blue) lines
/// through the contact point.
fn draw_contact(c: &Collision, world: &impulse::World, camera: &super::camera::Camera) {
    let (Some(a), Some(b)) = (
        world.particles.get(c.discs[0]),
        world.particles.get(c.discs[1]),
    ) else {
        return;
    };
    let contact = a.pos + c.normal * a.radius;
    let reach = 1.5 * a.radius.max(b.radius);
    let line = |dir: DVec2, color: Color| {
        let (p, q) = (
            camera.world_to_screen(contact - dir * reach),
            camera.world_to_screen(contact + dir * reach),
        );
        draw_line(p.x as f32, p.y as f32, q.x as f32, q.y as f32, 3.0, color);
    };
    line(c.normal, Color::new(0.84, 0.37, 0.0, 1.0));
    line(c.normal.perp(), Color::new(0.34, 0.71, 0.91, 1.0));
}
