//! The start screen: large tiles, each a lesson (PhET's way in). A tile
//! opens its scene with only the controls that scene needs and the dock on
//! the tab that shows it; *Free play* opens the sandbox with everything.
//! Shown on a plain start (no scene file, no gas, no shared link) and by
//! the top bar's *Start* button; while it is open nothing runs behind it.
//! A lesson opens paused on its tile's question (predict, observe,
//! explain): the strip asks it, with a Play button, until the answer has
//! been seen, and then gives the scene's caption, its answer.

use super::{scenes, DockTab, Sandbox};
use crate::app::lang::tr;

/// A lesson on the start screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tile {
    HeadOn,
    Glancing,
    Inelastic,
    PiBlocks,
    Gas,
    FreePlay,
}

/// A group of controls in the side dock.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Section {
    Collisions,
    Show,
    NewDiscs,
    Selected,
    Scene,
    View,
    More,
}

impl Tile {
    pub const ALL: [Tile; 6] = [
        Tile::HeadOn,
        Tile::Glancing,
        Tile::Inelastic,
        Tile::PiBlocks,
        Tile::Gas,
        Tile::FreePlay,
    ];

    /// Its title on the tile.
    pub fn title(self) -> String {
        match self {
            Tile::HeadOn => tr!("tile-head-on"),
            Tile::Glancing => tr!("tile-glancing"),
            Tile::Inelastic => tr!("tile-inelastic"),
            Tile::PiBlocks => tr!("tile-pi-blocks"),
            Tile::Gas => tr!("tile-gas"),
            Tile::FreePlay => tr!("tile-free-play"),
        }
    }

    /// One line under the title, in plain words.
    pub fn blurb(self) -> String {
        match self {
            Tile::HeadOn => tr!("tile-head-on-blurb"),
            Tile::Glancing => tr!("tile-glancing-blurb"),
            Tile::Inelastic => tr!("tile-inelastic-blurb"),
            Tile::PiBlocks => tr!("tile-pi-blocks-blurb"),
            Tile::Gas => tr!("tile-gas-blurb"),
            Tile::FreePlay => tr!("tile-free-play-blurb"),
        }
    }

    /// Its name in the state dump and the widget names ("tile_head_on").
    pub fn key(self) -> &'static str {
        match self {
            Tile::HeadOn => "head_on",
            Tile::Glancing => "glancing",
            Tile::Inelastic => "inelastic",
            Tile::PiBlocks => "pi_blocks",
            Tile::Gas => "gas",
            Tile::FreePlay => "free_play",
        }
    }

    /// The scene it opens: a preset's file name (the default scene for
    /// free play).
    fn scene(self) -> Option<&'static str> {
        Some(match self {
            Tile::HeadOn => "preset-1-head-on.toml",
            Tile::Glancing => "preset-4-glancing.toml",
            Tile::Inelastic => "preset-5-inelastic.toml",
            Tile::PiBlocks => "preset-7-pi-blocks.toml",
            Tile::Gas => "preset-8-gas.toml",
            Tile::FreePlay => return None,
        })
    }

    /// The dock's tab that shows what the lesson is about.
    fn tab(self) -> DockTab {
        match self {
            Tile::HeadOn | Tile::PiBlocks => DockTab::Collisions,
            Tile::Glancing => DockTab::Momenta,
            Tile::Inelastic | Tile::FreePlay => DockTab::Totals,
            Tile::Gas => DockTab::Speeds,
        }
    }

    /// Whether the lesson is about momentum: its first wall hit pauses it
    /// (a wall's push changes the total the lesson says is kept).
    pub fn about_momentum(self) -> bool {
        matches!(self, Tile::HeadOn | Tile::Glancing | Tile::Inelastic)
    }

    /// Whether the lesson shows `section` of the side dock.
    pub fn shows(self, section: Section) -> bool {
        use Section::*;
        match self {
            Tile::FreePlay => true,
            Tile::HeadOn | Tile::Glancing | Tile::Inelastic => {
                matches!(section, Collisions | Show | Selected | View)
            }
            Tile::PiBlocks => matches!(section, Show | View),
            Tile::Gas => matches!(section, Collisions | Show | NewDiscs | View),
        }
    }
}

impl Sandbox {
    /// Opens `tile`'s scene, with only its controls, and closes the start
    /// screen.
    pub(super) fn start_with(&mut self, tile: Tile) {
        self.panels.start_open = false;
        match tile.scene() {
            Some(file) => {
                if let Some(k) = scenes::PRESETS.iter().position(|p| p.path.ends_with(file)) {
                    self.open_preset(k);
                }
            }
            None => {
                let origin = tr!("origin-default");
                match impulse::Scene::parse(impulse::catalogue::DEFAULT.text, &origin) {
                    Ok(scene) => {
                        let _ = self.open_scene(scene, origin); // reported
                    }
                    Err(e) => self.report(tr!("sandbox-cannot-open", error = e.to_string())),
                }
            }
        }
        self.panels.focus = tile;
        self.panels.docks_open = true;
        self.panels.dock_expanded = true;
        self.panels.tab = tile.tab();
        // A lesson waits, paused on its question, for the class to guess
        // (predict, then observe, then explain); free play runs at once.
        let lesson = tile != Tile::FreePlay;
        self.open.lesson = lesson.then_some(tile);
        self.clock.paused = lesson;
        self.panels.paused_by_modal = false;
        // Said after the scene's name, as the strip shows it.
        self.ask();
    }

    /// Says the open lesson's question, while it is unanswered.
    pub(super) fn ask(&mut self) {
        if let Some(question) = self.lesson_question() {
            self.announce(question);
        }
    }

    /// The open lesson, while its answer is still to be seen: before its
    /// first collision (the π blocks: until their count is final), and
    /// while its discs are as the lesson set them.
    pub(super) fn lesson_unanswered(&self) -> Option<Tile> {
        let tile = self.open.lesson?;
        let answered = match tile {
            Tile::PiBlocks => self.world.collisions_over(),
            _ => self.world.total_pair_collisions > 0,
        };
        (!answered && !self.open.edited).then_some(tile)
    }

    /// The start screen's lesson open now, if any.
    pub fn lesson(&self) -> Option<Tile> {
        self.open.lesson
    }

    /// Whether a lesson waits at its start, paused on its question (Enter
    /// then plays it, and the question stays in the strip when the keys
    /// are in the controls).
    pub fn lesson_waiting(&self) -> bool {
        self.clock.paused && self.world.time == 0.0 && self.lesson_unanswered().is_some()
    }

    /// What the strip shows of an unanswered lesson: its question instead
    /// of its answer.
    pub fn lesson_question(&self) -> Option<String> {
        Some(self.lesson_unanswered()?.blurb())
    }
}
