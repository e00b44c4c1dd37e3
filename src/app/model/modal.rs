//! What a command means while something covers the world: the recovery
//! question, the start screen, or the help. Each lets through only what
//! answers it or changes the window itself; the rest waits.

use super::{Command, Sandbox};

impl Sandbox {
    /// What a command means while the recovery question is open: R and
    /// Esc answer it; what only changes the view goes through; the rest
    /// waits.
    pub(super) fn under_modal(&self, command: Command) -> Option<Command> {
        if !self.modal_open() {
            return self.under_help(command);
        }
        use Command::*;
        let question = self.recovery.offered.is_some();
        match command {
            Reset | RestoreRecovery if question => Some(RestoreRecovery),
            Escape | SetRecoveryAside if question => Some(SetRecoveryAside),
            // The start screen: a tile, a preset's key, or Esc for the
            // scene that is open.
            StartWith(_) | OpenPreset(_) | OpenEmpty | CloseStart if !question => Some(command),
            Escape if !question && self.panels.help_open => Some(ToggleHelp),
            Escape if !question => Some(CloseStart),
            Quit
            | Screenshot
            | Fullscreen
            | SetScale(_)
            | SetTabHeight(_)
            | KeepTabHeight
            | NextScale
            | SetTheme(_)
            | SetLanguage(_)
            | Describe
            | ToggleHelp
            | ToggleSound
            | Fit
            | ZoomIn
            | ZoomOut
            | ZoomAt { .. }
            | Pan(_)
            | Pinch { .. } => Some(command),
            _ => None,
        }
    }

    /// What a command means while the help is open: it covers the world,
    /// so nothing changes behind it (its keys scroll the list, where Home
    /// and Enter made a disc out of sight); Esc, H and its close button
    /// close it; the window's own settings (size, language, theme, sound,
    /// full screen), a screenshot (of the key list, for a handout) and
    /// quitting go through.
    fn under_help(&self, command: Command) -> Option<Command> {
        if !self.panels.help_open {
            return Some(command);
        }
        use Command::*;
        match command {
            Escape | ToggleHelp | Quit | Screenshot | Fullscreen | SetScale(_) | NextScale
            | SetTheme(_) | SetLanguage(_) | ToggleSound | Describe => Some(command),
            _ => None,
        }
    }
}
