//! Every key, declared once: which key (with modifiers) gives which
//! command, the keys as the help shows them, the help line, and the
//! on-screen control that does the same. The window's key handling, the
//! help window and the controls' tooltips read this table; a test holds the
//! README's key table against it.

use super::command::{Command, Dir, Law};
use super::DockTab;

/// A key, by what is printed on it (the window maps its key codes to these).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Key {
    Space,
    Tab,
    Escape,
    Delete,
    Backspace,
    Left,
    Right,
    Up,
    Down,
    PageUp,
    PageDown,
    Home,
    End,
    Equal,
    Minus,
    KpAdd,
    KpSubtract,
    LeftBracket,
    RightBracket,
    Comma,
    Period,
    /// The digit keys 0 … 9.
    Digit(u8),
    /// A letter, upper case.
    Letter(char),
    /// F1 … F12.
    F(u8),
}

/// Whether Shift must be up, down, or either.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shift {
    Up,
    Down,
    Either,
}

/// A key with its modifiers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Chord {
    pub key: Key,
    pub ctrl: bool,
    pub shift: Shift,
}

impl Chord {
    /// Whether the chord is pressed with these modifiers down.
    pub fn matches(&self, key: Key, ctrl: bool, shift: bool) -> bool {
        self.key == key
            && self.ctrl == ctrl
            && match self.shift {
                Shift::Up => !shift,
                Shift::Down => shift,
                Shift::Either => true,
            }
    }
}

/// When a key acts: once when pressed, or every frame while held.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Trigger {
    Press,
    Hold,
}

/// One line of the help: its keys (or mouse gesture), what they do, the
/// control that does the same, and the chords with their commands.
pub struct Binding {
    /// The keys as the help shows them ("E / Shift+E").
    pub keys: &'static str,
    /// What they do.
    pub help: &'static str,
    /// Where the on-screen control that does the same is, if any.
    pub control: Option<&'static str>,
    pub trigger: Trigger,
    /// Each chord and the command it gives.
    pub acts: &'static [(Chord, Command)],
}

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
        Some("View: Zoom + / −"),
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
        Some("Fit view"),
        &[(key(letter('F')), C::Fit)],
    ),
    line(
        "Space",
        "pause / resume",
        Some("Play / Pause"),
        &[(key(K::Space), C::TogglePause)],
    ),
    line(
        "N",
        "one step, paused",
        Some("Step"),
        &[(key(letter('N')), C::Step)],
    ),
    line(
        "[ / ]",
        "slower / faster",
        Some("« Slower, Faster »"),
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
        "J",
        "run to the next collision and pause at impact",
        Some("Show, Collisions tab"),
        &[(key(letter('J')), C::NextCollision)],
    ),
    line(
        ", / .",
        "back / forward through the recorded past; Shift: ×10",
        Some("◀ Back, Forward ▶"),
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
        Some("⟲ Reset"),
        &[(key(letter('R')), C::Reset)],
    ),
    line(
        "1 … 9, 0, P",
        "open a classroom preset / the preset menu",
        Some("Presets…"),
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
        Some("Undo"),
        &[(ctrl(letter('Z')), C::Undo)],
    ),
    line(
        "Ctrl+Shift+Z, Ctrl+Y",
        "redo it",
        Some("Redo"),
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
        Some("Scene: Save"),
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
        Some("View: Hide panels"),
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
        Some("? Help"),
        &[
            (key(letter('H')), C::ToggleHelp),
            (key(K::F(1)), C::ToggleHelp),
        ],
    ),
    line("Ctrl+Q", "quit", None, &[(ctrl(letter('Q')), C::Quit)]),
];

/// Keyboard pan speed, pixels per frame.
const PAN: f64 = 12.0;

/// The command `key` gives with these modifiers, pressed (`Trigger::Press`)
/// or held (`Trigger::Hold`).
pub fn command_for(key: Key, ctrl: bool, shift: bool, trigger: Trigger) -> Option<Command> {
    BINDINGS
        .iter()
        .filter(|b| b.trigger == trigger)
        .flat_map(|b| b.acts.iter())
        .find(|(chord, _)| chord.matches(key, ctrl, shift))
        .map(|(_, command)| command.clone())
}

/// The binding that gives `command`, if a key does.
pub fn binding_of(command: &Command) -> Option<&'static Binding> {
    BINDINGS
        .iter()
        .find(|b| b.acts.iter().any(|(_, c)| c == command))
}

/// The tooltip of a control that gives `command`: its keys and what they do
/// ("Space: pause / resume"); empty when no key gives it.
pub fn tooltip(command: &Command) -> String {
    binding_of(command).map_or_else(String::new, |b| format!("{}: {}", b.keys, b.help))
}

/// The bindings as the README's key table (Markdown).
#[cfg(test)]
pub fn markdown_table() -> String {
    let mut out = String::from("| Keys or mouse | Does | On screen |\n|---|---|---|\n");
    for b in BINDINGS {
        let keys = if mentions_the_mouse(b) {
            b.keys.to_string()
        } else {
            format!("`{}`", b.keys)
        };
        let help = b.help.replace('|', "\\|");
        let control = b.control.unwrap_or("");
        out.push_str(&format!("| {keys} | {help} | {control} |\n"));
    }
    out
}

/// Whether a line of the help is (also) about the mouse.
#[cfg(test)]
pub fn mentions_the_mouse(b: &Binding) -> bool {
    let keys = b.keys.to_lowercase();
    ["drag", "click", "wheel"].iter().any(|m| keys.contains(m))
}

/// Whether a key belongs to the browser, not to the page.
pub fn browser_keeps(binding: &Binding) -> bool {
    ["Ctrl+Q", "F11"].contains(&binding.keys)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_chord_gives_two_commands() {
        let chords: Vec<(Chord, Trigger)> = BINDINGS
            .iter()
            .flat_map(|b| b.acts.iter().map(move |(c, _)| (*c, b.trigger)))
            .collect();
        for (i, (a, ta)) in chords.iter().enumerate() {
            for (b, tb) in &chords[i + 1..] {
                let overlap = a.key == b.key
                    && a.ctrl == b.ctrl
                    && ta == tb
                    && (a.shift == b.shift || a.shift == Shift::Either || b.shift == Shift::Either);
                assert!(!overlap, "{a:?} and {b:?}");
            }
        }
    }

    #[test]
    fn keys_give_their_commands_and_tooltips_name_them() {
        let cmd = |k, ctrl, shift| command_for(k, ctrl, shift, Trigger::Press);
        assert_eq!(cmd(Key::Space, false, false), Some(Command::TogglePause));
        assert_eq!(
            cmd(Key::Letter('E'), false, true),
            Some(Command::NudgeLaw(Law::Restitution, Dir::Down))
        );
        assert_eq!(cmd(Key::Letter('Z'), true, true), Some(Command::Redo));
        assert_eq!(cmd(Key::Letter('Z'), true, false), Some(Command::Undo));
        assert_eq!(
            cmd(Key::Letter('Z'), false, false),
            Some(Command::ToggleCenterOfMassView)
        );
        assert_eq!(
            cmd(Key::Letter('Q'), false, false),
            None,
            "Q alone does nothing"
        );
        assert_eq!(
            cmd(Key::Digit(0), false, false),
            Some(Command::OpenPreset(9))
        );
        assert_eq!(tooltip(&Command::TogglePause), "Space: pause / resume");
        assert_eq!(tooltip(&Command::SetTheme(super::super::Theme::Light)), "");
        assert!(command_for(Key::Left, false, false, Trigger::Hold).is_some());
    }

    /// The README's key table is this table: `UPDATE_README=1 cargo test`
    /// writes it there.
    #[test]
    fn the_readme_key_table_is_the_bindings_table() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/README.md");
        let readme = std::fs::read_to_string(path).unwrap();
        let (start, end) = ("<!-- keys: start -->\n", "<!-- keys: end -->");
        let a = readme.find(start).expect("the README marks its key table") + start.len();
        let b = readme
            .find(end)
            .expect("the README marks its key table's end");
        let wanted = markdown_table();
        if readme[a..b] != wanted && std::env::var_os("UPDATE_README").is_some() {
            let updated = format!("{}{wanted}{}", &readme[..a], &readme[b..]);
            std::fs::write(path, updated).unwrap();
            return;
        }
        assert_eq!(
            readme[a..b],
            wanted,
            "the README's key table differs from the bindings: UPDATE_README=1 cargo test writes it"
        );
    }

    #[test]
    fn every_help_line_with_keys_has_a_chord_and_every_chord_its_line() {
        for b in BINDINGS {
            assert!(mentions_the_mouse(b) || !b.acts.is_empty(), "{}", b.keys);
            assert!(!b.help.is_empty());
        }
    }
}
