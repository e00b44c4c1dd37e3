//! The sandbox window: a fixed-step loop around a [`World`], with a camera,
//! mouse gestures and overlays. Everything here is presentation; the physics
//! lives in the `impulse` library.

mod camera;
mod clock;
mod cull;
mod discs;
pub mod display;
mod draw;
mod dump;
mod export;
mod frame_stats;
mod hud;
mod input;
mod interaction;
mod lesson;
mod panel;
mod plot;
mod readouts;
mod recovery;
mod scenes;
mod trails;

use camera::Camera;
use clock::FixedStepClock;
use draw::Overlays;
use glam::DVec2;
use impulse::{Scene, World};
use interaction::{Gesture, NewDisc};
use macroquad::miniquad::conf::{Conf, LinuxBackend, Platform};
use macroquad::prelude::*;
use std::collections::VecDeque;
use std::path::PathBuf;

/// Options for the window, from the command line.
#[derive(Clone, Debug, clap::Args)]
pub struct WindowOptions {
    /// Scene file to open (TOML); the built-in sandbox scene when absent.
    pub scene: Option<PathBuf>,
    /// Open a gas of N equal discs (periodic box, 30 % of the area covered)
    /// instead of a scene file: for trying large numbers of discs.
    #[arg(long, value_name = "N", conflicts_with = "scene", value_parser = gas_count)]
    pub gas: Option<usize>,
    /// Start paused.
    #[arg(long)]
    pub paused: bool,
    /// Physics time step in seconds [default: the scene's, else 1/240].
    #[arg(long, value_parser = crate::headless::positive_seconds)]
    pub dt: Option<f64>,
    /// Keep FILE updated with the state as JSON (rewritten atomically each frame).
    #[arg(long, value_name = "FILE")]
    pub dump_state: Option<PathBuf>,
    /// Save the last frame as a PNG when the window closes.
    #[arg(long, value_name = "FILE")]
    pub screenshot: Option<PathBuf>,
    /// Close the window after this many seconds of real time.
    #[arg(long, value_name = "SECONDS", value_parser = crate::headless::positive_seconds)]
    pub exit_after: Option<f64>,
    /// Folder for saved scenes (Ctrl+S); created when first needed.
    #[arg(long, value_name = "DIR", default_value = "impulse-out")]
    pub out: PathBuf,
    /// Write every frame's timings (frame, physics, drawing, presenting; ms)
    /// to FILE as CSV when the window closes, and their medians on stderr.
    #[arg(long, value_name = "FILE")]
    pub frame_stats: Option<PathBuf>,
    /// Seconds between autosaves of the sandbox to the recovery file, which
    /// the next start offers to restore if this window does not close
    /// normally; 0 turns autosave off.
    #[arg(long, value_name = "SECONDS", default_value_t = recovery::DEFAULT_EVERY,
          value_parser = crate::headless::non_negative_seconds)]
    pub autosave: f64,
    /// Window size in pixels, WIDTHxHEIGHT.
    #[arg(long, default_value = "1280x800", value_parser = window_size)]
    pub size: (i32, i32),
}

fn window_size(s: &str) -> Result<(i32, i32), String> {
    let parsed = s
        .split_once('x')
        .and_then(|(w, h)| Some((w.parse::<i32>().ok()?, h.parse::<i32>().ok()?)));
    match parsed {
        Some((w, h)) if (200..=8192).contains(&w) && (200..=8192).contains(&h) => Ok((w, h)),
        _ => Err(format!(
            "{s:?} is not a window size like 1280x800 (200 to 8192 px)"
        )),
    }
}

/// Most discs `--gas` builds.
pub const MAX_GAS: usize = 1_000_000;

fn gas_count(s: &str) -> Result<usize, String> {
    match s.parse::<usize>() {
        Ok(n) if (1..=MAX_GAS).contains(&n) => Ok(n),
        _ => Err(format!(
            "{s:?} is not a number of discs from 1 to {MAX_GAS}"
        )),
    }
}

/// The scene `--gas N` opens: `impulse::presets::Gas` with N discs.
fn gas_scene(count: usize) -> (Scene, String) {
    let mut world = impulse::presets::Gas {
        count,
        ..Default::default()
    }
    .build();
    // Like a scene file without a [simulation] section: `auto` chooses
    // (the preset's fixed brute force would freeze the window at 10⁵ discs).
    world.method = impulse::method::Setting::Auto;
    world.broad_phase = impulse::method::Setting::Auto;
    world.substeps = impulse::method::Setting::Auto;
    let scene = Scene::from_world(
        &world,
        Some(format!("Gas of {count} discs")),
        Some(format!(
            "{count} equal discs covering 30 % of a periodic box (--gas {count})"
        )),
    );
    (scene, format!("--gas {count}"))
}

/// The scene the window opens without a file: something is already moving.
pub const DEFAULT_SCENE: &str = include_str!("../../assets/scenes/default.toml");

/// Loads the scene, then opens the window (or explains why it cannot).
pub fn run(options: WindowOptions) -> anyhow::Result<()> {
    for (flag, file) in [
        ("--dump-state", &options.dump_state),
        ("--screenshot", &options.screenshot),
        ("--frame-stats", &options.frame_stats),
    ] {
        if let Some(file) = file {
            writable_place(flag, file)?;
        }
    }
    let (scene, origin) = match (&options.scene, options.gas) {
        (_, Some(count)) => gas_scene(count),
        (Some(path), None) => (Scene::load(path)?, path.display().to_string()),
        (None, None) => {
            let origin = "built-in default scene".to_string();
            (Scene::parse(DEFAULT_SCENE, &origin)?, origin)
        }
    };
    let world = scene.build(&origin)?;
    if let Some(problem) = display::problem() {
        anyhow::bail!("{problem}; {}", display::HEADLESS_HINT);
    }
    let title = match &scene.name {
        Some(name) => format!("Impulse - {name}"),
        None => "Impulse".to_string(),
    };
    let conf = Conf {
        window_title: title,
        window_width: options.size.0,
        window_height: options.size.1,
        window_resizable: true,
        sample_count: 4,
        platform: Platform {
            linux_backend: LinuxBackend::X11WithWaylandFallback,
            ..Default::default()
        },
        ..Default::default()
    };
    display::guard_window_start();
    macroquad::Window::from_config(conf, App::new(options, scene, origin, world).run());
    Ok(())
}

/// Refuses, before any window opens, an output file whose folder does not
/// exist or which is a folder itself (the window would only find out when it
/// writes, frame after frame).
fn writable_place(flag: &str, file: &std::path::Path) -> anyhow::Result<()> {
    let folder = match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => std::path::Path::new("."),
    };
    if !folder.is_dir() {
        anyhow::bail!("{flag} {}: no folder {}", file.display(), folder.display());
    }
    if file.is_dir() {
        anyhow::bail!("{flag} {}: is a folder, not a file", file.display());
    }
    Ok(())
}

fn ms_since(start: std::time::Instant, end: std::time::Instant) -> f64 {
    end.duration_since(start).as_secs_f64() * 1e3
}

/// The window's whole state.
struct App {
    options: WindowOptions,
    scene: Scene,
    scene_origin: String,
    world: World,
    camera: Camera,
    clock: FixedStepClock,
    gesture: Gesture,
    overlays: Overlays,
    selected: Option<usize>,
    new_disc: NewDisc,
    toast: Option<(String, f64)>,
    /// Recent per-step wall-clock times (µs) for the HUD.
    step_micros: VecDeque<f64>,
    steps_last_frame: u32,
    frame: u64,
    last_mouse: DVec2,
    fullscreen: bool,
    font: f32,
    quit: bool,
    panel: panel::Panel,
    lesson: lesson::LessonOverlays,
    totals: plot::Totals,
    history: impulse::history::History,
    trails: trails::Trails,
    /// F12 asked for a screenshot of the next frame, to this file.
    screenshot_request: Option<PathBuf>,
    /// Timings of the frames drawn so far.
    frame_stats: frame_stats::FrameStats,
    /// The discs' GPU batch, made at the first frame (it needs the window).
    disc_batch: Option<discs::DiscBatch>,
    /// Autosave, and the offer to restore an earlier session.
    recovery: recovery::Recovery,
}

impl App {
    fn new(options: WindowOptions, scene: Scene, scene_origin: String, world: World) -> Self {
        let dt = options
            .dt
            .or(scene.simulation.dt)
            .unwrap_or(crate::headless::DEFAULT_DT);
        let mut clock = FixedStepClock::new(dt, 64);
        clock.paused = options.paused;
        let size = world.size;
        let path = options.scene.as_ref().map(|p| p.display().to_string());
        let options_keep_all = options.frame_stats.is_some();
        let (recovery, recovery_problem) =
            recovery::Recovery::new(&recovery::folder(&options.out), options.autosave);
        let mut app = App {
            options,
            scene,
            scene_origin,
            camera: Camera::fitting(size, DVec2::new(1280.0, 800.0), 30.0),
            world,
            clock,
            gesture: Gesture::Idle,
            overlays: Overlays::default(),
            selected: None,
            new_disc: NewDisc {
                radius: 0.4,
                mass: 1.0,
            },
            toast: None,
            step_micros: VecDeque::new(),
            steps_last_frame: 0,
            frame: 0,
            last_mouse: DVec2::ZERO,
            fullscreen: false,
            font: 20.0,
            quit: false,
            panel: panel::Panel::new(path.unwrap_or_default()),
            lesson: lesson::LessonOverlays::default(),
            totals: plot::Totals::default(),
            history: impulse::history::History::default(),
            trails: trails::Trails::default(),
            screenshot_request: None,
            frame_stats: frame_stats::FrameStats::new(options_keep_all),
            disc_batch: None,
            recovery,
        };
        if let Some(problem) = recovery_problem {
            app.report(problem);
        }
        if app.recovery.offered.is_some() {
            eprintln!(
                "impulse: an earlier session did not close normally; R restores it ({})",
                app.recovery.path().display()
            );
        }
        app
    }

    async fn run(mut self) {
        prevent_quit();
        let mut pending: Option<(std::time::Instant, frame_stats::FrameTimes)> = None;
        loop {
            let frame_start = std::time::Instant::now();
            if let Some((start, mut times)) = pending.take() {
                times.frame_ms = ms_since(start, frame_start);
                self.frame_stats.push(times);
            }
            let viewport = DVec2::new(screen_width() as f64, screen_height() as f64);
            self.camera.viewport = viewport;
            if self.frame == 0 {
                self.fit_camera();
                display::mark_open();
            }
            self.panel_ui();
            self.handle_keys();
            self.handle_mouse();
            let step_start = std::time::Instant::now();
            self.advance_physics(get_frame_time() as f64);
            let step_ms = ms_since(step_start, std::time::Instant::now());
            let timed_out = self
                .options
                .exit_after
                .is_some_and(|limit| get_time() >= limit);
            let closing = self.quit || is_quit_requested() || timed_out;
            if closing {
                self.recovery.finish();
            } else {
                self.autosave();
            }
            let requested = self.screenshot_request.take();
            let wanted = (closing && self.options.screenshot.is_some()) || requested.is_some();
            let capture = wanted.then(dump::capture_frame);
            let draw_start = std::time::Instant::now();
            self.draw();
            let draw_ms = ms_since(draw_start, std::time::Instant::now());
            self.frame += 1;
            self.write_dump();
            let mut times = self.frame_times(step_ms, draw_ms);
            let present_start = std::time::Instant::now();
            if let Some(target) = capture {
                next_frame().await; // finishes the frame, panel included
                if closing {
                    self.save_screenshot(&target);
                }
                if let Some(path) = requested {
                    self.save_screenshot_key(&target, &path);
                }
            } else if !closing {
                next_frame().await;
            }
            times.present_ms = ms_since(present_start, std::time::Instant::now());
            pending = Some((frame_start, times));
            if closing {
                break;
            }
        }
        self.write_frame_stats();
    }

    /// This frame's record, its frame and present times still to come.
    fn frame_times(&self, step_ms: f64, draw_ms: f64) -> frame_stats::FrameTimes {
        frame_stats::FrameTimes {
            frame: self.frame,
            discs: self.world.particles.len(),
            velocity: self.overlays.velocity,
            momentum: self.overlays.momentum,
            readouts: self.overlays.readouts.name(),
            steps: self.steps_last_frame,
            frame_ms: 0.0,
            step_ms,
            draw_ms,
            present_ms: 0.0,
        }
    }

    /// `--frame-stats`: the CSV file and a line of medians.
    fn write_frame_stats(&self) {
        let Some(path) = &self.options.frame_stats else {
            return;
        };
        let csv = self.frame_stats.csv();
        match crate::files::write_atomically(path, csv.as_bytes()) {
            Ok(()) => eprintln!(
                "impulse: frame times in {}: {}",
                path.display(),
                self.frame_stats.summary_line()
            ),
            Err(e) => eprintln!("impulse: cannot write frame times {}: {e}", path.display()),
        }
    }

    fn advance_physics(&mut self, frame_seconds: f64) {
        let steps = self.clock.advance(frame_seconds);
        self.steps_last_frame = steps;
        for _ in 0..steps {
            let stats = self.world.step(self.clock.dt);
            self.gesture.pin_held(&mut self.world);
            self.step_micros
                .push_back(stats.timings.total().as_secs_f64() * 1e6);
            if self.step_micros.len() > 240 {
                self.step_micros.pop_front();
            }
        }
        self.after_steps(steps);
    }

    fn toast(&mut self, message: impl Into<String>) {
        self.toast_for(message, 3.0);
    }

    fn toast_for(&mut self, message: impl Into<String>, seconds: f64) {
        self.toast = Some((message.into(), get_time() + seconds));
    }

    fn reset_scene(&mut self) {
        match self.scene.build(&self.scene_origin) {
            Ok(world) => {
                self.world = world;
                self.forget_past();
                self.selected = None;
                self.gesture = Gesture::Idle;
                self.toast("Scene reset");
            }
            Err(e) => self.toast(format!("Cannot reset: {e}")),
        }
    }

    fn draw(&mut self) {
        clear_background(Color::new(0.09, 0.10, 0.14, 1.0));
        draw::draw_boundary(&self.world, &self.camera);
        self.trails.draw(&self.camera, self.overlays.thick);
        let batch = self.disc_batch.get_or_insert_with(discs::DiscBatch::new);
        draw::draw_discs(
            &self.world,
            &self.camera,
            self.selected,
            &self.overlays,
            batch,
        );
        draw::draw_arrows(&self.world, &self.camera, &self.overlays);
        readouts::draw_readouts(
            &self.world,
            &self.camera,
            &self.overlays,
            self.selected,
            self.font * 0.8,
        );
        if let Gesture::Launching { start, .. } = self.gesture {
            let cursor = self.camera.screen_to_world(self.last_mouse);
            draw::draw_launch_preview(
                &self.world,
                &self.camera,
                start,
                cursor,
                self.new_disc,
                self.font,
            );
        }
        // Messages and menus centre on the part the side panel leaves free.
        let viewport = vec2(
            self.camera.viewport.x as f32 - self.panel.width_on_screen(),
            self.camera.viewport.y as f32,
        );
        if self.overlays.hud {
            hud::text_panel(10.0, 10.0, &self.hud_lines(), self.font, 0.75);
        }
        hud::draw_scale_bar(&self.camera, self.font);
        if let Some(prompt) = self.recovery_prompt() {
            hud::draw_toast(&prompt, viewport, self.font);
        } else if let Some((message, until)) = &self.toast {
            if get_time() < *until {
                hud::draw_toast(message, viewport, self.font);
            }
        }
        if let Some(description) = &self.scene.description {
            if self.overlays.hud {
                hud::draw_caption(description, viewport, self.font);
            }
        }
        if self.overlays.presets {
            let entries: Vec<(String, String, String)> = scenes::PRESETS
                .iter()
                .map(|p| {
                    let scene = Scene::parse(p.text, p.path).ok();
                    let name = scene.as_ref().and_then(|s| s.name.clone());
                    let description = scene.and_then(|s| s.description);
                    (
                        p.key.to_string(),
                        name.unwrap_or_else(|| p.path.to_string()),
                        description.unwrap_or_default(),
                    )
                })
                .collect();
            hud::draw_preset_menu(viewport, self.font * 0.8, &entries);
        }
        self.draw_lesson(viewport);
        if self.overlays.help {
            hud::draw_help(viewport, self.font);
        }
    }

    fn hud_lines(&self) -> Vec<String> {
        let m = self.world.metrics();
        let status = if self.clock.paused {
            "PAUSED".to_string()
        } else {
            format!("speed x{}", self.clock.time_scale())
        };
        let mut micros: Vec<f64> = self.step_micros.iter().copied().collect();
        micros.sort_by(f64::total_cmp);
        let median_step = micros.get(micros.len() / 2).copied().unwrap_or(0.0);
        let name = self.scene.name.as_deref().unwrap_or("Sandbox");
        let mut lines = vec![
            format!("Impulse - {name}"),
            format!(
                "{} discs   t = {:.2} s   {status}",
                m.count, self.world.time
            ),
            format!(
                "p = ({:+.3}, {:+.3}) kg m/s   |p| = {:.3}",
                m.momentum.x,
                m.momentum.y,
                m.momentum.length()
            ),
            format!("KE = {:.3} J", m.kinetic_energy),
            format!(
                "collisions: {} disc-disc + {} wall = {}",
                self.world.total_pair_collisions,
                self.world.total_wall_hits,
                self.world.total_pair_collisions + self.world.total_wall_hits
            ),
            format!(
                "e = {:.2}   wall e = {:.2}   g = {:.2} m/s^2   {}",
                self.world.restitution,
                self.world.wall_restitution,
                self.world.gravity.length(),
                self.world.boundary.name()
            ),
            format!(
                "FPS {}   step {:.1} us x{}   dt = {:.2} ms",
                get_fps(),
                median_step,
                self.steps_last_frame,
                self.clock.dt * 1e3
            ),
            self.method_line(),
            format!(
                "new disc: r = {:.2} m  m = {:.2} kg   H: help",
                self.new_disc.radius, self.new_disc.mass
            ),
        ];
        let arrows = match (self.overlays.velocity, self.overlays.momentum) {
            (true, true) => Some("white v, pink p / mean mass"),
            (true, false) => Some("white v"),
            (false, true) => Some("pink p / mean mass"),
            (false, false) => None,
        };
        if let Some(arrows) = arrows {
            let secs = draw::ARROW_SECONDS;
            lines.push(format!("arrows: {arrows}, x {secs} s"));
        }
        lines
    }

    /// "impulse x4 / grid (auto: ...)": what the steps use, and why.
    fn method_line(&self) -> String {
        let plan = self
            .world
            .plan()
            .cloned()
            .unwrap_or_else(|| self.world.plan_for(self.clock.dt));
        let substeps = if plan.method.uses_substeps() {
            format!(" x{}", plan.substeps)
        } else {
            String::new()
        };
        let broad = if plan.method == impulse::method::Method::Exact {
            "cells"
        } else {
            plan.broad_phase.name()
        };
        let mut line = format!("method {}{substeps} / {broad}", plan.method.name());
        if !plan.reason.is_empty() {
            line.push_str(&format!("   auto: {}", plan.reason));
        }
        line
    }

    fn save_screenshot(&self, target: &RenderTarget) {
        let Some(path) = &self.options.screenshot else {
            return;
        };
        let (w, h, rgba) = dump::finished_frame(target);
        match dump::write_png(path, w, h, &rgba) {
            Ok(()) => eprintln!("impulse: screenshot saved to {}", path.display()),
            Err(e) => eprintln!("impulse: cannot save screenshot {}: {e}", path.display()),
        }
    }

    /// Saves the frame F12 asked for and says where.
    fn save_screenshot_key(&mut self, target: &RenderTarget, path: &std::path::Path) {
        let (w, h, rgba) = dump::finished_frame(target);
        let saved = std::fs::create_dir_all(&self.options.out)
            .and_then(|()| dump::write_png(path, w, h, &rgba));
        match saved {
            Ok(()) => {
                eprintln!("impulse: screenshot saved to {}", path.display());
                self.toast(format!("Screenshot saved to {}", path.display()));
            }
            Err(e) => self.report(format!("Screenshot not saved to {}: {e}", path.display())),
        }
    }

    fn write_dump(&self) {
        let Some(path) = &self.options.dump_state else {
            return;
        };
        let mut state = dump::StateDump::of(&self.world, &self.camera);
        state.frame = self.frame;
        state.paused = self.clock.paused;
        state.time_scale = self.clock.time_scale();
        state.dt = self.clock.dt;
        state.selected = self.selected;
        state.history_len = self.history.len();
        state.history_cursor = self.history.cursor();
        state.collisions_recorded = self.world.ledger.recorded;
        state.held = self.gesture.held();
        state.scene_name = self.scene.name.clone();
        state.scene_origin = self.scene_origin.clone();
        state.panel_visible = self.panel.visible;
        state.panel_widgets = self.panel.widgets.clone();
        state.timing = self.frame_stats.recent();
        state.recovery = dump::RecoveryDump {
            file: self.recovery.path().display().to_string(),
            saves: self.recovery.saves,
            error: self.recovery.error.clone(),
            offered: self.recovery.offered.is_some(),
        };
        if let Err(e) = dump::write_state(path, &state) {
            eprintln!("impulse: cannot write state dump {}: {e}", path.display());
        }
    }
}
