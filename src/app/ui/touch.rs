//! A finger on a touch screen: a press held past the tooltip's delay shows
//! the tooltip and presses nothing.

/// A finger held on a control shows its tooltip once the tooltip's delay
/// has passed, as a resting mouse does; letting go then must not press the
/// control. So while a finger is on the screen a press is a tap only as long
/// as that delay (egui's own limit, 0.8 s, stays for the mouse), and its
/// tooltips go where the hand does not cover them ([`tip`]).
pub fn hold_is_not_a_tap(ctx: &egui::Context) {
    let finger = !macroquad::input::touches().is_empty();
    super::tip::set_finger(ctx, finger);
    let limit = longest_click(finger, ctx.style().interaction.tooltip_delay);
    ctx.options_mut(|o| o.input_options.max_click_duration = limit);
}

/// egui's own limit on a click's length (s), for the mouse.
static MOUSE_CLICK: std::sync::LazyLock<f64> =
    std::sync::LazyLock::new(|| egui::Options::default().input_options.max_click_duration);

/// How long a press may last and still be a click or tap (s).
fn longest_click(finger: bool, tooltip_delay: f32) -> f64 {
    if finger {
        f64::from(tooltip_delay)
    } else {
        *MOUSE_CLICK
    }
}

#[cfg(test)]
mod tests {
    use super::longest_click;

    /// Whether a button pressed at 0.1 s and let go at `up` s was clicked,
    /// with presses limited to `limit` s.
    fn clicked(limit: f64, up: f64) -> bool {
        let ctx = egui::Context::default();
        ctx.options_mut(|o| o.input_options.max_click_duration = limit);
        let at = egui::pos2(20.0, 10.0);
        let button = |pressed: bool, time: f64| egui::RawInput {
            time: Some(time),
            events: vec![egui::Event::PointerButton {
                pos: at,
                button: egui::PointerButton::Primary,
                pressed,
                modifiers: egui::Modifiers::NONE,
            }],
            ..Default::default()
        };
        // A first pass lays the button out (egui hits what the last pass
        // drew) with the pointer already over it.
        let over = egui::RawInput {
            time: Some(0.0),
            events: vec![egui::Event::PointerMoved(at)],
            ..Default::default()
        };
        let mut was_clicked = false;
        for input in [over, button(true, 0.1), button(false, up)] {
            let _ = ctx.run(input, |ctx| {
                egui::CentralPanel::default().show(ctx, |ui| {
                    was_clicked |= ui.button("Play").clicked();
                });
            });
        }
        was_clicked
    }

    #[test]
    fn a_finger_let_go_after_the_tooltips_delay_does_not_press_but_a_mouse_may() {
        let (delay, up) = (0.5, 0.75);
        assert!(clicked(longest_click(true, delay), 0.3), "a tap presses");
        assert!(
            !clicked(longest_click(true, delay), up),
            "a held finger does not"
        );
        assert!(
            clicked(longest_click(false, delay), up),
            "a slow mouse click does"
        );
    }
}
