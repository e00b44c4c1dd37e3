//! The bindings table itself: every line of the help, in order.

use super::{Binding, Chord, Key, Shift, Trigger};
use crate::app::model::command::{Command, Dir, Law};
use crate::app::model::DockTab;

const fn key(key: Key) -> Chord {
    Chord {
        key,
        ctrl: false,
        shift: Shift::Either,
    }
}

const fn plain(key: Key) -> Chord {
    Chord {
        key,
        ctrl: false,
        shift: Shift::Up,
    }
}

const fn shifted(key: Key) -> Chord {
    Chord {
        key,
        ctrl: false,
        shift: Shift::Down,
    }
}

const fn ctrl(key: Key) -> Chord {
    Chord {
        key,
        ctrl: true,
        shift: Shift::Up,
    }
}

const fn ctrl_shift(key: Key) -> Chord {
    Chord {
        key,
        ctrl: true,
        shift: Shift::Down,
    }
}

const fn letter(c: char) -> Key {
    Key::Letter(c)
}

const fn line(
    keys: &'static str,
    help: &'static str,
    control: Option<&'static str>,
    acts: &'static [(Chord, Command)],
) -> Binding {
    Binding {
        keys,
        help,
        control,
        trigger: Trigger::Press,
        acts,
    }
}

/// A line of the help about the mouse: no key.
const fn mouse(keys: &'static str, help: &'static str) -> Binding {
    line(keys, help, None, &[])
}

use Command as C;
use Key as K;

/// Every binding, in the help's order.
pub static BINDINGS: &[Binding] = &[
    mouse(
        "Left drag on empty space",
        "launch a new disc along the drag",
    ),
    mouse(
        "Left drag on a disc",
        "grab and fling it (it keeps the mouse's velocity)",
    ),
    mouse("Drag the selected disc's arrow tip", "set its velocity"),
    mouse("Left click", "select a disc; on empty space, deselect"),
    Binding {
        keys: "Right or middle drag, arrow keys",
        help: "pan",
        control: None,
        trigger: Trigger::Hold,
        acts: &[
            (key(K::Left), C::Pan(glam::DVec2::new(PAN, 0.0))),
            (key(K::Right), C::Pan(glam::DVec2::new(-PAN, 0.0))),
            (key(K::Up), C::Pan(glam::DVec2::new(0.0, PAN))),
            (key(K::Down), C::Pan(glam::DVec2::new(0.0, -PAN))),
        ],
    },
    line(
        "Wheel, + / −",
        "zoom at the cursor / at the centre",
        Some("View"),
        &[
            (key(K::Equal), C::ZoomIn),
            (key(K::KpAdd), C::ZoomIn),
            (key(K::Minus), C::ZoomOut),
            (key(K::KpSubtract), C::ZoomOut),
        ],
    ),
    line(
        "F",
        "fit the box to the window",
        None,
        &[(key(letter('F')), C::Fit)],
    ),
    line(
        "Space",
        "pause / resume",
        None,
        &[(key(K::Space), C::TogglePause)],
    ),
    line(
        "N",
        "one step, paused",
        None,
        &[(key(letter('N')), C::Step)],
    ),
    line(
        "[ / ]",
        "slower / faster",
        None,
        &[
            (key(K::LeftBracket), C::Slower),
            (key(K::RightBracket), C::Faster),
        ],
    ),
    line(
        "V / M",
        "velocity / momentum arrows",
        Some("Show"),
        &[
            (key(letter('V')), C::ToggleVelocity),
            (key(letter('M')), C::ToggleMomentum),
        ],
    ),
    line(
        "I",
        "values beside: none / the selected disc / every disc",
        Some("Show"),
        &[(key(letter('I')), C::CycleReadouts)],
    ),
    line(
        "O",
        "centre of mass and its velocity",
        Some("Show"),
        &[(key(letter('O')), C::ToggleCenterOfMass)],
    ),
    line(
        "A",
        "path traces, a dot every 0.1 s",
        Some("Show"),
        &[(key(letter('A')), C::ToggleTrails)],
    ),
    line(
        "F3",
        "colour-blind-safe colours",
        Some("Show"),
        &[(key(K::F(3)), C::TogglePalette)],
    ),
    line(
        "Z",
        "centre-of-mass view on or off: the view moves with it",
        Some("Show"),
        &[(plain(letter('Z')), C::ToggleCenterOfMassView)],
    ),
    line(
        "S",
        "sound on / off: a click at each impact, by its impulse (silent while paused or faster than ×2)",
        None,
        &[(key(letter('S')), C::ToggleSound)],
    ),
    line(
        "J",
        "run to the next collision and pause at impact",
        Some("Show, Collisions tab"),
        &[(key(letter('J')), C::NextCollision)],
    ),
    line(
        ", / .",
        "back / forward through the recorded past; Shift: ×10",
        None,
        &[
            (plain(K::Comma), C::Scrub(-1)),
            (shifted(K::Comma), C::Scrub(-10)),
            (plain(K::Period), C::Scrub(1)),
            (shifted(K::Period), C::Scrub(10)),
        ],
    ),
    line(
        "E / Shift+E",
        "restitution between discs ±0.1",
        Some("Collisions"),
        &[
            (plain(letter('E')), C::NudgeLaw(Law::Restitution, Dir::Up)),
            (
                shifted(letter('E')),
                C::NudgeLaw(Law::Restitution, Dir::Down),
            ),
        ],
    ),
    line(
        "W / Shift+W",
        "restitution at the walls ±0.1",
        Some("Collisions"),
        &[
            (
                plain(letter('W')),
                C::NudgeLaw(Law::WallRestitution, Dir::Up),
            ),
            (
                shifted(letter('W')),
                C::NudgeLaw(Law::WallRestitution, Dir::Down),
            ),
        ],
    ),
    line(
        "G",
        "gravity on / off",
        Some("Collisions"),
        &[(key(letter('G')), C::ToggleGravity)],
    ),
    line(
        "PgUp / PgDn, Home / End",
        "radius / mass of new discs",
        Some("New discs"),
        &[
            (key(K::PageUp), C::StepNewRadius(Dir::Up)),
            (key(K::PageDown), C::StepNewRadius(Dir::Down)),
            (key(K::Home), C::StepNewMass(Dir::Up)),
            (key(K::End), C::StepNewMass(Dir::Down)),
        ],
    ),
    line(
        "Delete / Backspace",
        "delete the selected disc",
        Some("Selected disc"),
        &[
            (key(K::Delete), C::DeleteSelected),
            (key(K::Backspace), C::DeleteSelected),
        ],
    ),
    line(
        "C",
        "clear all discs",
        Some("Scene"),
        &[(key(letter('C')), C::Clear)],
    ),
    line(
        "R",
        "reset the scene (asked after a session that did not close normally: restore it)",
        None,
        &[(key(letter('R')), C::Reset)],
    ),
    line(
        "1 … 9, 0, P",
        "open a classroom preset / the preset menu",
        None,
        &[
            (key(K::Digit(1)), C::OpenPreset(0)),
            (key(K::Digit(2)), C::OpenPreset(1)),
            (key(K::Digit(3)), C::OpenPreset(2)),
            (key(K::Digit(4)), C::OpenPreset(3)),
            (key(K::Digit(5)), C::OpenPreset(4)),
            (key(K::Digit(6)), C::OpenPreset(5)),
            (key(K::Digit(7)), C::OpenPreset(6)),
            (key(K::Digit(8)), C::OpenPreset(7)),
            (key(K::Digit(9)), C::OpenPreset(8)),
            (key(K::Digit(0)), C::OpenPreset(9)),
            (key(letter('P')), C::TogglePresets),
        ],
    ),
    line(
        "Ctrl+N",
        "a new empty box",
        Some("Presets…: the last one"),
        &[(ctrl(letter('N')), C::OpenEmpty)],
    ),
    line(
        "Ctrl+Z",
        "undo the last change to the scene",
        None,
        &[(ctrl(letter('Z')), C::Undo)],
    ),
    line(
        "Ctrl+Shift+Z, Ctrl+Y",
        "redo it",
        None,
        &[
            (ctrl_shift(letter('Z')), C::Redo),
            (ctrl(letter('Y')), C::Redo),
        ],
    ),
    line(
        "Esc",
        "close what is open, else deselect; after Enter in a field, keys act on the world again; \
         asked after a session that did not close normally: set it aside",
        None,
        &[(key(K::Escape), C::Escape)],
    ),
    line(
        "Ctrl+S",
        "save the scene; it reopens exactly",
        Some("Scene"),
        &[(ctrl(letter('S')), C::Save)],
    ),
    line(
        "X",
        "export totals, discs, collisions and wall impacts as CSV",
        Some("Scene"),
        &[(key(letter('X')), C::Export)],
    ),
    line(
        "F12",
        "screenshot into the output folder",
        Some("Scene"),
        &[(key(K::F(12)), C::Screenshot)],
    ),
    line(
        "T / U / D / F4",
        "bottom dock: Totals / Collisions / Momenta / Speeds",
        Some("the tab row"),
        &[
            (key(letter('T')), C::ShowTab(DockTab::Totals)),
            (key(letter('U')), C::ShowTab(DockTab::Collisions)),
            (key(letter('D')), C::ShowTab(DockTab::Momenta)),
            (key(K::F(4)), C::ShowTab(DockTab::Speeds)),
        ],
    ),
    line(
        "Tab",
        "hide or show the panels; the top bar stays",
        Some("View"),
        &[(key(K::Tab), C::ToggleDocks)],
    ),
    line(
        "L",
        "hide or show the controls at the side",
        Some("Controls"),
        &[(key(letter('L')), C::ToggleSide)],
    ),
    line(
        "F2",
        "text and controls 1.0 / 1.5 / 2.0 times as large, for a projector",
        Some("View"),
        &[(key(K::F(2)), C::NextScale)],
    ),
    line(
        "Y / B / K",
        "method / broad phase / substeps",
        Some("More: Details"),
        &[
            (plain(letter('Y')), C::CycleMethod),
            (key(letter('B')), C::CycleBroadPhase),
            (key(letter('K')), C::CycleSubsteps),
        ],
    ),
    line(
        "F11",
        "full screen",
        Some("View"),
        &[(key(K::F(11)), C::Fullscreen)],
    ),
    line(
        "H or F1",
        "the list of keys and mouse actions",
        None,
        &[
            (key(letter('H')), C::ToggleHelp),
            (key(K::F(1)), C::ToggleHelp),
        ],
    ),
    line("Ctrl+Q", "quit", None, &[(ctrl(letter('Q')), C::Quit)]),
];

/// Keyboard pan speed, pixels per frame.
const PAN: f64 = 12.0;

/// The on-screen label of each command that has a button: the buttons read
/// it here, and the help names the control after it.
pub static LABELS: &[(Command, &str)] = &[
    (C::TogglePause, "Play / Pause"),
    (C::Step, "Step"),
    (C::Reset, "⟲ Reset"),
    (C::Undo, "Undo"),
    (C::Redo, "Redo"),
    (C::Slower, "« Slower"),
    (C::Faster, "Faster »"),
    (C::TogglePresets, "Presets…"),
    (C::Fit, "Fit view"),
    (C::ToggleHelp, "? Help"),
    (C::NextCollision, "Next collision"),
    (C::Scrub(-1), "◀ Back"),
    (C::Scrub(1), "Forward ▶"),
    (C::DeleteSelected, "Delete"),
    (C::Save, "Save"),
    (C::Clear, "Clear discs"),
    (C::Export, "Export CSV"),
    (C::Screenshot, "Screenshot"),
    (C::NextScale, "Projector size"),
    (C::ZoomIn, "Zoom +"),
    (C::ZoomOut, "Zoom −"),
    (C::Fullscreen, "Full screen"),
    (C::ToggleDocks, "Hide panels"),
    (C::ShowStart, "Start"),
    (C::ToggleDrawer, "☰ Controls"),
    (C::ShowAllControls, "All controls"),
    (C::ReopenKept, "Reopen my last sandbox"),
    (C::ToggleSound, "Sound"),
];
