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
    name: &'static str,
    control: Option<&'static str>,
    acts: &'static [(Chord, Command)],
) -> Binding {
    Binding {
        name,
        control,
        trigger: Trigger::Press,
        acts,
    }
}

/// A line of the help about the mouse: no key.
const fn mouse(name: &'static str) -> Binding {
    line(name, None, &[])
}

use Command as C;
use Key as K;

/// Every binding, in the help's order.
pub static BINDINGS: &[Binding] = &[
    mouse("launch"),
    mouse("fling"),
    mouse("aim"),
    mouse("select"),
    Binding {
        name: "pan",
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
        "aim-keys",
        None,
        &[
            (plain(K::Left), C::AimSelected(glam::DVec2::new(-AIM, 0.0))),
            (plain(K::Right), C::AimSelected(glam::DVec2::new(AIM, 0.0))),
            (plain(K::Up), C::AimSelected(glam::DVec2::new(0.0, AIM))),
            (plain(K::Down), C::AimSelected(glam::DVec2::new(0.0, -AIM))),
            (
                shifted(K::Left),
                C::AimSelected(glam::DVec2::new(-10.0 * AIM, 0.0)),
            ),
            (
                shifted(K::Right),
                C::AimSelected(glam::DVec2::new(10.0 * AIM, 0.0)),
            ),
            (
                shifted(K::Up),
                C::AimSelected(glam::DVec2::new(0.0, 10.0 * AIM)),
            ),
            (
                shifted(K::Down),
                C::AimSelected(glam::DVec2::new(0.0, -10.0 * AIM)),
            ),
        ],
    ),
    line(
        "select-next",
        None,
        &[
            (plain(letter('Q')), C::SelectNext(1)),
            (shifted(letter('Q')), C::SelectNext(-1)),
        ],
    ),
    line("launch-centre", None, &[(key(K::Enter), C::LaunchAtCentre)]),
    line(
        "zoom",
        Some("section-view"),
        &[
            (key(K::Equal), C::ZoomIn),
            (key(K::KpAdd), C::ZoomIn),
            (key(K::Minus), C::ZoomOut),
            (key(K::KpSubtract), C::ZoomOut),
        ],
    ),
    line("fit", None, &[(key(letter('F')), C::Fit)]),
    line("pause", None, &[(key(K::Space), C::TogglePause)]),
    line("step", None, &[(key(letter('N')), C::Step)]),
    line(
        "speed",
        None,
        &[
            (key(K::LeftBracket), C::Slower),
            (key(K::RightBracket), C::Faster),
        ],
    ),
    line(
        "arrows",
        Some("section-show"),
        &[
            (key(letter('V')), C::ToggleVelocity),
            (key(letter('M')), C::ToggleMomentum),
        ],
    ),
    line(
        "readouts",
        Some("section-show"),
        &[(key(letter('I')), C::CycleReadouts)],
    ),
    line(
        "center-of-mass",
        Some("section-show"),
        &[(key(letter('O')), C::ToggleCenterOfMass)],
    ),
    line(
        "trails",
        Some("section-show"),
        &[(key(letter('A')), C::ToggleTrails)],
    ),
    line(
        "palette",
        Some("section-show"),
        &[(key(K::F(3)), C::TogglePalette)],
    ),
    line(
        "com-view",
        Some("section-show"),
        &[(plain(letter('Z')), C::ToggleCenterOfMassView)],
    ),
    line("sound", None, &[(key(K::F(8)), C::ToggleSound)]),
    line(
        "next-collision",
        Some("section-show-collisions-tab"),
        &[(key(letter('J')), C::NextCollision)],
    ),
    line(
        "scrub",
        None,
        &[
            (plain(K::Comma), C::Scrub(-1)),
            (shifted(K::Comma), C::Scrub(-10)),
            (plain(K::Period), C::Scrub(1)),
            (shifted(K::Period), C::Scrub(10)),
        ],
    ),
    line(
        "restitution",
        Some("section-collisions"),
        &[
            (plain(letter('E')), C::NudgeLaw(Law::Restitution, Dir::Up)),
            (
                shifted(letter('E')),
                C::NudgeLaw(Law::Restitution, Dir::Down),
            ),
        ],
    ),
    line(
        "wall-restitution",
        Some("section-collisions"),
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
        "gravity",
        Some("section-collisions"),
        &[(key(letter('G')), C::ToggleGravity)],
    ),
    line(
        "new-discs",
        Some("section-new-discs"),
        &[
            (key(K::PageUp), C::StepNewRadius(Dir::Up)),
            (key(K::PageDown), C::StepNewRadius(Dir::Down)),
            (key(K::Home), C::StepNewMass(Dir::Up)),
            (key(K::End), C::StepNewMass(Dir::Down)),
        ],
    ),
    line(
        "delete",
        Some("section-selected-disc"),
        &[
            (key(K::Delete), C::DeleteSelected),
            (key(K::Backspace), C::DeleteSelected),
        ],
    ),
    line(
        "clear",
        Some("section-scene"),
        &[(key(letter('C')), C::Clear)],
    ),
    line("reset", None, &[(key(letter('R')), C::Reset)]),
    line(
        "presets",
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
        "new-box",
        Some("section-presets-last"),
        &[(ctrl(letter('N')), C::OpenEmpty)],
    ),
    line("undo", None, &[(ctrl(letter('Z')), C::Undo)]),
    line(
        "redo",
        None,
        &[
            (ctrl_shift(letter('Z')), C::Redo),
            (ctrl(letter('Y')), C::Redo),
        ],
    ),
    line("escape", None, &[(key(K::Escape), C::Escape)]),
    line(
        "save",
        Some("section-scene"),
        &[(ctrl(letter('S')), C::Save)],
    ),
    line(
        "export",
        Some("section-scene"),
        &[(key(letter('X')), C::Export)],
    ),
    line(
        "screenshot",
        Some("section-scene"),
        &[(key(K::F(12)), C::Screenshot)],
    ),
    line(
        "tabs",
        Some("section-tab-row"),
        &[
            (key(letter('T')), C::ShowTab(DockTab::Totals)),
            (key(letter('U')), C::ShowTab(DockTab::Collisions)),
            (key(letter('D')), C::ShowTab(DockTab::Momenta)),
            (key(K::F(4)), C::ShowTab(DockTab::Speeds)),
            // Every tab, in the row's order (a browser's own order too).
            (ctrl(K::Digit(1)), C::ShowTab(DockTab::Totals)),
            (ctrl(K::Digit(2)), C::ShowTab(DockTab::Collisions)),
            (ctrl(K::Digit(3)), C::ShowTab(DockTab::Discs)),
            (ctrl(K::Digit(4)), C::ShowTab(DockTab::Speeds)),
            (ctrl(K::Digit(5)), C::ShowTab(DockTab::Momenta)),
            (ctrl(K::Digit(6)), C::ShowTab(DockTab::Words)),
        ],
    ),
    mouse("tab-height"),
    line(
        "docks",
        Some("section-view"),
        &[(key(letter('S')), C::ToggleDocks)],
    ),
    Binding {
        name: "focus",
        control: None,
        trigger: Trigger::Panels,
        acts: &[],
    },
    Binding {
        name: "regions",
        control: None,
        trigger: Trigger::Panels,
        acts: &[],
    },
    line(
        "side",
        Some("section-controls"),
        &[(key(letter('L')), C::ToggleSide)],
    ),
    line(
        "scale",
        Some("section-view"),
        &[(key(K::F(2)), C::NextScale)],
    ),
    line(
        "method",
        Some("section-more-details"),
        &[
            (plain(letter('Y')), C::CycleMethod),
            (key(letter('B')), C::CycleBroadPhase),
            (key(letter('K')), C::CycleSubsteps),
        ],
    ),
    line(
        "fullscreen",
        Some("section-view"),
        &[(key(K::F(11)), C::Fullscreen)],
    ),
    line(
        "help",
        None,
        &[
            (key(letter('H')), C::ToggleHelp),
            (key(K::F(1)), C::ToggleHelp),
        ],
    ),
    line("quit", None, &[(ctrl(letter('Q')), C::Quit)]),
];

/// Keyboard pan speed, pixels per frame.
const PAN: f64 = 12.0;
/// One press of an arrow key aiming a disc (m/s).
const AIM: f64 = crate::app::model::keyboard::AIM_STEP;

/// The on-screen label of each command that has a button (its message in
/// `keys.ftl`): the buttons read it here, and the help names the control
/// after it.
pub static LABELS: &[(Command, &str)] = &[
    (C::TogglePause, "label-toggle-pause"),
    (C::Step, "label-step"),
    (C::Reset, "label-reset"),
    (C::Undo, "label-undo"),
    (C::Redo, "label-redo"),
    (C::Slower, "label-slower"),
    (C::Faster, "label-faster"),
    (C::TogglePresets, "label-toggle-presets"),
    (C::Fit, "label-fit"),
    (C::ToggleHelp, "label-toggle-help"),
    (C::NextCollision, "label-next-collision"),
    (C::Scrub(-1), "label-back"),
    (C::Scrub(1), "label-forward"),
    (C::DeleteSelected, "label-delete-selected"),
    (C::Save, "label-save"),
    (C::Clear, "label-clear"),
    (C::Export, "label-export"),
    (C::Screenshot, "label-screenshot"),
    (C::NextScale, "label-next-scale"),
    (C::ZoomIn, "label-zoom-in"),
    (C::ZoomOut, "label-zoom-out"),
    (C::Fullscreen, "label-fullscreen"),
    (C::ToggleDocks, "label-toggle-docks"),
    (C::ShowStart, "label-show-start"),
    (C::ToggleDrawer, "label-toggle-drawer"),
    (C::ShowAllControls, "label-show-all-controls"),
    (C::ReopenKept, "label-reopen-kept"),
    (C::ToggleSound, "label-toggle-sound"),
    (C::Describe, "label-describe"),
];
