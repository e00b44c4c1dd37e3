//! Every panel of the window, in egui (through `egui-macroquad`): the top
//! bar, the controls docked at the side (or, where the window is small, in
//! a drawer), the caption strip and the bottom dock with its tabs, and the
//! popups the user opens (help, presets, the recovery question).
//!
//! Each panel is a [`View`]: it reads the model ([`Sandbox`]) and pushes
//! [`Command`]s; it never changes the model itself and never reaches into
//! another view. Where everything goes is decided before any panel is
//! drawn, by [`crate::app::layout::layout`], from the window's size, the UI
//! scale and which docks are open; the panels take exactly the rectangles
//! it gives, so a message or a tab that opens never moves the world (a
//! scene whose caption needs two rows gets them when it opens). The pass runs first in each frame, so the key and mouse bindings
//! know whether a text field has the keyboard and whether the pointer is on
//! a panel.
//!
//! - [`top_bar`]: scene, time, running or paused, the totals, the counts.
//! - [`side`]: the side dock's sections (also the drawer's).
//! - [`dock`]: the bottom dock's tab row and its tabs, one file each.
//! - [`strip`]: the strip under the world: scale bar, caption, messages.
//! - [`popups`]: help (from the bindings table), presets, recovery.
//! - [`start`]: the start screen's tiles.
//! - [`dialog`]: the boxes over the world and scroll areas, whose own parts
//!   Tab passes over.
//! - [`marks`]: what the views note for the state dump and the keyboard.
//! - [`regions`]: F6, the keyboard's jump between the window's parts.
//! - [`touch`]: a finger's press held for a tooltip presses nothing.

mod dialog;
mod dock;
mod focus;
mod marks;
mod popups;
mod regions;
mod side;
mod start;
mod strip;
pub(crate) mod tip;
mod top_bar;
mod touch;
mod typing;
pub mod widgets;

use crate::app::layout::{self, Docks, Rects, SideDock};
use crate::app::look;
use crate::app::model::{Command, Sandbox, Theme};
use marks::to_px;
pub use marks::{ListScroll, Marks, Stop};
use serde::Serialize;

/// A panel: reads the model, pushes commands.
pub trait View {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx);
}

/// What a view is given: the model to read, where its commands go, and
/// where it notes its widgets (for the state dump) and text fields.
pub struct Cx<'a> {
    pub model: &'a Sandbox,
    pub out: &'a mut Vec<Command>,
    pub marks: &'a mut Marks,
    /// The side dock is a drawer: the top bar carries its button.
    pub drawer: bool,
    /// Where the drawer is while it is open (points): the strip's text
    /// stops short of it.
    pub open_drawer: Option<egui::Rect>,
    /// Where the keys go: the strip says how to give them back.
    pub keys: Keys,
}

/// Where the keys go.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Keys {
    /// To the world: its shortcuts.
    World,
    /// To a control that has the keyboard.
    Controls,
    /// To the panels after Enter applied a field, all but the clock's
    /// (Space, N, J), which act on the simulation.
    AfterField,
    /// To the dock's top edge: the arrows make the tab taller or shorter.
    TabEdge,
}

impl Cx<'_> {
    /// Pushes a command.
    pub fn send(&mut self, command: Command) {
        self.out.push(command);
    }

    /// Notes a widget's rectangle under `name` (for the state dump), and
    /// its layer, so that one a dialog covers is left out
    /// ([`Marks::leave_out_covered`]).
    pub fn note(&mut self, name: impl Into<String>, response: &egui::Response) {
        let name = name.into();
        if response.has_focus() {
            self.marks.focused = Some(name.clone());
        }
        if response.sense.is_focusable() {
            self.marks.stops.push(Stop::control(response));
        }
        self.marks
            .named
            .insert(name.clone(), (response.layer_id, response.id));
        self.marks.note(name, response.rect);
    }
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
    /// The side dock: "docked", "drawer" or "hidden".
    pub side: String,
    /// The drawer's rectangle, while it is open over the world.
    pub drawer: Option<[f32; 4]>,
    /// The open tab had no room and folded to the tab row.
    pub tab_folded: bool,
    /// The smallest font size drawn, in physical pixels.
    pub min_text_px: f32,
    /// The UI scale.
    pub ui_scale: f32,
}

/// The panels between frames: each view with its own state, and what the
/// key bindings need to know of them.
pub struct Panels {
    /// The scale and theme egui was last given.
    applied: Option<(f32, Theme)>,
    top_bar: top_bar::TopBar,
    side: side::SideDock,
    dock: dock::BottomDock,
    strip: strip::Strip,
    popups: popups::Popups,
    start: start::StartScreen,
    /// This frame's notes.
    pub marks: Marks,
    /// A control has the keyboard (or had it last frame, when Esc or Tab
    /// may have taken it away): the world's keys stay quiet.
    pub typing: bool,
    /// A text field was left with Enter: the keyboard stays with the panel
    /// (no shortcuts) until a click in the world or Esc.
    pub panel_keyboard: bool,
    /// Where the keyboard was, frame to frame.
    trail: FocusTrail,
    /// The pointer is on a panel or popup: the world ignores it.
    pub pointer_on_ui: bool,
    /// This frame's layout.
    pub layout: Layout,
    /// This frame's rectangles.
    pub rects: Option<Rects>,
}

/// Where the keyboard was, frame to frame.
#[derive(Default)]
struct FocusTrail {
    /// A control had the keyboard last frame.
    had_focus: bool,
    /// The last Tab was Shift+Tab.
    tab_back: bool,
    /// What had the keyboard when the last frame's views were laid out.
    seen: Option<egui::Id>,
    /// A jump between the window's parts (F6) to carry out.
    jump: Option<regions::Jump>,
    /// The part of the window the keyboard is in.
    part: regions::Part,
    /// The last frame's parts.
    parts: Option<regions::Parts>,
    /// The text field last left with Enter: Tab goes on from it.
    left_field: Option<egui::Id>,
    /// F6 opened the drawer: F6 out of the controls closes it again (it
    /// stayed over the world the person went back to).
    drawer_by_jump: bool,
}

impl Panels {
    /// The panels at start; `path` fills the scene section's path field.
    pub fn new(path: String) -> Self {
        Panels {
            applied: None,
            top_bar: top_bar::TopBar,
            side: side::SideDock::new(path),
            dock: dock::BottomDock::new(),
            strip: strip::Strip,
            popups: popups::Popups,
            start: start::StartScreen,
            marks: Marks::default(),
            typing: false,
            trail: FocusTrail::default(),
            panel_keyboard: false,
            pointer_on_ui: false,
            layout: Layout::default(),
            rects: None,
        }
    }

    /// F6 (`back`: Shift+F6) was pressed: the next frame gives the
    /// keyboard to the window's next part ([`regions`]).
    pub fn jump_to_next_part(&mut self, back: bool, modal: bool) {
        if !modal {
            self.trail.jump = Some(regions::Jump {
                back,
                to: None,
                waited: 0,
            });
        }
    }

    /// Carries out a jump F6 asked for ([`regions`]).
    fn jump(&mut self, ctx: &egui::Context, model: &Sandbox, out: &mut Vec<Command>) {
        let (Some(jump), Some(parts), Some(rects)) =
            (self.trail.jump.take(), &self.trail.parts, &self.rects)
        else {
            return;
        };
        let tab = format!("tab_{}", model.panels.tab.key().to_lowercase());
        let from = (jump, self.trail.part);
        let drawer_open = matches!(rects.side_dock, SideDock::Drawer { open: true });
        self.trail.drawer_by_jump &= drawer_open;
        match parts.carry_out(ctx, from, &self.marks, rects, &tab, out) {
            regions::Jumped::Waiting(jump) => {
                self.trail.jump = Some(jump);
                self.trail.drawer_by_jump = true;
            }
            regions::Jumped::Done(to) => {
                let left = from.1 == regions::Part::Controls && to != regions::Part::Controls;
                if left && std::mem::take(&mut self.trail.drawer_by_jump) {
                    out.push(Command::ToggleDrawer);
                }
                if to == regions::Part::World {
                    self.panel_keyboard = false;
                }
            }
            regions::Jumped::Nothing => {}
        }
    }

    /// The frame's egui pass: lays the panels out, draws each, and returns
    /// what their clicks asked for. Runs before the key and mouse bindings.
    pub fn pass(&mut self, model: &Sandbox, mouse: glam::DVec2) -> Vec<Command> {
        let mut out = Vec::new();
        egui_macroquad::cfg(touch::hold_is_not_a_tap);
        egui_macroquad::ui(|ctx| self.frame(ctx, model, mouse, &mut out));
        if let Some(field) = self.marks.left_with_enter {
            self.trail.left_field = Some(field);
            self.panel_keyboard = true;
        }
        out
    }

    fn frame(
        &mut self,
        ctx: &egui::Context,
        model: &Sandbox,
        mouse: glam::DVec2,
        out: &mut Vec<Command>,
    ) {
        let p = &model.panels;
        if self.applied.is_none() {
            ctx.set_fonts(look::font_definitions());
        }
        let dpi = macroquad::window::screen_dpi_scale();
        let wanted_ppp = dpi * p.scale;
        if self.applied != Some((p.scale, p.theme))
            || (ctx.pixels_per_point() - wanted_ppp).abs() > 1e-3
        {
            look::apply(ctx, wanted_ppp, p.theme);
            self.applied = Some((p.scale, p.theme));
        }
        look::fit_tooltips(ctx);
        let ppp = px_per_point(ctx);
        typing::drop_characters_typed_with_ctrl(ctx);
        let keypad_enter = macroquad::input::is_key_pressed(macroquad::input::KeyCode::KpEnter);
        typing::keypad_enter_as_enter(ctx, keypad_enter);
        let saving = typing::enter_before_saving(ctx);
        // Before the views, on the last frame's notes: a field given the
        // keyboard now gains it as it is made, and selects its text.
        self.jump(ctx, model, out);
        // After Enter in a field, Tab and Shift+Tab go on from that field
        // (egui, with nothing focused, went to the first control or the
        // last): egui moves on from what has the keyboard.
        if let Some(field) = self.trail.left_field.filter(|_| self.panel_keyboard) {
            let tab = ctx.input(|i| i.key_pressed(egui::Key::Tab));
            if tab && ctx.memory(|m| m.focused().is_none()) {
                ctx.memory_mut(|m| m.request_focus(field));
            }
        }
        dialog::note_focus(ctx, &mut self.trail.seen);
        let last_stops = self.marks.stops.iter().map(|s| s.id).collect();
        self.marks = Marks {
            ppp,
            last_stops,
            ..Marks::default()
        };
        let screen = ctx.screen_rect();
        let window = (screen.width() * ppp, screen.height() * ppp);
        let docks = Docks {
            shown: p.docks_open,
            side: p.side_open,
            tab_open: p.dock_expanded,
            drawer_open: p.drawer_open,
            tab_height: p.tab_height,
            caption_lines: self.strip.lines(),
        };
        let rects = layout::layout(window, p.scale, docks);
        let points = |r: layout::Rect| {
            egui::Rect::from_min_size(
                egui::pos2(r.x / ppp, r.y / ppp),
                egui::vec2(r.w / ppp, r.h / ppp),
            )
        };
        let mut cx = Cx {
            model,
            out,
            marks: &mut self.marks,
            drawer: matches!(rects.side_dock, SideDock::Drawer { .. }),
            open_drawer: rects.drawer.map(points),
            keys: if self.typing && ctx.memory(|m| m.has_focus(dock::edge::id())) {
                Keys::TabEdge
            } else if self.typing {
                Keys::Controls
            } else if self.panel_keyboard {
                Keys::AfterField
            } else {
                Keys::World
            },
        };
        let mut panels = Vec::new();
        // The start screen first: egui's Tab walks the controls in the
        // order they are made, so its tiles come before the panels behind
        // it (it is drawn over them all the same).
        self.start
            .show(ctx, &mut cx, points(rects.top_bar).bottom());
        let top_bar = cx.marks.stops.len();
        egui::TopBottomPanel::top("top_bar")
            .exact_height(points(rects.top_bar).height())
            .show(ctx, |ui| self.top_bar.ui(ui, &mut cx));
        let controls = cx.marks.stops.len();
        panels.push(rects.top_bar.as_array());
        // The drawer next, though it floats over the panels made after it:
        // Tab goes from its button in the top bar into it, not first
        // through the tabs it covers.
        if let Some(drawer) = rects.drawer {
            let r = points(drawer);
            dialog::Dialog::new("drawer", None)
                .place(dialog::Place::At(r.min))
                .fixed_size(egui::vec2(r.width() - 16.0, r.height() - 48.0))
                .show(ctx, &mut cx, |ui, cx| self.side.ui(ui, cx));
        }
        if let Some(side) = rects.side {
            egui::SidePanel::right("controls")
                .resizable(false)
                .exact_width(points(side).width())
                .show(ctx, |ui| self.side.ui(ui, &mut cx));
            panels.push(side.as_array());
        }
        let tabs = cx.marks.stops.len();
        if let (Some(row), content) = (rects.tab_row, rects.tab_content) {
            let height = row.h + content.map_or(0.0, |c| c.h);
            egui::TopBottomPanel::bottom("dock")
                .resizable(false)
                .exact_height(height / ppp)
                .show(ctx, |ui| {
                    let edge = content.zip(layout::tab_range(window, p.scale, docks)).map(
                        |(c, (least, most))| dock::edge::TabEdge {
                            height: c.h,
                            least,
                            most,
                            row: row.h,
                            ppp,
                        },
                    );
                    self.dock.show(ui, &mut cx, row.h / ppp, edge)
                });
            panels.push(row.as_array());
            if let Some(content) = content {
                panels.push(content.as_array());
            }
        }
        let parts = regions::Parts {
            top_bar: top_bar..controls,
            controls: controls..tabs,
            tabs: tabs..cx.marks.stops.len(),
        };
        egui::TopBottomPanel::bottom("strip")
            .exact_height(points(rects.caption).height())
            .show(ctx, |ui| self.strip.ui(ui, &mut cx));
        panels.push(rects.caption.as_array());
        self.popups.show(ctx, &mut cx);
        self.marks.leave_out_covered();
        // A slider's value box typed into keeps the keyboard too.
        let boxed = egui::Id::new(widgets::TYPING_IN_A_BOX);
        if ctx
            .data_mut(|d| d.remove_temp::<bool>(boxed))
            .unwrap_or(false)
        {
            self.marks.text_focus = true;
        }
        // The layout says where the side dock is: a drawer left open while
        // it docked again is closed, not kept for later.
        if p.drawer_open && !matches!(rects.side_dock, SideDock::Drawer { .. }) {
            out.push(Command::CloseDrawer);
        }
        // Ctrl+S in a field: saved after what the field applied.
        if saving {
            out.push(Command::Save);
        }
        let world = ctx.available_rect();
        let over_area = ctx.is_pointer_over_area() || ctx.is_using_pointer();
        let m = egui::pos2(mouse.x as f32 / ppp, mouse.y as f32 / ppp);
        self.pointer_on_ui = over_area || !world.contains(m);
        // Tab (and Shift+Tab) move the keyboard through the controls; while
        // one has it, the world's keys are off, until Esc (egui lets go) or
        // a click in the world.
        if let Some(back) = ctx.input(|i| {
            i.events.iter().rev().find_map(|e| match e {
                egui::Event::Key {
                    key: egui::Key::Tab,
                    pressed: true,
                    modifiers,
                    ..
                } => Some(modifiers.shift),
                _ => None,
            })
        }) {
            self.trail.tab_back = back;
        }
        let with_panel = self.panel_keyboard || self.marks.left_with_enter.is_some();
        let before = self.trail.part;
        self.trail.part = parts.part_now(ctx, &self.marks, before, with_panel);
        self.trail.parts = Some(parts);
        let mut focused = dialog::pass_over_containers(ctx, &self.marks, self.trail.tab_back);
        if let Some(id) = focused {
            if !self.pointer_on_ui && ctx.input(|i| i.pointer.any_pressed()) {
                ctx.memory_mut(|m| m.surrender_focus(id));
                focused = None;
            }
        }
        if let Some(id) = focused {
            focus::focus_ring(ctx, id, p.theme);
        }
        let tooltips: Vec<egui::LayerId> = ctx.memory(|m| {
            let layers = m.areas().visible_layer_ids();
            layers
                .into_iter()
                .filter(|l| l.order == egui::Order::Tooltip)
                .collect()
        });
        self.marks.tooltips = tooltips.len();
        self.marks.tooltip_rect = tooltips
            .first()
            .and_then(|l| egui::AreaState::load(ctx, l.id))
            .map(|a| to_px(a.rect(), ppp));
        self.marks.focus_rect = focused
            .and_then(|id| ctx.read_response(id))
            .map(|r| to_px(r.rect, ppp));
        // egui lets go of a control at the start of the frame whose key
        // (Esc, Tab, Enter) left it: that key belongs to the control. So
        // does the Esc that closed a menu.
        let has_focus = focused.is_some() || self.marks.text_focus || self.marks.menu_open;
        self.typing = has_focus || self.trail.had_focus;
        self.trail.had_focus = has_focus;
        self.layout = Layout {
            window: [window.0, window.1],
            world: rects.world.as_array(),
            panels,
            side: match rects.side_dock {
                SideDock::Docked => "docked",
                SideDock::Drawer { .. } => "drawer",
                SideDock::Hidden => "hidden",
            }
            .to_string(),
            drawer: rects.drawer.map(|r| r.as_array()),
            tab_folded: rects.tab_folded,
            min_text_px: look::min_text_points(ctx) * ppp,
            ui_scale: p.scale,
        };
        self.rects = Some(rects);
    }
}

/// The app's pixels per egui point. The app's pixels are macroquad's: the
/// mouse, the camera and the dump use them (a window's pixels on a desktop,
/// CSS pixels in a browser), while egui draws `dpi` times as many device
/// pixels on a high-density screen, so text is as large and sharper there.
pub fn px_per_point(ctx: &egui::Context) -> f32 {
    ctx.pixels_per_point() / macroquad::window::screen_dpi_scale()
}
