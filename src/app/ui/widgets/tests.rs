//! The slider's value box as a person types into it.

use super::{slider, Reading};
use egui::{pos2, vec2, Context, Event, Key, Modifiers, PointerButton, Pos2, Rect};

use super::key_press as press;

/// A frame's input in a 400 × 300 window at `time`, with `events`.
fn input(time: Option<f64>, events: Vec<Event>) -> egui::RawInput {
    egui::RawInput {
        time,
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, vec2(400.0, 300.0))),
        events,
        ..Default::default()
    }
}

/// What became of typing `text` into the value box of a slider over
/// `range` showing `start`: the value it holds after Enter, and the line
/// shown under it (in English) then, and 10 s later.
fn typed(
    text: &str,
    start: f64,
    range: std::ops::RangeInclusive<f64>,
    reading: Reading,
) -> (f64, Option<String>, Option<String>) {
    let ctx = Context::default();
    let mut value = start;
    let pass = |time: f64, events: Vec<Event>, value: &mut f64| {
        let mut track = Rect::NOTHING;
        let out = ctx.run(input(Some(time), events), |ctx| {
            egui::CentralPanel::default().show(ctx, |ui| {
                ui.set_width(300.0);
                let (r, _) = slider(ui, "Restitution", value, range.clone(), reading);
                track = r.rect;
            });
        });
        // The line under the slider, if any: the text shapes below the track.
        let below: Vec<String> = out
            .shapes
            .iter()
            .filter_map(|c| match &c.shape {
                egui::Shape::Text(t) if t.pos.y > track.bottom() => {
                    Some(t.galley.text().to_string())
                }
                _ => None,
            })
            .collect();
        ((!below.is_empty()).then(|| below.join(" ")), track)
    };
    let (_, track) = pass(0.0, vec![], &mut value);
    // The value box sits right of the track: a click there starts typing.
    let at = pos2(track.right() + 40.0, track.center().y);
    let click = |pressed| Event::PointerButton {
        pos: at,
        button: PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    };
    pass(0.1, vec![Event::PointerMoved(at), click(true)], &mut value);
    pass(0.2, vec![click(false)], &mut value);
    let select_all = press(Key::A, Modifiers::COMMAND);
    pass(0.3, vec![select_all, Event::Text(text.into())], &mut value);
    pass(0.4, vec![press(Key::Enter, Modifiers::NONE)], &mut value);
    let (then, _) = pass(0.5, vec![], &mut value);
    let (later, _) = pass(10.5, vec![], &mut value);
    (value, then, later)
}

#[test]
fn a_number_typed_past_the_range_is_set_to_its_end_and_the_slider_says_so() {
    let (value, said, later) = typed("5", 0.8, 0.0..=1.0, Reading::new(2, ""));
    assert_eq!(value, 1.0);
    let said = said.expect("a line under the slider");
    assert!(
        said.contains("5 is outside 0.00 to 1.00: set to 1.00"),
        "{said}"
    );
    assert_eq!(later, None, "the line goes after a few seconds");
    // In the range: taken as typed, nothing said.
    let (value, said, _) = typed("0.5", 0.8, 0.0..=1.0, Reading::new(2, ""));
    assert_eq!((value, said), (0.5, None));
}

#[test]
fn a_sign_typed_into_a_size_is_dropped_and_said() {
    // Gravity, pointing down: −9.8 as the textbook writes it is 9.8 down.
    let gravity = Reading::new(2, " m/s²").magnitude();
    let (value, said, _) = typed("-9.8", 0.0, 0.0..=20.0, gravity);
    assert!((value - 9.8).abs() < 1e-12, "{value}");
    let said = said.expect("a line under the slider");
    assert!(said.contains("−9.8 read as 9.80 m/s²"), "{said}");
    // A size past the range is set to its end, sign or not.
    let (value, said, _) = typed("-50", 0.0, 0.0..=20.0, gravity);
    assert_eq!(value, 20.0);
    assert!(said.is_some_and(|s| s.contains("−50 is outside")));
}

/// A slider with the keyboard (reached by Tab), after each of `keys` in
/// turn: its value, from `start` on `range`.
fn after_arrows(
    start: f64,
    range: std::ops::RangeInclusive<f64>,
    reading: Reading,
    keys: &[(Key, Modifiers)],
) -> Vec<f64> {
    let ctx = Context::default();
    let mut value = start;
    let mut pass = |events: Vec<Event>| {
        let _ = ctx.run(input(None, events), |ctx| {
            egui::CentralPanel::default().show(ctx, |ui| {
                ui.set_width(300.0);
                slider(ui, "Restitution", &mut value, range.clone(), reading);
            });
        });
        value
    };
    pass(vec![]);
    pass(vec![press(Key::Tab, Modifiers::NONE)]);
    pass(vec![]);
    keys.iter()
        .map(|&(key, modifiers)| pass(vec![press(key, modifiers)]))
        .collect()
}

/// The review's "three presses took restitution from 1.00 to 0.95": egui
/// moves a slider's knob a point a press. A press is now a twentieth of the
/// range, on that grid; with Shift a hundredth.
#[test]
fn the_arrows_move_a_slider_a_twentieth_of_its_range_and_shift_a_hundredth() {
    let left = (Key::ArrowLeft, Modifiers::NONE);
    let right = (Key::ArrowRight, Modifiers::NONE);
    let fine = (Key::ArrowLeft, Modifiers::SHIFT);
    let values = after_arrows(
        1.0,
        0.0..=1.0,
        Reading::new(2, ""),
        &[left, left, left, fine, right, right],
    );
    let expected = [0.95, 0.90, 0.85, 0.84, 0.85, 0.90];
    for (v, e) in values.iter().zip(expected) {
        assert!((v - e).abs() < 1e-12, "{values:?}");
    }
    // At the end it stays; on a logarithmic track, by its decades.
    let values = after_arrows(1.0, 0.0..=1.0, Reading::new(2, ""), &[right]);
    assert_eq!(values, [1.0]);
    let values = after_arrows(
        1.0,
        0.1..=10.0,
        Reading::new(2, "").log(),
        &[right, left, left],
    );
    let expected = [10f64.powf(0.1), 1.0, 10f64.powf(-0.1)];
    for (v, e) in values.iter().zip(expected) {
        assert!((v - e).abs() < 1e-9, "{values:?}");
    }
}
