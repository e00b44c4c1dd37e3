//! What the window remembers between runs: the language the person chose,
//! whether they turned sound on, the text size, the theme and the open
//! tab's height (a teacher sets the projector's once). A small TOML file, `settings.toml`,
//! beside the recovery file (`$XDG_STATE_HOME/impulse/`, see
//! [`super::recovery::folder`]); in the browser the same name in the page's
//! local storage. Tests isolate it the way they isolate recovery (their own
//! `XDG_STATE_HOME`). A file that cannot be read is reported once and the
//! defaults hold; a write that fails is reported and nothing else changes.

use super::recovery::keep;
use super::Theme;
use crate::app::lang::{tr, Lang};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The settings file's name.
pub const FILE_NAME: &str = "settings.toml";

/// What is remembered.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
// Unknown fields are passed over, so that a file written by a newer
// Impulse still gives an older one its language.
#[serde(default)]
pub struct Settings {
    /// The language chosen in View (a tag: "es", "pt-BR"); none: the
    /// system's or the browser's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub language: Option<String>,
    /// Sound was turned on.
    pub sound: bool,
    /// The size of text and controls chosen in View or with F2.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub text_size: Option<f32>,
    /// The theme chosen in View.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theme: Option<Theme>,
    /// The open tab's height (px) its top edge was last set to; none: the
    /// tab's own.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tab_height: Option<f32>,
}

/// The settings and where they are kept.
#[derive(Clone, Debug)]
pub struct Remembered {
    path: PathBuf,
    pub settings: Settings,
}

impl Remembered {
    /// The settings kept in `dir`, or the defaults and what was wrong.
    pub fn load(dir: &Path) -> (Remembered, Option<String>) {
        let path = dir.join(FILE_NAME);
        let read = keep::read(&path).map(|text| {
            text.map_err(|e| e.to_string())
                .and_then(|t| toml::from_str::<Settings>(&t).map_err(|e| e.message().to_string()))
        });
        let (settings, problem) = match read {
            None => (Settings::default(), None),
            Some(Ok(settings)) => (settings, None),
            Some(Err(e)) => (
                Settings::default(),
                Some(tr!(
                    "settings-unreadable",
                    file = path.display().to_string(),
                    error = e
                )),
            ),
        };
        (Remembered { path, settings }, problem)
    }

    /// The language remembered, if it is one Impulse speaks.
    pub fn language(&self) -> Option<Lang> {
        self.settings.language.as_deref().and_then(Lang::from_tag)
    }

    /// Changes the settings by `change` and, if that changed them, writes
    /// them; what went wrong, if anything.
    pub fn change(&mut self, change: impl FnOnce(&mut Settings)) -> Option<String> {
        let before = self.settings.clone();
        change(&mut self.settings);
        if self.settings == before {
            return None;
        }
        self.save()
    }

    /// Writes the settings (atomically); what went wrong, if anything.
    pub fn save(&self) -> Option<String> {
        let text = toml::to_string(&self.settings).unwrap_or_default();
        keep::write(&self.path, &text).err().map(|e| {
            tr!(
                "settings-not-saved",
                place = keep::place(&self.path),
                error = e.to_string()
            )
        })
    }
}

/// The language to speak: the command line's, else the one chosen before,
/// else the system's (or the browser's), else English.
pub fn choose_language(
    pinned: Option<Lang>,
    remembered: Option<Lang>,
    system: Option<Lang>,
) -> Lang {
    pinned.or(remembered).or(system).unwrap_or(Lang::En)
}

/// The language a window starting now speaks ([`choose_language`], the
/// settings read from `dir`, a problem with them left for the sandbox to
/// report).
pub fn language_at_start(dir: &Path, pinned: Option<Lang>, system: Option<Lang>) -> Lang {
    let (remembered, _) = Remembered::load(dir);
    choose_language(pinned, remembered.language(), system)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_are_remembered_and_a_bad_file_keeps_the_defaults() {
        let dir = tempfile::tempdir().unwrap();
        let (mut r, problem) = Remembered::load(dir.path());
        assert_eq!((r.settings.clone(), problem), (Settings::default(), None));
        r.settings.language = Some("pt-BR".into());
        r.settings.sound = true;
        r.settings.text_size = Some(2.0);
        r.settings.theme = Some(Theme::Light);
        r.settings.tab_height = Some(320.0);
        assert_eq!(r.save(), None);
        let (again, problem) = Remembered::load(dir.path());
        assert_eq!(problem, None);
        assert_eq!(again.language(), Some(Lang::PtBr));
        assert_eq!(again.settings, r.settings);
        // A file from a newer Impulse, with a field this one does not know.
        let text = std::fs::read_to_string(dir.path().join(FILE_NAME)).unwrap();
        std::fs::write(dir.path().join(FILE_NAME), text + "later = 1\n").unwrap();
        let (newer, problem) = Remembered::load(dir.path());
        assert_eq!((newer.settings, problem), (r.settings.clone(), None));
        std::fs::write(dir.path().join(FILE_NAME), "theme = \"dim\"\n").unwrap();
        let (bad, problem) = Remembered::load(dir.path());
        assert_eq!(bad.settings, Settings::default());
        assert!(problem.unwrap().contains(FILE_NAME));
    }

    #[test]
    fn a_change_is_written_only_when_it_changes_something() {
        let dir = tempfile::tempdir().unwrap();
        let (mut r, _) = Remembered::load(dir.path());
        assert_eq!(r.change(|s| s.sound = false), None);
        assert!(!dir.path().join(FILE_NAME).exists(), "nothing changed");
        assert_eq!(r.change(|s| s.text_size = Some(1.5)), None);
        let (again, _) = Remembered::load(dir.path());
        assert_eq!(again.settings.text_size, Some(1.5));
    }

    #[test]
    fn the_text_size_and_theme_chosen_are_where_the_next_start_opens() {
        use crate::app::model::{tests::sandbox_with, Command};
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_with(dir.path(), "preset-4-glancing.toml", true, 0.0);
        assert_eq!((s.panels.scale, s.panels.theme), (1.0, Theme::Dark));
        s.apply(Command::NextScale);
        s.apply(Command::NextScale);
        s.apply(Command::SetTheme(Theme::Light));
        let again = sandbox_with(dir.path(), "preset-4-glancing.toml", true, 0.0);
        assert_eq!(
            (again.panels.scale, again.panels.theme),
            (2.0, Theme::Light)
        );
        s.apply(Command::SetScale(1.7));
        let (r, _) = Remembered::load(dir.path());
        assert_eq!(r.settings.text_size, Some(1.7));
        // A number outside the slider's range is kept as the window took it.
        s.apply(Command::SetScale(9.0));
        let (r, _) = Remembered::load(dir.path());
        assert_eq!(r.settings.text_size, Some(s.panels.scale));
        assert!(s.panels.scale <= 2.5);
    }

    #[test]
    fn the_tab_height_set_is_where_the_next_start_opens_once_let_go() {
        use crate::app::model::{tests::sandbox_with, Command};
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_with(dir.path(), "preset-4-glancing.toml", true, 0.0);
        assert_eq!(s.panels.tab_height, None);
        // Dragged: written once, when let go, not at every step.
        s.apply(Command::SetTabHeight(Some(250.0)));
        s.apply(Command::SetTabHeight(Some(300.0)));
        assert_eq!(Remembered::load(dir.path()).0.settings.tab_height, None);
        s.apply(Command::KeepTabHeight);
        let again = sandbox_with(dir.path(), "preset-4-glancing.toml", true, 0.0);
        assert_eq!(again.panels.tab_height, Some(300.0));
        // Back to the tab's own height, and so at the next start.
        s.apply(Command::SetTabHeight(None));
        s.apply(Command::KeepTabHeight);
        let again = sandbox_with(dir.path(), "preset-4-glancing.toml", true, 0.0);
        assert_eq!(again.panels.tab_height, None);
    }

    #[test]
    fn the_command_line_comes_first_then_the_choice_then_the_system() {
        use Lang::*;
        assert_eq!(choose_language(Some(En), Some(De), Some(Fr)), En);
        assert_eq!(choose_language(None, Some(De), Some(Fr)), De);
        assert_eq!(choose_language(None, None, Some(Fr)), Fr);
        assert_eq!(choose_language(None, None, None), En);
    }
}
