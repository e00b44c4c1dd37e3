//! Every action a person can take, by key, button, menu or gesture, as one
//! enum. The window turns input into these; [`super::Sandbox::apply`]
//! carries them out.

use super::overlays::ReadoutScope;
use super::{DockTab, Theme};
use glam::DVec2;
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::{Method, Setting};
use impulse::Boundary;

/// A coefficient of the collision law that a control sets: declared, with
/// its ranges, beside the laws in the core.
pub use impulse::laws::Law;

/// Where a disc edit was typed: its answer goes back there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EditPlace {
    /// The side dock's fields for the selected disc.
    Fields,
    /// The same fields with the velocity typed as a speed and a direction
    /// (sent as v_x and v_y): the answer says the speed and the direction.
    Polar,
    /// A cell of the Discs table.
    Table,
}

/// Which way a stepped control moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    Down,
    Up,
}

/// One action.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    // Time.
    TogglePause,
    /// One step, paused.
    Step,
    Slower,
    Faster,
    /// One of the clock's time scales, by index.
    SetTimeScale(usize),
    /// Run to the next impact (between discs or on a wall) and pause there.
    NextCollision,
    /// Back (negative) or forward through the recorded past.
    Scrub(isize),

    // Scenes.
    OpenPreset(usize),
    /// The empty box.
    OpenEmpty,
    /// A scene file by its path (the path field).
    OpenFile(String),
    /// The person names the scene (the *Scene* section's name field).
    RenameScene(String),
    /// A scene's text, named (a dropped file), or why it could not be read.
    OpenText {
        name: String,
        text: Result<String, String>,
    },
    Reset,
    Clear,
    Save,
    Share,
    Export,
    Screenshot,
    Undo,
    Redo,
    RestoreRecovery,
    SetRecoveryAside,
    /// The start screen (the top bar's Start button).
    ShowStart,
    /// A tile of the start screen.
    StartWith(super::start::Tile),
    /// Leave the start screen with the scene that is open.
    CloseStart,
    /// Every control in the side dock, not only the lesson's.
    ShowAllControls,
    /// The browser's kept sandbox, set aside by a shared link.
    ReopenKept,

    // Laws and method.
    SetLaw(Law, f64),
    NudgeLaw(Law, Dir),
    /// Friction μ, or none (no limit).
    SetFriction(Option<f64>),
    /// |g| pointing down (0: off).
    SetGravity(f64),
    ToggleGravity,
    SetBoundary(Boundary),
    SetMethod(Setting<Method>),
    SetBroadPhase(Setting<BroadPhaseKind>),
    SetSubsteps(Setting<u32>),
    CycleMethod,
    CycleBroadPhase,
    CycleSubsteps,

    // New discs and the discs themselves.
    SetNewRadius(f64),
    SetNewMass(f64),
    StepNewRadius(Dir),
    StepNewMass(Dir),
    SizeFollowsMass(bool),
    Select(Option<usize>),
    /// The next disc (`1`) or the previous one (`-1`) becomes the selected
    /// one: the world's keyboard path.
    SelectNext(i32),
    /// While paused, the selected disc's velocity changes by this much
    /// (m/s): the arrow keys aim it.
    AimSelected(DVec2),
    /// A new disc, at rest, at the centre of the view (Enter).
    LaunchAtCentre,
    /// The scene described in words, said to a screen reader.
    Describe,
    /// New values typed for disc `disc`, in [`super::edit::FIELDS`] order
    /// (`None`: untouched); read and checked by the model.
    EditDisc {
        disc: usize,
        /// Typed text per quantity, in [`super::edit::FIELDS`] order.
        text: [Option<String>; 6],
        from: EditPlace,
    },
    DeleteSelected,
    /// The left button or a finger went down, moved, came up (window px).
    PointerDown(DVec2),
    PointerMove(DVec2),
    PointerUp(DVec2),

    // What is drawn.
    ToggleVelocity,
    ToggleMomentum,
    ToggleDeltaP,
    CycleReadouts,
    SetReadouts(ReadoutScope),
    ToggleCenterOfMass,
    ToggleTrails,
    TogglePalette,
    ToggleCenterOfMassView,
    /// A click at each impact, on or off.
    ToggleSound,

    // The view.
    ZoomIn,
    ZoomOut,
    /// Zoom by `factor` keeping window point `at` still.
    ZoomAt {
        at: DVec2,
        factor: f64,
    },
    /// Pan by window pixels.
    Pan(DVec2),
    /// Two fingers moved: from `before` to `after` (window px).
    Pinch {
        before: [DVec2; 2],
        after: [DVec2; 2],
    },
    Fit,

    // Panels.
    /// A tab's key, or the tab chosen from the tab menu (the row's narrow
    /// form): shown, never folded. Both had folded the dock where the tab
    /// was in sight, as a second click on a tab does.
    ShowTab(DockTab),
    /// A tab clicked in the tab row: chosen, or folded when it was open.
    ClickTab(DockTab),
    /// A tab clicked where the window leaves it no room: the strip says
    /// what makes room (L, where the side panel is docked; else another
    /// text size), which the row's own note had no room to say.
    SayNoRoomForTab {
        side_docked: bool,
    },
    ToggleDockExpanded,
    /// The open tab's height in px (its top edge dragged); None: its own.
    SetTabHeight(Option<f32>),
    /// The tab's height is set (the drag let go, a key pressed): remembered
    /// for the next start.
    KeepTabHeight,
    ToggleDocks,
    ToggleSide,
    ToggleDrawer,
    /// The drawer closes (the side dock docked again).
    CloseDrawer,
    ToggleHelp,
    TogglePresets,
    /// Esc: closes what is open, else deselects.
    Escape,
    SetScale(f32),
    NextScale,
    SetTheme(Theme),
    /// The window's language, remembered for the next start.
    SetLanguage(crate::app::lang::Lang),
    Fullscreen,
    Quit,
}

impl Command {
    /// Whether the command only runs, pauses or steps the clock: the keys
    /// that still act after Enter has left a field, while the others wait
    /// for Esc or a click in the world (a digit typed on would open a
    /// preset).
    pub fn runs_the_clock(&self) -> bool {
        matches!(
            self,
            Command::TogglePause | Command::Step | Command::NextCollision
        )
    }

    /// The kind of change to the scene this command may make, as undo names
    /// it; `None` for commands that never change the scene. Whether it did
    /// is seen after it ran: only then is the scene remembered.
    pub fn edit_kind(&self) -> Option<&'static str> {
        use Command::*;
        Some(match self {
            OpenPreset(_)
            | OpenEmpty
            | OpenFile(_)
            | OpenText { .. }
            | RestoreRecovery
            | StartWith(_)
            | ReopenKept => "edit-open-scene",
            Reset => "edit-reset",
            RenameScene(_) => "edit-rename",
            Clear => "edit-clear",
            SetLaw(Law::Restitution, _) | NudgeLaw(Law::Restitution, _) => "edit-restitution",
            SetLaw(Law::WallRestitution, _) | NudgeLaw(Law::WallRestitution, _) => {
                "edit-wall-restitution"
            }
            SetLaw(Law::Roughness, _) | NudgeLaw(Law::Roughness, _) => "edit-roughness",
            SetLaw(Law::WallRoughness, _) | NudgeLaw(Law::WallRoughness, _) => {
                "edit-wall-roughness"
            }
            SetFriction(_) => "edit-friction",
            SetGravity(_) | ToggleGravity => "edit-gravity",
            SetBoundary(_) => "edit-edges",
            SetMethod(_) | CycleMethod => "edit-method",
            SetBroadPhase(_) | CycleBroadPhase => "edit-broad-phase",
            SetSubsteps(_) | CycleSubsteps => "edit-substeps",
            EditDisc { .. } => "edit-disc",
            DeleteSelected => "edit-delete",
            AimSelected(_) => "edit-aim",
            LaunchAtCentre => "edit-add-disc",
            // A gesture's release names its own change (pointer.rs).
            _ => return None,
        })
    }

    /// The command as meant where the controls are a drawer (a small window,
    /// a large text size): showing or hiding the controls (L) opens or shuts
    /// the drawer. Hiding the side there would hide the drawer's button
    /// instead, and the controls with it.
    pub fn in_layout(self, drawer: bool) -> Command {
        match self {
            Command::ToggleSide if drawer => Command::ToggleDrawer,
            other => other,
        }
    }

    /// Whether a change this command makes means the scene's caption may
    /// no longer hold: a change to the discs, or to a law they obey ("the
    /// moving disc stops dead" fails at e = 0.5, "momentum stays the same"
    /// under gravity). The method and its settings keep the caption.
    pub fn voids_caption(&self) -> bool {
        use Command::*;
        matches!(
            self,
            EditDisc { .. }
                | DeleteSelected
                | AimSelected(_)
                | LaunchAtCentre
                | SetLaw(..)
                | NudgeLaw(..)
                | SetFriction(_)
                | SetGravity(_)
                | ToggleGravity
                | SetBoundary(_)
        )
    }
}
