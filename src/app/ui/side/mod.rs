//! The side dock (or, where the window is small, the drawer): the transport
//! buttons and, in collapsible sections that scroll, what the collisions do
//! (Collisions), what is drawn (Show), new discs, the selected disc, scene
//! files, the view and, under *More*, the rough-disc laws and the solver's
//! details. Every control that has a key says so in its tooltip, from the
//! bindings table.
//!
//! - [`laws`]: the Collisions section and the advanced laws under More.
//! - [`discs`]: New discs and Selected disc.
//! - [`files`]: Scene, View and Details.

mod discs;
pub mod files;
mod laws;

use super::dialog::scroll;
use super::widgets::{button_text_width, command_button, wide_labelled_button};
use super::{Cx, View};
use crate::app::lang::tr;
use crate::app::model::overlays::{spin_shown, ReadoutScope, DELTA_P_MAX_DISCS};
use crate::app::model::start::{Section, Tile};
use crate::app::model::Command;
use crate::app::ui::tip::Tip;
use egui::{CollapsingHeader, Ui};

/// The side dock's own state: the fields being typed in.
pub struct SideDock {
    fields: discs::DiscFields,
    /// The scene path field.
    path: String,
    /// The scene name field.
    name: files::NameField,
    /// Whether *Selected disc* opens for the person's next pick.
    selected_section: SelectedSection,
}

/// Whether *Selected disc* follows the person's picks: it opens when they
/// pick a disc, and scrolls into sight (a click on a disc showed a folded
/// header, often below the fold, its fields two steps away), until they
/// fold it by hand. A disc selected for them (a new one, a preset's)
/// leaves the controls where they were.
#[derive(Default)]
struct SelectedSection {
    folded_by_hand: bool,
    /// The model's count of picks when last seen.
    picks: u32,
    /// Opened for a pick: to be brought into sight once open.
    reveal: bool,
}

impl SelectedSection {
    /// `Some(true)` when the section should open this frame: the person
    /// picked a disc since the last.
    fn follow(&mut self, picks: u32, selected: Option<usize>) -> Option<bool> {
        let picked = picks != self.picks && selected.is_some();
        self.picks = picks;
        let open = picked && !self.folded_by_hand;
        self.reveal |= open;
        open.then_some(true)
    }

    /// After the section was shown: a click on its header says whether the
    /// person wants it; opened for a pick, its header goes to the top
    /// of the controls unless the whole of it is in sight.
    fn shown(&mut self, ui: &Ui, section: Shown) {
        if let Some(open) = section.clicked {
            self.folded_by_hand = !open;
            self.reveal = false;
        }
        if let (true, Some(whole)) = (self.reveal, section.whole) {
            if !ui.clip_rect().contains_rect(whole) {
                ui.scroll_to_rect(section.header, Some(egui::Align::TOP));
            }
            self.reveal = false;
        }
    }
}

/// What a section's frame did: `clicked` is `Some(open)` when its header
/// was clicked, whether it is open now; `whole` its place once fully open.
struct Shown {
    clicked: Option<bool>,
    header: egui::Rect,
    whole: Option<egui::Rect>,
}

impl SideDock {
    pub fn new(path: String) -> Self {
        SideDock {
            fields: discs::DiscFields::default(),
            path,
            name: files::NameField::default(),
            selected_section: SelectedSection::default(),
        }
    }
}

/// A collapsing section whose header is noted under `name`.
fn section(
    ui: &mut Ui,
    cx: &mut Cx,
    (title, name, open): (&str, &str, bool),
    body: impl FnOnce(&mut Ui, &mut Cx),
) {
    section_opened(ui, cx, (title, name, open), None, body);
}

/// A [`section`] opened or closed this frame by `set` (`None`: as it was).
fn section_opened(
    ui: &mut Ui,
    cx: &mut Cx,
    (title, name, open): (&str, &str, bool),
    set: Option<bool>,
    body: impl FnOnce(&mut Ui, &mut Cx),
) -> Shown {
    // Tab reaches the header before its body: its place among the frame's
    // stops is the one before the body's.
    let place = cx.marks.stops.len();
    let r = CollapsingHeader::new(title)
        .id_salt(name)
        .default_open(open)
        .open(set)
        .show(ui, |ui| body(ui, cx));
    cx.note(name, &r.header_response);
    cx.marks.move_stop_to(r.header_response.id, place);
    let header = &r.header_response;
    // Its state, not its openness, which is still on the way there.
    let clicked = header.clicked().then(|| {
        egui::collapsing_header::CollapsingState::load(ui.ctx(), header.id)
            .is_some_and(|s| s.is_open())
    });
    let whole = match &r.body_response {
        Some(body) if r.fully_open() => Some(header.rect.union(body.rect)),
        _ => None,
    };
    Shown {
        clicked,
        header: header.rect,
        whole,
    }
}

impl View for SideDock {
    fn ui(&mut self, ui: &mut Ui, cx: &mut Cx) {
        transport(ui, cx);
        ui.separator();
        let focus = cx.model.panels.focus;
        let fields = &mut self.fields;
        let path = &mut self.path;
        let name = &mut self.name;
        let selected_section = &mut self.selected_section;
        let open_selected =
            selected_section.follow(cx.model.panels.picks, cx.model.selected_disc());
        // Room beside the controls for the scroll handle shown at rest: at
        // text size 1 the value fields ran under it.
        let bar = &mut ui.spacing_mut().scroll;
        bar.floating_allocated_width = bar.floating_width + bar.bar_outer_margin + 2.0;
        scroll(
            ui,
            cx,
            egui::ScrollArea::vertical(),
            "controls",
            |ui, cx| {
                ui.set_width(ui.available_width());
                if focus != Tile::FreePlay {
                    let line = tr!("controls-for", lesson = focus.title());
                    ui.add(egui::Label::new(line).wrap());
                    command_button(ui, cx, Command::ShowAllControls, Some("all_controls"));
                }
                let title = match cx.model.selected_disc() {
                    Some(i) => tr!(
                        "selected-disc-numbered",
                        disc = crate::app::numbers::disc_number(i)
                    ),
                    None => tr!("section-selected-disc"),
                };
                for s in SECTIONS {
                    if !focus.shows(s) {
                        continue;
                    }
                    match s {
                        Section::Collisions => {
                            let title = tr!("section-collisions");
                            section(ui, cx, (&title, "section_collisions", true), laws::laws)
                        }
                        Section::Show => {
                            let title = tr!("section-show");
                            section(ui, cx, (&title, "section_show", true), show)
                        }
                        Section::NewDiscs => {
                            let title = tr!("section-new-discs");
                            section(
                                ui,
                                cx,
                                (&title, "section_new_discs", false),
                                discs::new_discs,
                            )
                        }
                        Section::Selected => {
                            let shown = section_opened(
                                ui,
                                cx,
                                (&title, "section_selected", false),
                                open_selected,
                                |ui, cx| fields.ui(ui, cx),
                            );
                            selected_section.shown(ui, shown);
                        }
                        Section::Scene => {
                            let title = tr!("section-scene");
                            section(ui, cx, (&title, "section_scene", false), |ui, cx| {
                                files::scene(ui, cx, path, name);
                            })
                        }
                        Section::View => {
                            let title = tr!("section-view");
                            section(ui, cx, (&title, "section_view", false), files::view)
                        }
                        Section::More => {
                            let title = tr!("section-more");
                            section(ui, cx, (&title, "section_more", false), |ui, cx| {
                                ui.add(egui::Label::new(tr!("section-more-line")).wrap());
                                if !spin_shown(&cx.model.world) {
                                    laws::advanced(ui, cx);
                                    ui.separator();
                                }
                                files::details(ui, cx);
                            })
                        }
                    }
                }
            },
        );
    }
}

/// The sections in the dock's order.
const SECTIONS: [Section; 7] = [
    Section::Collisions,
    Section::Show,
    Section::NewDiscs,
    Section::Selected,
    Section::Scene,
    Section::View,
    Section::More,
];

/// Play or pause, step, reset, undo, redo, then slower, faster, presets,
/// fit and help: in the drawer these five under "… more", a menu (in German
/// at a projector's size the ten buttons took seven rows, two thirds of the
/// drawer, and left the sections two hundred pixels).
fn transport(ui: &mut Ui, cx: &mut Cx) {
    let rest = [
        (Command::Slower, "slower"),
        (Command::Faster, "faster"),
        (Command::TogglePresets, "presets"),
        (Command::Fit, "fit"),
        (Command::ToggleHelp, "help"),
    ];
    ui.horizontal_wrapped(|ui| {
        // As wide as the wider of its two labels: "⏸ Pause" is wider than
        // "▶ Play", and the buttons after it had moved a place as the clock
        // started (a teacher who paused and clicked where Undo was pressed
        // Redo).
        let (play, pause) = (format!("▶ {}", tr!("play")), format!("⏸ {}", tr!("pause")));
        let width = button_text_width(ui, play.as_str()).max(button_text_width(ui, pause.as_str()))
            + 2.0 * ui.spacing().button_padding.x;
        let label = if cx.model.clock.paused { play } else { pause };
        wide_labelled_button(ui, cx, (label, width), Command::TogglePause, Some("play"));
        command_button(ui, cx, Command::Step, Some("step"));
        command_button(ui, cx, Command::Reset, Some("reset"));
        command_button(ui, cx, Command::Undo, Some("undo"));
        command_button(ui, cx, Command::Redo, Some("redo"));
        if !cx.drawer {
            for (command, name) in rest {
                command_button(ui, cx, command, Some(name));
            }
            return;
        }
        // The menu's contents are laid out while it is open (egui's answer
        // says so only as it closes).
        let mut open = false;
        let menu = ui.menu_button(tr!("top-bar-more"), |ui| {
            open = true;
            for (command, name) in rest {
                if command_button(ui, cx, command, Some(name)).clicked() {
                    ui.close_menu();
                }
            }
        });
        cx.marks.menu_open |= open;
        cx.note("transport_more", &menu.response);
    });
}

/// A checkbox that sends `command` when clicked.
fn toggle(
    ui: &mut Ui,
    cx: &mut Cx,
    on: bool,
    label: &str,
    command: Command,
    hover: &str,
) -> egui::Response {
    let mut value = on;
    let tip = crate::app::model::bindings::tooltip(&command);
    let hover = match (hover.is_empty(), tip.is_empty()) {
        (true, _) => tip,
        (false, true) => hover.to_string(),
        (false, false) => format!("{hover}\n{tip}"),
    };
    let mut r = ui.checkbox(&mut value, label);
    if !hover.is_empty() {
        r = r.tip(hover);
    }
    if r.clicked() {
        cx.send(command);
    }
    r
}

/// What is drawn over the discs.
fn show(ui: &mut Ui, cx: &mut Cx) {
    let o = cx.model.overlays;
    let names = crate::app::look::arrow_names(cx.model.panels.theme);
    let colour = |id: &str| crate::app::lang::text(id, &[]);
    toggle(
        ui,
        cx,
        o.velocity,
        &tr!("show-velocity", colour = colour(names.velocity)),
        Command::ToggleVelocity,
        &tr!("show-velocity-hover"),
    );
    toggle(
        ui,
        cx,
        o.momentum,
        &tr!("show-momentum", colour = colour(names.momentum)),
        Command::ToggleMomentum,
        &tr!("show-momentum-hover"),
    );
    toggle(
        ui,
        cx,
        o.delta_p,
        &tr!("show-delta-p", colour = colour(names.delta_p)),
        Command::ToggleDeltaP,
        &tr!("show-delta-p-hover", most = DELTA_P_MAX_DISCS),
    );
    let scopes = [
        (ReadoutScope::Off, tr!("readouts-none")),
        (ReadoutScope::Selected, tr!("readouts-selected")),
        (ReadoutScope::All, tr!("readouts-all")),
    ];
    let current = scopes
        .iter()
        .find(|(s, _)| *s == o.readouts)
        .map_or_else(String::new, |(_, l)| l.clone());
    let tip = crate::app::model::bindings::tooltip(&Command::CycleReadouts);
    let hover = format!("{tip}\n{}", tr!("readouts-hover"));
    let names = scopes.clone().map(|(_, label)| label);
    let at = scopes.iter().position(|(s, _)| *s == o.readouts);
    let words = (&*tr!("readouts-label"), &*hover, "readouts");
    if let Some(k) = super::widgets::pick(ui, cx, words, &names, at, &current) {
        cx.send(Command::SetReadouts(scopes[k].0));
    }
    toggle(
        ui,
        cx,
        o.center_of_mass,
        &tr!("show-center-of-mass"),
        Command::ToggleCenterOfMass,
        &tr!("show-center-of-mass-hover"),
    );
    toggle(
        ui,
        cx,
        cx.model.record.trails.on,
        &tr!("help-trails"),
        Command::ToggleTrails,
        "",
    );
    toggle(
        ui,
        cx,
        o.safe_palette,
        &tr!("show-safe-palette"),
        Command::TogglePalette,
        "",
    );
    ui.horizontal_wrapped(|ui| {
        command_button(ui, cx, Command::NextCollision, Some("next_collision"));
        command_button(ui, cx, Command::Scrub(-1), None);
        command_button(ui, cx, Command::Scrub(1), None);
        toggle(
            ui,
            cx,
            o.com_view.is_some(),
            &tr!("show-com-view"),
            Command::ToggleCenterOfMassView,
            &tr!("show-com-view-hover"),
        );
    });
}
