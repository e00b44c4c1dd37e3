//! The sandbox window: the model ([`model::Sandbox`], no window in it) and
//! around it what only a window has. Each frame: the panels ([`ui`]) are
//! laid out ([`layout`]) and drawn and say what was clicked; keys, the mouse
//! and touches become commands ([`input`], through the bindings table);
//! the model applies them and ticks; the world is drawn ([`drawing`]) in
//! the rectangle the layout gave it; the state dump is written ([`dump`]).
//! Everything here is presentation; the physics lives in the `impulse`
//! library.

mod audio;
#[cfg(not(target_arch = "wasm32"))]
pub mod display;
mod drawing;
mod dump;
mod frame_stats;
mod idle;
mod input;
pub mod lang;
pub mod layout;
mod look;
pub mod model;
pub mod numbers;
mod options;
mod page;
mod screenshot;
mod ui;

use frame_stats::ms_since;
use glam::DVec2;
use impulse::{Scene, World};
use macroquad::miniquad::conf::Conf;
#[cfg(not(target_arch = "wasm32"))]
use macroquad::miniquad::conf::{LinuxBackend, Platform};
use macroquad::prelude::*;
use model::Sandbox;
pub use options::WindowOptions;
#[cfg(not(target_arch = "wasm32"))]
use options::{gas_scene, writable_place};

/// The scene behind the start screen, and Free play's: something is moving.
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
            let origin = lang::tr!("origin-default");
            (Scene::parse(DEFAULT_SCENE, &origin)?, origin)
        }
    };
    let world = scene.build(&origin)?;
    if let Some(problem) = display::problem() {
        anyhow::bail!("{problem}; {}", display::HEADLESS_HINT);
    }
    lang::set_language(model::settings::language_at_start(
        &model::recovery::folder(&options.out),
        options.lang,
        system_language(),
    ));
    let title = match scene.name_in(lang::language().code()) {
        Some(name) => format!("Impulse - {name}"),
        None => "Impulse".to_string(),
    };
    let (width, height) = options.look.size;
    let plain = options.scene.is_none() && options.gas.is_none();
    let sample_count = if options.look.no_antialias { 1 } else { 4 };
    let app = App::new(options, (scene, origin, world), plain, false);
    let conf = Conf {
        window_title: title,
        window_width: width,
        window_height: height,
        window_resizable: true,
        sample_count,
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
    lang::set_language(model::settings::language_at_start(
        &model::recovery::folder(&options.out),
        None,
        system_language(),
    ));
    let default = || {
        let origin = lang::tr!("origin-default");
        let scene = Scene::parse(DEFAULT_SCENE, &origin).expect("the default scene parses");
        (scene, origin)
    };
    // A shared link opens its scene; a damaged one says so over the default.
    let (mut scene, mut origin, mut problem) = match model::share::scene_in(&crate::web::fragment())
    {
        Some(Ok(scene)) => (scene, lang::tr!("origin-shared-link"), None),
        Some(Err(why)) => {
            let (scene, origin) = default();
            (
                scene,
                origin,
                Some(lang::tr!("link-cannot-open", error = why)),
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
            problem = Some(lang::tr!("link-cannot-open", error = e.to_string()));
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
    let from_link = origin == lang::tr!("origin-shared-link");
    let plain = problem.is_none() && !from_link;
    let mut app = App::new(options, (scene, origin, world), plain, from_link);
    if let Some(problem) = problem {
        app.model.report(problem);
    }
    macroquad::Window::from_config(conf, app.run());
}

/// The language the system (the desktop's locale) or the page
/// (`navigator.language`) asks for, if the window speaks it.
fn system_language() -> Option<lang::Lang> {
    #[cfg(target_arch = "wasm32")]
    return crate::web::browser_language()
        .as_deref()
        .and_then(lang::Lang::from_tag);
    #[cfg(not(target_arch = "wasm32"))]
    lang::system_language()
}

/// The window's WM_CLASS on X11 (the idle waker finds the window by it).
const WM_CLASS: &str = "impulse";

/// The window: the model and what only a window has.
struct App {
    options: WindowOptions,
    model: Sandbox,
    panels: ui::Panels,
    painter: drawing::Painter,
    input: input::Input,
    frame: u64,
    /// Timings of the frames drawn so far.
    frame_stats: frame_stats::FrameStats,
    /// Whether the window draws its next frame at once or sleeps.
    idle: idle::Idle,
    /// The state last handed to the page to keep, and when (the browser).
    kept: (u64, f64),
    /// Samples per pixel of the drawing surface, once the first frame has
    /// asked OpenGL (the desktop).
    samples: Option<i32>,
    /// What the browser's page around the canvas was last told.
    page: page::Page,
}

impl App {
    /// The window on `scene`; `plain` when nothing chose it (no file, no
    /// gas, no shared link): then the start screen shows, unless
    /// `--no-start`.
    fn new(
        options: WindowOptions,
        (scene, origin, world): (Scene, String, World),
        plain: bool,
        from_link: bool,
    ) -> Self {
        let path = options.scene.as_ref().map(|p| p.display().to_string());
        let keep_all = options.frame_stats.is_some();
        let model = Sandbox::new(model::Start {
            scene,
            origin,
            world,
            paused: options.paused,
            dt: options.dt,
            out: options.out.clone(),
            recovery: (model::recovery::folder(&options.out), options.autosave),
            scale: options.look.ui_scale,
            start_screen: plain && !options.no_start,
            from_link,
            lang: options.lang,
            system_lang: system_language(),
            theme: options.look.light.then_some(model::Theme::Light),
        });
        if model.recovery.offered.is_some() {
            eprintln!(
                "impulse: an earlier session ended with unsaved changes; R restores it ({})",
                model.recovery.path().display()
            );
        }
        App {
            options,
            model,
            panels: ui::Panels::new(path.unwrap_or_default()),
            painter: drawing::Painter::default(),
            input: input::Input::default(),
            frame: 0,
            frame_stats: frame_stats::FrameStats::new(keep_all),
            idle: idle::Idle::new(WM_CLASS),
            kept: (0, f64::NEG_INFINITY),
            samples: None,
            page: page::Page::default(),
        }
    }

    async fn run(mut self) {
        prevent_quit();
        let mut pending: Option<(impulse::clock::Instant, frame_stats::FrameTimes)> = None;
        let mut previous = (0.0, 0.0); // the last frame's time and its physics (s)
        loop {
            let frame_start = impulse::clock::Instant::now();
            if let Some((start, mut times)) = pending.take() {
                times.frame_ms = ms_since(start, frame_start);
                previous = (times.frame_ms / 1e3, times.step_ms / 1e3);
                self.frame_stats.push(times);
            }
            self.model.begin_frame(get_time());
            let (mx, my) = mouse_position();
            let mouse = DVec2::new(mx as f64, my as f64);
            let mut commands = self.panels.pass(&self.model, mouse);
            if let Some(rects) = &self.panels.rects {
                let world = rects.world;
                let covered = rects.drawer.map_or(0.0, |d| world.x + world.w - d.x);
                self.model.place_world(world.as_array(), covered);
            }
            if self.frame == 0 {
                self.model.fit_camera();
                #[cfg(not(target_arch = "wasm32"))]
                {
                    display::mark_open();
                    self.samples = Some(display::samples_per_pixel());
                }
            }
            commands.extend(self.input.commands(&mut self.panels, &self.model, mouse));
            commands.extend(self.page.commands());
            let running = !self.model.clock.paused;
            let drawer = self
                .panels
                .rects
                .as_ref()
                .is_some_and(|r| matches!(r.side_dock, layout::SideDock::Drawer { .. }));
            for command in commands {
                self.model.apply(command.in_layout(drawer));
            }
            self.carry_out_requests();
            let step_start = impulse::clock::Instant::now();
            let budget = model::clock::physics_budget(previous.0, previous.1);
            self.model.tick(get_frame_time() as f64, budget);
            let step_ms = ms_since(step_start, impulse::clock::Instant::now());
            audio::play(self.model.take_sounds());
            self.keep_for_the_page();
            let world_keys = !(self.panels.typing || self.panels.panel_keyboard);
            self.page.update(&mut self.model, world_keys);
            let timed_out = self
                .options
                .exit_after
                .is_some_and(|limit| get_time() >= limit);
            let closing = self.model.session.requests.quit || is_quit_requested() || timed_out;
            if closing {
                self.model.on_close();
            }
            let requested = self.model.session.requests.screenshot.take();
            let wanted = (closing && self.options.screenshot.is_some()) || requested.is_some();
            let draw_start = impulse::clock::Instant::now();
            self.painter.draw(&self.model, mouse);
            egui_macroquad::draw();
            // The whole frame, panels included, read back before it is shown.
            let capture = wanted.then(screenshot::screen_image);
            let draw_ms = ms_since(draw_start, impulse::clock::Instant::now());
            self.frame += 1;
            self.write_dump();
            let mut times = self.frame_times(step_ms, draw_ms);
            let present_start = impulse::clock::Instant::now();
            if let Some(image) = capture {
                if let (true, Some(path)) = (closing, &self.options.screenshot) {
                    screenshot::save_screenshot(path, &image);
                }
                if let Some(path) = requested {
                    screenshot::save_screenshot_key(&mut self.model, &image, &path);
                }
            }
            if !closing {
                let busy = idle::busy(&self.model, running, self.frame);
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

    /// The state dump: into `--dump-state`'s file on the desktop; in the
    /// browser, reported to the page every frame for up to 2,000 discs and
    /// every 30th beyond (a long JSON each frame would cost more than the
    /// drawing).
    fn write_dump(&self) {
        let path = self.options.dump_state.as_deref();
        if cfg!(target_arch = "wasm32") {
            if self.model.world.particles.len() > 2_000 && self.frame % 30 != 1 {
                return;
            }
        } else if path.is_none() {
            return;
        }
        let window = dump::Window {
            frame: dump::FrameDump {
                frame: self.frame,
                sleeping: self.idle.sleeping(),
                idle_frames: self.idle.idle_frames,
                samples: self.samples,
            },
            panels: &self.panels,
            world_text_px: self.painter.smallest_text(),
            readouts: self.painter.readouts,
            timing: self.frame_stats.recent(),
        };
        dump::write(path, &dump::state(&self.model, window));
    }

    /// In the browser: hands the page the sandbox to keep when it is hidden
    /// or left (`impulse_keep_now`), at most four times a second and only
    /// when it changed.
    fn keep_for_the_page(&mut self) {
        if !cfg!(target_arch = "wasm32") {
            return;
        }
        if !self.model.worth_keeping() {
            #[cfg(target_arch = "wasm32")]
            crate::web::keep_latest(None);
            self.kept.0 = 0;
            return;
        }
        let now = get_time();
        if now - self.kept.1 < 0.25 {
            return;
        }
        let print = self.model.fingerprint();
        if print == self.kept.0 {
            return;
        }
        self.kept = (print, now);
        #[cfg(target_arch = "wasm32")]
        crate::web::keep_latest(Some((
            format!("impulse:{}", self.model.recovery.path().display()),
            self.model.current_scene().to_toml(),
        )));
    }

    /// What only the window can do, as the model asked.
    fn carry_out_requests(&mut self) {
        if std::mem::take(&mut self.model.session.requests.fullscreen) {
            self.input.fullscreen = !self.input.fullscreen;
            set_fullscreen(self.input.fullscreen);
        }
    }

    /// This frame's record, its frame and present times still to come.
    fn frame_times(&self, step_ms: f64, draw_ms: f64) -> frame_stats::FrameTimes {
        let overlays = &self.model.overlays;
        frame_stats::FrameTimes {
            frame: self.frame,
            discs: self.model.world.particles.len(),
            velocity: overlays.velocity,
            momentum: overlays.momentum,
            readouts: overlays.readouts.name(),
            steps: self.model.steps.steps_last_frame,
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
}
