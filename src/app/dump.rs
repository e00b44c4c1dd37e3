//! Files the window writes for tests and documentation: a JSON state dump
//! and PNG screenshots, both written atomically (temporary file, then rename).
//! The dump is read from the model and what the window measured; its
//! groups are flattened, so the JSON is one flat object as tests read it.

use super::model::camera::Camera;
use super::model::Sandbox;
use impulse::{Metrics, Particle};
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::Path;

/// Everything a test needs to check what the window did.
#[derive(Serialize)]
pub struct StateDump<'a> {
    #[serde(flatten)]
    pub frame: FrameDump,
    #[serde(flatten)]
    pub clock: ClockDump,
    #[serde(flatten)]
    pub pointer: PointerDump,
    #[serde(flatten)]
    pub counts: CountsDump,
    #[serde(flatten)]
    pub scene: SceneDump,
    /// The world's size and laws, as in a scene file's `[world]` table
    /// (`walls` only when a box lacks some).
    #[serde(flatten)]
    pub laws: impulse::laws::Laws,
    #[serde(flatten)]
    pub panels: PanelsDump,
    /// How fast simulated time goes, and what the top bar says about it.
    pub realtime: RealtimeDump,
    /// Medians of the recent frames' timings (ms).
    pub timing: super::frame_stats::TimingSummary,
    /// Autosave: the recovery file, saves written, the last failure, and
    /// whether an earlier session is being offered.
    pub recovery: RecoveryDump,
    #[serde(flatten)]
    pub totals: TotalsDump,
    /// The sound switch and the clicks played.
    pub sound: SoundDump,
    /// Every disc.
    pub particles: &'a [Particle],
}

/// The frame and the idle window.
#[derive(Serialize)]
pub struct FrameDump {
    /// Frames drawn so far.
    pub frame: u64,
    /// The window draws only on input or a timer now: nothing has moved
    /// or changed for a while (see `idle`).
    pub sleeping: bool,
    /// Frames drawn by the idle timer, so far.
    pub idle_frames: u64,
    /// Samples per pixel of the drawing surface, as OpenGL reports it: 4
    /// with edges smoothed, 0 or 1 with `--no-antialias` (none in the
    /// browser).
    pub samples: Option<i32>,
}

/// Simulated time and the clock.
#[derive(Serialize)]
pub struct ClockDump {
    /// Simulated time (s).
    pub time: f64,
    /// Physics steps so far.
    pub steps: u64,
    /// Whether the clock is paused.
    pub paused: bool,
    /// Simulated seconds per real second.
    pub time_scale: f64,
    /// Physics step (s).
    pub dt: f64,
    /// Snapshots kept for rewinding.
    pub history_len: usize,
    /// The snapshot shown while rewound.
    pub history_cursor: Option<usize>,
}

/// The view, the selection and the gesture.
#[derive(Serialize)]
pub struct PointerDump {
    /// The view.
    pub camera: CameraDump,
    /// Selected disc.
    pub selected: Option<usize>,
    /// Disc held by the mouse.
    pub held: Option<usize>,
}

/// The counts: one count, as the top bar and the ledger give it.
#[derive(Serialize)]
pub struct CountsDump {
    /// Collisions between discs the ledger has recorded.
    pub collisions_recorded: u64,
    /// Impacts on walls the ledger has recorded.
    pub wall_hits_recorded: u64,
    /// Impacts counted: between discs, and with walls.
    pub pair_collisions: u64,
    pub wall_hits: u64,
    /// The top bar's line of counts.
    pub count_line: String,
    /// Resting contacts in the last step (not counted as collisions).
    pub resting_contacts: usize,
    /// Discs with their values beside them, of those on screen that were
    /// to have them ([shown, wanted]); the world says so when fewer.
    pub readouts_shown: [usize; 2],
    /// Where the selected disc's values were drawn (px: x, y, width,
    /// height), if they were.
    pub selected_readout: Option<[f64; 4]>,
    /// The π blocks' final line ("31 collisions: π ≈ 3.1"), once shown.
    pub pi_result: Option<String>,
}

/// The open scene and what its steps use.
#[derive(Serialize)]
pub struct SceneDump {
    /// The open scene's name.
    pub scene_name: Option<String>,
    /// Where the open scene came from (a file, a preset, the default).
    pub scene_origin: String,
    /// Method setting ("auto" or a name).
    pub method: String,
    /// Broad-phase setting.
    pub broad_phase: String,
    /// Substep setting.
    pub substeps: String,
    /// What the last step used.
    pub plan: Option<impulse::auto::Plan>,
    /// What the method cannot promise right now, as the top bar says it.
    pub warnings: Vec<impulse::warnings::Warning>,
}

/// The panels.
#[derive(Serialize)]
pub struct PanelsDump {
    /// Whether the side dock (the controls) is shown.
    pub panel_visible: bool,
    /// Screen rectangles [x, y, width, height] (px) of named widgets drawn
    /// this frame: sliders, text fields, buttons, tabs, table cells.
    pub panel_widgets: BTreeMap<String, [f32; 4]>,
    /// Where the world and every panel went, and the smallest text drawn.
    pub layout: super::ui::Layout,
    /// Which panels, tabs and popups are open; messages shown.
    pub ui: UiDump,
}

/// The totals.
#[derive(Serialize)]
pub struct TotalsDump {
    /// Totals (`kinetic_energy` of moving, `rotational_energy` of turning,
    /// `angular_momentum` about the origin).
    pub metrics: Metrics,
    /// Kinetic energy of moving and turning plus gravitational potential
    /// energy (J), as the top bar's total says.
    pub total_energy: f64,
    /// Whether spin is shown: spin lines on the discs, spin values in the
    /// readouts, the Discs table and the top bar.
    pub spin_shown: bool,
}

/// The panels in a dump.
#[derive(Default, Serialize)]
pub struct UiDump {
    pub docks_open: bool,
    pub side_open: bool,
    /// The side dock's drawer is open (where it is a drawer).
    pub drawer_open: bool,
    pub dock_expanded: bool,
    pub tab: String,
    pub help_open: bool,
    pub presets_open: bool,
    /// The start screen's tiles.
    pub start_open: bool,
    pub theme: String,
    #[serde(flatten)]
    pub keys: KeysDump,
    /// The window's language ("en", "pt-BR", "qps").
    pub language: String,
    #[serde(flatten)]
    pub edits: EditsDump,
    /// Tooltips showing (one at most: two stacked was a fault).
    pub tooltips: usize,
    /// Where a tooltip showing is: [x, y, w, h] in pixels.
    pub tooltip: Option<[f32; 4]>,
    /// Named labels cut short for want of room ("scene_name", "caption",
    /// "message"): whole on hover.
    pub cut: Vec<String>,
}

/// Who has the keyboard.
#[derive(Default, Serialize)]
pub struct KeysDump {
    /// A text field has the keyboard.
    pub typing: bool,
    /// A field was left with Enter: the panel keeps the keyboard.
    pub panel_keyboard: bool,
    /// The named control that has the keyboard (Tab moves it), if any.
    pub focus: Option<String>,
    /// Where whatever has the keyboard is, named or not: [x, y, w, h] in
    /// pixels (the ring Tab moves).
    pub focus_rect: Option<[f32; 4]>,
    /// Lists to read that scroll (no controls in them; Tab stops on them
    /// and the keys scroll them), by name, with how far each is scrolled.
    pub lists: std::collections::BTreeMap<String, crate::app::ui::ListScroll>,
}

/// Undo, the scene's edits and the messages.
#[derive(Default, Serialize)]
pub struct EditsDump {
    /// Changes that can be undone and redone.
    pub undo_levels: [usize; 2],
    /// The scene's discs were edited since it opened.
    pub scene_edited: bool,
    /// The view moves with the centre of mass.
    pub center_of_mass_view: bool,
    /// New discs and mass edits take the radius of one density.
    pub size_follows_mass: bool,
    /// The Discs table's last message.
    pub table_note: Option<String>,
    /// The message in the strip under the world, while shown.
    pub message: Option<String>,
}

/// The frame budget in a dump.
#[derive(Default, Serialize)]
pub struct RealtimeDump {
    /// Simulated seconds per real second over the last ten seconds running.
    pub ratio: Option<f64>,
    /// What the top bar says ("running at 0.31× real time"), if anything.
    pub shown: Option<String>,
    pub steps_last_frame: u32,
    /// Steps due last frame that the frame budget dropped.
    pub steps_dropped: u32,
}

/// Sound in a dump.
#[derive(Default, Serialize)]
pub struct SoundDump {
    /// The switch (S, the top bar's button).
    pub on: bool,
    /// Clicks the model handed to the player so far.
    pub events_played: u64,
}

/// Autosave in a dump.
#[derive(Default, Serialize)]
pub struct RecoveryDump {
    pub file: String,
    pub saves: u64,
    pub error: Option<String>,
    pub offered: bool,
}

/// The camera in a dump.
#[derive(Serialize)]
pub struct CameraDump {
    /// World point at the centre of the world's rectangle.
    pub center: [f64; 2],
    /// Pixels per metre.
    pub scale: f64,
    /// Size of the world's rectangle (px).
    pub viewport: [f64; 2],
    /// Its top-left corner in the window (px).
    pub origin: [f64; 2],
}

impl From<&Camera> for CameraDump {
    fn from(c: &Camera) -> Self {
        CameraDump {
            center: c.center.to_array(),
            scale: c.scale,
            viewport: c.viewport.to_array(),
            origin: c.origin.to_array(),
        }
    }
}

/// What the window measured this frame, beside the model.
pub struct Window<'a> {
    pub frame: FrameDump,
    pub panels: &'a super::ui::Panels,
    /// The smallest text the world's drawing drew (px), if any.
    pub world_text_px: Option<f32>,
    /// Discs with their values beside them, and discs on screen that were to
    /// have them.
    pub readouts: crate::app::drawing::readouts::Shown,
    pub timing: super::frame_stats::TimingSummary,
}

/// The dump of the sandbox `m` as the window shows it.
pub fn state<'a>(m: &'a Sandbox, window: Window<'a>) -> StateDump<'a> {
    let world = &m.world;
    let panels = window.panels;
    let mut layout = panels.layout.clone();
    if let Some(px) = window.world_text_px {
        layout.min_text_px = layout.min_text_px.min(px);
    }
    StateDump {
        frame: window.frame,
        clock: ClockDump {
            time: world.time,
            steps: world.steps,
            paused: m.clock.paused,
            time_scale: m.clock.time_scale(),
            dt: m.clock.dt,
            history_len: m.record.history.len(),
            history_cursor: m.record.history.cursor(),
        },
        pointer: PointerDump {
            camera: (&m.view.camera).into(),
            selected: m.selected,
            held: m.pointer.gesture.held(),
        },
        counts: CountsDump {
            collisions_recorded: world.ledger.recorded,
            wall_hits_recorded: world.ledger.recorded_walls,
            pair_collisions: world.total_pair_collisions,
            wall_hits: world.total_wall_hits,
            count_line: super::model::lesson::count_line(world),
            resting_contacts: world.resting_contacts,
            readouts_shown: [window.readouts.shown, window.readouts.wanted],
            selected_readout: window.readouts.selected_at,
            pi_result: super::model::lesson::pi_result(world),
        },
        scene: SceneDump {
            scene_name: m.open.scene.name.clone(),
            scene_origin: m.open.origin.clone(),
            method: world.method.to_string(),
            broad_phase: world.broad_phase.to_string(),
            substeps: world.substeps.to_string(),
            plan: world.plan().cloned(),
            warnings: impulse::warnings::warnings(world, m.clock.dt),
        },
        laws: world.laws,
        panels: PanelsDump {
            panel_visible: m.panels.docks_open && m.panels.side_open,
            panel_widgets: panels.marks.widgets.clone(),
            layout,
            ui: UiDump {
                docks_open: m.panels.docks_open,
                side_open: m.panels.side_open,
                drawer_open: m.panels.drawer_open,
                dock_expanded: m.panels.dock_expanded,
                tab: m.panels.tab.key().to_string(),
                help_open: m.panels.help_open,
                presets_open: m.panels.presets_open,
                start_open: m.panels.start_open,
                theme: m.panels.theme.name().to_string(),
                keys: KeysDump {
                    typing: panels.typing,
                    panel_keyboard: panels.panel_keyboard,
                    focus: panels.marks.focused.clone(),
                    focus_rect: panels.marks.focus_rect,
                    lists: panels.marks.lists.clone(),
                },
                language: crate::app::lang::language().code().to_string(),
                edits: EditsDump {
                    undo_levels: m.undo.levels().into(),
                    scene_edited: m.open.edited,
                    center_of_mass_view: m.overlays.com_view.is_some(),
                    size_follows_mass: m.new_discs.size_follows_mass,
                    table_note: m.messages.table.as_ref().map(|n| n.text.clone()),
                    message: m.message().map(str::to_string),
                },
                tooltips: panels.marks.tooltips,
                tooltip: panels.marks.tooltip_rect,
                cut: panels.marks.cut.iter().cloned().collect(),
            },
        },
        realtime: RealtimeDump {
            ratio: m.sim_rate(),
            shown: m.slow_note(),
            steps_last_frame: m.steps.steps_last_frame,
            steps_dropped: m.steps.steps_dropped,
        },
        timing: window.timing,
        recovery: RecoveryDump {
            file: m.recovery.path().display().to_string(),
            saves: m.recovery.saves,
            error: m.recovery.error.clone(),
            offered: m.recovery.offered.is_some(),
        },
        totals: TotalsDump {
            metrics: world.metrics(),
            total_energy: world.total_energy(),
            spin_shown: super::model::overlays::spin_shown(world),
        },
        sound: SoundDump {
            on: m.session.sound.on,
            events_played: m.session.sound.played,
        },
        particles: &world.particles,
    }
}

/// Writes the dump: into `--dump-state`'s file on the desktop; in the
/// browser, reported to the page (`window.impulseState`).
pub fn write(path: Option<&Path>, state: &StateDump) {
    #[cfg(not(target_arch = "wasm32"))]
    if let Some(path) = path {
        if let Err(e) = write_state(path, state) {
            eprintln!("impulse: cannot write state dump {}: {e}", path.display());
        }
    }
    #[cfg(target_arch = "wasm32")]
    {
        let _ = path;
        if let Ok(json) = serde_json::to_string(state) {
            crate::web::report_state(&json);
        }
    }
}

/// Writes the dump as JSON.
#[cfg(not(target_arch = "wasm32"))]
pub fn write_state(path: &Path, dump: &StateDump) -> std::io::Result<()> {
    let json = serde_json::to_vec_pretty(dump).map_err(std::io::Error::other)?;
    crate::files::write_atomically(path, &json)
}
