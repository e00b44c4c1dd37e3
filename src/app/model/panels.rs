//! Which panels, tabs and popups are open, the UI scale and the theme:
//! the model's part of the screen, which the layout and the views read.

use super::start;
use crate::app::lang::tr;

/// The bottom dock's tabs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DockTab {
    Totals,
    Collisions,
    Discs,
    Speeds,
    Momenta,
    Words,
}

impl DockTab {
    /// Every tab, in the row's order (`Ctrl+1` … `Ctrl+6` follow it).
    pub const IN_ROW: [DockTab; 6] = [
        DockTab::Totals,
        DockTab::Collisions,
        DockTab::Discs,
        DockTab::Speeds,
        DockTab::Momenta,
        DockTab::Words,
    ];

    /// Its name in the state dump and the widget names ("Totals").
    pub fn key(self) -> &'static str {
        match self {
            DockTab::Totals => "Totals",         // not words: the dump's name
            DockTab::Collisions => "Collisions", // not words: the dump's name
            DockTab::Discs => "Discs",           // not words: the dump's name
            DockTab::Speeds => "Speeds",         // not words: the dump's name
            DockTab::Momenta => "Momenta",       // not words: the dump's name
            DockTab::Words => "Words",           // not words: the dump's name
        }
    }

    /// The tab's title, in the window's language.
    pub fn title(self) -> String {
        match self {
            DockTab::Totals => tr!("tab-totals"),
            DockTab::Collisions => tr!("tab-collisions"),
            DockTab::Discs => tr!("tab-discs"),
            DockTab::Speeds => tr!("tab-speeds"),
            DockTab::Momenta => tr!("tab-momenta"),
            DockTab::Words => tr!("tab-words"),
        }
    }
}

/// Dark (the default, for a screen) or light (for a projector in a bright room).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Theme {
    Dark,
    Light,
}

impl Theme {
    /// "dark" or "light".
    pub fn name(self) -> &'static str {
        match self {
            Theme::Dark => "dark",
            Theme::Light => "light",
        }
    }

    /// The other one.
    pub fn other(self) -> Theme {
        match self {
            Theme::Dark => Theme::Light,
            Theme::Light => Theme::Dark,
        }
    }
}

/// The scales F2 cycles through; 2.0 is the projector's.
pub const UI_SCALES: [f32; 3] = [1.0, 1.5, 2.0];
/// The range of the scale slider.
pub const UI_SCALE_RANGE: std::ops::RangeInclusive<f32> = 1.0..=2.5;

/// The next of [`UI_SCALES`] after `scale` (back to the first after the last).
pub fn next_scale(scale: f32) -> f32 {
    UI_SCALES
        .iter()
        .copied()
        .find(|&s| s > scale + 1e-3)
        .unwrap_or(UI_SCALES[0])
}

/// Why the open tab has no room, and what makes room: L hides a docked
/// side panel; beside a drawer (which L only opens) another text size.
pub fn no_room_for_tab(side_docked: bool) -> String {
    match side_docked {
        true => tr!("dock-no-room"),
        false => {
            let key = super::bindings::keys_of(&super::Command::NextScale);
            tr!("dock-no-room-drawer", key = key)
        }
    }
}

/// Which panels, tabs and popups are open, and how large everything is.
#[derive(Clone, Debug, PartialEq)]
pub struct Panels {
    /// Scale of every text and control (F2, the slider).
    pub scale: f32,
    /// Dark or light.
    pub theme: Theme,
    /// The side and bottom docks (Tab hides both for a full-size world).
    pub docks_open: bool,
    /// The side dock (L).
    pub side_open: bool,
    /// Where the side dock is a drawer (a small window): whether it is open.
    pub drawer_open: bool,
    /// The bottom dock's chosen tab.
    pub tab: DockTab,
    /// Whether the bottom dock shows its tab or only the tab row.
    pub dock_expanded: bool,
    /// The tab's height (px) chosen by dragging its top edge; its own
    /// height while None. The layout keeps it within what the world leaves.
    pub tab_height: Option<f32>,
    /// The key list.
    pub help_open: bool,
    /// The preset menu.
    pub presets_open: bool,
    /// The start screen's tiles.
    pub start_open: bool,
    /// The lesson chosen on the start screen: which controls the side dock
    /// shows (Free play: all).
    pub focus: start::Tile,
    /// The simulation was running when a modal screen paused it.
    pub paused_by_modal: bool,
    /// How many times the person picked a disc (a click on it, Q, a row of
    /// the Discs table): each pick opens *Selected disc* in the side dock.
    /// A disc selected otherwise (a new one, a preset's) leaves it as it is.
    pub picks: u32,
}

impl Panels {
    pub(super) fn new(scale: f32, theme: Theme) -> Self {
        let mut panels = Panels {
            scale: 1.0,
            theme,
            docks_open: true,
            side_open: true,
            drawer_open: false,
            picks: 0,
            tab: DockTab::Totals,
            dock_expanded: true,
            tab_height: None,
            help_open: false,
            presets_open: false,
            start_open: false,
            focus: start::Tile::FreePlay,
            paused_by_modal: false,
        };
        panels.set_scale(scale);
        panels
    }

    /// Sets the UI scale (kept in [`UI_SCALE_RANGE`]).
    pub fn set_scale(&mut self, scale: f32) {
        let scale = if scale.is_finite() { scale } else { 1.0 };
        self.scale = scale.clamp(*UI_SCALE_RANGE.start(), *UI_SCALE_RANGE.end());
    }

    /// Opens the bottom dock on `tab`, and never folds it: its key pressed
    /// while it was in sight folded the dock, and a teacher pressing T
    /// "to show the Totals" hid them.
    pub fn show_tab(&mut self, tab: DockTab) {
        (self.docks_open, self.dock_expanded, self.tab) = (true, true, tab);
    }
}
