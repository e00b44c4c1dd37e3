//! Opening and saving scenes: the classroom presets on the number keys (and
//! a menu), files by path or dropped, Ctrl+S, which saves the current state
//! as a scene file that reopens exactly, a shared link, and undo and redo.

use super::undo::Moment;
use super::{DockTab, Note, Sandbox};
use crate::app::lang::tr;
use impulse::Scene;
use std::path::{Path, PathBuf};

mod names;
use names::named_after;
pub use names::{free_file, keep_file, slug};

/// A preset: the key that opens it, and its scene file (from the core's
/// catalogue, compiled in).
pub struct Preset {
    /// The key's label ("1" … "9", "0", "Ctrl+N", or "" for the menu only).
    pub key: &'static str,
    /// Where the file lives in the repository.
    pub path: &'static str,
    /// The file's text.
    pub text: &'static str,
}

macro_rules! preset {
    ($key:literal, $file:ident) => {
        Preset {
            key: $key,
            path: impulse::catalogue::$file.path,
            text: impulse::catalogue::$file.text,
        }
    };
}

/// The presets, in menu order: the digit keys' ten, the π blocks at their
/// other mass ratios and the rough discs (menu only), and the empty box
/// last (Ctrl+N).
pub const PRESETS: [Preset; 16] = [
    preset!("1", PRESET_1_HEAD_ON),
    preset!("2", PRESET_2_HEAVY_HITS_LIGHT),
    preset!("3", PRESET_3_LIGHT_HITS_HEAVY),
    preset!("4", PRESET_4_GLANCING),
    preset!("5", PRESET_5_INELASTIC),
    preset!("6", PRESET_6_CRADLE),
    preset!("7", PRESET_7_PI_BLOCKS),
    preset!("8", PRESET_8_GAS),
    preset!("9", PRESET_9_BILLIARDS),
    preset!("0", PRESET_0_PILE),
    preset!("", PI_BLOCKS_1),
    preset!("", PI_BLOCKS_10000),
    preset!("", PI_BLOCKS_1000000),
    preset!("", PRESET_SPIN_OFF_A_WALL),
    preset!("", PRESET_ROUGH_GAS),
    preset!("Ctrl+N", PRESET_EMPTY), // not words: a key, named by keys-new-box
];

/// The presets' scenes (parsed once).
fn preset_scenes() -> &'static [Option<Scene>] {
    static SCENES: std::sync::OnceLock<Vec<Option<Scene>>> = std::sync::OnceLock::new();
    SCENES.get_or_init(|| {
        PRESETS
            .iter()
            .map(|p| Scene::parse(p.text, p.path).ok())
            .collect()
    })
}

/// "key  name" of every preset, for menus, in the window's language.
pub fn preset_labels() -> Vec<String> {
    let lang = crate::app::lang::language().code();
    PRESETS
        .iter()
        .zip(preset_scenes())
        .map(|(p, scene)| {
            let name = scene
                .as_ref()
                .and_then(|s| s.name_in(lang))
                .map_or_else(|| p.path.to_string(), str::to_string);
            match p.key {
                "" => name,
                // not words: the browser keeps this key (a window of its own)
                "Ctrl+N" if cfg!(target_arch = "wasm32") => name,
                // not words: the empty box's key, in the window's words
                "Ctrl+N" => format!("{}   {name}", tr!("keys-new-box")),
                key => format!("{key}   {name}"),
            }
        })
        .collect()
}

/// The one-line description of preset `index`, if its file has one, in
/// the window's language.
pub fn preset_description(index: usize) -> Option<String> {
    let lang = crate::app::lang::language().code();
    preset_scenes()
        .get(index)?
        .as_ref()?
        .description_in(lang)
        .map(str::to_string)
}

impl Sandbox {
    /// The caption as the window shows and says it: after an edit it
    /// begins "Before the edits:", as the preset's answer may no longer
    /// hold; not where the caption says what to do (the sandbox's and the
    /// empty boxes'), which an edit does not make untrue ("Before the
    /// edits: Drag on empty space…" read as nonsense).
    pub fn shown_caption(&self) -> Option<String> {
        use impulse::catalogue::{DEFAULT, EMPTY, PRESET_EMPTY};
        if let Some(question) = self.lesson_question() {
            return Some(question);
        }
        // Known by their captions (the sandbox's origin is a word in the
        // language of the start), read from their files once.
        static WHAT_TO_DO: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
        let what_to_do = WHAT_TO_DO.get_or_init(|| {
            [DEFAULT, EMPTY, PRESET_EMPTY]
                .iter()
                .filter_map(|f| Scene::parse(f.text, f.path).ok()?.description)
                .collect()
        });
        let text = self.scene_description()?;
        let says_what_to_do = self
            .open
            .scene
            .description
            .as_ref()
            .is_some_and(|d| what_to_do.contains(d));
        Some(match self.open.edited && !says_what_to_do {
            true => tr!("caption-edited", caption = text),
            false => text,
        })
    }

    /// Opens preset `index` of [`PRESETS`].
    pub(super) fn open_preset(&mut self, index: usize) {
        let Some(preset) = PRESETS.get(index) else {
            return;
        };
        self.panels.presets_open = false;
        match Scene::parse(preset.text, preset.path) {
            Ok(scene) => {
                if self.open_scene(scene, preset.path.to_string()).is_err() {
                    return;
                }
                // The gas presets are about the speed distribution: show it.
                if preset.path.contains("gas") {
                    self.panels.tab = DockTab::Speeds;
                }
                if preset.path == impulse::catalogue::PRESET_SPIN_OFF_A_WALL.path {
                    // The spin preset is about the angle and the spin: its
                    // disc's path traced, its values (ω among them) beside it.
                    self.record.trails.on = true;
                    self.selected = Some(0);
                }
            }
            Err(e) => self.report(tr!(
                "scene-cannot-open",
                file = preset.path,
                error = e.to_string()
            )),
        }
    }

    /// Replaces the world with `scene`'s; on an error says why (in the
    /// window and on the terminal), keeps the current scene and returns
    /// what it said.
    pub(super) fn open_scene(&mut self, scene: Scene, origin: String) -> Result<(), String> {
        match scene.build(&origin) {
            Ok(world) => {
                // What the user changed is one undo away: say so.
                let lang = crate::app::lang::language().code();
                let left = self.open.unsaved.then(|| {
                    let name = self.open.scene.name_in(lang).unwrap_or(&self.open.origin);
                    name.to_string()
                });
                self.world = world;
                self.open.edited = scene.edited;
                self.open.unsaved = false;
                self.forget_past();
                self.steps.realtime.clear();
                self.clock.dt = scene.step_for(self.session.dt);
                self.selected = None;
                self.pointer.cancel();
                let name = scene.name_in(lang).unwrap_or(&origin).to_string();
                self.open.scene = scene;
                self.open.origin = origin;
                self.open.saved_to = None;
                self.open.opened = self.open.opened.wrapping_add(1);
                self.open.setup = None;
                self.open.lesson = None;
                // A note on the scene before ("Saved … in …") is not about
                // this one.
                self.messages.scene = None;
                self.fit_camera();
                self.say_opened(name, left);
                Ok(())
            }
            Err(e) => {
                let message = tr!("scene-kept", error = e.to_string());
                self.report(message.clone());
                Err(message)
            }
        }
    }

    /// The scene as it opened, again; `Some(true)` if that dropped edits
    /// made since (`apply` says which), `None` if it could not be built
    /// (said here).
    pub(super) fn reset_scene(&mut self) -> Option<bool> {
        match self.open.scene.build(&self.open.origin) {
            Ok(world) => {
                let edits_dropped = self.open.edited && !self.open.scene.edited;
                self.open.edited = self.open.scene.edited;
                self.open.setup = None;
                self.world = world;
                self.forget_past();
                self.selected = None;
                self.pointer.cancel();
                Some(edits_dropped)
            }
            Err(e) => {
                self.toast(tr!("scene-cannot-reset", error = e.to_string()));
                None
            }
        }
    }

    /// Removes every disc.
    pub(super) fn clear_discs(&mut self) {
        self.world.particles.clear();
        self.forget_past();
        self.selected = None;
        self.pointer.cancel();
        self.toast(tr!("scene-cleared"));
    }

    /// Opens the scene file at `path` (the path field); a bad file is
    /// reported and the current scene stays.
    pub(super) fn open_file(&mut self, path: &str) {
        let path = path.trim().to_string();
        if path.is_empty() {
            self.messages.scene = Some(Note::error(tr!("scene-path-empty")));
            return;
        }
        // A name alone is looked for where Save puts files too: the Save
        // note names the file alone, and typed back it was "not found".
        let found = names::find_scene_file(Path::new(&path), &self.session.out);
        let result = match found.as_deref().map(Scene::load) {
            Some(Ok(scene)) => {
                let origin = found.as_deref().map(|f| f.display().to_string());
                self.open_scene(scene, origin.unwrap_or_else(|| path.clone()))
            }
            Some(Err(e)) => {
                let message = tr!("scene-kept", error = e.to_string());
                self.report(message.clone());
                Err(message)
            }
            None => {
                let folder = crate::files::shown(&self.session.out);
                let message = tr!("scene-not-found", name = path.as_str(), folder = folder);
                self.report(message.clone());
                Err(message)
            }
        };
        self.messages.scene = Some(match result {
            Ok(()) => Note::ok(tr!("scene-opened", name = path.as_str())),
            Err(e) => Note::error(e),
        });
    }

    /// Opens a scene from its text (a dropped file); a bad one is reported
    /// and the scene kept.
    pub(super) fn open_text(&mut self, name: &str, text: &Result<String, String>) {
        let scene = text
            .as_ref()
            .map_err(Clone::clone)
            .and_then(|text| Scene::parse(text, name).map_err(|e| e.to_string()));
        match scene {
            Ok(scene) => {
                let _ = self.open_scene(scene, name.to_string()); // reported
            }
            Err(e) => self.report(tr!("scene-kept", error = e)),
        }
    }

    /// The person names the scene: the name in every language (the
    /// preset's translated names go), and the preset's caption with them,
    /// which described the preset, not this scene. A name with no letter
    /// or digit is refused (it would name no file).
    pub(super) fn rename_scene(&mut self, name: &str) {
        let name = name.trim();
        if !name.chars().any(char::is_alphanumeric) {
            self.messages.scene = Some(Note::error(tr!("scene-name-empty")));
            return;
        }
        if self.scene_name() == name {
            return;
        }
        let scene = &mut self.open.scene;
        scene.name = Some(name.to_string());
        scene.description = None;
        scene.translations.clear();
        self.open.edited = false;
        self.messages.scene = Some(Note::ok(tr!("scene-renamed", name = name)));
    }

    /// The name of the files the scene is saved and exported under: its
    /// name as the window shows it, in the window's language (a Spanish
    /// class's saved head-on hit is `choque-frontal-masas-iguales.toml`).
    pub(super) fn file_stem(&self) -> String {
        slug(&self.scene_name())
    }

    /// Saves the current state as a scene file in the output folder; the
    /// write is atomic, so a failure leaves any older file as it was.
    /// Returns the file written, or what was reported; the scene section
    /// says the same under its buttons.
    pub(super) fn save_scene(&mut self) -> Result<PathBuf, String> {
        let scene = self.current_scene();
        let dir = self.session.out.clone();
        let stem = self.file_stem();
        let text = scene.to_toml();
        // Saved before this session under the same name: back into that
        // file (atomically, as every save); else a new one beside the rest.
        let again = self.open.saved_to.clone().filter(|p| {
            !cfg!(target_arch = "wasm32")
                && p.file_stem()
                    .is_some_and(|s| named_after(&s.to_string_lossy(), &stem))
                && p.exists()
        });
        let result = match again {
            #[cfg(not(target_arch = "wasm32"))]
            Some(path) => names::write_kept(path, text.as_bytes()),
            _ => keep_file(&dir, &stem, "toml", text.as_bytes()),
        };
        match result {
            Ok(path) => {
                eprintln!("impulse: saved {}", path.display());
                self.open.unsaved = false;
                self.open.saved_to = Some(path.clone());
                let (file, folder) = crate::files::name_and_folder(&path);
                // The strip has the file's name alone, which a projector's
                // one line shows whole (with its folder the line broke
                // before the name and read "Saved …"); the Scene section
                // has the folder too.
                let (said, noted) = if cfg!(target_arch = "wasm32") {
                    let said = tr!("scene-downloaded", file = crate::files::shown(&path));
                    (said.clone(), said)
                } else {
                    let noted = tr!("scene-saved", file = file.as_str(), folder = folder);
                    (tr!("scene-saved-short", file = file), noted)
                };
                // The discs as they are now, not as the scene opened: said,
                // once the clock has run (a file saved after the collision
                // reopened with none left, and nothing had said so).
                let (said, noted) = match self.world.time > 0.0 {
                    true => {
                        let time = crate::app::numbers::plain(self.world.time, 2);
                        let at = |saved: String| {
                            tr!("scene-saved-at", saved = saved, time = time.as_str())
                        };
                        (at(said), at(noted))
                    }
                    false => (said, noted),
                };
                self.toast(said);
                self.messages.scene = Some(Note::ok(noted));
                Ok(path)
            }
            Err(e) => {
                let message = tr!("scene-not-saved", error = e);
                self.report(message.clone());
                self.messages.scene = Some(Note::error(message.clone()));
                Err(message)
            }
        }
    }

    /// Puts the scene into the page's address, to send as a link (the
    /// browser build); a scene too large for a link says so and offers
    /// the file instead.
    pub(super) fn share_link(&mut self) {
        match super::share::fragment_for(&self.current_scene()) {
            Ok(fragment) => {
                #[cfg(target_arch = "wasm32")]
                crate::web::set_fragment(&fragment);
                let _ = fragment;
                self.toast(tr!("scene-shared"));
            }
            Err(why) => {
                self.report(tr!("scene-not-shared", error = why.to_string()));
            }
        }
    }

    /// The sandbox as it is now, as a scene that reopens exactly.
    pub fn current_scene(&self) -> Scene {
        let mut scene = Scene::from_world(
            &self.world,
            self.open.scene.name.clone(),
            self.open.scene.description.clone(),
        );
        scene.simulation.dt = Some(self.clock.dt);
        scene.edited = self.open.edited;
        scene.translations = self.open.scene.translations.clone();
        scene
    }

    /// The scene as it is now, for undo.
    pub(super) fn moment(&self) -> Moment {
        Moment {
            world: self.world.clone(),
            scene: self.open.scene.clone(),
            origin: self.open.origin.clone(),
            edited: self.open.edited,
        }
    }

    /// Ctrl+Z: the scene as it was before the last change.
    pub(super) fn undo_change(&mut self) {
        let present = self.moment();
        match self.undo.undo(present) {
            Some((moment, what)) => {
                self.put_back(moment, what);
                self.toast(tr!("undone", what = crate::app::lang::text(what, &[])));
            }
            None => self.toast(tr!("nothing-to-undo")),
        }
    }

    /// Ctrl+Shift+Z or Ctrl+Y: the change the last undo took back.
    pub(super) fn redo_change(&mut self) {
        let present = self.moment();
        match self.undo.redo(present) {
            Some((moment, what)) => {
                self.put_back(moment, what);
                self.toast(tr!("redone", what = crate::app::lang::text(what, &[])));
            }
            None => self.toast(tr!("nothing-to-redo")),
        }
    }

    /// The scene as it was at `moment`, taken back (or forward) over a
    /// change of kind `what`. The rewind history and the plot keep what led
    /// up to that moment in this run (an edit undone, "what if e = 0.3?",
    /// keeps the graph being discussed); across a new scene or a reset,
    /// nothing.
    fn put_back(&mut self, moment: Moment, what: &str) {
        let resized = moment.world.laws.size != self.world.laws.size;
        // A reset starts the run again: what was recorded since belongs to
        // another run than the moment before it.
        let same_run = !matches!(what, "edit-open-scene" | "edit-reset");
        let at = moment.world.time;
        self.world = moment.world;
        self.open = super::OpenScene {
            scene: moment.scene,
            origin: moment.origin,
            edited: moment.edited,
            unsaved: true,
            saved_to: self.open.saved_to.take(),
            opened: match what {
                "edit-open-scene" => self.open.opened.wrapping_add(1),
                _ => self.open.opened,
            },
            // Which set-up a reset would bring back is no longer known.
            setup: None,
            // Back across another scene's opening, it is no lesson's.
            lesson: self.open.lesson.filter(|_| what != "edit-open-scene"),
        };
        // What came after the moment belongs to the undone timeline; the
        // ledger came back with the world.
        if same_run {
            self.record.history.keep_before(at);
            self.record.history.record(&self.world);
            self.record.totals.keep_before(at);
            let now = self.world.metrics();
            self.record.totals.push(&self.world, &now);
        } else {
            self.record.history.clear();
            self.record.totals.restart(&self.world);
        }
        // "Applied to disc 2" no longer holds; the toast says what undo did.
        self.messages.fields = None;
        self.messages.table = None;
        self.pointer.cancel();
        if self.selected_disc().is_none() {
            self.selected = None;
        }
        if resized && self.view.fitted {
            self.fit_camera();
        }
    }
}

#[cfg(test)]
mod tests;
