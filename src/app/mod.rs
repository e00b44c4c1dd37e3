//! The sandbox window: a fixed-step loop around a [`World`], with a camera,
//! mouse gestures and overlays in the world (macroquad) and docked panels
//! around it (egui, [`ui`]). Everything here is presentation; the physics
//! lives in the `impulse` library.

mod camera;
mod clock;
mod cull;
mod discs;
#[cfg(not(target_arch = "wasm32"))]
pub mod display;
mod draw;
mod dump;
mod export;
mod frame_stats;
mod idle;
mod input;
mod interaction;
mod lesson;
mod plot;
mod readouts;
mod recovery;
mod scenes;
mod share;
mod trails;
mod ui;
mod undo;

use camera::Camera;
use clock::{FixedStepClock, RealtimeMeter};
use draw::{Look, Overlays};
use glam::DVec2;
use impulse::{Scene, World};
use interaction::{Gesture, NewDisc};
use macroquad::miniquad::conf::Conf;
#[cfg(not(target_arch = "wasm32"))]
use macroquad::miniquad::conf::{LinuxBackend, Platform};
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
    #[arg(long, value_name = "N", conflicts_with = "scene", value_parser = crate::cli::gas_count)]
    pub gas: Option<usize>,
    /// Start paused.
    #[arg(long)]
    pub paused: bool,
    /// Physics time step in seconds [default: the scene's, else 1/240].
    #[arg(long, value_parser = crate::cli::positive_seconds)]
    pub dt: Option<f64>,
    /// Keep FILE updated with the state as JSON (rewritten atomically each frame).
    #[arg(long, value_name = "FILE")]
    pub dump_state: Option<PathBuf>,
    /// Save the last frame as a PNG when the window closes.
    #[arg(long, value_name = "FILE")]
    pub screenshot: Option<PathBuf>,
    /// Close the window after this many seconds of real time.
    #[arg(long, value_name = "SECONDS", value_parser = crate::cli::positive_seconds)]
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
          value_parser = crate::cli::non_negative_seconds)]
    pub autosave: f64,
    /// Window size in pixels, WIDTHxHEIGHT.
    #[arg(long, default_value = "1280x800", value_parser = crate::cli::window_size)]
    pub size: (i32, i32),
    /// Size of every text and line, 1 to 2.5 (F2 cycles 1, 1.5 and 2; 2 is
    /// for a projector).
    #[arg(long, value_name = "SCALE", default_value_t = 1.0, value_parser = crate::cli::ui_scale)]
    pub ui_scale: f32,
    /// Start in the light theme (for a projector in a bright room).
    #[arg(long)]
    pub light: bool,
}

#[cfg(not(target_arch = "wasm32"))]
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
pub const DEFAULT_SCENE: &str = impulse::catalogue::DEFAULT.text;

#[cfg(not(target_arch = "wasm32"))]
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
    let (width, height) = options.size;
    let app = App::new(options, scene, origin, world);
    let conf = Conf {
        window_title: title,
        window_width: width,
        window_height: height,
        window_resizable: true,
        sample_count: 4,
        platform: Platform {
            linux_backend: LinuxBackend::X11WithWaylandFallback,
            linux_wm_class: WM_CLASS,
            // Frames only when asked for (see `idle`), where the window
            // can be woken.
            blocking_event_loop: app.idle.wakes(),
            ..Default::default()
        },
        ..Default::default()
    };
    let conf = macroquad::conf::Conf {
        miniquad_conf: conf,
        update_on: Some(macroquad::conf::UpdateTrigger {
            key_down: true,
            mouse_down: true,
            mouse_up: true,
            mouse_motion: true,
            mouse_wheel: true,
            specific_key: None,
            touch: true,
        }),
        ..Default::default()
    };
    display::guard_window_start();
    macroquad::Window::from_config(conf, app.run());
    Ok(())
}

/// The options a window has when nothing is given: clap's defaults.
#[cfg(target_arch = "wasm32")]
fn default_options() -> WindowOptions {
    use clap::{Args, FromArgMatches};
    let command = WindowOptions::augment_args(clap::Command::new("impulse"));
    let matches = command.get_matches_from(["impulse"]);
    WindowOptions::from_arg_matches(&matches).expect("the defaults parse")
}

/// In the browser: the sandbox on the scene a shared link carries, else the
/// default scene. The canvas fills the page and follows its pixel ratio.
#[cfg(target_arch = "wasm32")]
pub fn run_in_browser() {
    impulse::clock::set_clock(crate::web::now);
    let options = default_options();
    let default = || {
        let origin = "built-in default scene".to_string();
        let scene = Scene::parse(DEFAULT_SCENE, &origin).expect("the default scene parses");
        (scene, origin)
    };
    // A shared link opens its scene; a damaged one says so over the default.
    let (mut scene, mut origin, mut problem) = match share::scene_in(&crate::web::fragment()) {
        Some(Ok(scene)) => (scene, "the shared link".to_string(), None),
        Some(Err(why)) => {
            let (scene, origin) = default();
            (
                scene,
                origin,
                Some(format!("This link's scene cannot open: {why}")),
            )
        }
        None => {
            let (scene, origin) = default();
            (scene, origin, None)
        }
    };
    let world = match scene.build(&origin) {
        Ok(world) => world,
        Err(e) => {
            problem = Some(format!("This link's scene cannot open: {e}"));
            (scene, origin) = default();
            scene.build(&origin).expect("the default scene builds")
        }
    };
    let conf = Conf {
        window_title: "Impulse".to_string(),
        high_dpi: true,
        sample_count: 4,
        ..Default::default()
    };
    let mut app = App::new(options, scene, origin, world);
    app.pending_report = problem.or(app.pending_report.take());
    macroquad::Window::from_config(conf, app.run());
}

#[cfg(not(target_arch = "wasm32"))]
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

fn ms_since(start: impulse::clock::Instant, end: impulse::clock::Instant) -> f64 {
    end.duration_since(start).as_secs_f64() * 1e3
}

/// The window's WM_CLASS on X11 (the idle waker finds the window by it).
const WM_CLASS: &str = "impulse";

/// The window's whole state.
struct App {
    options: WindowOptions,
    scene: Scene,
    scene_origin: String,
    world: World,
    camera: Camera,
    /// The view shows the whole box: it is fitted again when the world's
    /// rectangle changes (until the user zooms or pans).
    camera_fitted: bool,
    clock: FixedStepClock,
    gesture: Gesture,
    overlays: Overlays,
    selected: Option<usize>,
    new_disc: NewDisc,
    toast: Option<(String, f64)>,
    /// Recent per-step wall-clock times (µs) for the Details section.
    step_micros: VecDeque<f64>,
    steps_last_frame: u32,
    /// Steps the clock asked for last frame that the frame budget dropped.
    steps_dropped: u32,
    /// Simulated seconds per real second, lately.
    realtime: RealtimeMeter,
    frame: u64,
    last_mouse: DVec2,
    fullscreen: bool,
    quit: bool,
    ui: ui::UiState,
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
    /// The world's font, loaded at the first frame.
    world_text: Option<readouts::WorldText>,
    /// Autosave, and the offer to restore an earlier session.
    recovery: recovery::Recovery,
    /// Undo and redo of changes to the scene.
    undo: undo::Undo,
    /// The scene when the left button went down in the world, remembered
    /// for undo if the gesture changes it.
    press_moment: Option<undo::Moment>,
    /// The discs were edited since the scene opened: its caption may no
    /// longer hold.
    scene_edited: bool,
    /// New discs and mass edits take the radius of one density.
    size_follows_mass: bool,
    /// A problem found before the window opened, shown in its first frame.
    pending_report: Option<String>,
    /// Two fingers down on a touch screen: where they were last frame.
    pinch: Option<[DVec2; 2]>,
    /// Whether the window draws its next frame at once or sleeps.
    idle: idle::Idle,
}

impl App {
    fn new(options: WindowOptions, scene: Scene, scene_origin: String, world: World) -> Self {
        let dt = scene.step_for(options.dt);
        let mut clock = FixedStepClock::new(dt, 64);
        clock.paused = options.paused;
        let size = world.laws.size;
        let path = options.scene.as_ref().map(|p| p.display().to_string());
        let options_keep_all = options.frame_stats.is_some();
        let (recovery, recovery_problem) =
            recovery::Recovery::new(&recovery::folder(&options.out), options.autosave);
        let mut ui = ui::UiState::new(path.unwrap_or_default());
        ui.set_scale(options.ui_scale);
        if options.light {
            ui.theme = ui::theme::Theme::Light;
        }
        let mut app = App {
            options,
            scene,
            scene_origin,
            camera: Camera::fitting(size, DVec2::new(1280.0, 800.0), 30.0),
            camera_fitted: true,
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
            steps_dropped: 0,
            realtime: RealtimeMeter::default(),
            frame: 0,
            last_mouse: DVec2::ZERO,
            fullscreen: false,
            quit: false,
            ui,
            lesson: lesson::LessonOverlays::default(),
            totals: plot::Totals::default(),
            history: impulse::history::History::default(),
            trails: trails::Trails::default(),
            screenshot_request: None,
            frame_stats: frame_stats::FrameStats::new(options_keep_all),
            disc_batch: None,
            world_text: None,
            recovery,
            undo: undo::Undo::default(),
            press_moment: None,
            scene_edited: false,
            size_follows_mass: false,
            pending_report: None,
            pinch: None,
            idle: idle::Idle::new(WM_CLASS),
        };
        // Shown once the window exists (the toast reads its clock).
        app.pending_report = recovery_problem;
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
        let mut pending: Option<(impulse::clock::Instant, frame_stats::FrameTimes)> = None;
        let mut previous = (0.0, 0.0); // the last frame's time and its physics (s)
        let mut time_scale = self.clock.time_scale();
        loop {
            if self.clock.time_scale() != time_scale {
                time_scale = self.clock.time_scale();
                self.realtime.clear(); // measured against the scale asked for
            }
            let frame_start = impulse::clock::Instant::now();
            if let Some((start, mut times)) = pending.take() {
                times.frame_ms = ms_since(start, frame_start);
                previous = (times.frame_ms / 1e3, times.step_ms / 1e3);
                self.frame_stats.push(times);
            }
            let (mx, my) = mouse_position();
            let mouse = DVec2::new(mx as f64, my as f64);
            self.ui_pass(mouse);
            if self.frame == 0 {
                self.fit_camera();
                #[cfg(not(target_arch = "wasm32"))]
                display::mark_open();
                if let Some(problem) = self.pending_report.take() {
                    self.report(problem);
                }
            }
            self.handle_keys();
            self.handle_touches();
            if !self.pinching() {
                self.handle_mouse(mouse);
            }
            self.open_dropped_files();
            let step_start = impulse::clock::Instant::now();
            let budget = clock::physics_budget(previous.0, previous.1);
            let running = !self.clock.paused;
            self.advance_physics(get_frame_time() as f64, budget);
            if self.camera_fitted && self.follows_discs() {
                self.fit_camera();
            }
            let step_ms = ms_since(step_start, impulse::clock::Instant::now());
            self.realtime
                .push(get_time(), self.world.time, running && !self.clock.paused);
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
            let draw_start = impulse::clock::Instant::now();
            self.draw();
            egui_macroquad::draw();
            // The whole frame, panels included, read back before it is shown.
            let capture = wanted.then(dump::screen_image);
            let draw_ms = ms_since(draw_start, impulse::clock::Instant::now());
            self.frame += 1;
            self.write_dump();
            let mut times = self.frame_times(step_ms, draw_ms);
            let present_start = impulse::clock::Instant::now();
            if let Some(image) = capture {
                if closing {
                    self.save_screenshot(&image);
                }
                if let Some(path) = requested {
                    self.save_screenshot_key(&image, &path);
                }
            }
            if !closing {
                let busy = self.busy(running);
                let due = self.options.exit_after;
                self.idle.frame_done(busy, (mx, my), due);
                next_frame().await;
            }
            times.present_ms = ms_since(present_start, impulse::clock::Instant::now());
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

    /// Runs the steps the clock asks for, as long as they fit in `budget`
    /// seconds of wall clock (at least one); the rest are dropped, so a
    /// machine that cannot keep up runs the simulation slower instead of
    /// dropping frames.
    fn advance_physics(&mut self, frame_seconds: f64, budget: f64) {
        let due = self.clock.advance(frame_seconds);
        let start = impulse::clock::Instant::now();
        let mut steps = 0;
        // Small scenes: the totals just before and after each step with an
        // impact, so the plot drops at the instant of an inelastic collision.
        let sample_collisions = self.world.particles.len() <= plot::SAMPLE_COLLISIONS_MAX_DISCS;
        while steps < due {
            if steps > 0 && start.elapsed().as_secs_f64() >= budget {
                break;
            }
            let before = sample_collisions.then(|| (self.world.time, self.world.metrics()));
            let stats = self.world.step(self.clock.dt);
            if let Some((t, m)) = before.filter(|_| stats.pair_collisions + stats.wall_hits > 0) {
                self.totals.push_at(t, &self.world, &m);
                let now = self.world.metrics();
                self.totals.push(&self.world, &now);
            }
            if stats.separated_pairs > 0 {
                self.toast_separated(stats.separated_pairs, stats.separation_energy);
            }
            self.gesture.pin_held(&mut self.world);
            self.step_micros
                .push_back(stats.timings.total().as_secs_f64() * 1e6);
            if self.step_micros.len() > 240 {
                self.step_micros.pop_front();
            }
            steps += 1;
        }
        self.steps_last_frame = steps;
        self.steps_dropped = due - steps;
        self.after_steps(steps);
    }

    /// Simulated seconds per real second lately, while running.
    fn sim_rate(&self) -> Option<f64> {
        self.realtime.ratio()
    }

    /// "running at 0.31× real time" when the simulation goes more than 10 %
    /// slower than the time scale asks.
    fn slow_note(&self) -> Option<String> {
        let rate = self.sim_rate()?;
        if self.clock.paused || rate >= 0.9 * self.clock.time_scale() {
            return None;
        }
        let digits = if rate < 0.1 { 3 } else { 2 };
        Some(format!(
            "running at {}× real time",
            ui::numbers::plain(rate, digits)
        ))
    }

    /// Says that `exact` pushed `pairs` overlapping pairs apart as it took
    /// the discs over, and the potential energy that added (J): the energy
    /// readout jumps, and this is why.
    fn toast_separated(&mut self, pairs: usize, energy: f64) {
        let pairs = if pairs == 1 {
            "1 overlapping pair".to_string()
        } else {
            format!("{pairs} overlapping pairs")
        };
        let energy = if energy.abs() < 1e-9 {
            String::new()
        } else if energy > 0.0 {
            format!(", which raised the energy by {energy:.3} J")
        } else {
            format!(", which lowered the energy by {:.3} J", -energy)
        };
        self.toast_for(
            format!("exact needs discs apart: it separated {pairs} of discs{energy}"),
            6.0,
        );
    }

    fn toast(&mut self, message: impl Into<String>) {
        self.toast_for(message, 4.0);
    }

    fn toast_for(&mut self, message: impl Into<String>, seconds: f64) {
        self.toast = Some((message.into(), get_time() + seconds));
    }

    fn reset_scene(&mut self) {
        match self.scene.build(&self.scene_origin) {
            Ok(world) => {
                self.remember("reset");
                self.scene_edited = self.scene.edited;
                self.world = world;
                self.forget_past();
                self.selected = None;
                self.gesture = Gesture::Idle;
                self.toast("Scene reset");
            }
            Err(e) => self.toast(format!("Cannot reset: {e}")),
        }
    }

    /// The theme's colours and the UI scale, for the world's drawing.
    fn look(&self) -> Look {
        Look {
            colors: self.ui.theme.world(),
            scale: self.ui.scale,
        }
    }

    fn draw(&mut self) {
        let look = self.look();
        // The centre-of-mass view draws a copy with relative velocities.
        let seen = self.world_as_seen();
        let world = seen.as_ref().unwrap_or(&self.world);
        clear_background(draw::color(look.colors.background));
        let text = self.world_text.get_or_insert_with(readouts::WorldText::new);
        text.begin_frame();
        draw::draw_boundary(world, &self.camera, look);
        self.trails.draw(&self.camera, look.scale);
        let batch = self.disc_batch.get_or_insert_with(discs::DiscBatch::new);
        draw::draw_discs(
            world,
            &self.camera,
            self.selected,
            &self.overlays,
            batch,
            look,
        );
        draw::draw_arrows(world, &self.camera, &self.overlays, look);
        self.draw_lesson();
        let Some(text) = self.world_text.as_ref() else {
            return;
        };
        readouts::draw_readouts(
            world,
            &self.camera,
            &self.overlays,
            self.selected,
            look,
            text,
        );
        if let Gesture::Launching { start, .. } = self.gesture {
            let cursor = self.camera.screen_to_world(self.last_mouse);
            draw::draw_launch_preview(
                &self.world,
                &self.camera,
                start,
                cursor,
                self.new_disc_now(),
                look,
                text,
            );
        }
    }

    /// "impulse ×4 / grid (auto: ...)": what the steps use, and why.
    fn method_line(&self) -> String {
        let plan = self
            .world
            .plan()
            .cloned()
            .unwrap_or_else(|| self.world.plan_for(self.clock.dt));
        let substeps = if plan.method.uses_substeps() {
            format!(" ×{}", plan.substeps)
        } else {
            String::new()
        };
        let broad = if plan.method == impulse::method::Method::Exact {
            "cells"
        } else {
            plan.broad_phase.name()
        };
        let mut line = format!("in use: {}{substeps} / {broad}", plan.method.name());
        if !plan.reason.is_empty() {
            line.push_str(&format!(" (auto: {})", plan.reason));
        }
        line
    }
}
