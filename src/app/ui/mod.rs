//! Every panel of the window, in egui (through `egui-macroquad`): the top
//! bar, the controls docked at the side, the message strip and the bottom
//! dock with its tabs, and the popups the user opens (help, presets, the
//! recovery question). The world is drawn by macroquad in the rectangle the
//! panels leave free; nothing docked is ever drawn over it.
//!
//! Panels claim space in a fixed order (top bar, side, dock, strip) and
//! the world gets what is left ([`Layout::world`]). The pass runs first in
//! each frame, so the key and mouse bindings know whether a text field has
//! the keyboard ([`UiState::typing`]) and whether the pointer is on a panel.
//! Clicks become [`Action`]s, carried out once egui no longer borrows the app.
//!
//! - [`theme`]: the UI scale, text sizes and the dark and light themes.
//! - [`numbers`]: plain numbers with units.
//! - [`top_bar`]: scene, time, running or paused, the totals.
//! - [`controls`]: the side dock's collapsible sections.
//! - [`dock`]: the bottom dock's tabs (Totals, Collisions, Discs, Speeds, Momenta).
//! - [`discs_table`]: the Discs tab's table and its validated edits.
//! - [`popups`]: help, the preset menu and the recovery question.
//! - [`strip`]: the line under the world: scale bar, caption, messages.

mod controls;
pub mod discs_table;
mod dock;
mod laws;
pub mod numbers;
mod popups;
mod strip;
pub mod theme;
mod top_bar;

use super::App;
use serde::Serialize;
use std::collections::BTreeMap;
use theme::Theme;

/// The bottom dock's tabs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DockTab {
    Totals,
    Collisions,
    Discs,
    Speeds,
    Momenta,
}

impl DockTab {
    pub const ALL: [DockTab; 5] = [
        DockTab::Totals,
        DockTab::Collisions,
        DockTab::Discs,
        DockTab::Speeds,
        DockTab::Momenta,
    ];

    /// The tab's title.
    pub fn title(self) -> &'static str {
        match self {
            DockTab::Totals => "Totals",
            DockTab::Collisions => "Collisions",
            DockTab::Discs => "Discs",
            DockTab::Speeds => "Speeds",
            DockTab::Momenta => "Momenta",
        }
    }
}

/// A line of feedback under a control.
#[derive(Clone, Debug, PartialEq)]
pub struct Note {
    pub text: String,
    pub error: bool,
}

impl Note {
    pub fn ok(text: impl Into<String>) -> Self {
        Note {
            text: text.into(),
            error: false,
        }
    }
    pub fn error(text: impl Into<String>) -> Self {
        Note {
            text: text.into(),
            error: true,
        }
    }
}

/// What a click asked for, done once the pass is over.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    OpenPreset(usize),
    CenterOfMassFrame,
    /// Undo the last change to the scene.
    Undo,
    /// Redo what undo took back.
    Redo,
    NextCollision,
    Scrub(isize),
    ApplySelected,
    DeleteSelected,
    Open,
    Save,
    /// Put the scene into the page address (the browser build).
    Share,
    Reset,
    Clear,
    Export,
    Screenshot,
    Fit,
    Zoom(f64),
    Fullscreen,
    RecoveryRestore,
    RecoverySetAside,
}

/// Where everything went this frame, in screen pixels (origin top-left):
/// the `layout` object of the state dump.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Layout {
    /// The window's size.
    pub window: [f32; 2],
    /// The world's rectangle [x, y, w, h].
    pub world: [f32; 4],
    /// Every docked panel and every other box drawn that is not a popup the
    /// user opened, [x, y, w, h].
    pub panels: Vec<[f32; 4]>,
    /// The smallest font size drawn, in physical pixels.
    pub min_text_px: f32,
    /// The UI scale.
    pub ui_scale: f32,
}

/// The panels' state between frames.
pub struct UiState {
    /// Scale of every text and line (F2, the slider).
    pub scale: f32,
    /// Dark or light.
    pub theme: Theme,
    /// The scale and theme egui was last given.
    applied: Option<(f32, Theme)>,
    /// The side dock (L).
    pub side_open: bool,
    /// The side and bottom docks (Tab hides both for a full-size world).
    pub docks_open: bool,
    /// The bottom dock's chosen tab.
    pub tab: DockTab,
    /// Whether the bottom dock shows its tab or only the tab strip.
    pub dock_expanded: bool,
    /// The key list.
    pub help_open: bool,
    /// The preset menu.
    pub presets_open: bool,
    /// A text field has the keyboard: the shortcuts stay quiet.
    pub typing: bool,
    /// A text field was left with Enter: the keyboard stays with the
    /// panel (no shortcuts) until a click in the world or Esc.
    pub panel_keyboard: bool,
    /// Set during the pass by a text field that has the keyboard.
    text_focus: bool,
    /// The pointer is on a panel or popup: the world ignores it.
    pub pointer_on_ui: bool,
    /// Screen rectangles of named widgets (px), for the state dump.
    pub widgets: BTreeMap<String, [f32; 4]>,
    /// This frame's layout.
    pub layout: Layout,
    /// The side dock's fields for the selected disc.
    pub fields: controls::DiscFields,
    /// The Discs tab's edit in progress and its last message.
    pub table: discs_table::TableState,
    /// The scene path field and how the last open or save went.
    pub path: String,
    pub scene_note: Option<Note>,
    /// The friction slider's μ, kept while friction is off.
    pub friction: f64,
}

impl UiState {
    /// The state at start: docks open, scale 1, dark.
    pub fn new(path: String) -> Self {
        UiState {
            scale: 1.0,
            theme: Theme::Dark,
            applied: None,
            side_open: true,
            docks_open: true,
            tab: DockTab::Totals,
            dock_expanded: true,
            help_open: false,
            presets_open: false,
            typing: false,
            panel_keyboard: false,
            text_focus: false,
            pointer_on_ui: false,
            widgets: BTreeMap::new(),
            layout: Layout::default(),
            fields: Default::default(),
            table: Default::default(),
            path,
            scene_note: None,
            friction: 0.5,
        }
    }

    /// Sets the UI scale; at the projector's scale (2 and up) the bottom
    /// dock folds to its tab strip, so the world keeps its room.
    pub fn set_scale(&mut self, scale: f32) {
        let scale = scale.clamp(*theme::UI_SCALE_RANGE.start(), *theme::UI_SCALE_RANGE.end());
        if scale >= 2.0 && self.scale < 2.0 {
            self.dock_expanded = false;
        }
        self.scale = scale;
    }

    /// Notes a text field's response: while it has the keyboard, the
    /// shortcuts stay quiet.
    fn note_text_field(&mut self, response: &egui::Response) {
        self.text_focus |= response.has_focus();
        // Left with Enter: the keyboard stays with the panel (a digit typed
        // next must not open a preset) until a click in the world or Esc.
        if response.lost_focus() && response.ctx.input(|i| i.key_pressed(egui::Key::Enter)) {
            self.panel_keyboard = true;
        }
    }

    /// Records a widget's rectangle (egui points) under `name`, in pixels.
    fn note_widget(&mut self, name: impl Into<String>, rect: egui::Rect, ppp: f32) {
        self.widgets.insert(name.into(), to_px(rect, ppp));
    }
}

/// What the panels can change (the laws and the four choices), to notice a
/// change and undo it.
#[derive(Clone, Copy, PartialEq)]
struct Laws {
    laws: impulse::laws::Laws,
    choices: impulse::auto::Choices,
}

impl Laws {
    fn of(w: &impulse::World) -> Laws {
        Laws {
            laws: w.laws,
            choices: w.choices(),
        }
    }

    fn put(self, w: &mut impulse::World) {
        w.laws = self.laws;
        let impulse::auto::Choices {
            method,
            broad_phase,
            substeps,
            parallel,
        } = self.choices;
        (w.method, w.broad_phase, w.substeps, w.parallel) =
            (method, broad_phase, substeps, parallel);
    }

    /// Which law `w` has changed from these, if any (for undo's message).
    fn changed_in(self, w: &impulse::World) -> Option<&'static str> {
        let (now, was) = (w.laws, self.laws);
        if Laws::of(w) == self {
            None
        } else if now.restitution != was.restitution {
            Some("restitution")
        } else if now.wall_restitution != was.wall_restitution {
            Some("wall restitution")
        } else if now.tangential_restitution != was.tangential_restitution {
            Some("roughness")
        } else if now.wall_tangential_restitution != was.wall_tangential_restitution {
            Some("wall roughness")
        } else if now.friction != was.friction {
            Some("friction")
        } else if now.gravity != was.gravity {
            Some("gravity")
        } else if now.boundary != was.boundary || now.walls != was.walls {
            Some("edges")
        } else {
            Some("method")
        }
    }
}

/// The app's pixels per egui point. The app's pixels are macroquad's: the
/// mouse, the camera and the dump use them (a window's pixels on a desktop,
/// CSS pixels in a browser), while egui draws `dpi` times as many device
/// pixels on a high-density screen, so text is as large and sharper there.
pub fn px_per_point(ctx: &egui::Context) -> f32 {
    ctx.pixels_per_point() / macroquad::window::screen_dpi_scale()
}

/// An egui rectangle (points) as [x, y, w, h] in pixels.
fn to_px(rect: egui::Rect, ppp: f32) -> [f32; 4] {
    [
        rect.min.x * ppp,
        rect.min.y * ppp,
        rect.width() * ppp,
        rect.height() * ppp,
    ]
}

impl App {
    /// The frame's egui pass: every panel, then what its clicks asked for.
    /// Runs before the key and mouse bindings; sets the camera's rectangle.
    pub(super) fn ui_pass(&mut self, mouse: glam::DVec2) {
        let mut actions = Vec::new();
        let laws_before = Laws::of(&self.world);
        egui_macroquad::ui(|ctx| {
            let dpi = macroquad::window::screen_dpi_scale();
            let wanted_ppp = dpi * self.ui.scale;
            if self.ui.applied != Some((self.ui.scale, self.ui.theme))
                || (ctx.pixels_per_point() - wanted_ppp).abs() > 1e-3
            {
                theme::apply(ctx, wanted_ppp, self.ui.theme);
                self.ui.applied = Some((self.ui.scale, self.ui.theme));
            }
            let ppp = px_per_point(ctx);
            self.ui.widgets.clear();
            self.ui.text_focus = false;
            let mut panels = Vec::new();
            panels.push(to_px(self.top_bar(ctx), ppp));
            if self.ui.docks_open && self.ui.side_open {
                panels.push(to_px(self.controls(ctx, &mut actions), ppp));
            }
            if self.ui.docks_open {
                panels.push(to_px(self.dock(ctx, &mut actions), ppp));
            }
            panels.push(to_px(self.strip(ctx), ppp));
            let world = ctx.available_rect();
            self.popups(ctx, &mut actions);
            // Only a text field keeps the keyboard. egui moves focus to
            // buttons on Tab and the arrow keys, which are shortcuts here
            // (Tab hides the docks, the arrows pan), and a focused button
            // would take Space as a click.
            if !self.ui.text_focus {
                if let Some(id) = ctx.memory(|m| m.focused()) {
                    ctx.memory_mut(|m| m.surrender_focus(id));
                }
            }
            self.ui.typing = self.ui.text_focus;
            let over_area = ctx.is_pointer_over_area() || ctx.is_using_pointer();
            let m = egui::pos2(mouse.x as f32 / ppp, mouse.y as f32 / ppp);
            self.ui.pointer_on_ui = over_area || !world.contains(m);
            let screen = ctx.screen_rect();
            // A panel's content may reach past the window's edge; what is
            // drawn is clipped to the window.
            let panels = panels
                .into_iter()
                .map(|[x, y, w, h]| {
                    let (right, bottom) = (
                        (x + w).min(screen.width() * ppp),
                        (y + h).min(screen.height() * ppp),
                    );
                    [x, y, right - x, bottom - y]
                })
                .collect();
            self.ui.layout = Layout {
                window: [screen.width() * ppp, screen.height() * ppp],
                world: to_px(world, ppp),
                panels,
                min_text_px: theme::min_text_points(ctx) * ppp,
                ui_scale: self.ui.scale,
            };
        });
        // A law changed on a panel (a slider, a menu) can be undone: the
        // scene before it is the scene now with the old laws.
        if let Some(what) = laws_before.changed_in(&self.world) {
            let mut before = self.moment();
            laws_before.put(&mut before.world);
            let now = macroquad::time::get_time();
            self.undo.remember(|| before, what, now);
        }
        for action in actions {
            self.act(action);
        }
        self.place_world();
    }

    /// Gives the camera the world's rectangle; a view that was fitted stays
    /// fitted when the rectangle changes (a resize, a dock opened, a scale).
    fn place_world(&mut self) {
        let [x, y, w, h] = self.ui.layout.world;
        let origin = glam::DVec2::new(f64::from(x), f64::from(y));
        let size = glam::DVec2::new(f64::from(w), f64::from(h)).max(glam::DVec2::ONE);
        if origin != self.camera.origin || size != self.camera.viewport {
            self.camera.set_rect(origin, size);
            if self.camera_fitted {
                self.fit_camera();
            }
        }
    }

    /// Carries out what a click asked for.
    fn act(&mut self, action: Action) {
        match action {
            Action::OpenPreset(k) => {
                self.ui.presets_open = false;
                self.open_preset(k);
            }
            Action::CenterOfMassFrame => self.toggle_center_of_mass_view(),
            Action::Undo => self.undo_change(),
            Action::Redo => self.redo_change(),
            Action::NextCollision => self.run_to_next_collision(),
            Action::Scrub(k) => self.scrub(k),
            Action::ApplySelected => self.apply_disc_fields(),
            Action::DeleteSelected => self.delete_selected(),
            Action::Open => self.open_from_panel(),
            Action::Save => self.save_from_panel(),
            Action::Share => self.share_link(),
            Action::Reset => self.reset_scene(),
            Action::Clear => self.clear_discs(),
            Action::Export => self.export_data(),
            Action::Screenshot => self.request_screenshot(),
            Action::Fit => self.fit_camera(),
            Action::Zoom(factor) => {
                let centre = self.camera.screen_center();
                self.camera.zoom_at(centre, factor);
                self.camera_fitted = false;
            }
            Action::Fullscreen => self.toggle_fullscreen(),
            Action::RecoveryRestore => self.restore_recovery(),
            Action::RecoverySetAside => self.set_recovery_aside(),
        }
    }

    /// Fits the box into the world's rectangle; in a box with open sides,
    /// the box and every disc that has left it.
    pub(super) fn fit_camera(&mut self) {
        let margin = 24.0 * f64::from(self.ui.scale);
        let (mut lo, mut hi) = (glam::DVec2::ZERO, self.world.laws.size);
        if self.follows_discs() {
            for p in self.world.particles.iter().filter(|p| p.pos.is_finite()) {
                lo = lo.min(p.pos - glam::DVec2::splat(p.radius));
                hi = hi.max(p.pos + glam::DVec2::splat(p.radius));
            }
        }
        self.camera.fit_rect(lo, hi, margin);
        self.camera_fitted = true;
    }

    /// Whether a fitted view follows the discs out of the box: a box with
    /// open sides (the π blocks leave through theirs).
    pub(super) fn follows_discs(&self) -> bool {
        self.world.laws.boundary == impulse::Boundary::Box && !self.world.laws.walls.all()
    }
}

/// A red or green line of feedback.
fn show_note(ui: &mut egui::Ui, note: &Note) -> egui::Response {
    let color = if note.error {
        if ui.visuals().dark_mode {
            egui::Color32::from_rgb(255, 120, 110)
        } else {
            egui::Color32::from_rgb(170, 0, 0)
        }
    } else if ui.visuals().dark_mode {
        egui::Color32::from_rgb(120, 230, 140)
    } else {
        egui::Color32::from_rgb(0, 110, 30)
    };
    ui.add(egui::Label::new(egui::RichText::new(&note.text).color(color)).wrap())
}
