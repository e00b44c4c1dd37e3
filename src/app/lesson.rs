//! The classroom layer over the sandbox: conservation shown (the centre of
//! mass, the centre-of-mass frame; the plots are in the bottom dock), the
//! collision ledger with "run to the next collision" and the contact's
//! normal and tangent drawn at the instant of impact, rewind, and export.
//!
//! Keys: T / U / D / F4 open the dock's Totals, Collisions, Momenta and
//! Speeds tabs, O centre of mass, Z centre-of-mass frame, J run to the next
//! collision, `,` / `.` rewind and forward (Shift: ten times as far),
//! X export CSV files, A trails, F2 text size, F3 colour-blind-safe palette,
//! F12 screenshot into the output folder.

use super::ui::{theme, DockTab};
use super::{export, plot, scenes, App};
use glam::DVec2;
use impulse::ledger::Collision;
use macroquad::prelude::*;

/// Collisions the window keeps in the ledger.
pub const LEDGER_KEEP: usize = 50;
/// How far "run to the next collision" looks ahead (simulated seconds).
const NEXT_COLLISION_LIMIT: f64 = 60.0;

/// Which classroom overlays are on in the world.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LessonOverlays {
    /// The centre of mass and its velocity.
    pub center_of_mass: bool,
    /// The contact's normal and tangent at the instant of impact.
    pub contact: bool,
    /// The centre-of-mass view, with the camera's offset from the centre
    /// of mass when it was turned on.
    pub com_view: Option<DVec2>,
}

impl App {
    /// Keys of the classroom layer (after the typing guard).
    pub(super) fn handle_lesson_keys(&mut self) {
        let shift = is_key_down(KeyCode::LeftShift) || is_key_down(KeyCode::RightShift);
        for (key, tab) in [
            (KeyCode::T, DockTab::Totals),
            (KeyCode::U, DockTab::Collisions),
            (KeyCode::D, DockTab::Momenta),
            (KeyCode::F4, DockTab::Speeds),
        ] {
            if is_key_pressed(key) {
                self.show_tab(tab);
            }
        }
        if is_key_pressed(KeyCode::O) {
            self.lesson.center_of_mass = !self.lesson.center_of_mass;
        }
        if is_key_pressed(KeyCode::Z) {
            self.toggle_center_of_mass_view();
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
            self.ui.set_scale(theme::next_scale(self.ui.scale));
            self.toast(format!("Text size ×{}", self.ui.scale));
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
        if is_key_pressed(KeyCode::F12) {
            self.request_screenshot();
        }
    }

    /// Opens the bottom dock on `tab`; the same key again folds it.
    pub(super) fn show_tab(&mut self, tab: DockTab) {
        let ui = &mut self.ui;
        if ui.docks_open && ui.dock_expanded && ui.tab == tab {
            ui.dock_expanded = false;
        } else {
            ui.docks_open = true;
            ui.dock_expanded = true;
            ui.tab = tab;
        }
    }

    /// Saves the next frame as a PNG in the output folder (F12).
    pub(super) fn request_screenshot(&mut self) {
        let stem = scenes::slug(self.scene.name.as_deref().unwrap_or("scene"));
        self.screenshot_request = Some(scenes::free_file(&self.options.out, &stem, "png"));
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

    /// Z: the centre-of-mass view on or off. The camera moves with the
    /// centre of mass and arrows and readouts show velocities relative to
    /// it; the discs' velocities are never changed.
    pub(super) fn toggle_center_of_mass_view(&mut self) {
        if self.lesson.com_view.take().is_some() {
            self.toast("Centre-of-mass view off: velocities as seen from the box");
            return;
        }
        let m = self.world.metrics();
        self.lesson.com_view = Some(self.camera.center - m.center_of_mass);
        self.camera_fitted = false;
        self.toast(format!(
            "Centre-of-mass view: moving with the centre of mass at {}; Z again to leave",
            super::ui::numbers::vector(m.center_of_mass_velocity, 3, "m/s")
        ));
    }

    /// In the centre-of-mass view: the camera follows the centre of mass,
    /// and the world as drawn has velocities relative to it.
    pub(super) fn world_as_seen(&mut self) -> Option<impulse::World> {
        let offset = self.lesson.com_view?;
        let m = self.world.metrics();
        self.camera.center = m.center_of_mass + offset;
        let mut seen = self.world.clone();
        for p in &mut seen.particles {
            p.vel -= m.center_of_mass_velocity;
        }
        Some(seen)
    }

    /// Runs to the next pair collision and pauses there, the ledger open.
    pub(super) fn run_to_next_collision(&mut self) {
        self.clock.paused = true;
        let found = self
            .world
            .run_to_next_collision(self.clock.dt, NEXT_COLLISION_LIMIT);
        self.history.record(&self.world);
        self.lesson.contact = true;
        self.ui.docks_open = true;
        self.ui.dock_expanded = true;
        self.ui.tab = DockTab::Collisions;
        match found {
            Some(c) => {
                let (dp, dke) = c.total_change();
                self.toast(format!(
                    "Collision of discs {} and {} at t = {}: total momentum changed by {}, kinetic energy by {}",
                    c.discs[0],
                    c.discs[1],
                    super::ui::numbers::with_unit(c.time, 4, "s"),
                    super::ui::numbers::vector(dp, 3, "kg·m/s"),
                    super::ui::numbers::with_unit(dke, 3, "J")
                ));
            }
            None => self.toast(format!("No collision within {NEXT_COLLISION_LIMIT:.0} s")),
        }
    }

    /// Shows an earlier (or later) recorded moment; pauses.
    pub(super) fn scrub(&mut self, delta: isize) {
        self.clock.paused = true;
        self.gesture = Default::default();
        match self.history.scrub(&mut self.world, delta) {
            Some(t) => {
                // The snapshot brought back its ledger and counters; the
                // plot keeps what led up to this moment.
                let (oldest, newest) = self.history.span().unwrap_or((t, t));
                self.toast(format!(
                    "Rewound to t = {t:.3} s (recorded: {oldest:.3} to {newest:.3} s); Space resumes from here"
                ));
            }
            None => self.toast("Nothing recorded yet"),
        }
    }

    /// Writes the totals, the discs and the ledger as CSV files.
    pub(super) fn export_data(&mut self) {
        let stem = scenes::slug(self.scene.name.as_deref().unwrap_or("scene"));
        let samples: Vec<plot::Sample> = self.totals.samples().copied().collect();
        let dir = self.options.out.clone();
        if cfg!(target_arch = "wasm32") {
            for (name, text) in export::files(&stem, &samples, &self.world) {
                let (stem, _) = name.rsplit_once('.').unwrap_or((&name, ""));
                let _ = scenes::keep_file(&dir, stem, "csv", text.as_bytes()); // downloads
            }
            self.toast("Downloaded the totals, discs and collisions as CSV files");
            return;
        }
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

    /// The classroom overlays in the world: the centre of mass, and at the
    /// instant of impact the contact's normal and tangent.
    pub(super) fn draw_lesson(&self) {
        let scale = self.ui.scale;
        if self.lesson.center_of_mass {
            super::draw::draw_center_of_mass(
                &self.world,
                &self.camera,
                super::draw::ARROW_SECONDS,
                scale,
            );
        }
        if self.lesson.contact {
            if let Some(c) = self.world.ledger.last() {
                if (self.world.time - c.time).abs() < 1e-9 {
                    draw_contact(c, &self.world, &self.camera, scale);
                }
            }
        }
    }
}

/// At the instant of impact: the normal (orange) and tangent (blue) lines
/// through the contact point.
fn draw_contact(c: &Collision, world: &impulse::World, camera: &super::camera::Camera, scale: f32) {
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
        draw_line(
            p.x as f32,
            p.y as f32,
            q.x as f32,
            q.y as f32,
            3.0 * scale,
            color,
        );
    };
    line(c.normal, Color::new(0.84, 0.37, 0.0, 1.0));
    line(c.normal.perp(), Color::new(0.34, 0.71, 0.91, 1.0));
}

/// For the π blocks (two discs, one wall, a mass ratio of 100^k): k, the
/// number of decimals of π their collision count spells (31 for k = 1).
pub fn pi_decimals(world: &impulse::World) -> Option<u32> {
    let [a, b] = world.particles.as_slice() else {
        return None;
    };
    let one_wall =
        world.laws.boundary == impulse::Boundary::Box && world.laws.walls.names().len() == 1;
    let k = (a.mass.max(b.mass) / a.mass.min(b.mass)).log10() / 2.0;
    let round = k.round();
    (one_wall && (k - round).abs() < 1e-9 && (0.0..=8.0).contains(&round)).then_some(round as u32)
}

/// "31 collisions: π ≈ 3.1" once the π blocks can collide no more.
pub fn pi_result(world: &impulse::World) -> Option<String> {
    let k = pi_decimals(world)?;
    if !world.collisions_over() {
        return None;
    }
    let count = world.total_pair_collisions + world.total_wall_hits;
    let digits = count.to_string();
    let (whole, decimals) = digits.split_at(1.min(digits.len()));
    let pi = if k == 0 || decimals.is_empty() {
        whole.to_string()
    } else {
        format!("{whole}.{decimals}")
    };
    Some(format!("{count} collisions: π ≈ {pi}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use impulse::Scene;

    fn pi_world(file: &str) -> impulse::World {
        let path = format!("{}/assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
        Scene::load(std::path::Path::new(&path))
            .and_then(|s| s.build(&path))
            .unwrap()
    }

    #[test]
    fn the_pi_blocks_say_their_count_once_it_is_final_and_not_before() {
        for (file, k, line) in [
            ("pi-blocks-1.toml", 0, "3 collisions: π ≈ 3"),
            ("preset-7-pi-blocks.toml", 1, "31 collisions: π ≈ 3.1"),
            ("pi-blocks-10000.toml", 2, "314 collisions: π ≈ 3.14"),
            ("pi-blocks-1000000.toml", 3, "3141 collisions: π ≈ 3.141"),
        ] {
            let mut world = pi_world(file);
            assert_eq!(pi_decimals(&world), Some(k), "{file}");
            assert_eq!(pi_result(&world), None, "{file}: nothing counted yet");
            let mut said_at = None;
            for _ in 0..40 * 240 {
                world.step(1.0 / 240.0);
                if said_at.is_none() && pi_result(&world).is_some() {
                    said_at = Some(world.total_pair_collisions + world.total_wall_hits);
                }
            }
            // Said exactly when the last collision was over, and true.
            assert_eq!(pi_result(&world).as_deref(), Some(line), "{file}");
            assert_eq!(
                said_at,
                Some(line.split(' ').next().unwrap().parse().unwrap())
            );
        }
    }

    #[test]
    fn other_scenes_are_not_pi_blocks() {
        let mut world = pi_world("preset-7-pi-blocks.toml");
        world.laws.walls = impulse::Walls::ALL;
        assert_eq!(pi_decimals(&world), None, "four walls never end the count");
        let mut world = pi_world("preset-7-pi-blocks.toml");
        world.particles[1].mass = 50.0;
        assert_eq!(pi_decimals(&world), None, "50 is not a power of 100");
        assert_eq!(pi_decimals(&pi_world("preset-1-head-on.toml")), None);
    }
}
