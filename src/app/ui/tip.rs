//! Tooltips for a finger. egui shows a tooltip once the pointer has rested
//! on a control, under the control, and not after a click until the pointer
//! moves. A finger does not rest or move as a mouse does: it lands, and
//! after a tap egui would show no tooltip until a drag. egui knows touch
//! screens from touch events, but egui-macroquad passes it only the mouse
//! that macroquad makes of a finger. So while a finger is on the screen
//! (`set_finger`, once a frame) [`Tip::tip`] shows a control's tooltip once
//! the finger has been held on it for the tooltip's delay (a shorter press
//! is a tap, see `hold_is_not_a_tap`), and where a hand coming from below
//! does not cover it: above the control, else to its right, else to its
//! left, egui's own order for a touch screen.

use egui::{Context, Id, Response, WidgetText};

/// Where this frame's finger flag is kept in egui's memory.
fn finger_id() -> Id {
    Id::new("impulse_finger_on_screen")
}

/// Tells the tooltips of this frame whether a finger is on the screen.
pub fn set_finger(ctx: &Context, finger: bool) {
    ctx.data_mut(|d| d.insert_temp(finger_id(), finger));
}

fn finger(ctx: &Context) -> bool {
    ctx.data(|d| d.get_temp(finger_id())).unwrap_or(false)
}

/// A tooltip on a response, placed for a finger when one is down.
pub trait Tip {
    /// The tooltip shown when egui would show `on_hover_text`'s.
    fn tip(self, text: impl Into<WidgetText>) -> Self;
    /// The tooltip shown now, as `show_tooltip_text` shows it.
    fn tip_now(&self, text: impl Into<WidgetText>);
}

impl Tip for Response {
    fn tip(self, text: impl Into<WidgetText>) -> Self {
        if !finger(&self.ctx) {
            return self.on_hover_text(text);
        }
        if held_for_the_delay(&self) {
            show_text(&stand_in(&self), text);
        }
        self
    }

    fn tip_now(&self, text: impl Into<WidgetText>) {
        if finger(&self.ctx) {
            show_text(&stand_in(self), text);
        } else {
            show_text(self, text);
        }
    }
}

/// `text` in a tooltip now, as wide as the style's tooltip width at most
/// (as egui's `on_hover_text` makes it; its `show_tooltip_text` keeps the
/// width the tooltip first had, wider than a window made narrower since).
fn show_text(r: &Response, text: impl Into<WidgetText>) {
    r.show_tooltip_ui(|ui| {
        ui.set_max_width(ui.spacing().tooltip_width);
        ui.label(text);
    });
}

/// Whether the finger down on `r` has been held there for the tooltip's
/// delay (asking for a frame when the delay will have passed). Pressed on
/// `r` and still on it: egui's own "pressed on" ends when the press grows
/// too long to be a tap, which for a finger is this same delay.
fn held_for_the_delay(r: &Response) -> bool {
    let (down, origin, start, now) = r.ctx.input(|i| {
        let p = &i.pointer;
        (
            p.primary_down(),
            p.press_origin(),
            p.press_start_time(),
            i.time,
        )
    });
    let on_it = origin.is_some_and(|o| r.interact_rect.contains(o)) && r.contains_pointer();
    let (true, true, Some(start)) = (down, on_it, start) else {
        return false;
    };
    let delay = f64::from(r.ctx.style().interaction.tooltip_delay);
    if now - start < delay {
        r.ctx
            .request_repaint_after_secs((delay - (now - start)) as f32);
        return false;
    }
    true
}

/// `r` with its rectangle stretched down to the screen's bottom edge:
/// egui, finding no room under it, places the tooltip as it does on a touch
/// screen.
fn stand_in(r: &Response) -> Response {
    let mut shown = r.clone();
    shown.rect.max.y = shown.rect.max.y.max(r.ctx.screen_rect().bottom());
    shown
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::{pos2, vec2, Pos2, Rect};

    /// A press is a tap only up to the tooltip's delay, as the window sets
    /// it while a finger is down.
    fn finger_click_limit(ctx: &Context) {
        let delay = f64::from(ctx.style().interaction.tooltip_delay);
        ctx.options_mut(|o| o.input_options.max_click_duration = delay);
    }

    /// One pass of egui at `time` with `events`, a button at `at` with its
    /// tooltip, a finger down or not; the rectangle of the tooltip showing.
    fn pass(
        ctx: &Context,
        time: f64,
        events: Vec<egui::Event>,
        at: Pos2,
        finger: bool,
    ) -> Option<Rect> {
        let input = egui::RawInput {
            time: Some(time),
            screen_rect: Some(Rect::from_min_size(Pos2::ZERO, vec2(800.0, 600.0))),
            events,
            ..Default::default()
        };
        let _ = ctx.run(input, |ctx| {
            set_finger(ctx, finger);
            egui::Area::new(Id::new("buttons"))
                .fixed_pos(at)
                .show(ctx, |ui| ui.button("Play").tip("Space: pause / resume"));
        });
        let layers = ctx.memory(|m| m.areas().visible_layer_ids());
        layers
            .into_iter()
            .find(|l| l.order == egui::Order::Tooltip)
            .and_then(|l| egui::AreaState::load(ctx, l.id).map(|a| a.rect()))
    }

    /// The rectangle of the tooltip a button at `at` shows in each pass
    /// (every 0.1 s), the pointer arriving on it at 0.3 s (egui places the
    /// area in its first passes) and, with a finger, pressing it there and
    /// holding.
    fn tooltip_of_button(at: Pos2, finger: bool) -> Vec<Option<Rect>> {
        let ctx = Context::default();
        if finger {
            finger_click_limit(&ctx);
        }
        let on = at + vec2(5.0, 5.0);
        let mut shown = Vec::new();
        for k in 0..=18 {
            let mut events = Vec::new();
            if k == 3 {
                events.push(egui::Event::PointerMoved(on));
                if finger {
                    events.push(egui::Event::PointerButton {
                        pos: on,
                        button: egui::PointerButton::Primary,
                        pressed: true,
                        modifiers: egui::Modifiers::NONE,
                    });
                }
            }
            shown.push(pass(&ctx, f64::from(k) * 0.1, events, at, finger));
        }
        shown
    }

    /// The tooltip's place once settled: from the pass after the first it
    /// shows in (egui sizes it in that one), the same in every pass.
    fn settled(passes: &[Option<Rect>]) -> Rect {
        let first = passes.iter().position(Option::is_some).expect("a tooltip");
        let after = &passes[first + 1..];
        assert!(
            after.len() >= 2 && after.iter().all(|p| *p == after[0]),
            "{passes:?}"
        );
        after[0].unwrap()
    }

    #[test]
    fn a_finger_held_on_a_control_shows_its_tooltip_above_or_beside_it_never_under_it() {
        // Mid-screen: under the control for the mouse, above it for a finger.
        let at = pos2(300.0, 300.0);
        let mouse = settled(&tooltip_of_button(at, false));
        assert!(mouse.top() > at.y + 10.0, "mouse: {mouse:?}");
        let passes = tooltip_of_button(at, true);
        let finger = settled(&passes);
        assert!(finger.bottom() <= at.y, "finger: {finger:?}");
        // Not before the finger has been held for the tooltip's delay (0.5
        // s from the press at 0.1 s): a tap shows nothing.
        let first = passes.iter().position(Option::is_some).unwrap();
        assert!(
            first as f64 * 0.1 >= 0.6 - 1e-9,
            "shown at pass {first}: {passes:?}"
        );
        // At the screen's top, as the top bar's Play: no room above, so to
        // the right, level with the control.
        let at = pos2(10.0, 4.0);
        let finger = settled(&tooltip_of_button(at, true));
        assert!(finger.left() > at.x + 20.0, "finger at the top: {finger:?}");
        assert!(finger.top() <= at.y + 1.0, "finger at the top: {finger:?}");
        // At the top right corner: to the left.
        let at = pos2(770.0, 4.0);
        let finger = settled(&tooltip_of_button(at, true));
        assert!(finger.right() <= at.x, "finger at the corner: {finger:?}");
        assert!(
            finger.top() <= at.y + 1.0,
            "finger at the corner: {finger:?}"
        );
    }

    /// egui shows no tooltip after a click until the pointer moves, and a
    /// finger never moves before it lands: after a tap, a finger held on
    /// a control still shows its tooltip.
    #[test]
    fn after_a_tap_a_held_finger_still_shows_the_tooltip() {
        let ctx = Context::default();
        finger_click_limit(&ctx);
        let on = pos2(305.0, 305.0);
        let button = |pressed| egui::Event::PointerButton {
            pos: on,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        };
        // The pointer there at 0.3 s, a tap at 0.4 s, a press at 1.0 s held
        // to 2.0 s.
        let mut shown = false;
        for k in 0..=20 {
            let events = match k {
                3 => vec![egui::Event::PointerMoved(on)],
                4 => vec![button(true)],
                5 => vec![button(false)],
                10 => vec![button(true)],
                _ => vec![],
            };
            shown = pass(&ctx, f64::from(k) * 0.1, events, pos2(300.0, 300.0), true).is_some();
        }
        assert!(shown, "no tooltip after a tap");
    }
}
