//! Every key, declared once: which key (with modifiers) gives which
//! command, the keys as the help shows them, the help line, and the
//! on-screen control that does the same. The window's key handling, the
//! help window and the controls' tooltips read this table; a test holds the
//! README's key table against it. The words are messages of `keys.ftl`
//! (`keys-<name>`, `help-<name>`, `label-…`, `section-…`), so the help and
//! the tooltips speak the window's language.

use super::command::Command;
use super::DockTab;
use crate::app::lang::text;

/// A key, by what is printed on it (the window maps its key codes to these).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Key {
    Space,
    Enter,
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

/// When a key acts: once when pressed, or every frame while held; or the
/// panels take it (Tab moves through the controls), and the help only says
/// so.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Trigger {
    Press,
    Hold,
    Panels,
}

/// One line of the help: its keys (or mouse gesture), what they do, the
/// control that does the same, and the chords with their commands.
pub struct Binding {
    /// Its name in the Fluent files: `keys-<name>` are the keys as the help
    /// shows them ("E / Shift+E"), `help-<name>` what they do.
    pub name: &'static str,
    /// The message naming the section of the on-screen control that does
    /// the same, if any.
    pub control: Option<&'static str>,
    pub trigger: Trigger,
    /// Each chord and the command it gives.
    pub acts: &'static [(Chord, Command)],
}

mod table;

impl Binding {
    /// The keys as the help shows them, in the window's language.
    pub fn keys(&self) -> String {
        text(&format!("keys-{}", self.name), &[])
    }

    /// What they do, in the window's language.
    pub fn help(&self) -> String {
        text(&format!("help-{}", self.name), &[])
    }
}

pub use table::{BINDINGS, LABELS};

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

/// The keys that give `command`, as the help writes them ("Ctrl+Z"), for
/// a message that names them; empty for a command without keys.
pub fn keys_of(command: &Command) -> String {
    binding_of(command).map(|b| b.keys()).unwrap_or_default()
}

/// The tooltip of a control that gives `command`: its keys and what they do
/// ("Space: pause / resume"); empty when no key gives it.
pub fn tooltip(command: &Command) -> String {
    binding_of(command)
        .filter(|b| !(cfg!(target_arch = "wasm32") && browser_keeps(b)))
        .map_or_else(String::new, |b| format!("{}: {}", b.keys(), b.help()))
}

/// A chord as the keyboard prints it ("T", "F4", "Ctrl+3"), in the
/// window's language; `None` for a key without a printed letter, digit
/// or F-number (the help's own lines name those).
pub fn chord_text(chord: &Chord) -> Option<String> {
    let key = match chord.key {
        Key::Letter(c) => c.to_string(),
        Key::Digit(d) => d.to_string(),
        Key::F(n) => format!("F{n}"),
        _ => return None,
    };
    let shift = match chord.shift {
        Shift::Down => format!("{}+", text("key-shift", &[])),
        Shift::Up | Shift::Either => String::new(),
    };
    let ctrl = if chord.ctrl {
        format!("{}+", text("key-ctrl", &[]))
    } else {
        String::new()
    };
    Some(format!("{ctrl}{shift}{key}"))
}

/// A tab's tooltip: the keys that show it, and only it ("U, Ctrl+2: show
/// this tab"); the help's line names every tab's keys at once.
pub fn tab_tooltip(tab: DockTab) -> String {
    let keys: Vec<String> = BINDINGS
        .iter()
        .flat_map(|b| b.acts.iter())
        .filter(|(_, c)| *c == Command::ShowTab(tab))
        .filter_map(|(chord, _)| chord_text(chord))
        .collect();
    text("tab-keys", &[("keys", keys.join(", ").into())])
}

/// The bindings as the README's key table (Markdown).
#[cfg(test)]
pub fn markdown_table() -> String {
    let mut out = String::from("| Keys or mouse | Does | On screen |\n|---|---|---|\n");
    for b in BINDINGS {
        let keys = if mentions_the_mouse(b) {
            b.keys()
        } else {
            format!("`{}`", b.keys())
        };
        let help = b.help().replace('|', "\\|");
        let control = control_of(b).unwrap_or_default();
        out.push_str(&format!("| {keys} | {help} | {control} |\n"));
    }
    out
}

/// Whether a line of the help is (also) about the mouse.
#[cfg(test)]
pub fn mentions_the_mouse(b: &Binding) -> bool {
    let keys = b.keys().to_lowercase();
    ["drag", "click", "wheel"].iter().any(|m| keys.contains(m))
}

/// The on-screen label of the button that gives `command`, if one does.
pub fn label(command: &Command) -> Option<String> {
    LABELS
        .iter()
        .find(|(c, _)| c == command)
        .map(|(_, id)| text(id, &[]))
}

/// Where a help line's keys have an on-screen twin: the labels of its
/// commands' buttons (from [`LABELS`]) after the section they are in
/// ("Selected disc › Delete"), or either alone. (The button's label
/// with its section in brackets, inside the help's own, read "(Delete
/// (Selected disc))".)
pub fn control_of(b: &Binding) -> Option<String> {
    let mut labels: Vec<String> = Vec::new();
    for (_, c) in b.acts {
        if let Some(l) = label(c).filter(|l| !labels.contains(l)) {
            labels.push(l);
        }
    }
    let section = b.control.map(|id| text(id, &[]));
    match (labels.is_empty(), section) {
        (false, Some(section)) => Some(format!("{section} › {}", labels.join(", "))),
        (false, None) => Some(labels.join(", ")),
        (true, section) => section,
    }
}

/// A control's label split into its icon (a first word of no letter or
/// digit: the "⟲" of "⟲ Reset") and its words; `None` and the whole label
/// where it has no icon.
pub fn icon_and_words(label: &str) -> (Option<&str>, &str) {
    match label.split_once(' ') {
        Some((icon, words)) if !icon.chars().any(char::is_alphanumeric) => (Some(icon), words),
        _ => (None, label),
    }
}

/// Whether a key belongs to the browser, not to the page: the page never
/// sees Ctrl+Q or Ctrl+N (a browser window of its own), F6 goes to the
/// address bar, F11 is the browser's full screen and F12 its developer
/// tools (the page's screenshot is a download, from *Scene*).
pub fn browser_keeps(binding: &Binding) -> bool {
    ["quit", "fullscreen", "new-box", "regions", "screenshot"].contains(&binding.name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::model::command::{Dir, Law};

    /// Where a key's button is, in every language, has no brackets of its
    /// own: the help puts it in brackets after what the key does, and a
    /// section in brackets within them read "(Apagar (Disco selecionado))".
    #[test]
    fn where_a_keys_button_is_needs_no_brackets_inside_the_helps() {
        use crate::app::lang::{set_language, Lang};
        let mut combined = 0;
        for lang in Lang::SHIPPED {
            set_language(lang);
            for b in BINDINGS {
                let control = control_of(b).unwrap_or_default();
                assert!(!control.contains(['(', ')']), "{lang:?}: {control}");
                combined += usize::from(control.contains('›'));
            }
        }
        set_language(Lang::En);
        assert!(combined > 0, "no button with its section: nothing tested");
    }

    /// Every tab has a key, `Ctrl` and its place in the row; each tab's
    /// tooltip names its own keys, in the window's language.
    #[test]
    fn ctrl_and_a_digit_show_the_rows_tabs_and_each_tab_names_its_keys() {
        for (n, tab) in DockTab::IN_ROW.into_iter().enumerate() {
            let digit = Key::Digit(n as u8 + 1);
            assert_eq!(
                command_for(digit, true, false, Trigger::Press),
                Some(Command::ShowTab(tab)),
                "Ctrl+{}",
                n + 1
            );
        }
        assert_eq!(tab_tooltip(DockTab::Totals), "T, Ctrl+1: show this tab");
        assert_eq!(tab_tooltip(DockTab::Speeds), "F4, Ctrl+4: show this tab");
        assert_eq!(tab_tooltip(DockTab::Words), "Ctrl+6: show this tab");
        use crate::app::lang::{set_language, Lang};
        set_language(Lang::De);
        let german = tab_tooltip(DockTab::Discs);
        set_language(Lang::En);
        assert_eq!(german, "Strg+3: diesen Reiter zeigen");
    }

    /// In the browser the page must keep its own Ctrl keys from the
    /// browser (Ctrl+S saved the page too): `web/impulse.js` lists them,
    /// and the list is every Ctrl chord of the table the browser lets the
    /// page have.
    #[test]
    fn the_browser_page_keeps_every_ctrl_key_of_the_table() {
        let js = include_str!("../../../../web/impulse.js");
        let line = js
            .lines()
            .find(|l| l.contains("const OWN_CTRL"))
            .expect("impulse.js lists the page's Ctrl keys");
        let listed: std::collections::BTreeSet<&str> = line.split('"').skip(1).step_by(2).collect();
        let code = |key: Key| match key {
            Key::Letter(c) => format!("Key{c}"),
            Key::Digit(d) => format!("Digit{d}"),
            other => format!("{other:?}"),
        };
        let wanted: std::collections::BTreeSet<String> = BINDINGS
            .iter()
            .filter(|b| !browser_keeps(b))
            .flat_map(|b| b.acts.iter())
            .filter(|(chord, _)| chord.ctrl)
            .map(|(chord, _)| code(chord.key))
            .collect();
        let listed: std::collections::BTreeSet<String> =
            listed.into_iter().map(str::to_string).collect();
        assert_eq!(listed, wanted);
    }

    /// The browser's own function keys (F6 the address bar, F11 full
    /// screen, F12 the developer tools) are left out of the page's help:
    /// a browser review found F12 listed as "screenshot into the output
    /// folder".
    #[test]
    fn the_browsers_function_keys_are_left_to_it() {
        let mut seen = 0;
        for b in BINDINGS {
            for (chord, _) in b.acts {
                if matches!(chord.key, Key::F(6 | 11 | 12)) {
                    seen += 1;
                    assert!(browser_keeps(b), "{}", b.name);
                }
            }
        }
        assert!(seen >= 2, "{seen}");
        // F6 is read by the window itself (its line has no chords).
        let regions = BINDINGS.iter().find(|b| b.name == "regions").unwrap();
        assert!(browser_keeps(regions));
    }

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
        assert_eq!(cmd(Key::Digit(7), true, false), None, "Ctrl+7 does nothing");
        assert_eq!(
            cmd(Key::Letter('S'), false, false),
            Some(Command::ToggleDocks)
        );
        assert_eq!(
            cmd(Key::Digit(0), false, false),
            Some(Command::OpenPreset(9))
        );
        assert_eq!(tooltip(&Command::TogglePause), "Space: pause / resume");
        assert_eq!(tooltip(&Command::SetTheme(super::super::Theme::Light)), "");
        assert!(command_for(Key::Left, false, false, Trigger::Hold).is_some());
    }

    /// The key table of the user's documents (`docs/keys.md`, which the
    /// README links) is this table: `UPDATE_README=1 cargo test` writes it
    /// there.
    #[test]
    fn the_documented_key_table_is_the_bindings_table() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/keys.md");
        let doc = std::fs::read_to_string(path).unwrap();
        let (start, end) = ("<!-- keys: start -->\n", "<!-- keys: end -->");
        let a = doc.find(start).expect("docs/keys.md marks its key table") + start.len();
        let b = doc
            .find(end)
            .expect("docs/keys.md marks its key table's end");
        let wanted = markdown_table();
        if doc[a..b] != wanted && std::env::var_os("UPDATE_README").is_some() {
            let updated = format!("{}{wanted}{}", &doc[..a], &doc[b..]);
            std::fs::write(path, updated).unwrap();
            return;
        }
        assert_eq!(
            doc[a..b],
            wanted,
            "docs/keys.md's key table differs from the bindings: UPDATE_README=1 cargo test writes it"
        );
    }

    #[test]
    fn every_help_line_with_keys_has_a_chord_and_every_chord_its_line() {
        for b in BINDINGS {
            let panels = b.trigger == Trigger::Panels;
            assert!(
                mentions_the_mouse(b) || panels || !b.acts.is_empty(),
                "{}",
                b.name
            );
        }
    }

    #[test]
    fn every_binding_and_label_has_its_words_in_english() {
        let english = crate::app::lang::Words::new(crate::app::lang::Lang::En);
        for b in BINDINGS {
            for id in [format!("keys-{}", b.name), format!("help-{}", b.name)] {
                assert!(english.has(&id), "{id}");
            }
            if let Some(section) = b.control {
                assert!(english.has(section), "{section}");
            }
        }
        for (_, id) in LABELS {
            assert!(english.has(id), "{id}");
        }
    }
}
