//! The page's accessible mirror (the browser): real HTML controls beside
//! the canvas for the main commands, named from the bindings table in the
//! window's language, so that a screen reader and the keyboard reach what
//! the canvas draws. The model says what the mirror holds
//! ([`Sandbox::mirror`]); `web/impulse.js` builds it and sends back which
//! control was used ([`Mirror::command`]).

#![cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]

use super::bindings::{binding_of, icon_and_words, keys_of, label, tooltip, Key};
use super::scenes::preset_labels;
use super::{Command, Sandbox};
use crate::app::lang::{language, native_name, tr, Lang};
use serde::Serialize;

/// The commands the mirror offers as buttons, in its order.
pub const MIRROR_COMMANDS: [Command; 6] = [
    Command::TogglePause,
    Command::Step,
    Command::Reset,
    Command::NextCollision,
    Command::ToggleSound,
    Command::Describe,
];

/// One button of the mirror.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MirrorButton {
    /// Its accessible name (the on-screen button's label).
    pub label: String,
    /// What it does and its key, as the tooltip says.
    pub hint: String,
    /// Its key in the DOM's words, for `aria-keyshortcuts`.
    pub shortcut: String,
    /// For a switch: whether it is on (`aria-pressed`).
    pub pressed: Option<bool>,
}

/// A list to choose from (presets, languages).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MirrorChoice {
    pub label: String,
    pub options: Vec<String>,
    /// The option shown as chosen.
    pub chosen: Option<usize>,
}

/// Everything the mirror holds.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Mirror {
    /// The page's language tag (`<html lang>`).
    pub lang: String,
    /// The region's name ("Impulse: controls").
    pub title: String,
    /// The canvas's name: what it is and the key that lists the keys.
    pub canvas: String,
    pub buttons: Vec<MirrorButton>,
    pub presets: MirrorChoice,
    pub languages: MirrorChoice,
    /// The live region's name.
    pub said: String,
}

/// A DOM `KeyboardEvent.key` name for a key, as `aria-keyshortcuts` wants
/// (not words: the same in every language).
fn dom_key(key: Key) -> String {
    match key {
        // not words: the DOM's key names below
        Key::Space => "Space".into(), // not words: a DOM key name
        Key::Enter => "Enter".into(), // not words: a DOM key name
        Key::Letter(c) => c.to_string(),
        Key::F(n) => format!("F{n}"),
        Key::Digit(d) => d.to_string(),
        Key::Escape => "Escape".into(), // not words: a DOM key name
        other => format!("{other:?}"),
    }
}

impl Sandbox {
    /// What the page's mirror holds now.
    pub fn mirror(&self) -> Mirror {
        let buttons = MIRROR_COMMANDS
            .iter()
            .map(|c| MirrorButton {
                // Play or Pause, what a press does now: "Play / Pause" read
                // as "not pressed" said neither which nor what.
                label: match c {
                    Command::TogglePause if self.clock.paused => tr!("play"),
                    Command::TogglePause => tr!("pause"),
                    // Without the icon before the words ("⟲ Reset" was
                    // read "anticlockwise open circle arrow Reset").
                    _ => icon_and_words(&label(c).unwrap_or_default()).1.to_string(),
                },
                hint: tooltip(c),
                shortcut: binding_of(c)
                    .and_then(|b| b.acts.iter().find(|(_, a)| a == c))
                    .map(|(chord, _)| dom_key(chord.key))
                    .unwrap_or_default(),
                pressed: match c {
                    Command::ToggleSound => Some(self.session.sound.on),
                    _ => None,
                },
            })
            .collect();
        let current = language();
        Mirror {
            lang: current.code().to_string(),
            title: tr!("mirror-title"),
            canvas: tr!("mirror-canvas", keys = keys_of(&Command::ToggleHelp)),
            buttons,
            presets: MirrorChoice {
                label: label(&Command::TogglePresets).unwrap_or_default(),
                options: preset_labels(),
                chosen: None,
            },
            languages: MirrorChoice {
                // A label of its own here, capitalised ("language" follows
                // the drop-down on screen).
                label: capitalised(&tr!("language-label")),
                options: Lang::SHIPPED.iter().map(|l| native_name(*l)).collect(),
                chosen: Lang::SHIPPED.iter().position(|l| *l == current),
            },
            said: tr!("mirror-said"),
        }
    }
}

/// `text` with its first letter a capital.
fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars.next().map_or_else(String::new, |first| {
        first.to_uppercase().chain(chars).collect()
    })
}

impl Mirror {
    /// The command a control of the mirror gives: button `index` (list 0),
    /// preset `index` (list 1) or language `index` (list 2).
    pub fn command(list: u32, index: usize) -> Option<Command> {
        match list {
            0 => MIRROR_COMMANDS.get(index).cloned(),
            1 => (index < super::scenes::PRESETS.len()).then_some(Command::OpenPreset(index)),
            2 => Lang::SHIPPED.get(index).map(|l| Command::SetLanguage(*l)),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::sandbox_in;
    use super::*;

    #[test]
    fn the_mirror_is_named_from_the_bindings_in_the_windows_language() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
        let m = s.mirror();
        assert_eq!(m.lang, "en");
        let names: Vec<&str> = m.buttons.iter().map(|b| b.label.as_str()).collect();
        // What a press does now, not "Play / Pause, not pressed"; no icon
        // read aloud ("⟲ Reset").
        assert_eq!(names[0], "Play", "paused");
        assert_eq!(m.buttons[0].pressed, None);
        assert!(names.contains(&"Reset"), "{names:?}");
        assert!(names.contains(&"Next collision"));
        assert_eq!(m.buttons[0].shortcut, "Space");
        assert_eq!(m.languages.label, "Language");
        assert!(m.canvas.contains("H, F1 or ?"), "{}", m.canvas);
        s.apply(Command::TogglePause);
        assert_eq!(s.mirror().buttons[0].label, "Pause", "running");
        assert!(m.buttons[3].hint.starts_with("J: "));
        assert_eq!(m.presets.options.len(), super::super::scenes::PRESETS.len());
        assert_eq!(Mirror::command(0, 3), Some(Command::NextCollision));
        assert_eq!(Mirror::command(2, 1), Some(Command::SetLanguage(Lang::Es)));
        assert_eq!(Mirror::command(0, 99), None);
        s.apply(Command::SetLanguage(Lang::Es));
        let m = s.mirror();
        assert_eq!(m.lang, "es");
        assert_eq!(m.languages.chosen, Some(1));
        assert_eq!(
            s.take_announcements().last().map(String::as_str),
            Some("Idioma: Español"),
            "the switch is said in the new language"
        );
        assert_eq!(s.message(), Some("Idioma: Español"), "and shown in it");
        assert_ne!(m.buttons[3].label, "Next collision", "in Spanish");
        crate::app::lang::set_language(Lang::En);
    }
}
