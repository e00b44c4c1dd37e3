//! The sandbox as a class acts on it, with no window in it: the world and
//! its scene, the selection, the overlays and settings, undo and the rewind
//! history, the ledger's view, the trails and the totals' series.
//!
//! A person's action is a [`Command`]; [`Sandbox::apply`] is the one place
//! where one changes anything, and it remembers the scene for undo only
//! when the command changed it (a click that selects is not an edit). The
//! window also tells it its clock ([`Sandbox::begin_frame`]) and the
//! world's rectangle ([`Sandbox::place_world`]).
//! Time passing is [`Sandbox::tick`]: the physics steps, the totals, the
//! trails, the rewind history and autosave. Keys map to commands through
//! one table ([`bindings`]). The window (`super`) turns keys, clicks and
//! gestures into commands and draws what is here; no macroquad or egui
//! type appears in this module, so it is tested headlessly like the core.
//!
//! - [`command`]: every action, and which of them edit the scene.
//! - [`apply`]: carrying a command out.
//! - [`tick`]: time passing; next collision; rewind.
//! - [`scenes`]: presets, opening, saving, sharing, undo.
//! - [`pointer`]: mouse and touch gestures on the world; the camera.
//! - pure parts: [`camera`], [`clock`], [`gesture`], [`undo`], [`totals`],
//!   [`trails`], [`overlays`], [`lesson`], [`export`], [`share`],
//!   [`recovery`], [`sound`] (the clicks each frame plays).

pub mod apply;
pub mod bindings;
pub mod camera;
pub mod clock;
pub mod command;
pub mod edit;
pub mod export;
pub mod gesture;
pub mod keyboard;
pub mod lesson;
pub mod mirror;
pub mod modal;
pub mod narration;
pub mod open;
pub mod overlays;
pub mod panels;
pub mod pointer;
pub mod recovery;
pub mod scenes;
pub mod settings;
pub mod share;
pub mod sound;
pub mod start;
pub mod tick;
pub mod totals;
pub mod trails;
pub mod undo;

pub use command::Command;
pub use open::OpenScene;
pub use panels::{next_scale, no_room_for_tab, DockTab, Panels, Theme, UI_SCALE_RANGE};

use crate::app::lang::tr;
use crate::app::numbers::plain;
use camera::Camera;
use clock::{FixedStepClock, RealtimeMeter};
use gesture::NewDisc;
use glam::DVec2;
use impulse::{Scene, World};
use overlays::Overlays;
use std::collections::VecDeque;
use std::path::PathBuf;

/// Above this many discs, a scene slower than asked suggests fewer.
const MANY_DISCS: usize = 10_000;

/// A line of feedback under a control.
#[derive(Clone, Debug, PartialEq)]
pub struct Note {
    pub text: String,
    pub error: bool,
}

impl Note {
    pub fn ok(text: impl Into<String>) -> Self {
        Note {
            text: text.into(),
            error: false,
        }
    }
    pub fn error(text: impl Into<String>) -> Self {
        Note {
            text: text.into(),
            error: true,
        }
    }
}

/// The view of the world: the camera, whether it is fitted to the box, and
/// the centre-of-mass view.
#[derive(Clone, Debug)]
pub struct WorldView {
    pub camera: Camera,
    /// The view shows the whole box: it is fitted again when the world's
    /// rectangle changes (until the user zooms or pans).
    pub fitted: bool,
    /// Pixels at the right of the world's rectangle under the drawer, when
    /// open: a fitted view fits the box in the rest.
    pub covered: f64,
}

/// The disc a launch makes, and whether its size follows its mass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewDiscs {
    pub disc: NewDisc,
    /// New discs and mass edits take the radius of one density.
    pub size_follows_mass: bool,
}

/// What was recorded as time went on: the totals' series, the rewind
/// history and the trails.
#[derive(Clone, Default)]
pub struct Record {
    pub totals: totals::Totals,
    pub history: impulse::history::History,
    pub trails: trails::Trails,
}

impl Record {
    /// Records `world` as it is now, with its `metrics`: the totals, the
    /// trails and a moment for the rewind.
    pub fn moment(&mut self, world: &World, metrics: &impulse::Metrics) {
        self.totals.push(world, metrics);
        self.trails.record(world);
        self.history.record(world);
    }
}

/// How the last frames' physics went, for the Details section and the top
/// bar's "running slower" note.
#[derive(Clone, Debug, Default)]
pub struct StepReport {
    /// Recent per-step wall-clock times (µs).
    pub step_micros: VecDeque<f64>,
    pub steps_last_frame: u32,
    /// Steps the clock asked for last frame that the frame budget dropped.
    pub steps_dropped: u32,
    /// Simulated seconds per real second, lately.
    pub realtime: RealtimeMeter,
}

/// What the sandbox says: the message in the strip (until a moment of the
/// window's clock) and the notes under the fields that caused them.
#[derive(Clone, Debug, Default)]
pub struct Messages {
    pub toast: Option<(String, f64)>,
    /// Under the selected disc's fields.
    pub fields: Option<Note>,
    /// Above the Discs table.
    pub table: Option<Note>,
    /// Under the scene's path field.
    pub scene: Option<Note>,
    /// What is said to a person who cannot see the screen.
    pub narration: narration::Narration,
}

/// What only the window can do, asked for by a command and taken by the
/// window at the end of the frame.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Requests {
    pub quit: bool,
    pub fullscreen: bool,
    /// A screenshot of the next frame, to this file.
    pub screenshot: Option<PathBuf>,
}

/// Where the sandbox keeps its files and what the command line fixed.
#[derive(Clone, Debug)]
pub struct Session {
    /// Folder for saved scenes, exports and screenshots.
    pub out: PathBuf,
    /// `--dt`, over every scene's own step.
    pub dt: Option<f64>,
    /// The window's clock now (s), set at the start of each frame.
    pub now: f64,
    /// What only the window can do, asked for by commands.
    pub requests: Requests,
    /// What is remembered between runs (language, sound, text size, theme).
    pub settings: settings::Remembered,
    /// The sound switch and the clicks the window is to play.
    pub sound: sound::Sound,
}

/// The whole sandbox.
pub struct Sandbox {
    pub world: World,
    pub open: OpenScene,
    pub clock: FixedStepClock,
    pub view: WorldView,
    pub selected: Option<usize>,
    pub pointer: pointer::Pointer,
    pub new_discs: NewDiscs,
    pub overlays: Overlays,
    pub record: Record,
    pub undo: undo::Undo,
    pub panels: Panels,
    pub messages: Messages,
    pub steps: StepReport,
    pub recovery: recovery::Recovery,
    pub session: Session,
}

/// How a sandbox starts.
pub struct Start {
    pub scene: Scene,
    pub origin: String,
    pub world: World,
    pub paused: bool,
    pub dt: Option<f64>,
    pub out: PathBuf,
    /// The recovery file's folder and the seconds between autosaves.
    pub recovery: (PathBuf, f64),
    /// `--ui-scale`: the text size for this run, over the one remembered.
    pub scale: Option<f32>,
    /// `--light`: the theme for this run, over the one remembered.
    pub theme: Option<Theme>,
    /// Open on the start screen.
    pub start_screen: bool,
    /// The scene came from a shared link (the browser).
    pub from_link: bool,
    /// `--lang`: the language for this run, over the one remembered.
    pub lang: Option<crate::app::lang::Lang>,
    /// The system's (or the browser's) language, if Impulse speaks it.
    pub system_lang: Option<crate::app::lang::Lang>,
}

impl Sandbox {
    /// A sandbox on `start.scene`; a problem found on the way (an unreadable
    /// recovery file) is its first message.
    pub fn new(start: Start) -> Self {
        let dt = start.scene.step_for(start.dt);
        let mut clock = FixedStepClock::new(dt, 64);
        clock.paused = start.paused;
        let size = start.world.laws.size;
        // The language first, so that every message is in it.
        let (remembered, unreadable) = settings::Remembered::load(&start.recovery.0);
        let sound_on = remembered.settings.sound;
        let scale = start.scale.or(remembered.settings.text_size).unwrap_or(1.0);
        let theme = start
            .theme
            .or(remembered.settings.theme)
            .unwrap_or(Theme::Dark);
        crate::app::lang::set_language(settings::choose_language(
            start.lang,
            remembered.language(),
            start.system_lang,
        ));
        let (recovery, problem) = recovery::Recovery::new(&start.recovery.0, start.recovery.1);
        let problem = problem.or(unreadable);
        let mut sandbox = Sandbox {
            world: start.world,
            open: OpenScene {
                edited: start.scene.edited,
                unsaved: false,
                scene: start.scene,
                origin: start.origin,
                saved_to: None,
                opened: 0,
                setup: None,
                lesson: None,
            },
            clock,
            view: WorldView {
                camera: Camera::fitting(size, DVec2::new(1280.0, 800.0), 30.0),
                fitted: true,
                covered: 0.0,
            },
            selected: None,
            pointer: pointer::Pointer::default(),
            new_discs: NewDiscs {
                disc: NewDisc {
                    radius: 0.4,
                    mass: 1.0,
                },
                size_follows_mass: false,
            },
            overlays: Overlays::default(),
            record: Record::default(),
            undo: undo::Undo::default(),
            panels: Panels {
                tab_height: remembered.settings.tab_height.filter(|h| h.is_finite()),
                ..Panels::new(scale, theme)
            },
            messages: Messages::default(),
            steps: StepReport::default(),
            recovery,
            session: Session {
                out: start.out,
                dt: start.dt,
                now: 0.0,
                requests: Requests::default(),
                settings: remembered,
                sound: sound::Sound::new(sound_on),
            },
        };
        sandbox.panels.start_open = start.start_screen;
        if cfg!(target_arch = "wasm32") {
            sandbox.reopen_in_browser(start.from_link);
        }
        if sandbox.modal_open() {
            sandbox.pause_for_modal();
        }
        if let Some(problem) = problem {
            sandbox.report(problem);
        }
        sandbox
    }

    /// The open scene's name in the window's language, or "Sandbox".
    pub fn scene_name(&self) -> String {
        let lang = crate::app::lang::language().code();
        self.open
            .scene
            .name_in(lang)
            .map_or_else(|| tr!("scene-untitled"), str::to_string)
    }

    /// What follows the scene's name once its discs or laws no longer hold
    /// its caption ("(edited)", as the caption says "Before the edits").
    /// The sandbox, made to be edited, has none.
    pub fn edited_mark(&self) -> Option<String> {
        let lang = crate::app::lang::language().code();
        let named = self.open.scene.name_in(lang).is_some();
        (named && self.open.edited).then(|| tr!("scene-edited-mark"))
    }

    /// The open scene's description (its caption) in the window's
    /// language, if it has one.
    pub fn scene_description(&self) -> Option<String> {
        let lang = crate::app::lang::language().code();
        self.open.scene.description_in(lang).map(str::to_string)
    }

    /// The window's clock at the start of a frame (s).
    pub fn begin_frame(&mut self, now: f64) {
        self.session.now = now;
    }

    /// A message in the strip for a few seconds.
    pub fn toast(&mut self, message: impl Into<String>) {
        self.toast_for(message, 4.0);
    }

    pub fn toast_for(&mut self, message: impl Into<String>, seconds: f64) {
        let message = message.into();
        self.announce(message.clone());
        self.messages.toast = Some((message, self.session.now + seconds));
    }

    /// The message shown now, if any.
    pub fn message(&self) -> Option<&str> {
        self.messages
            .toast
            .as_ref()
            .filter(|(_, until)| self.session.now < *until)
            .map(|(m, _)| m.as_str())
    }

    /// A message for both the window and the terminal.
    pub fn report(&mut self, message: String) {
        eprintln!("impulse: {message}");
        self.toast_for(message, 8.0);
    }

    /// Changes what is remembered for the next start; a failed write is
    /// reported, and the change holds for this run.
    pub fn remember(&mut self, change: impl FnOnce(&mut settings::Settings)) {
        if let Some(problem) = self.session.settings.change(change) {
            self.report(problem);
        }
    }

    /// Whether a modal question or the start screen waits for an answer
    /// (the simulation stays paused behind it).
    pub fn modal_open(&self) -> bool {
        self.recovery.offered.is_some() || self.panels.start_open
    }

    /// A modal screen opened: the simulation waits for it.
    pub(super) fn pause_for_modal(&mut self) {
        if !self.clock.paused {
            self.clock.paused = true;
            self.panels.paused_by_modal = true;
        }
    }

    /// A modal screen closed: the simulation runs again if it ran before
    /// and nothing else is open.
    pub(super) fn resume_after_modal(&mut self) {
        if !self.modal_open() && std::mem::take(&mut self.panels.paused_by_modal) {
            self.clock.paused = false;
        }
    }

    /// The disc a launch makes now: with "size follows mass", its radius
    /// from its mass.
    pub fn new_disc_now(&self) -> NewDisc {
        let mut d = self.new_discs.disc;
        if self.new_discs.size_follows_mass {
            d.radius = gesture::radius_for_mass(d.mass).min(self.biggest_radius());
        }
        d
    }

    /// The largest radius a disc may have in this box.
    pub fn biggest_radius(&self) -> f64 {
        0.45 * self.world.laws.size.min_element()
    }

    /// The selected disc, if it exists.
    pub fn selected_disc(&self) -> Option<usize> {
        self.selected.filter(|&i| i < self.world.particles.len())
    }

    /// Simulated seconds per real second lately, while running.
    pub fn sim_rate(&self) -> Option<f64> {
        self.steps.realtime.ratio()
    }

    /// "running at 0.31× real time" when the simulation goes more than 10 %
    /// slower than the time scale asks; with many discs, that fewer would
    /// run faster (the steps and the drawing both grow with their number).
    pub fn slow_note(&self) -> Option<String> {
        let rate = self.sim_rate()?;
        if self.clock.paused || rate >= 0.9 * self.clock.time_scale() {
            return None;
        }
        let digits = if rate < 0.1 { 3 } else { 2 };
        let rate = plain(rate, digits);
        Some(if self.world.particles.len() > MANY_DISCS {
            tr!("running-slower-many", rate = rate)
        } else {
            tr!("running-slower", rate = rate)
        })
    }

    /// The method the steps use now ("impulse").
    pub fn method_in_use(&self) -> String {
        let plan = self
            .world
            .plan()
            .cloned()
            .unwrap_or_else(|| self.world.plan_for(self.clock.dt));
        plan.method.name().to_string()
    }

    /// "impulse ×4 / grid (auto: ...)": what the steps use, and why.
    pub fn method_line(&self) -> String {
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
        let method = format!("{}{substeps}", plan.method.name());
        if plan.reason.is_empty() {
            tr!("method-in-use", method = method, broad = broad)
        } else {
            tr!(
                "method-in-use-auto",
                method = method,
                broad = broad,
                reason = plan.reason.as_str()
            )
        }
    }
}

#[cfg(test)]
pub(crate) mod tests;
