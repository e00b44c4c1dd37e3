//! Never lose work: every few seconds, while the person has unsaved
//! changes, the sandbox is written, atomically, to a recovery file; a
//! window that closes with its work saved removes it, and one that closes
//! with work unsaved writes it a last time, so a file that is still there
//! at the next start means the last session ended with work in it (a quit
//! without saving, a crash, a killed process, a power cut), and the window
//! offers to restore it: `R` restores, `Esc` sets it aside
//! (renamed, not deleted). The simulation waits while it asks. In the
//! browser nothing is asked: a reload or a return reopens the kept sandbox,
//! and a shared link sets it aside (its own key, [`KEPT_NAME`]) for the
//! menu's "Reopen my last sandbox".
//!
//! The file is `recovery.toml` in `$XDG_STATE_HOME/impulse/` (else
//! `~/.local/state/impulse/`, else the output folder). A write that fails (a
//! full disk, a read-only folder) is reported once in the window and on the
//! terminal, and tried again at the next interval; nothing else changes.
//!
//! In the browser the same names are keys of the page's local storage
//! ([`keep`]); a scene too large for it is reported the same way.

use super::Sandbox;
use crate::app::lang::tr;
use impulse::Scene;
use std::path::{Path, PathBuf};

/// Seconds between autosaves, unless `--autosave` says otherwise.
pub const DEFAULT_EVERY: f64 = 5.0;
/// The recovery file's name.
pub const FILE_NAME: &str = "recovery.toml";
/// Where the browser keeps the sandbox a shared link set aside.
pub const KEPT_NAME: &str = "last-sandbox.toml";
/// Where a recovery the user set aside goes (the previous one is replaced).
pub const SET_ASIDE_NAME: &str = "recovery-set-aside.toml";

/// The autosave state of a window.
pub struct Recovery {
    path: PathBuf,
    /// Seconds between saves; 0 turns autosave off.
    every: f64,
    /// When the last save was tried (window clock, s).
    last_try: f64,
    /// The state hash last written, to skip saves when nothing moved.
    last_hash: Option<u64>,
    /// Saves written this session.
    pub saves: u64,
    /// The last failure, reported once until it changes or a save works.
    pub error: Option<String>,
    /// A recovery found at start, waiting for the user's answer.
    pub offered: Option<Scene>,
    /// In the browser, opened from a shared link: the sandbox the page
    /// kept, left in storage and reachable from the menu ("Reopen my last
    /// sandbox"); autosave waits for a change of the person's.
    pub aside: Option<Scene>,
}

/// Where recovery files live: the per-user state folder, else `fallback`.
pub fn folder(fallback: &Path) -> PathBuf {
    let from_env = |name: &str| std::env::var_os(name).filter(|v| !v.is_empty());
    if let Some(state) = from_env("XDG_STATE_HOME") {
        return PathBuf::from(state).join("impulse");
    }
    if let Some(home) = from_env("HOME") {
        return PathBuf::from(home).join(".local/state/impulse");
    }
    fallback.to_path_buf()
}

impl Recovery {
    /// Autosave into `dir` every `every` seconds (0: never). A readable
    /// recovery already there is offered; an unreadable one is set aside
    /// and reported in the returned message.
    pub fn new(dir: &Path, every: f64) -> (Recovery, Option<String>) {
        let path = dir.join(FILE_NAME);
        let mut recovery = Recovery {
            path,
            every,
            last_try: 0.0,
            last_hash: None,
            saves: 0,
            error: None,
            offered: None,
            aside: None,
        };
        let mut message = None;
        let origin = recovery.path.display().to_string();
        let found = keep::read(&recovery.path).map(|text| {
            text.map_err(|e| e.to_string())
                .and_then(|text| Scene::parse(&text, &origin).map_err(|e| e.to_string()))
        });
        if let Some(found) = found {
            match found {
                Ok(scene) => recovery.offered = Some(scene),
                Err(e) => {
                    message = Some(match recovery.set_aside() {
                        Ok(to) => tr!(
                            "recovery-unreadable-moved",
                            file = to.display().to_string(),
                            error = e
                        ),
                        Err(why) => tr!("recovery-unreadable-kept", error = why.to_string()),
                    });
                }
            }
        }
        (recovery, message)
    }

    /// The recovery file.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Whether a save is due at window time `now`: autosave is on, the
    /// interval has passed and no offer waits for an answer.
    pub fn due(&self, now: f64) -> bool {
        self.every > 0.0 && self.offered.is_none() && now - self.last_try >= self.every
    }

    /// Whether the state `hash` differs from the one last written.
    pub fn changed(&self, hash: u64) -> bool {
        self.last_hash != Some(hash)
    }

    /// Nothing changed at `now`: the next look is an interval later.
    pub fn skip(&mut self, now: f64) {
        self.last_try = now;
    }

    /// Writes `text` (the scene at state `hash`) atomically; returns a
    /// message when it failed with an error not reported before.
    pub fn save(&mut self, now: f64, hash: u64, text: &str) -> Option<String> {
        self.last_try = now;
        let written = keep::write(&self.path, text);
        match written {
            Ok(()) => {
                self.saves += 1;
                self.last_hash = Some(hash);
                self.error = None;
                None
            }
            Err(e) => {
                let message = tr!(
                    "autosave-failed",
                    place = keep::place(&self.path),
                    error = e.to_string()
                );
                let new = self.error.as_deref() != Some(message.as_str());
                self.error = Some(message.clone());
                new.then_some(message)
            }
        }
    }

    /// The user declined the offer: the file is kept under another name.
    pub fn set_aside(&mut self) -> std::io::Result<PathBuf> {
        self.offered = None;
        let to = self.path.with_file_name(SET_ASIDE_NAME);
        keep::rename(&self.path, &to)?;
        Ok(to)
    }

    /// The user restored it: the scene to open. The file stays until the
    /// next autosave replaces it.
    pub fn take_offer(&mut self) -> Option<Scene> {
        self.offered.take()
    }

    /// Nothing is left to keep (the work was saved): the file goes, so the
    /// next start does not ask.
    pub fn forget(&mut self) {
        if self.last_hash.take().is_some() {
            keep::remove(&self.path);
        }
    }

    /// Whether autosave is on (`--autosave 0` turns it off).
    pub fn enabled(&self) -> bool {
        self.every > 0.0
    }

    /// The window closes with nothing unsaved: nothing to recover next
    /// time.
    pub fn finish(&mut self) {
        if self.enabled() && self.offered.is_none() {
            keep::remove(&self.path);
        }
    }
}

/// Where the recovery text is kept: files on the desktop.
#[cfg(not(target_arch = "wasm32"))]
pub(super) mod keep {
    use std::path::Path;

    /// The text at `path`: `None` when there is none, an error when it
    /// cannot be read.
    pub fn read(path: &Path) -> Option<std::io::Result<String>> {
        path.exists().then(|| std::fs::read_to_string(path))
    }

    /// Writes `text` to `path` atomically and durably (folder created).
    pub fn write(path: &Path, text: &str) -> std::io::Result<()> {
        path.parent()
            .map_or(Ok(()), std::fs::create_dir_all)
            .and_then(|()| crate::files::write_durably(path, text.as_bytes()))
    }

    pub fn rename(from: &Path, to: &Path) -> std::io::Result<()> {
        std::fs::rename(from, to)
    }

    pub fn remove(path: &Path) {
        let _ = std::fs::remove_file(path);
    }

    /// `path` in a message.
    pub fn place(path: &Path) -> String {
        path.display().to_string()
    }
}

/// Where the recovery text is kept: the page's local storage in the
/// browser, the paths being its keys.
#[cfg(target_arch = "wasm32")]
pub(super) mod keep {
    use crate::web;
    use std::path::Path;

    fn key(path: &Path) -> String {
        format!("impulse:{}", path.display())
    }

    pub fn read(path: &Path) -> Option<std::io::Result<String>> {
        web::storage_get(&key(path)).map(Ok)
    }

    pub fn write(path: &Path, text: &str) -> std::io::Result<()> {
        web::storage_set(&key(path), text).map_err(std::io::Error::other)
    }

    pub fn rename(from: &Path, to: &Path) -> std::io::Result<()> {
        let text = web::storage_get(&key(from)).unwrap_or_default();
        web::storage_set(&key(to), &text).map_err(std::io::Error::other)?;
        web::storage_remove(&key(from));
        Ok(())
    }

    pub fn remove(path: &Path) {
        web::storage_remove(&key(path));
    }

    pub fn place(_path: &Path) -> String {
        crate::app::lang::tr!("browser-storage")
    }
}

impl Sandbox {
    /// Whether the sandbox is worth keeping now: on the desktop only while
    /// something the person made is unsaved (with nothing of theirs to
    /// lose, the next start need not ask); in the browser always, since a
    /// reload or a return reopens it, but not a shared link's scene until
    /// the person changes it (the kept sandbox stays).
    pub fn worth_keeping(&self) -> bool {
        if cfg!(target_arch = "wasm32") {
            // Nothing chosen yet on the start screen: a reload shows it again.
            !self.panels.start_open && (self.recovery.aside.is_none() || self.open.unsaved)
        } else {
            self.open.unsaved
        }
    }

    /// Writes the recovery file when a save is due, the state moved and it
    /// is worth keeping.
    pub(super) fn autosave(&mut self) {
        let now = self.session.now;
        if !self.recovery.due(now) {
            return;
        }
        if !self.worth_keeping() {
            self.recovery.skip(now);
            self.recovery.forget();
            return;
        }
        let hash = self.world.state_hash();
        if !self.recovery.changed(hash) {
            return self.recovery.skip(now);
        }
        let text = self.current_scene().to_toml();
        if let Some(problem) = self.recovery.save(now, hash, &text) {
            self.report(problem);
        }
    }

    /// The window closes. Unsaved work is written one last time and left
    /// for the next start to offer: a quit (Ctrl+Q, the window's close
    /// button) with changes not saved loses nothing, and asks nothing now.
    /// With nothing unsaved the file goes.
    pub fn on_close(&mut self) {
        let unanswered = self.recovery.offered.is_some();
        if self.recovery.enabled() && !unanswered && self.worth_keeping() {
            let (now, hash) = (self.session.now, self.world.state_hash());
            let text = self.current_scene().to_toml();
            if let Some(problem) = self.recovery.save(now, hash, &text) {
                eprintln!("impulse: {problem}");
            }
            return;
        }
        self.recovery.finish();
    }

    /// Opens the session that was offered (its Restore button, or `R`).
    pub(super) fn restore_recovery(&mut self) {
        if let Some(scene) = self.recovery.take_offer() {
            let origin = tr!(
                "origin-recovered",
                file = self.recovery.path().display().to_string()
            );
            let restored = self.open_scene(scene, origin).is_ok(); // a failure is reported
                                                                   // Kept nowhere but in the recovery file: still unsaved work.
            self.open.unsaved = true;
            // The kept sandbox is what the person wanted: no start screen.
            self.panels.start_open = false;
            // Back as it was left, paused, and said: it ran on at once,
            // with nothing to say it was back.
            self.panels.paused_by_modal = false;
            self.clock.paused = true;
            if restored {
                self.toast(tr!("recovery-restored", name = self.scene_name()));
            }
        }
    }

    /// Moves the offered session's file aside (its button, or `Esc`).
    pub(super) fn set_recovery_aside(&mut self) {
        if self.recovery.offered.is_none() {
            return;
        }
        match self.recovery.set_aside() {
            Ok(to) => self.toast(tr!("recovery-kept-in", file = to.display().to_string())),
            Err(e) => self.report(tr!("recovery-not-set-aside", error = e.to_string())),
        }
        self.resume_after_modal();
    }

    /// The browser's kept sandbox, set aside while a shared link's scene is
    /// open: opened again (the menu's "Reopen my last sandbox"); its own
    /// copy goes, since it is the sandbox again.
    pub(super) fn reopen_kept(&mut self) {
        if let Some(scene) = self.recovery.aside.clone() {
            let origin = tr!("origin-kept");
            if self.open_scene(scene, origin).is_ok() {
                self.recovery.aside = None;
                self.open.unsaved = true;
                self.panels.presets_open = false;
                keep::remove(&self.recovery.path.with_file_name(KEPT_NAME));
            }
        }
    }

    /// A sandbox set aside by an earlier shared link, if one is kept.
    fn kept_aside(&self) -> Option<Scene> {
        let path = self.recovery.path.with_file_name(KEPT_NAME);
        let text = keep::read(&path)?.ok()?;
        Scene::parse(&text, &path.display().to_string()).ok()
    }

    /// In the browser the kept sandbox reopens without a question: a
    /// reload or a return is no accident. With a shared link it is set
    /// aside instead, for the menu.
    pub(super) fn reopen_in_browser(&mut self, from_link: bool) {
        if !from_link {
            self.recovery.aside = self.kept_aside();
        }
        let Some(scene) = self.recovery.offered.take() else {
            return;
        };
        if from_link {
            // Kept under a name of its own as well, so the link's scene,
            // once changed and autosaved, never replaces it.
            if let Err(e) = keep::write(
                &self.recovery.path.with_file_name(KEPT_NAME),
                &scene.to_toml(),
            ) {
                self.report(tr!("kept-not-set-aside", error = e.to_string()));
            }
            self.recovery.aside = Some(scene);
            return;
        }
        let origin = tr!("origin-kept");
        if self.open_scene(scene, origin).is_ok() {
            self.open.unsaved = true;
            self.panels.start_open = false;
        }
    }

    /// The line shown while an earlier session is offered.
    pub fn recovery_prompt(&self) -> Option<String> {
        self.recovery.offered.as_ref().map(|scene| {
            let lang = crate::app::lang::language().code();
            let name = scene
                .name_in(lang)
                .map_or_else(|| tr!("scene-untitled"), str::to_string);
            let n = scene.particles.len();
            if cfg!(target_arch = "wasm32") {
                // A browser tab is closed, never quit: its sandbox is kept.
                tr!("recovery-question-browser", name = name, discs = n)
            } else {
                tr!("recovery-question", name = name, discs = n)
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = "[world]\nsize = [4.0, 4.0]\n\n[[particles]]\npos = [1.0, 1.0]\nvel = [0.0, 0.0]\nmass = 1.0\nradius = 0.5\n";

    #[test]
    fn saves_when_due_offers_after_an_abrupt_end_and_clears_after_a_normal_one() {
        let dir = tempfile::tempdir().unwrap();
        let (mut r, message) = Recovery::new(dir.path(), 5.0);
        assert!(message.is_none() && r.offered.is_none());
        assert!(r.due(5.0), "first save after one interval");
        assert!(!r.due(4.0), "not before");
        assert_eq!(r.save(5.0, 1, SCENE), None);
        assert_eq!(r.saves, 1);
        assert!(!r.due(9.0) && r.due(10.0));
        assert!(!r.changed(1), "nothing moved: no save");
        assert!(r.changed(2));
        // The process dies here: the next start finds the file.
        let (mut next, _) = Recovery::new(dir.path(), 5.0);
        let offered = next.offered.clone().expect("offered");
        assert_eq!(offered.particles.len(), 1);
        assert!(!next.due(100.0), "no autosave over an unanswered offer");
        assert!(next.take_offer().is_some());
        assert!(next.due(100.0));
        next.finish();
        assert!(
            !next.path().exists(),
            "a normal close leaves nothing to recover"
        );
    }

    #[test]
    fn declining_keeps_the_file_aside_and_a_broken_one_is_moved_not_lost() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join(FILE_NAME), SCENE).unwrap();
        let (mut r, _) = Recovery::new(dir.path(), 5.0);
        let aside = r.set_aside().unwrap();
        assert_eq!(std::fs::read_to_string(aside).unwrap(), SCENE);
        assert!(!r.path().exists());

        std::fs::write(dir.path().join(FILE_NAME), "not [toml").unwrap();
        let (r, message) = Recovery::new(dir.path(), 5.0);
        assert!(r.offered.is_none());
        assert!(message.is_some_and(|m| m.contains("unreadable")));
        let aside = dir.path().join(SET_ASIDE_NAME);
        assert_eq!(std::fs::read_to_string(aside).unwrap(), "not [toml");
    }

    #[test]
    fn a_failing_write_is_reported_once_and_retried() {
        let dir = tempfile::tempdir().unwrap();
        let blocker = dir.path().join("a-file");
        std::fs::write(&blocker, "").unwrap();
        // The folder would have to be inside a file: every write fails.
        let (mut r, _) = Recovery::new(&blocker.join("impulse"), 1.0);
        let first = r.save(1.0, 1, SCENE);
        assert!(first.is_some_and(|m| m.contains("Autosave")));
        assert_eq!(
            r.save(2.0, 2, SCENE),
            None,
            "the same failure is not repeated"
        );
        assert!(r.error.is_some() && r.saves == 0);
        assert!(r.due(3.0) && r.changed(3), "and it is tried again");
    }
}
