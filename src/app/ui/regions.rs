//! F6 and Shift+F6: the keyboard jumps between the window's parts (the
//! controls, the tabs, the top bar and back to the world), as in other
//! desktop programs; Tab then walks the part it landed in. Into the
//! controls it lands on the selected disc's mass where that shows (some
//! thirty Tabs from the top bar at a projector's size), and opens a closed
//! drawer first (which F6 out of the controls closes again).
//!
//! A part is known by its Tab stops, not by where its controls are drawn:
//! a field being scrolled into the drawer's sight is in the drawer before
//! its rectangle is.

use super::marks::{Marks, Stop};
use crate::app::layout::{Rects, SideDock};
use crate::app::model::Command;
use std::ops::Range;

/// The window's parts, in F6's order.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Part {
    /// The world: no control has the keyboard, the shortcuts work.
    #[default]
    World,
    /// The side dock or its drawer.
    Controls,
    /// The bottom dock: its tab row and the open tab.
    Tabs,
    TopBar,
}

/// Frames a jump waits for the drawer it opened.
const WAIT_FOR_DRAWER: u8 = 5;

/// F6's order: the controls first, the part a person reaches for.
const ORDER: [Part; 4] = [Part::World, Part::Controls, Part::Tabs, Part::TopBar];

/// A jump F6 asked for, carried out as the next frame begins, on the
/// controls the frame before noted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Jump {
    /// Shift+F6: the part before.
    pub back: bool,
    /// The part chosen, while it waits for a drawer to open.
    pub to: Option<Part>,
    /// Frames waited so far.
    pub waited: u8,
}

/// What a jump did.
#[derive(Debug, PartialEq)]
pub enum Jumped {
    /// The keyboard went to a control, or back to the world.
    Done(Part),
    /// The drawer was asked to open; the jump waits for it.
    Waiting(Jump),
    /// Nowhere to go.
    Nothing,
}

/// Each part's Tab stops in a frame: where they are in [`Marks::stops`]
/// (the views are made in the order top bar, controls, tabs).
#[derive(Clone, Debug, Default)]
pub struct Parts {
    pub top_bar: Range<usize>,
    pub controls: Range<usize>,
    pub tabs: Range<usize>,
}

impl Parts {
    fn stops(&self, part: Part) -> Range<usize> {
        match part {
            Part::World => 0..0,
            Part::Controls => self.controls.clone(),
            Part::Tabs => self.tabs.clone(),
            Part::TopBar => self.top_bar.clone(),
        }
    }

    /// The part that has the keyboard now: that of the control that has
    /// it; with none, `before` while the keyboard stays with the panel
    /// after Enter in a field (`with_panel`), else the world.
    pub fn part_now(
        &self,
        ctx: &egui::Context,
        marks: &Marks,
        before: Part,
        with_panel: bool,
    ) -> Part {
        let Some(focused) = ctx.memory(|m| m.focused()) else {
            return if with_panel { before } else { Part::World };
        };
        let Some(at) = marks.stops.iter().position(|s| s.id == focused) else {
            return before; // a control that is no stop (a menu's entry)
        };
        [Part::Controls, Part::Tabs, Part::TopBar]
            .into_iter()
            .find(|&part| self.stops(part).contains(&at))
            .unwrap_or(Part::World)
    }

    /// Carries out `jump` from the part `from` on the last frame's notes
    /// (`marks`, `rects`): the keyboard goes to the next part's first
    /// control (the selected disc's mass, the open tab's name), or back to
    /// the world. `tab`: the open tab's noted name.
    pub fn carry_out(
        &self,
        ctx: &egui::Context,
        (jump, from): (Jump, Part),
        marks: &Marks,
        rects: &Rects,
        tab: &str,
        out: &mut Vec<Command>,
    ) -> Jumped {
        let closed_drawer = matches!(rects.side_dock, SideDock::Drawer { open: false });
        let to = jump.to.unwrap_or_else(|| {
            let at = ORDER.iter().position(|&p| p == from).unwrap_or(0);
            let n = ORDER.len();
            (1..n)
                .map(|k| {
                    ORDER[if jump.back {
                        (at + n - k) % n
                    } else {
                        (at + k) % n
                    }]
                })
                .find(|&part| {
                    part == Part::World
                        || !self.stops(part).is_empty()
                        || (part == Part::Controls && closed_drawer)
                })
                .unwrap_or(Part::World)
        });
        if to == Part::World {
            if let Some(id) = ctx.memory(|m| m.focused()) {
                ctx.memory_mut(|m| m.surrender_focus(id));
            }
            return Jumped::Done(Part::World);
        }
        if to == Part::Controls && closed_drawer {
            // Asked to open; it shows in a frame or two.
            if jump.to.is_none() {
                out.push(Command::ToggleDrawer);
            }
            return match jump.waited {
                0..WAIT_FOR_DRAWER => Jumped::Waiting(Jump {
                    to: Some(to),
                    waited: jump.waited + 1,
                    ..jump
                }),
                _ => Jumped::Nothing,
            };
        }
        let range = self.stops(to);
        let shown = |stop: &Stop| {
            !stop.pass
                && ctx.memory(|m| m.allows_interaction(stop.layer))
                && ctx
                    .read_response(stop.id)
                    .is_some_and(|r| !marks.covered_over(stop.layer, r.rect))
        };
        let here =
            &marks.stops[range.start.min(marks.stops.len())..range.end.min(marks.stops.len())];
        let named = |name: &str| {
            let (_, id) = *marks.named.get(name)?;
            here.iter().find(|s| s.id == id && shown(s)).map(|s| s.id)
        };
        let first = || here.iter().find(|s| shown(s)).map(|s| s.id);
        let target = match to {
            Part::Controls => named("disc_mass").or_else(first),
            Part::Tabs => named(tab).or_else(|| named("tab_menu")).or_else(first),
            _ => first(),
        };
        match target {
            Some(id) => {
                ctx.memory_mut(|m| m.request_focus(id));
                Jumped::Done(to)
            }
            None => Jumped::Nothing,
        }
    }
}
